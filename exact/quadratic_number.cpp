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

// The few FLINT operations the sign bodies need, for rationals and integers
// alike (the integer versions never reduce a fraction).
void mul(Rational& r, const Rational& x, const Rational& y) { fmpq_mul(r.get(), x.get(), y.get()); }
void mul(Integer& r, const Integer& x, const Integer& y) { fmpz_mul(r.get(), x.get(), y.get()); }
void add(Rational& r, const Rational& x, const Rational& y) { fmpq_add(r.get(), x.get(), y.get()); }
void add(Integer& r, const Integer& x, const Integer& y) { fmpz_add(r.get(), x.get(), y.get()); }
void sub(Rational& r, const Rational& x, const Rational& y) { fmpq_sub(r.get(), x.get(), y.get()); }
void sub(Integer& r, const Integer& x, const Integer& y) { fmpz_sub(r.get(), x.get(), y.get()); }
void twice(Rational& r) { fmpq_mul_2exp(r.get(), r.get(), 1); }
void twice(Integer& r) { fmpz_mul_2exp(r.get(), r.get(), 1); }

// sign(a^2 - b^2 d), exactly.
template <class Number>
int sign_of_square_difference(const Number& a, const Number& b, const Number& d) {
    Number a2, b2d;
    mul(a2, a, a);
    mul(b2d, b, b);
    mul(b2d, b2d, d);
    sub(a2, a2, b2d);
    return a2.sign();
}

// The body of sign_of_quadratic (see the header for the proof).
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

// The body of sign_of_biquadratic (see the header for the proof); also the
// last step of sign_of_two_roots (e = 0).
template <class Number>
int biquadratic_sign(const Number& a, const Number& b, const Number& c, const Number& e, const Number& d1,
                     const Number& d2) {
    const int sv = d2.is_zero() ? 0 : quadratic_sign(c, e, d1);
    const int su = quadratic_sign(a, b, d1);
    if (sv == 0) return su;
    if (su == 0 || su == sv) return sv;
    // u^2 - v^2 d2 = (a^2 + b^2 d1 - (c^2 + e^2 d1) d2) + 2 (a b - c e d2) sqrt(d1)
    Number rational, root, t, w;
    mul(rational, a, a);
    mul(t, b, b);
    mul(t, t, d1);
    add(rational, rational, t);
    mul(w, c, c);
    mul(t, e, e);
    mul(t, t, d1);
    add(w, w, t);
    mul(w, w, d2);
    sub(rational, rational, w);
    mul(root, a, b);
    mul(t, c, e);
    mul(t, t, d2);
    sub(root, root, t);
    twice(root);
    return su * quadratic_sign(rational, root, d1);
}

// The body of sign_of_two_roots (see the header for the proof).
template <class Number>
int two_roots_sign(const Number& x, const Number& y, const Number& d1, const Number& z, const Number& d2) {
    const int sv = d2.is_zero() ? 0 : z.sign();
    if (sv == 0) return quadratic_sign(x, y, d1);
    if (d1.is_zero() || y.is_zero()) return quadratic_sign(x, z, d2);
    if (d1 == d2) {  // one field after all: x + (y + z) sqrt(d)
        Number yz;
        add(yz, y, z);
        return quadratic_sign(x, yz, d1);
    }
    // The whole sum in intervals first.
    const Interval ix = rough_enclosure(x.get()), iy = rough_enclosure(y.get()), iz = rough_enclosure(z.get());
    const Interval id1 = rough_enclosure(d1.get()), id2 = rough_enclosure(d2.get());
    if (ix.finite() && iy.finite() && iz.finite() && id1.finite() && id2.finite())
        if (const int s = proven_sign(ix + iy * id1.sqrt() + iz * id2.sqrt())) return s;
    return biquadratic_sign(x, y, z, Number(0), d1, d2);
}

}  // namespace

int sign_of_quadratic(const Rational& a, const Rational& b, const Rational& d) { return quadratic_sign(a, b, d); }

int sign_of_biquadratic(const Integer& a, const Integer& b, const Integer& c, const Integer& e, const Integer& d1,
                        const Integer& d2) {
    return biquadratic_sign(a, b, c, e, d1, d2);
}
int sign_of_quadratic(const Integer& a, const Integer& b, const Integer& d) { return quadratic_sign(a, b, d); }

int sign_of_two_roots(const Rational& x, const Rational& y, const Rational& d1, const Rational& z,
                      const Rational& d2) {
    return two_roots_sign(x, y, d1, z, d2);
}
int sign_of_two_roots(const Integer& x, const Integer& y, const Integer& d1, const Integer& z, const Integer& d2) {
    return two_roots_sign(x, y, d1, z, d2);
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
