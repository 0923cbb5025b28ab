// Signs of polynomials evaluated in plain doubles (round to nearest), with an
// error bound fixed by the sequence of operations (Shewchuk / CGAL style
// "semi-static" filters): no interval, no rounding-mode change, no branch
// until the final comparison. A zero magnitude means an exactly zero value.
//
// A value is carried as Rounded<N>: the double computed, its magnitude (the
// same operations applied to the absolute values of the inputs, with every
// subtraction made an addition), and at compile time its index N:
//   an exact input                                    N = 0
//   a rounded difference of two exact inputs          N = 1
//   y + z, y - z                                      N = max(N_y, N_z) + 1
//   y * z                                             N = N_y + N_z + 1
//   -y, 2 y (exact)                                   N = N_y
//
// Lemma. Let u = 2^-53 and gamma_N = N u / (1 - N u). If no operation
// overflows or underflows, the exact value x of the polynomial differs from
// the double x^ computed by at most gamma_N m, where m is the exact magnitude
// (the magnitude computed without rounding, from the inputs' doubles).
// Proof. Expand x^ along the operations into a sum of signed products of
// input doubles, without collecting like terms: each rounding multiplies
// everything below it by a factor (1 + d), |d| <= u, so a product carries at
// most r factors, r the roundings on its path, and the sum of the products'
// absolute values is m. The exact value x is the same expansion without
// those factors and with each rounded difference
// v^ = fl(a - b) replaced by the exact a - b = v^ (1 + t), |t| <= u (the error
// of a rounding to nearest is at most half an ulp of its result). By the
// rules above, r plus the number of rounded differences in a product is at
// most N, and |prod (1 + d) - 1| <= gamma_r, |prod (1 + t) - 1| <= gamma_i,
// gamma_r + gamma_i <= gamma_N (Higham, Accuracy and Stability, Lemma 3.1
// and 3.3). Summing over the products, |x^ - x| <= gamma_N m. (A fused
// multiply-add rounds once where the rules count two roundings: the bound
// holds with contraction too.)
//
// The computed magnitude m^ adds and multiplies nonnegative numbers only, at
// most N roundings on any path, so m^ >= (1 - u)^N m. certain_sign compares
// |x^| with fl((N + 1) u m^) >= (1 - u)^(N+1) (N + 1) u m >= gamma_N m, true for
// N <= 64 since (N + 1)(1 - u)^(N+1)(1 - N u) >= N + 1 - (N + 1)(2N + 1) u >= N.
// So |x^| > that bound proves sign(x) = sign(x^); otherwise the sign is
// unknown (0).
//
// Range. The lemma needs every nonzero result to be a normal double. The
// inputs of exact_circle (circle_semi_static.cpp: Rational::is_small_dyadic) are multiples of 2^-61 below 2^53 in magnitude;
// then every value of degree d in them is a multiple of 2^(-61 d) (sums and
// products of multiples stay multiples, and rounding to a double keeps a
// multiple of 2^q when the result is at least 2^(q+53), and is exact below),
// so for d <= 12 a nonzero result is at least 2^-732, far from underflow; and
// every magnitude of degree d <= 12 is at most 2^20 (2^54)^d < 2^700 for the
// polynomials of circle_semi_static.cpp (their magnitudes at inputs of 1 are
// below 2^20), far from overflow.
#pragma once

#include "util/flint_types.hpp"
#include "util/interval.hpp"

#include <algorithm>
#include <cmath>

