// A real algebraic number: a squarefree integer polynomial and either an exact
// rational value or an open isolating interval with rational endpoints.
// Comparisons and signs are exact. Queries may refine the interval (and may
// replace the polynomial by a factor that still has the number as a root),
// hence the non-const references below.
#pragma once

#include "exact/real_roots.hpp"
#include "util/flint_types.hpp"

#include <string>
#include <vector>

namespace ellvor {

class AlgebraicReal {
public:
    AlgebraicReal();  // zero

    static AlgebraicReal from_rational(const Rational& q);
    // The unique root of p in the open interval (lo, hi). Requires p
    // squarefree (or at least: the root is simple and the only root of p in
    // [lo, hi]); checks that p(lo) and p(hi) are nonzero with opposite signs
    // and throws Error otherwise. When lo == hi, p(lo) must be 0.
    static AlgebraicReal from_interval(const IntPolynomial& p, const Rational& lo, const Rational& hi);

    bool is_rational() const { return lo_ == hi_; }
    const Rational& rational_value() const;  // throws Error unless is_rational()
    // Primitive, positive leading coefficient, squarefree; for a rational
    // value it is den*x - num.
    const IntPolynomial& polynomial() const { return p_; }
    const Rational& lo() const { return lo_; }  // == hi() when rational
    const Rational& hi() const { return hi_; }

    // Shrinks the interval to width <= 2^-bits (no-op if rational).
    void refine(long bits);
    // Splits the interval at a rational x inside it (exact; may make the value
    // rational if x is the root).
    void split_at(const Rational& x);
    // A certified enclosure with about prec bits of relative accuracy
    // (absolute accuracy 2^-prec when the number is 0).
    Ball to_ball(long prec);
    double to_double();
    std::string str() const;  // "[lo, hi] root of p" or the rational

private:
    void set_rational(const Rational& q);
    // Replaces the polynomial by a factor g that still has the root inside.
    void set_polynomial(const IntPolynomial& g);

    IntPolynomial p_;
    Rational lo_, hi_;
    int sign_lo_ = 0;  // sign of p_ on (lo_, root)
};

// Exact -1 / 0 / +1 for x < y, x == y, x > y.
int compare(AlgebraicReal& x, AlgebraicReal& y);
// Exact sign of q(x).
int sign_at(const IntPolynomial& q, AlgebraicReal& x);
// The distinct real roots of p in ascending order, each defined by the
// squarefree factor of p that owns it. Throws Error on the zero polynomial.
std::vector<AlgebraicReal> real_roots(const IntPolynomial& p);

}  // namespace ellvor
