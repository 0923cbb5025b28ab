"""The module as a whole: the import line of the README, what build() accepts,
generate()'s checks, writing sites, and the scripts that use the module."""

import math
import os
import pathlib
import shutil
import subprocess
import sys
from fractions import Fraction

import pytest

import ellvor

# The children import the same build of the module as this process.
ENV = dict(os.environ, MPLBACKEND="Agg", PYTHONPATH=str(pathlib.Path(ellvor.__file__).resolve().parents[1]))


def run_python(*args, cwd):
    return subprocess.run([sys.executable, *args], capture_output=True, text=True, cwd=cwd, env=ENV, check=True)


def test_the_readme_import_line(root):
    out = run_python("-c", "import ellvor, sys; print(ellvor.build('data/example-300.ell')); "
                           "print('matplotlib' in sys.modules)", cwd=root).stdout.splitlines()
    assert out[0].startswith("<ellvor.Diagram: 300 sites (30 hidden), ")
    assert out[1] == "False"  # plotting is imported on use only


def test_build_accepts_paths_sites_and_lists(root):
    path = root / "data" / "example.ell"
    expected = ellvor.build(str(path)).edges.tolist()
    sites = ellvor.read_sites(path)
    for argument in (path, os.fsencode(path), sites, list(sites), tuple(sites)):
        assert ellvor.build(argument).edges.tolist() == expected
    with pytest.raises(TypeError):
        ellvor.build([sites[0], "1 1 0 0 0"])
    with pytest.raises(TypeError):
        ellvor.build(42)


def test_generate_checks_its_arguments(cli, write_sites):
    for kwargs in ({"kind": "squares"}, {"count": -1}, {"count": 10**7}, {"bits": 0}, {"bits": 1001},
                   {"box": 0}, {"box": "-1"}, {"nested_fraction": 1}, {"nested_fraction": "-0.1"},
                   {"count": 5000, "box": "1/100"}, {"crossing": "1/10"}, {"kind": "circles", "crossing": 2},
                   {"kind": "circles", "count": 10, "crossing": "1/10"}, {"kind": "nested", "crossing": "0.9"}):
        with pytest.raises(ValueError):
            ellvor.generate(**kwargs)
    nested = ellvor.generate("nested", count=40, seed=3)
    assert len(ellvor.build(nested).hidden) == 10  # a quarter by default, as the CLI
    assert all(e.is_circle for e in ellvor.generate("circles", count=30))
    # As `ellvor generate circles --crossing 3/10`: exactly 30% cross another circle.
    crossing = ellvor.generate("circles", count=100, seed=4, crossing="3/10")
    _, text, _ = cli("generate", "circles", "--count", 100, "--seed", 4, "--crossing", "3/10")
    assert list(crossing) == list(ellvor.read_sites(write_sites(text)))
    d = ellvor.build(crossing)
    assert d.validate() == ""


# An exact check of generated crossing ellipses independent of the library:
# the conic of one site along the other's rational boundary parametrization,
# a quartic in t over Fractions, whose distinct real roots (Sturm) are the
# points where the boundaries meet, t = infinity when the degree drops.

def _polynomial(*coefficients):
    """Coefficients low first, trailing zeros dropped."""
    p = [Fraction(c) for c in coefficients]
    while p and p[-1] == 0:
        p.pop()
    return p


def _add(p, q):
    n = max(len(p), len(q))
    return _polynomial(*((p[i] if i < len(p) else 0) + (q[i] if i < len(q) else 0) for i in range(n)))


def _scale(p, c):
    return _polynomial(*(c * x for x in p))


def _multiply(p, q):
    out = [Fraction(0)] * max(len(p) + len(q) - 1, 0)
    for i, x in enumerate(p):
        for j, y in enumerate(q):
            out[i + j] += x * y
    return _polynomial(*out)


def _remainder(p, q):
    p = list(p)
    while len(p) >= len(q):
        factor = p[-1] / q[-1]
        shift = len(p) - len(q)
        p = _add(p, [Fraction(0)] * shift + _scale(q, -factor))
    return p


def _derivative(p):
    return _polynomial(*(i * c for i, c in enumerate(p)))[1:]


def _is_squarefree(p):
    a, b = p, _derivative(p)
    while b:
        a, b = b, _remainder(a, b)
    return len(a) == 1


def _distinct_real_roots(p):
    """Sturm's theorem (p, p', -rem, ...), which counts each root once."""
    sequence = [p, _derivative(p)]
    while len(sequence[-1]) > 1:
        r = _remainder(sequence[-2], sequence[-1])
        if not r:
            break
        sequence.append(_scale(r, -1))

    def sign_changes(at_plus_infinity):
        signs = [(1 if q[-1] > 0 else -1) * (1 if at_plus_infinity or len(q) % 2 else -1) for q in sequence if q]
        return sum(a != b for a, b in zip(signs, signs[1:]))
    return sign_changes(False) - sign_changes(True)


def _rotation(e):
    return (1 - e.w ** 2) / (1 + e.w ** 2), 2 * e.w / (1 + e.w ** 2)


def _conic_along(e1, e2):
    """E2's conic (negative inside) at P1(t), times (1 + t^2)^2."""
    c1, s1 = _rotation(e1)
    c2, s2 = _rotation(e2)
    w = _polynomial(1, 0, 1)
    along_a, along_b = _scale(_polynomial(1, 0, -1), e1.a), _polynomial(0, 2 * e1.b)  # a cos, b sin, times W
    dx = _add(_add(_scale(w, e1.xc - e2.xc), _scale(along_a, c1)), _scale(along_b, -s1))
    dy = _add(_add(_scale(w, e1.yc - e2.yc), _scale(along_a, s1)), _scale(along_b, c1))
    xi, eta = _add(_scale(dx, c2), _scale(dy, s2)), _add(_scale(dx, -s2), _scale(dy, c2))
    return _add(_add(_scale(_multiply(xi, xi), 1 / e2.a ** 2), _scale(_multiply(eta, eta), 1 / e2.b ** 2)),
                _scale(_multiply(w, w), -1))