namespace ellvor::semi_static {

template <int N>
struct Rounded {
    static_assert(N <= 64, "the error constant of certain_sign is proven for N <= 64");
    double value = 0, magnitude = 0;
};

inline Rounded<0> exact(double v) { return {v, std::fabs(v)}; }
// a - b for exact inputs a, b.
inline Rounded<1> difference(double a, double b) {
    const double d = a - b;
    return {d, std::fabs(d)};
}

template <int A, int B>
Rounded<std::max(A, B) + 1> operator+(Rounded<A> y, Rounded<B> z) {
    return {y.value + z.value, y.magnitude + z.magnitude};
}
template <int A, int B>
Rounded<std::max(A, B) + 1> operator-(Rounded<A> y, Rounded<B> z) {
    return {y.value - z.value, y.magnitude + z.magnitude};
}
template <int A, int B>
Rounded<A + B + 1> operator*(Rounded<A> y, Rounded<B> z) {
    return {y.value * z.value, y.magnitude * z.magnitude};
}
template <int A>
Rounded<A> operator-(Rounded<A> y) {
    return {-y.value, y.magnitude};
}
template <int A>
Rounded<A> twice(Rounded<A> y) {
    return {2 * y.value, 2 * y.magnitude};
}

// fl((N + 1) u m^) >= gamma_N m >= |x^ - x| (the lemma and the paragraph above).
template <int N>
double error_bound(Rounded<N> x) {
    return (N + 1) * 0x1p-53 * x.magnitude;  // (N + 1) 2^-53 is exact: one rounding
}

// The sign of the exact value when the lemma proves it, else 0.
template <int N>
int certain_sign(Rounded<N> x) {
    const double bound = error_bound(x);
    return x.value > bound ? 1 : x.value < -bound ? -1 : 0;
}

// Whether |a| > |b| sqrt(r) is proven: |a| >= |a^| - E_a, |b| <= |b^| + E_b
// and r <= r^ + E_r (E = error_bound), compared squared in outward-rounded
// intervals (util/interval.hpp).
template <int A, int B, int R>
bool dominates(Rounded<A> a, Rounded<B> b, Rounded<R> r) {
    const Interval low = Interval(std::fabs(a.value)) - Interval(error_bound(a));
    const Interval high = Interval(std::fabs(b.value)) + Interval(error_bound(b));
    const Interval r_high = Interval(r.value) + Interval(error_bound(r));
    return low.lo > 0 && low.square().lo > (high.square() * r_high).hi;
}

// The sign of a + b sqrt(r) for r > 0 (the caller proves it), else 0. A zero
// magnitude proves a zero value (equal radii make whole terms vanish). When
// b has no certain sign (symmetric data can make it exactly 0), a decides if
// |a| > |b| sqrt(r) is proven (dominates). With opposite signs of a and b it
// is sign(a) sign(a^2 - b^2 r), as a^2 - b^2 r = (a - b sqrt(r)) (a + b sqrt(r))
// and a - b sqrt(r) has the sign of a.
template <int A, int B, int R>
int certain_sign_with_root(Rounded<A> a, Rounded<B> b, Rounded<R> r) {
    if (b.magnitude == 0) return certain_sign(a);
    if (a.magnitude == 0) return certain_sign(b);
    const int sa = certain_sign(a), sb = certain_sign(b);
    if (sa != 0 && sb == 0) return dominates(a, b, r) ? sa : 0;
    if (sa == 0 || sb == 0) return 0;
    if (sa == sb) return sa;
    return sa * certain_sign(a * a - b * b * r);
}

// A rational input known by its enclosure from enclose(const Rational&)
// (util/interval.hpp): [down(x^), up(x^)] around the double x^ nearest to it
// (Rational::to_double rounds to nearest), so x^ = up(lo), and x = x^ (1 + t)
// with |t| <= u (half an ulp of x^): index 1, counted like a rounded
// difference in the lemma above. Range: only 0 or 2^-30 <= |x^| <= 2^30.
// Such doubles are multiples of 2^-82, so a nonzero value of degree d <= 12
// in them (and their differences) is at least 2^(-82 d) >= 2^-984, a normal
// double; differences stay below 2^31, so a magnitude of degree 12 is at most
// 2^20 (2^31)^12 < 2^400. False outside the range (a later stage decides).
inline bool rounded_input(const Interval& enclosure, Rounded<1>& out) {
    const double x = Interval::up(enclosure.lo);
    const double m = std::fabs(x);
    if (m != 0 && !(m >= 0x1p-30 && m <= 0x1p30)) return false;
    out = {x, m};
    return true;
}

}  // namespace ellvor::semi_static
