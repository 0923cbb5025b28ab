// Certified balls as text and doubles for tables (the cells' CSV, JSON,
// GeoJSON and NumPy arrays): every printed bound is rounded outward, so the
// printed interval contains the ball, hence the exact value. Infinite
// endpoints print as "inf"/"-inf"; a ball that claims nothing (an
// indeterminate ball: NaN midpoint) as "nan" (NaN doubles).
#pragma once

#include "util/flint_types.hpp"

#include <string>
#include <utility>

namespace ellvor {

enum class Rounding { down, up };  // toward -infinity, toward +infinity

// mantissa * 10^exponent, exactly.
struct Decimal {
    Integer mantissa;
    long exponent = 0;
};

// q rounded to `digits` significant decimal digits in the direction `r`.
Decimal round_decimal(const Rational& q, int digits, Rounding r);
Rational decimal_value(const Decimal& d);
// The text of d: plain ("12.5", "0.00031") for decimal exponents in
// [-5, 21), else scientific ("1.25e-7", "3e25"); both parse_rational and
// Python's float() read it back. Trailing zeros are dropped unless kept (they
// are significant in certain_digits: then a last digit left of the point is
// written with an exponent, "1.20e3").
std::string decimal_text(const Decimal& d, bool keep_trailing_zeros = false);

// The ball's endpoints as text: lo rounded down, hi rounded up, with at least
// 17 significant digits and 3 more than the ball's own relative width shows
// (at most 60), so that a width of 1e-30 stays visible.
struct DecimalBounds {
    std::string lo, hi;
};
DecimalBounds decimal_bounds(const Ball& b);

// The digits of the ball that are certain: the decimal d with the most
// significant digits (at most 17) such that every point of the ball is within
// one unit of d's last digit; "nan" if not even one digit is (or the ball is
// not finite).
std::string certain_digits(const Ball& b);

// The ball's endpoints as doubles: lo rounded down, hi rounded up (+-inf
// beyond the double range; NaN for an indeterminate ball).
std::pair<double, double> double_bounds(const Ball& b);

}  // namespace ellvor