def _value(p, t):
    return sum(c * t ** i for i, c in enumerate(p))


def _crossing_and_nested(sites):
    """Sites crossing another (two meeting points, both simple roots) and sites inside another."""
    crosses, nested = set(), set()
    for i, e1 in enumerate(sites):
        for j in range(i + 1, len(sites)):
            e2 = sites[j]
            reach = max(e1.a, e1.b) + max(e2.a, e2.b)
            if (e1.xc - e2.xc) ** 2 + (e1.yc - e2.yc) ** 2 > reach ** 2:
                continue
            quartic = _conic_along(e1, e2)
            meeting = _distinct_real_roots(quartic) + (len(quartic) < 5)
            assert meeting in (0, 2), f"sites {i} and {j} meet in {meeting} points"
            if meeting == 2:
                # both crossings: simple roots, t = infinity at most once (degree 3)
                assert len(quartic) >= 4 and _is_squarefree(quartic), f"sites {i} and {j} touch"
                crosses.update((i, j))
            elif _value(quartic, 0) < 0:
                nested.add(i)
            elif _value(_conic_along(e2, e1), 0) < 0:
                nested.add(j)
    return crosses, nested


@pytest.mark.parametrize("kind, count, seed, crossing, crossing_sites, nested_sites", [
    ("ellipses", 120, 3, "3/10", 36, 0),
    ("ellipses", 61, 4, 1, 61, 0),
    ("nested", 80, 5, "1/2", 40, 20),
    ("ellipses", 50, 6, 0, 0, 0),
])
def test_generate_crossing_ellipses(cli, write_sites, kind, count, seed, crossing, crossing_sites, nested_sites):
    sites = ellvor.generate(kind, count=count, seed=seed, crossing=crossing)
    _, text, _ = cli("generate", kind, "--count", count, "--seed", seed, "--crossing", crossing)
    assert list(sites) == list(ellvor.read_sites(write_sites(text)))
    assert list(ellvor.generate(kind, count=count, seed=seed, crossing=crossing)) == list(sites)
    crosses, nested = _crossing_and_nested(list(sites))
    assert (len(crosses), len(nested)) == (crossing_sites, nested_sites)
    assert not crosses & nested
    assert "crossing" in ellvor.generate.__doc__


@pytest.mark.parametrize("fmt", ["ell", "cin"])
def test_sites_write_and_read_back_exactly(tmp_path, fmt):
    sites = ellvor.generate("circles", count=25, seed=8, bits=30)
    path = tmp_path / f"s.{fmt}"
    sites.write(path, fmt=fmt)
    back = ellvor.read_sites(path, fmt=fmt)
    assert list(back) == list(sites) and back.filename == str(path)
    assert back.lines.tolist() == list(range(1, 26))


def test_the_example_script(root, tmp_path):
    out = tmp_path / "example.png"
    text = run_python(str(root / "examples" / "plot_example.py"), str(out), cwd=tmp_path).stdout
    assert "300 sites (30 hidden)" in text and "\nvalid\n" in text and "incircle:" in text
    assert out.read_bytes()[:4] == b"\x89PNG"


def test_the_results_charts(root, tmp_path):
    for name in ("build_scaling", "precision_vs_time", "degeneracy_stress"):
        shutil.copy(root / "experiments" / "results" / f"{name}.csv", tmp_path)
    run_python(str(root / "experiments" / "plot_results.py"), "--dir", str(tmp_path), cwd=tmp_path)
    for name in ("build_scaling", "precision_vs_time", "degeneracy_stress"):
        assert pathlib.Path(tmp_path / f"{name}.png").read_bytes()[:4] == b"\x89PNG"


def test_generate_packing_as_the_cli(cli, write_sites):
    sites = ellvor.generate("packing", count=300, seed=5, packing_fraction="0.58", gap="1/1000", aspect=(1, 3))
    _, text, _ = cli("generate", "packing", "--count", 300, "--seed", 5, "--packing-fraction", "0.58", "--gap",
                     "1/1000", "--aspect", "1..3")
    assert list(sites) == list(ellvor.read_sites(write_sites(text)))
    assert list(ellvor.generate("packing", count=300, seed=5, packing_fraction="29/50", aspect=("1", "3"))) == list(sites)
    # The fraction reached, from the exact parameters: at least 0.58 of the box [0, 18]^2.
    area = sum(Fraction(e.a) * Fraction(e.b) for e in sites)
    assert math.pi * float(area) / 18**2 >= 0.58
    assert all(1 <= Fraction(e.a) / Fraction(e.b) <= 3 for e in sites)
    assert ellvor.build(sites).validate() == ""
    for kwargs in ({}, {"packing_fraction": 0}, {"packing_fraction": "0.9"}, {"packing_fraction": "0.84"},
                   {"packing_fraction": "0.5", "gap": -1}, {"packing_fraction": "0.5", "aspect": (2, 1)},
                   {"packing_fraction": "0.5", "aspect": (1, 2, 3)}, {"packing_fraction": "0.5", "count": 10}):
        with pytest.raises(ValueError):
            ellvor.generate("packing", **{"count": 100, **kwargs})
    with pytest.raises(ValueError, match="jammed at 0"):
        ellvor.generate("packing", count=100, packing_fraction="0.84")
    with pytest.raises(ValueError):
        ellvor.generate("ellipses", count=10, gap="1/100")
