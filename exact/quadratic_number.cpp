#include "exact/quadratic_number.hpp"

#include "util/error.hpp"
#include "util/interval.hpp"

#include <flint/fmpz.h>

#include <cmath>
#include <limits>

namespace ellvor {

namespace {

// ------------------------------------------------- double pre-check --

// An interval that contains the integer f, from its leading bits: cheaper
// than a correctly rounded conversion and enough for a pre-check. f = m 2^e
// with m in [1/2, 1) to within one ulp (FLINT's contract); two ulps of margin
// on each side leave no doubt about the rounding direction. Not finite when f
// is out of the comfortable double range (the callers then skip the
// pre-check).
constexpr slong kExponentRange = 900;  // keeps the scaled mantissas normal and finite
Interval not_finite() {
    constexpr double inf = std::numeric_limits<double>::infinity();
    return {-inf, inf};
}
// f = m 2^e, m enclosed.
Interval mantissa(const fmpz* f, slong& e) {
    const double m = fmpz_get_d_2exp(&e, f);
    return {Interval::down(Interval::down(m)), Interval::up(Interval::up(m))};
}
Interval scaled(const Interval& m, slong e) {
    if (e > kExponentRange || e < -kExponentRange) return not_finite();
    const double scale = std::ldexp(1.0, static_cast<int>(e));  // a power of two: exact products
    return {m.lo * scale, m.hi * scale};
}
constexpr slong kExactInDouble = slong(1) << 53;
bool small(const fmpz* f) { return !COEFF_IS_MPZ(*f) && *f > -kExactInDouble && *f < kExactInDouble; }

Interval rough_enclosure(const fmpz* f) {
    if (small(f)) return Interval(double(*f));
    slong e = 0;
    const Interval m = mantissa(f, e);
    return scaled(m, e);
}

Interval rough_enclosure(const fmpq* q) {
    const fmpz* num = fmpq_numref(q);
    const fmpz* den = fmpq_denref(q);
    if (small(num) && small(den)) return Interval(double(*num)) / Interval(double(*den));
    slong en = 0, ed = 0;
    const Interval mn = mantissa(num, en), md = mantissa(den, ed);
    return scaled(mn / md, en - ed);
}

int proven_sign(const Interval& v) { return v.positive() ? 1 : v.negative() ? -1 : 0; }

// ---------------------------------------------------------- exact --

// sign(a^2 - b^2 d), exactly.
int sign_of_square_difference(const Rational& a, const Rational& b, const Rational& d) {
    Rational a2, b2d;
    fmpq_mul(a2.get(), a.get(), a.get());
    fmpq_mul(b2d.get(), b.get(), b.get());
    fmpq_mul(b2d.get(), b2d.get(), d.get());
    return fmpq_cmp(a2.get(), b2d.get());
}
int sign_of_square_difference(const Integer& a, const Integer& b, const Integer& d) {
    Integer a2, b2d;
    fmpz_mul(a2.get(), a.get(), a.get());
    fmpz_mul(b2d.get(), b.get(), b.get());
    fmpz_mul(b2d.get(), b2d.get(), d.get());
    return fmpz_cmp(a2.get(), b2d.get());
}

// The common body of sign_of_quadratic over rationals and integers.
template <class Number>
int quadratic_sign(const Number& a, const Number& b, const Number& d) {
    const int sa = a.sign();
    const int sb = d.is_zero() ? 0 : b.sign();
    if (sb == 0) return sa;
    if (sa == 0 || sa == sb) return sb;
    // Opposite signs: |a| against |b| sqrt(d).
    const Interval ia = rough_enclosure(a.get()), ib = rough_enclosure(b.get()), id = rough_enclosure(d.get());
    if (ia.finite() && ib.finite() && id.finite())
        if (const int magnitude = proven_sign(ia.square() - ib.square() * id)) return sa * magnitude;
    const int c = sign_of_square_difference(a, b, d);
    return c > 0 ? sa : c < 0 ? sb : 0;
}

}  // namespace

int sign_of_quadratic(const Rational& a, const Rational& b, const Rational& d) { return quadratic_sign(a, b, d); }
int sign_of_quadratic(const Integer& a, const Integer& b, const Integer& d) { return quadratic_sign(a, b, d); }

int sign_of_two_roots(const Rational& x, const Rational& y, const Rational& d1, const Rational& z,
                      const Rational& d2) {
    const int sv = d2.is_zero() ? 0 : z.sign();
    if (sv == 0) return sign_of_quadratic(x, y, d1);
    const bool u_rational = d1.is_zero() || y.is_zero();
    if (u_rational) return sign_of_quadratic(x, z, d2);
    if (d1 == d2) {  // one field after all: x + (y + z) sqrt(d)
        Rational yz;
        fmpq_add(yz.get(), y.get(), z.get());
        return sign_of_quadratic(x, yz, d1);
    }
    // The whole sum in intervals first.
    const Interval ix = rough_enclosure(x.get()), iy = rough_enclosure(y.get()), iz = rough_enclosure(z.get());
    const Interval id1 = rough_enclosure(d1.get()), id2 = rough_enclosure(d2.get());
    if (ix.finite() && iy.finite() && iz.finite() && id1.finite() && id2.finite())
        if (const int s = proven_sign(ix + iy * id1.sqrt() + iz * id2.sqrt())) return s;
    const int su = sign_of_quadratic(x, y, d1);
    if (su == 0 || su == sv) return sv;
    // u and v of opposite signs: sign(u) * sign(u^2 - v^2).
    Rational rational, root, t;
    fmpq_mul(rational.get(), x.get(), x.get());
    fmpq_mul(t.get(), y.get(), y.get());
    fmpq_mul(t.get(), t.get(), d1.get());
    fmpq_add(rational.get(), rational.get(), t.get());
    fmpq_mul(t.get(), z.get(), z.get());
    fmpq_mul(t.get(), t.get(), d2.get());
    fmpq_sub(rational.get(), rational.get(), t.get());
    fmpq_mul(root.get(), x.get(), y.get());
    fmpq_mul_2exp(root.get(), root.get(), 1);
    return su * sign_of_quadratic(rational, root, d1);
}

// ------------------------------------------------------ QuadraticNumber --

QuadraticNumber::QuadraticNumber(const Rational& rational) : a_(rational) {}

QuadraticNumber::QuadraticNumber(Rational a, Rational b, Rational d) : a_(std::move(a)), b_(std::move(b)), d_(std::move(d)) {
    if (d_.sign() < 0) throw Error("QuadraticNumber: negative radicand " + d_.str());
    if (b_.is_zero() || d_.is_zero()) b_ = Rational(), d_ = Rational();
}

const Rational& QuadraticNumber::common_radicand(const QuadraticNumber& x, const QuadraticNumber& y) {
    if (x.is_rational()) return y.d_;
    if (y.is_rational() || x.d_ == y.d_) return x.d_;
    throw Error("QuadraticNumber: arithmetic across the fields Q(sqrt " + x.d_.str() + ") and Q(sqrt " + y.d_.str() +
                ")");
}

QuadraticNumber QuadraticNumber::operator-() const { return {-a_, -b_, d_}; }

QuadraticNumber operator+(const QuadraticNumber& x, const QuadraticNumber& y) {
    const Rational& d = QuadraticNumber::common_radicand(x, y);
    return {x.a_ + y.a_, x.b_ + y.b_, d};
}

QuadraticNumber operator-(const QuadraticNumber& x, const QuadraticNumber& y) {
    const Rational& d = QuadraticNumber::common_radicand(x, y);
    return {x.a_ - y.a_, x.b_ - y.b_, d};
}

QuadraticNumber operator*(const QuadraticNumber& x, const QuadraticNumber& y) {
    // (a1 + b1 r)(a2 + b2 r) = a1 a2 + b1 b2 d + (a1 b2 + a2 b1) r, r = sqrt(d);
    // a rational operand has b = 0, so the formula covers it.
    const Rational& d = QuadraticNumber::common_radicand(x, y);
    return {x.a_ * y.a_ + x.b_ * y.b_ * d, x.a_ * y.b_ + y.a_ * x.b_, d};
}

int compare(const QuadraticNumber& x, const QuadraticNumber& y) {
    return sign_of_two_roots(x.a_ - y.a_, x.b_, x.d_, -y.b_, y.d_);
}

Ball QuadraticNumber::to_ball(long prec) const {
    Ball r(a_, prec);
    if (is_rational()) return r;
    Ball root(d_, prec), b(b_, prec);
    arb_sqrt(root.get(), root.get(), prec);
    arb_addmul(r.get(), b.get(), root.get(), prec);
    return r;
}

std::string QuadraticNumber::str() const {
    if (is_rational()) return a_.str();
    return a_.str() + " + " + b_.str() + "*sqrt(" + d_.str() + ")";
}

}  // namespace ellvor
