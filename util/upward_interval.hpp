// Closed intervals of doubles computed under the processor's upward rounding
// mode (round toward +infinity), for the hot Krawczyk test of the Voronoi
// circle in doubles (subdivision/voronoi_circle_in_doubles.cpp). Everything
// else uses Interval (util/interval.hpp), which rounds to nearest and then
// steps each endpoint one ulp outward.
//
// Why this encloses: under FE_UPWARD every IEEE operation (+, -, *, /, sqrt)
// returns the least double >= its exact result, so an upper bound computed
// as `a.hi + b.hi` is one. A lower bound is the negation of an upper bound of
// the negated quantity, RD(x) = -RU(-x) (negation is exact in every mode):
// lo = -((-a.lo) - b.lo) <= a.lo + b.lo. No per-operation widening is needed.
// Overflow is sound too: an upper bound overflows to +inf and a lower one to
// -inf; a negative upper bound beyond the range rounds to -DBL_MAX (still
// above the exact value), a positive lower bound to +DBL_MAX.
// Special values are as in Interval: -0 and +0 compare equal (only division
// and sqrt see the sign; both are guarded below), NaN fails every comparison
// (so nothing is proved from it), and the products' NaN-ignoring hull handles
// 0 * inf the same way.
//
// Only valid inside an UpwardRoundingScope, and only in translation units
// compiled with -frounding-math (without it the compiler may fold
// -((-x) - y) into x + y, or constant-fold in round-to-nearest) and
// -ffp-contract=off (a fused multiply-add skips a rounding; baseline x86-64
// has no FMA, but -march=native would). The Makefile's ROUNDING_MATH flags
// give both and define ELLVOR_ROUNDING_MATH, which this header requires.
// tests/util/test_upward_interval.cpp checks every operation against exact
// results.
#pragma once

#include "util/error.hpp"
#include "util/interval.hpp"

#include <cfenv>
#include <cmath>

#ifndef ELLVOR_ROUNDING_MATH
#error "util/upward_interval.hpp needs the Makefile's ROUNDING_MATH flags (-frounding-math -ffp-contract=off)"
#endif

// For a function that opens an UpwardRoundingScope first and computes in
// it: GCC does not order floating-point operations with fesetround (its
// -frounding-math only stops folding), so such a function is kept out of
// inlining, cloning and the rest of interprocedural optimization, and reads
// its inputs through references after the scope is set. Clang's
// -frounding-math orders them itself (constrained intrinsics); noinline
// there.
#if defined(__clang__)
#define ELLVOR_UPWARD_ROUNDING_FUNCTION __attribute__((noinline))
#else
#define ELLVOR_UPWARD_ROUNDING_FUNCTION __attribute__((noipa))
#endif

namespace ellvor {

// Sets the rounding mode to FE_UPWARD for its lifetime and restores the mode
// it found (also when an exception leaves the scope). The mode belongs to the
// calling thread (C11 7.6), so other threads are not affected. Not copyable:
// one scope, one restore.
class UpwardRoundingScope {
public:
    UpwardRoundingScope() : saved_(std::fegetround()) {
        if (std::fesetround(FE_UPWARD) != 0) throw Error("cannot set the upward rounding mode");
    }
    ~UpwardRoundingScope() { std::fesetround(saved_); }
    UpwardRoundingScope(const UpwardRoundingScope&) = delete;
    UpwardRoundingScope& operator=(const UpwardRoundingScope&) = delete;

private:
    int saved_;
};

struct UpwardInterval {
    double lo = 0, hi = 0;

    UpwardInterval() = default;
    // An exact double.
    explicit UpwardInterval(double x) : lo(x), hi(x) {}
    UpwardInterval(double l, double h) : lo(l), hi(h) {}
    // The same enclosure: both types hold [lo, hi] as is (no rounding).
    explicit UpwardInterval(const Interval& x) : lo(x.lo), hi(x.hi) {}
    Interval interval() const { return {lo, hi}; }

    // Lower bounds of x * y and x / y: -RU(-x * y) = RD(x * y).
    static double mul_down(double x, double y) { return -((-x) * y); }
    static double div_down(double x, double y) { return -((-x) / y); }

