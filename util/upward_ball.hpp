// Midpoint-radius balls of doubles computed under the upward rounding mode,
// for the Voronoi circle's certificate by distances
// (subdivision/voronoi_circle_in_doubles.cpp), whose operands are points
// and site enclosures a few ulps wide. A ball {mid, rad} stands for the
// reals [mid - rad, mid + rad]. Where UpwardInterval's product picks its
// endpoint products by the operands' signs (branches that a random sign
// mispredicts half the time), a ball's operations are straight-line code:
// the midpoint's operation, and a radius that bounds the operands' radii's
// effect plus the midpoint's own rounding error.
//
// Why this encloses: under FE_UPWARD every radius term is a sum and product
// of nonnegative upper bounds, rounded up, so it is an upper bound. A
// midpoint m = RU(x) of an exact x is within one ulp of x, and
// ulp(x) <= 2^-52 |x| for a normal x; |x| <= |m| when x > 0, and
// |x| < |m| / (1 - 2^-52) when x < 0 (RU rounds towards zero), so
// ulp(x) <= 2^-52 (1 + 2^-51) |m|; below the normal range one ulp is
// 2^-1074 < DBL_MIN. So `rounding(m)` = 2^-52 (1 + 2^-51) |m| + DBL_MIN
// bounds it. Overflow: a result above the range rounds up to inf, one below
// it to -DBL_MAX, no bound of anything; |m| (1 + 2^-51) rounded up is inf
// for |m| within a few ulps of DBL_MAX, and so is the radius. Callers test
// finite() before they trust a ball; a reciprocal or square root of a ball
// that reaches zero (or below) is NaN.
//
// Only valid inside an UpwardRoundingScope and in translation units
// compiled with the Makefile's ROUNDING_MATH flags (util/upward_interval.hpp
// says why). tests/util/test_upward_ball.cpp checks each operation against
// exact results.
#pragma once

#include "util/upward_interval.hpp"

#include <cfloat>
#include <cmath>
#include <limits>

namespace ellvor {

struct UpwardBall {
    double mid = 0, rad = 0;

    UpwardBall() = default;
    // An exact double.
    explicit UpwardBall(double x) : mid(x), rad(0) {}
    UpwardBall(double m, double r) : mid(m), rad(r) {}
    // The ball around an interval: its midpoint rounded up, and the
    // larger distance to an endpoint rounded up.
    static UpwardBall around(const UpwardInterval& x) {
        const double m = 0.5 * (x.lo + x.hi);
        return {m, Interval::max(m - x.lo, x.hi - m)};
    }

    // RD(mid - rad) = -RU(rad - mid) and RU(mid + rad).
    double lower() const { return -(rad - mid); }
    double upper() const { return mid + rad; }
    // An upper bound of |x| over the ball.
    double magnitude() const { return std::fabs(mid) + rad; }
    bool finite() const { return std::isfinite(mid) && std::isfinite(rad); }

    static double rounding(double m) { return 0x1p-52 * (std::fabs(m) * (1 + 0x1p-51)) + DBL_MIN; }

    friend UpwardBall operator+(const UpwardBall& a, const UpwardBall& b) {
        const double m = a.mid + b.mid;
        return {m, (a.rad + b.rad) + rounding(m)};
    }
    friend UpwardBall operator-(const UpwardBall& a, const UpwardBall& b) {
        const double m = a.mid - b.mid;
        return {m, (a.rad + b.rad) + rounding(m)};
    }
    UpwardBall operator-() const { return {-mid, rad}; }
    // (a + e)(b + f) - a b = a f + e b + e f, |e| <= a.rad, |f| <= b.rad.
    friend UpwardBall operator*(const UpwardBall& a, const UpwardBall& b) {
        const double m = a.mid * b.mid;
        return {m, (std::fabs(a.mid) * b.rad + a.rad * (std::fabs(b.mid) + b.rad)) + rounding(m)};
    }
    // An exact double times a ball.
    friend UpwardBall operator*(double c, const UpwardBall& b) {
        const double m = c * b.mid;
        return {m, std::fabs(c) * b.rad + rounding(m)};
    }
    UpwardBall square() const { return *this * *this; }
    // 2x: the midpoint exact but for overflow, which rounding() catches.
    UpwardBall twice() const {
        const double m = 2 * mid;
        return {m, 2 * rad + rounding(m)};
    }
    // 1/x for a ball away from zero: |1/x - 1/mid| <= rad / (|mid| (|mid| - rad)).
    UpwardBall reciprocal() const {
        const double gap = -(rad - std::fabs(mid));  // RD(|mid| - rad)
        if (!(gap > 0)) return nan();
        const double m = 1 / mid;
        const double denominator = -((-std::fabs(mid)) * gap);  // RD(|mid| gap)
        return {m, rad / denominator + rounding(m)};
    }
    // sqrt(x) for a ball above zero: |sqrt(x) - sqrt(mid)| <= rad / sqrt(mid),
    // sqrt(mid) bounded below by the double under RU(sqrt(mid)).
    UpwardBall sqrt() const {
        if (!(-(rad - mid) > 0)) return nan();
        const double m = std::sqrt(mid);
        return {m, rad / Interval::down(m) + rounding(m)};
    }

private:
    static UpwardBall nan() {
        const double n = std::numeric_limits<double>::quiet_NaN();
        return {n, n};
    }
};

}  // namespace ellvor
