"""Exact conversions of Python numbers into sites, and their refusals."""

import decimal
import math
import pickle
from fractions import Fraction

import numpy as np
import pytest

import ellvor


def test_each_number_type_is_exact():
    e = ellvor.Ellipse(3, Fraction(1, 2), "0.1", 0.1, decimal.Decimal("-2.5"))
    assert e.a == Fraction(3) and e.b == Fraction(1, 2)
    assert e.w == Fraction(1, 10)  # a str is read as the .ell grammar: "0.1" is 1/10
    assert e.xc == Fraction(0.1) == Fraction(3602879701896397, 2**55)  # a float exactly, as Fraction(float)
    assert e.yc == Fraction(-5, 2)
    assert all(isinstance(v, Fraction) for v in (e.a, e.b, e.w, e.xc, e.yc))


@pytest.mark.parametrize("x", [1e-300, 2.0**-1074, 1.5e300, -0.0, 123456789.123456789, np.float64(0.3)])
def test_floats_convert_exactly(x):
    assert ellvor.Ellipse(1, 1, 0, x, 0).xc == Fraction(float(x))


def test_strings_follow_the_file_grammar():
    e = ellvor.Ellipse("3/6", "1.25e-3", "-7", ".5", "5.")
    assert (e.a, e.b, e.w, e.xc, e.yc) == (Fraction(1, 2), Fraction(1, 800), -7, Fraction(1, 2), 5)
    assert str(e) == "1/2 1/800 -7 1/2 5"


def test_anything_with_numerator_and_denominator():
    class Ratio:  # e.g. gmpy2.mpq
        numerator, denominator = 6, -4
    assert ellvor.Ellipse(1, 1, Ratio(), 0, 0).w == Fraction(-3, 2)


def test_huge_integers_are_exact():
    big = 3**2000
    assert ellvor.Ellipse(1, 1, 0, big, -big).xc == big


@pytest.mark.parametrize("bad", [float("nan"), float("inf"), -float("inf"), "nan", "inf", decimal.Decimal("NaN"),
                                 decimal.Decimal("Infinity")])
def test_non_finite_numbers_are_value_errors(bad):
    with pytest.raises(ValueError, match="not a finite number"):
        ellvor.Ellipse(1, 1, 0, bad, 0)


def test_a_zero_denominator_is_refused_before_flint():
    class Broken:
        numerator, denominator = 1, 0
    with pytest.raises(ellvor.InputError, match="zero denominator"):
        ellvor.Ellipse(1, 1, Broken(), 0, 0)
    with pytest.raises(ellvor.InputError, match="zero denominator"):
        ellvor.Ellipse(1, 1, "1/0", 0, 0)


@pytest.mark.parametrize("a, b, message", [(0, 1, "semi-axis a must be positive, found 0"),
                                            (1, "-1/2", "semi-axis b must be positive, found -1/2"),
                                            (-0.0, 1, "semi-axis a must be positive"),
                                            (2**41, 1, "differ by more than a factor 2\\^40")])
def test_bad_axes(a, b, message):
    with pytest.raises(ellvor.InputError, match=message) as err:
        ellvor.Ellipse(a, b, 0, 0, 0)
    assert isinstance(err.value, ValueError) and isinstance(err.value, ellvor.Error)
    assert err.value.filename is None and err.value.lineno is None and err.value.sites is None


def test_bad_strings_carry_the_parser_message():
    with pytest.raises(ellvor.InputError) as err:
        ellvor.Ellipse(1, 1, 0, "1.2.3", 0)
    assert str(err.value) == ("xc: expected a rational number (an integer, p/q, or a decimal such as -1.25e-3), "
                              "found '1.2.3' (more than one '.')")


def test_numbers_beyond_4096_bits():
    with pytest.raises(ellvor.InputError, match="limited to 4096 bits"):
        ellvor.Ellipse(1, 1, 0, 2**5000, 0)
    with pytest.raises(ellvor.InputError, match="limited to 4096 bits"):
        ellvor.Ellipse(1, 1, 0, Fraction(1, 3**3000), 0)


def test_numpy_scalars():
    assert [ellvor.Ellipse(1, 1, 0, x, 0).xc for x in (np.int64(-5), np.uint8(7), np.float32(0.1))] == \
        [-5, 7, Fraction(float(np.float32(0.1)))]


@pytest.mark.parametrize("bad", [True, np.bool_(True), None, [1], object()])
def test_other_types_are_type_errors(bad):
    with pytest.raises(TypeError):
        ellvor.Ellipse(1, 1, 0, bad, 0)


def test_ellipse_value_semantics():
    e = ellvor.Ellipse("3/2", "1/2", 0, "0.1", -7)
    assert repr(e) == "Ellipse('3/2', '1/2', '0', '1/10', '-7')"
    assert e == ellvor.Ellipse(Fraction(3, 2), 0.5, 0, Fraction(1, 10), -7)
    assert hash(e) == hash(ellvor.Ellipse(1.5, 0.5, 0, "1/10", -7))
    assert pickle.loads(pickle.dumps(e)) == e
    # A quarter turn with swapped axes is the same point set, not the same ellipse.
    turned = ellvor.Ellipse("1/2", "3/2", 1, "0.1", -7)
    assert turned != e and turned.same_point_set(e)
    c = ellvor.Ellipse.circle(1, 2, "1/3")
    assert c.is_circle and (c.a, c.xc, c.yc) == (Fraction(1, 3), 1, 2)


def test_sites_to_array_gives_the_nearest_doubles():
    s = ellvor.Sites([ellvor.Ellipse(1, "1/3", "0.1", 2, -3), ellvor.Ellipse.circle(10, 0, 2)])
    a = s.to_array()
    assert a.shape == (2, 5) and a.dtype == np.float64
    assert a[0].tolist() == [1.0, 1 / 3, 0.1, 2.0, -3.0]
    assert len(s) == 2 and s[-1] == ellvor.Ellipse.circle(10, 0, 2) and s.filename is None
    with pytest.raises(IndexError):
        s[2]


def test_float_conversion_matches_fraction_on_random_doubles():
    rng = np.random.default_rng(5)
    xs = np.concatenate([rng.standard_normal(200) * 10.0 ** rng.integers(-300, 300, 200),
                         rng.integers(-2**53, 2**53, 50).astype(float)])
    for x in xs:
        if math.isfinite(x) and x != 0:
            assert ellvor.Ellipse(1, 1, 0, x, 0).xc == Fraction(x)