    friend UpwardInterval operator+(UpwardInterval a, UpwardInterval b) {
        return {-((-a.lo) - b.lo), a.hi + b.hi};
    }
    friend UpwardInterval operator-(UpwardInterval a, UpwardInterval b) { return {-(b.hi - a.lo), a.hi - b.lo}; }
    UpwardInterval operator-() const { return {-hi, -lo}; }
    // The cases of Interval's product (by the endpoints' signs; the hull of
    // all four products when both hold zero or a product is NaN). Always
    // inlined: GCC called it, and the calls were 14 % of the Krawczyk test's
    // instructions (callgrind, ellipse_speed.md).
    friend __attribute__((always_inline)) UpwardInterval operator*(UpwardInterval a, UpwardInterval b) {
        double lo, hi;
        if (a.lo >= 0) {
            if (b.lo >= 0) lo = mul_down(a.lo, b.lo), hi = a.hi * b.hi;
            else if (b.hi <= 0) lo = mul_down(a.hi, b.lo), hi = a.lo * b.hi;
            else lo = mul_down(a.hi, b.lo), hi = a.hi * b.hi;
        } else if (a.hi <= 0) {
            if (b.lo >= 0) lo = mul_down(a.lo, b.hi), hi = a.hi * b.lo;
            else if (b.hi <= 0) lo = mul_down(a.hi, b.hi), hi = a.lo * b.lo;
            else lo = mul_down(a.lo, b.hi), hi = a.lo * b.lo;
        } else if (b.lo >= 0) {
            lo = mul_down(a.lo, b.hi), hi = a.hi * b.hi;
        } else if (b.hi <= 0) {
            lo = mul_down(a.hi, b.lo), hi = a.lo * b.lo;
        } else {
            return hull_of_products(a, b);
        }
        if (lo != lo || hi != hi) return hull_of_products(a, b);
        return {lo, hi};
    }
    static UpwardInterval hull_of_products(UpwardInterval a, UpwardInterval b) {
        using I = Interval;
        const double l1 = mul_down(a.lo, b.lo), l2 = mul_down(a.lo, b.hi), l3 = mul_down(a.hi, b.lo),
                     l4 = mul_down(a.hi, b.hi);
        const double h1 = a.lo * b.lo, h2 = a.lo * b.hi, h3 = a.hi * b.lo, h4 = a.hi * b.hi;
        return {I::min(I::min(l1, l2), I::min(l3, l4)), I::max(I::max(h1, h2), I::max(h3, h4))};
    }
    // An exact double times an interval (two products instead of four).
    friend UpwardInterval operator*(double c, UpwardInterval b) {
        return c >= 0 ? UpwardInterval{mul_down(c, b.lo), c * b.hi} : UpwardInterval{mul_down(c, b.hi), c * b.lo};
    }
    // Division by an interval that does not contain zero (callers check), as
    // Interval's: the hull of the four quotients.
    friend UpwardInterval operator/(UpwardInterval a, UpwardInterval b) {
        using I = Interval;
        const double l1 = div_down(a.lo, b.lo), l2 = div_down(a.lo, b.hi), l3 = div_down(a.hi, b.lo),
                     l4 = div_down(a.hi, b.hi);
        const double h1 = a.lo / b.lo, h2 = a.lo / b.hi, h3 = a.hi / b.lo, h4 = a.hi / b.hi;
        return {I::min(I::min(l1, l2), I::min(l3, l4)), I::max(I::max(h1, h2), I::max(h3, h4))};
    }
    UpwardInterval square() const {
        if (lo >= 0) return {mul_down(lo, lo), hi * hi};
        if (hi <= 0) return {mul_down(hi, hi), lo * lo};
        return {0, Interval::max(lo * lo, hi * hi)};
    }
    // 2x: exact but for overflow, which the negated lower bound sends to -inf
    // (2 * lo rounded upward would stop at -DBL_MAX, above the exact value).
    UpwardInterval twice() const { return {-((-2.0) * lo), 2.0 * hi}; }
    // 1/x; for x > 0 two quotients, else the general division.
    UpwardInterval reciprocal() const {
        if (lo > 0) return {div_down(1.0, hi), 1.0 / lo};
        return UpwardInterval(1.0) / *this;
    }
    // Square root of the nonnegative part. IEEE sqrt is correctly rounded in
    // the current mode (glibc's sqrt is the SSE2 instruction on x86-64, and
    // its argument here is never negative): RU(sqrt(hi)) is an upper bound,
    // and the double below RU(sqrt(lo)) is below sqrt(lo) (RU is less than
    // one ulp above it). Interval::down only steps the bit pattern.
    UpwardInterval sqrt() const {
        return {lo > 0 ? Interval::down(std::sqrt(lo)) : 0.0, std::sqrt(Interval::max(hi, 0.0))};
    }

    bool contains_zero() const { return lo <= 0 && hi >= 0; }
    bool positive() const { return lo > 0; }
    bool negative() const { return hi < 0; }
    bool finite() const { return std::isfinite(lo) && std::isfinite(hi); }
};

}  // namespace ellvor
