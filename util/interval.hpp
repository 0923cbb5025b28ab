// Closed intervals of doubles with outward rounding, for the fast filters.
// Each operation is computed in the current rounding mode (round-to-nearest
// but inside util/upward_interval.hpp's scopes) and then widened by one ulp
// on each side, which contains the exact result (the rounding error of one
// IEEE operation is at most half an ulp to nearest, under one ulp in any
// directed mode). A filter built on these intervals
// therefore decides only what is provably right, and says "undecided" when an
// interval straddles zero.
#pragma once

#include "util/flint_types.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace ellvor {

struct Interval {
    double lo = 0, hi = 0;

    // The next double below / above x (what std::nextafter does, inlined:
    // stepping the IEEE bit pattern). +infinity and NaN pass through; -inf
    // steps to the most negative double. Branch-free but for that test (it
    // was a third of an ellipse build's instructions): -0 becomes +0 (x +
    // 0.0), whose next double is the least subnormal; then the pattern,
    // read as a signed integer, steps by +1 when it is positive and by -1
    // (toward zero) when negative.
    static double up(double x) {
        if (!(x < std::numeric_limits<double>::infinity())) return x;
        const double y = x + 0.0;
        std::int64_t bits;
        std::memcpy(&bits, &y, sizeof bits);
        bits += (bits >> 63) | 1;
        double z;
        std::memcpy(&z, &bits, sizeof bits);
        return z;
    }
    static double down(double x) { return -up(-x); }
    // std::fmin / std::fmax (a NaN operand yields the other one), inlined:
    // the library calls cost more than the comparisons.
    static double min(double a, double b) { return (b < a || a != a) ? b : a; }
    static double max(double a, double b) { return (b > a || a != a) ? b : a; }

    Interval() = default;
    // An exact double.
    explicit Interval(double x) : lo(x), hi(x) {}
    Interval(double l, double h) : lo(l), hi(h) {}
    // An enclosure of a real known to within one ulp of x (e.g. a correctly
    // rounded conversion).
    // {down(x), up(x)} from one bit pattern for a finite nonzero x (an
    // Ellipse makes six of these on each enclosure() call): the pattern,
    // read as a signed integer, steps by -(s|1) and +(s|1), s its sign mask.
    static Interval around(double x) {
        if (!(std::fabs(x) < std::numeric_limits<double>::infinity()) || x == 0) return {down(x), up(x)};
        std::int64_t bits;
        std::memcpy(&bits, &x, sizeof bits);
        const std::int64_t step = (bits >> 63) | 1;
        const std::int64_t below = bits - step, above = bits + step;
        Interval r;
        std::memcpy(&r.lo, &below, sizeof below);
        std::memcpy(&r.hi, &above, sizeof above);
        return r;
    }

    friend Interval operator+(Interval a, Interval b) { return {down(a.lo + b.lo), up(a.hi + b.hi)}; }
    friend Interval operator-(Interval a, Interval b) { return {down(a.lo - b.hi), up(a.hi - b.lo)}; }
    Interval operator-() const { return {-hi, -lo}; }
    // By the endpoints' signs, two products where one factor keeps its sign
    // (all but the last case; the filters' intervals rarely hold zero);
    // the NaN-ignoring hull of all four when both hold zero or a product is
    // NaN (0 * inf), which the sign cases cannot order.
    friend Interval operator*(Interval a, Interval b) {
        double lo, hi;
        if (a.lo >= 0) {
            if (b.lo >= 0) lo = a.lo * b.lo, hi = a.hi * b.hi;
            else if (b.hi <= 0) lo = a.hi * b.lo, hi = a.lo * b.hi;
            else lo = a.hi * b.lo, hi = a.hi * b.hi;
        } else if (a.hi <= 0) {
            if (b.lo >= 0) lo = a.lo * b.hi, hi = a.hi * b.lo;
            else if (b.hi <= 0) lo = a.hi * b.hi, hi = a.lo * b.lo;
            else lo = a.lo * b.hi, hi = a.lo * b.lo;
        } else if (b.lo >= 0) {
            lo = a.lo * b.hi, hi = a.hi * b.hi;
        } else if (b.hi <= 0) {
            lo = a.hi * b.lo, hi = a.lo * b.lo;
        } else {
            return hull_of_products(a, b);
        }
        if (lo != lo || hi != hi) return hull_of_products(a, b);
        return {down(lo), up(hi)};
    }
    static Interval hull_of_products(Interval a, Interval b) {
        const double p1 = a.lo * b.lo, p2 = a.lo * b.hi, p3 = a.hi * b.lo, p4 = a.hi * b.hi;
        return {down(min(min(p1, p2), min(p3, p4))), up(max(max(p1, p2), max(p3, p4)))};
    }
    // An exact double times an interval (two products instead of four).
    friend Interval operator*(double c, Interval b) {
        return c >= 0 ? Interval{down(c * b.lo), up(c * b.hi)} : Interval{down(c * b.hi), up(c * b.lo)};
    }
    // Division by an interval that does not contain zero (callers check).
    friend Interval operator/(Interval a, Interval b) {
        const double q1 = a.lo / b.lo, q2 = a.lo / b.hi, q3 = a.hi / b.lo, q4 = a.hi / b.hi;
        return {down(min(min(q1, q2), min(q3, q4))), up(max(max(q1, q2), max(q3, q4)))};
    }
    Interval square() const {
        if (lo >= 0) return {down(lo * lo), up(hi * hi)};
        if (hi <= 0) return {down(hi * hi), up(lo * lo)};
        return {0, up(max(lo * lo, hi * hi))};
    }
    // Square root of the nonnegative part.
    Interval sqrt() const { return {lo > 0 ? down(std::sqrt(lo)) : 0.0, up(std::sqrt(std::fmax(hi, 0.0)))}; }

    bool contains_zero() const { return lo <= 0 && hi >= 0; }
    bool positive() const { return lo > 0; }
    bool negative() const { return hi < 0; }
    bool finite() const { return std::isfinite(lo) && std::isfinite(hi); }
    double mid() const { return 0.5 * (lo + hi); }
};

// An enclosure of a ball (its endpoints rounded outward).
inline Interval enclose(const Ball& b) {
    Arf x;
    arb_get_lbound_arf(x.get(), b.get(), 64);
    const double lo = arf_get_d(x.get(), ARF_RND_FLOOR);
    arb_get_ubound_arf(x.get(), b.get(), 64);
    const double hi = arf_get_d(x.get(), ARF_RND_CEIL);
    return {lo, hi};
}

// The ball of an interval's points (its ends are doubles: exact at any
// precision; the ball's radius is rounded up).
inline Ball ball_of(const Interval& x, long prec) {
    Arf lo, hi;
    arf_set_d(lo.get(), x.lo);
    arf_set_d(hi.get(), x.hi);
    Ball b;
    arb_set_interval_arf(b.get(), lo.get(), hi.get(), prec);
    return b;
}

// An enclosure of a rational: [down(x^), up(x^)] around its nearest double x^
// (Rational::to_double), so x^ = up(lo) (circles/semi_static.hpp reads it so).
inline Interval enclose(const Rational& q) { return Interval::around(q.to_double()); }

}  // namespace ellvor
