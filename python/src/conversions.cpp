// Python numbers to exact Rationals and back (bindings.hpp).
#include "python/src/bindings.hpp"

#include "sites/rational_parse.hpp"
#include "util/error.hpp"

#include <cmath>

namespace ellvor::python {
namespace {

std::string type_name(py::handle value) { return py::str(py::type::handle_of(value).attr("__name__")); }

std::string too_large(const std::string& what) {
    return what + ": number is too large: numerator and denominator are limited to " +
           std::to_string(kMaxRationalBits) + " bits";
}

// A Python int as an Integer, refusing more than kMaxRationalBits bits
// before FLINT sees it.
Integer to_integer(py::handle value, const std::string& what) {
    const long bits = py::cast<long>(value.attr("bit_length")());
    if (bits > kMaxRationalBits) throw InputError(too_large(what));
    const std::string hex = py::str(py::reinterpret_borrow<py::object>(value).attr("__format__")("x"));
    Integer z;
    fmpz_set_str(z.get(), hex.c_str(), 16);
    return z;
}

Rational from_double(double d, const std::string& what) {
    if (!std::isfinite(d)) throw InputError(what + ": not a finite number: " + std::to_string(d));
    if (d == 0) return Rational(0);
    int e = 0;
    const double m = std::frexp(d, &e);  // d = m 2^e, 0.5 <= |m| < 1: m 2^53 is an integer
    Rational r(static_cast<long>(std::ldexp(m, 53)));
    const long shift = static_cast<long>(e) - 53;
    if (shift >= 0) fmpq_mul_2exp(r.get(), r.get(), static_cast<ulong>(shift));
    else fmpq_div_2exp(r.get(), r.get(), static_cast<ulong>(-shift));
    return r;
}

// An integer-like object (int, NumPy integers: anything with __index__) as a Python int.
py::object as_int(py::handle value, const std::string& what) {
    PyObject* n = PyNumber_Index(value.ptr());
    if (!n) {
        PyErr_Clear();
        throw py::type_error(what + ": numerator and denominator must be integers");
    }
    return py::reinterpret_steal<py::object>(n);
}

// numerator / denominator, both integers.
Rational from_ratio(py::handle num, py::handle den, const std::string& what) {
    Integer p = to_integer(as_int(num, what), what), q = to_integer(as_int(den, what), what);
    if (q.is_zero()) throw InputError(what + ": zero denominator");
    if (q.sign() < 0) p = -p, q = -q;
    return Rational(p, q);  // canonical: FLINT divides out the gcd
}

}  // namespace

Rational to_rational(py::handle value, const std::string& what) {
    PyObject* v = value.ptr();
    Rational r;
    if (PyBool_Check(v) || type_name(value) == "bool_") {  // NumPy's bool_ has __index__ too
        throw py::type_error(what + ": expected a number, got " + type_name(value));
    } else if (PyLong_Check(v)) {
        r = Rational(to_integer(value, what));
    } else if (PyIndex_Check(v) && !PyFloat_Check(v)) {
        r = Rational(to_integer(as_int(value, what), what));  // NumPy integers
    } else if (PyFloat_Check(v)) {
        r = from_double(PyFloat_AsDouble(v), what);
    } else if (PyUnicode_Check(v)) {
        std::string error;
        if (!parse_rational(py::cast<std::string>(value), r, error)) throw InputError(what + ": " + error);
    } else if (py::hasattr(value, "numerator") && py::hasattr(value, "denominator")) {
        r = from_ratio(value.attr("numerator"), value.attr("denominator"), what);
    } else if (py::hasattr(value, "as_integer_ratio")) {
        // Decimal, NumPy floats: exact ratios; NaN and infinities raise here.
        py::tuple ratio;
        try {
            ratio = value.attr("as_integer_ratio")();
        } catch (py::error_already_set& e) {
            if (!e.matches(PyExc_ValueError) && !e.matches(PyExc_OverflowError)) throw;
            throw InputError(what + ": not a finite number: " + py::cast<std::string>(py::str(value)));
        }
        r = from_ratio(ratio[0], ratio[1], what);
    } else {
        throw py::type_error(what + ": expected an int, a Fraction, a float or a str, got " + type_name(value));
    }
    if (r.bits() > kMaxRationalBits) throw InputError(too_large(what));
    return r;
}

py::int_ to_python_int(const Integer& z) {
    char* text = fmpz_get_str(nullptr, 16, z.get());
    PyObject* n = PyLong_FromString(text, nullptr, 16);
    flint_free(text);
    if (!n) throw py::error_already_set();
    return py::reinterpret_steal<py::int_>(n);
}

py::object to_fraction(const Rational& q) {
    static const char* const kModule = "fractions";
    return py::module_::import(kModule).attr("Fraction")(to_python_int(q.numerator()), to_python_int(q.denominator()));
}

py::tuple ball_tuple(const Ball& b, long bits) {
    Rational lo, hi;
    ball_endpoints(b, lo, hi);
    // The digits `ellvor voronoi-circle --bits N` prints (cli/command_voronoi_circle.cpp).
    const long digits = std::max(20L, static_cast<long>(std::ceil(bits * 0.30103)) + 5);
    return py::make_tuple(to_fraction(lo), to_fraction(hi), b.str(digits));
}

}  // namespace ellvor::python
