// Real numbers of a real quadratic field: a + b sqrt(d) with rationals a, b
// and a rational radicand d >= 0. The closed-form circle predicates
// (circles/circle_predicates.hpp) live in such fields: everything they
// compare is a rational, one element of Q(sqrt d), or the difference of two
// elements of different fields.
//
// Every sign here is exact: decided by case analysis on the signs of the
// parts and, when they disagree, by comparing squares in rationals. A double
// interval pre-check (outward rounded, util/interval.hpp) answers first when
// it proves the sign; it never decides anything it does not prove.
#pragma once

#include "util/flint_types.hpp"

#include <string>

namespace ellvor {

// sign(a + b sqrt(d)), d >= 0. Proof: when a and b sqrt(d) do not have
// opposite signs the sign is read off; otherwise |a| and |b| sqrt(d) compare
// as a^2 and b^2 d, so the sign is sign(a) * sign(a^2 - b^2 d).
int sign_of_quadratic(const Rational& a, const Rational& b, const Rational& d);
// The same for integers (no fractions to reduce: the fast path of the
// closed-form predicates, which scale their sites to integers).
int sign_of_quadratic(const Integer& a, const Integer& b, const Integer& d);

// sign(x + y sqrt(d1) + z sqrt(d2)), d1, d2 >= 0 (any two radicands). Proof:
// with u = x + y sqrt(d1) and v = z sqrt(d2), the sign is read off unless u
// and v have opposite signs; then it is sign(u) * sign(u^2 - v^2), and
// u^2 - v^2 = (x^2 + y^2 d1 - z^2 d2) + 2 x y sqrt(d1) is again an element of
// Q(sqrt d1), decided by sign_of_quadratic. Exact zeros (sqrt 8 - 2 sqrt 2)
// come out as 0.
int sign_of_two_roots(const Rational& x, const Rational& y, const Rational& d1, const Rational& z,
                      const Rational& d2);
int sign_of_two_roots(const Integer& x, const Integer& y, const Integer& d1, const Integer& z, const Integer& d2);

// sign(a + b sqrt(d1) + c sqrt(d2) + e sqrt(d1) sqrt(d2)), d1, d2 >= 0: the
// sign of a product of two elements of Q(sqrt d1), Q(sqrt d2) plus another
// (cross and dot products of vectors with coordinates in two fields). Proof:
// with u = a + b sqrt(d1), v = c + e sqrt(d1) in Q(sqrt d1) it is u + v
// sqrt(d2), whose sign is read off unless sign(u) = -sign(v); then it is
// sign(u) * sign(u^2 - v^2 d2), and u^2 - v^2 d2 is again in Q(sqrt d1).
int sign_of_biquadratic(const Integer& a, const Integer& b, const Integer& c, const Integer& e, const Integer& d1,
                        const Integer& d2);

class QuadraticNumber {
public:
    QuadraticNumber() = default;  // 0
    QuadraticNumber(const Rational& rational);  // NOLINT: a rational is a quadratic number (implicit on purpose)
    // a + b sqrt(d); throws Error if d < 0. Stored normalized: when b or d is
    // zero both are (then the number is the rational a).
    QuadraticNumber(Rational a, Rational b, Rational d);

    const Rational& rational_part() const { return a_; }
    const Rational& root_coefficient() const { return b_; }
    const Rational& radicand() const { return d_; }
    // No square-root part (b = d = 0). A perfect-square radicand is not
    // recognized: 1 + sqrt(4) is "irrational" here, and that is harmless.
    bool is_rational() const { return d_.is_zero(); }

    int sign() const { return sign_of_quadratic(a_, b_, d_); }

    // Arithmetic within one field: the operands must share their radicand
    // unless one of them is rational; throws Error otherwise (different
    // radicands may still be one field, e.g. 8 and 2, but nothing here needs
    // that, and mixing fields is what compare() is for).
    QuadraticNumber operator-() const;
    friend QuadraticNumber operator+(const QuadraticNumber& x, const QuadraticNumber& y);
    friend QuadraticNumber operator-(const QuadraticNumber& x, const QuadraticNumber& y);
    friend QuadraticNumber operator*(const QuadraticNumber& x, const QuadraticNumber& y);

    // sign(x - y) for numbers of any two fields, exactly (sign_of_two_roots).
    friend int compare(const QuadraticNumber& x, const QuadraticNumber& y);
    friend bool operator==(const QuadraticNumber& x, const QuadraticNumber& y) { return compare(x, y) == 0; }
    friend bool operator!=(const QuadraticNumber& x, const QuadraticNumber& y) { return compare(x, y) != 0; }

    // An Arb enclosure at `prec` bits (for printing and tests).
    Ball to_ball(long prec) const;
    // "a + b*sqrt(d)", or "a" for a rational.
    std::string str() const;

private:
    // The radicand of the result of x op y (Error if the fields differ).
    static const Rational& common_radicand(const QuadraticNumber& x, const QuadraticNumber& y);

    Rational a_, b_, d_;
};

}  // namespace ellvor
