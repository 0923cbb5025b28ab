#include "util/interval_trig.hpp"

#include "util/flint_types.hpp"

#include <array>
#include <cmath>
#include <limits>

namespace ellvor {
namespace {

// Sines take the Taylor terms to r^17, cosines to r^18 (both to y^17, y^18
// for the hyperbolic ones).
constexpr int kDegree = 18;
// Beyond these the argument goes to Arb.
constexpr double kMaxReduced = 0x1p19;
constexpr double kMaxHyperbolic = 16;
constexpr long kFallbackPrecision = 128;
// |r| below this needs no reduction (pi/4 = 0.78539...).
constexpr double kNoReduction = 0.785;
// 2/pi rounded: only chooses k; any k gives a correct (if larger) r.
constexpr double kTwoOverPi = 0x1.45f306dc9c883p-1;

// Enclosures of 1/n!, n = 0 .. kDegree + 2, by interval division.
struct InverseFactorials {
    std::array<Interval, kDegree + 3> of;
    InverseFactorials() {
        of[0] = Interval(1.0);
        for (int n = 1; n < static_cast<int>(of.size()); ++n) of[n] = of[n - 1] / Interval(static_cast<double>(n));
    }
};

const InverseFactorials& inverse_factorials() {
    static const InverseFactorials table;
    return table;
}

// An upper bound of m^n for m >= 0.
double power_up(double m, int n) {
    Interval p(1.0), base(m);
    for (; n > 0; n >>= 1) {
        if (n & 1) p = p * base;
        base = base.square();
    }
    return p.hi;
}

// The even and odd Taylor sums of sin / cos (alternating = true) or sinh /
// cosh at the interval r, each with its Lagrange remainder: the derivatives
// of order 19 and 20 are at most `derivative_bound` in modulus between 0
// and r.
void taylor(const Interval& r, bool alternating, double derivative_bound, Interval& odd, Interval& even) {
    const InverseFactorials& f = inverse_factorials();
    const auto coefficient = [&f, alternating](int n) {
        return alternating && (n / 2) % 2 ? -f.of[n] : f.of[n];
    };
    const Interval r2 = r.square();
    Interval s = coefficient(kDegree - 1), c = coefficient(kDegree);
    for (int n = kDegree - 3; n >= 1; n -= 2) s = coefficient(n) + r2 * s;
    for (int n = kDegree - 2; n >= 0; n -= 2) c = coefficient(n) + r2 * c;
    s = r * s;
    const double m = std::fmax(std::fabs(r.lo), std::fabs(r.hi));
    const double odd_error = (Interval(power_up(m, kDegree + 1)) * f.of[kDegree + 1] * Interval(derivative_bound)).hi;
    const double even_error = (Interval(power_up(m, kDegree + 2)) * f.of[kDegree + 2] * Interval(derivative_bound)).hi;
    odd = s + Interval(-odd_error, odd_error);
    even = c + Interval(-even_error, even_error);
}

// s = fl(x + y) and its error e = x + y - s, exact (Knuth's TwoSum, round
// to nearest, no overflow).
double two_sum(double x, double y, double& e) {
    const double s = x + y, y_part = s - x;
    e = (x - (s - y_part)) + (y - y_part);
    return s;
}

Interval clamp_unit(const Interval& x) { return {Interval::max(x.lo, -1.0), Interval::min(x.hi, 1.0)}; }

// sin and cos at a double, by Arb.
void sin_cos_by_arb(double x, Interval& sin, Interval& cos) {
    Ball b, s, c;
    arb_set_d(b.get(), x);
    arb_sin_cos(s.get(), c.get(), b.get(), kFallbackPrecision);
    sin = enclose(s);
    cos = enclose(c);
}

// sin and cos at a finite double.
void sin_cos_at(double x, Interval& sin, Interval& cos) {
    if (std::fabs(x) <= kNoReduction) {
        taylor(Interval(x), true, 1.0, sin, cos);
        return;
    }
    if (!(std::fabs(x) <= kMaxReduced)) return sin_cos_by_arb(x, sin, cos);
    // x = k pi/2 + r. k c1 and k c2 are exact; the two differences are kept
    // exactly as double + error (nearly always exact anyway: Sterbenz), so r
    // is enclosed to a few of its own ulps even near a multiple of pi/2.
    const double k = std::nearbyint(x * kTwoOverPi);
    double a_error, b_error;
    const double a = two_sum(x, -(k * HalfPiSplit::c1), a_error);
    const double b = two_sum(a, -(k * HalfPiSplit::c2), b_error);
    const Interval r = Interval(b) + ((Interval(a_error) + Interval(b_error)) - k * Interval(HalfPiSplit::c3) -
                                      k * Interval(-HalfPiSplit::error, HalfPiSplit::error));
    Interval s, c;
    taylor(r, true, 1.0, s, c);
    switch (static_cast<long long>(k) & 3) {
        case 0: sin = s, cos = c; break;
        case 1: sin = c, cos = -s; break;
        case 2: sin = -s, cos = -c; break;
        default: sin = -c, cos = s; break;
    }
    sin = clamp_unit(sin);
    cos = clamp_unit(cos);
}

// sinh and cosh at a double y >= 0.
void sinh_cosh_at(double y, Interval& sinh, Interval& cosh) {
    if (!(y <= kMaxHyperbolic)) {
        Ball b, s, c;
        arb_set_d(b.get(), y);
        arb_sinh_cosh(s.get(), c.get(), b.get(), kFallbackPrecision);
        sinh = enclose(s);
        cosh = enclose(c);
        return;
    }
    // y = 2^k t with t <= 1/2 (exact), where cosh t <= 2 bounds every derivative.
    int k = 0;
    double t = y;
    while (t > 0.5) t *= 0.5, ++k;
    taylor(Interval(t), false, 2.0, sinh, cosh);
    for (; k > 0; --k) {
        const Interval s = sinh;
        sinh = 2.0 * (s * cosh);
        cosh = Interval(1.0) + 2.0 * s.square();
    }
    cosh.lo = Interval::max(cosh.lo, 1.0);
}

}  // namespace

void sin_cos(const Interval& x, Interval& sin, Interval& cos) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    if (std::isnan(x.lo) || std::isnan(x.hi)) {
        sin = cos = Interval(nan, nan);
        return;
    }
    if (x.lo == x.hi && std::isfinite(x.lo)) return sin_cos_at(x.lo, sin, cos);
    const double m = x.mid();
    if (!std::isfinite(m)) {
        sin = cos = Interval(-1.0, 1.0);
        return;
    }
    Interval sm, cm;
    sin_cos_at(m, sm, cm);
    // The radius about m, rounded up.
    const double h = Interval::max((Interval(x.hi) - Interval(m)).hi, (Interval(m) - Interval(x.lo)).hi);
    if (!(h < 4)) {
        sin = cos = Interval(-1.0, 1.0);
        return;
    }
    // sin(m + t) = sin m cos t + cos m sin t, |t| <= h.
    const Interval cos_t(Interval::max(-1.0, (Interval(1.0) - 0.5 * Interval(h).square()).lo), 1.0);
    const double sin_t_bound = Interval::min(h, 1.0);
    const Interval sin_t(-sin_t_bound, sin_t_bound);
    sin = clamp_unit(sm * cos_t + cm * sin_t);
    cos = clamp_unit(cm * cos_t - sm * sin_t);
}

void sinh_cosh(const Interval& y, Interval& sinh, Interval& cosh) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    if (std::isnan(y.lo) || std::isnan(y.hi)) {
        sinh = cosh = Interval(nan, nan);
        return;
    }
    if (!y.finite()) {
        const double inf = std::numeric_limits<double>::infinity();
        sinh = Interval(-inf, inf);
        cosh = Interval(1.0, inf);
        return;
    }
    // sinh is odd and increasing, cosh even and increasing in |y|.
    const auto at = [](double v, Interval& s, Interval& c) {
        sinh_cosh_at(std::fabs(v), s, c);
        if (v < 0) s = -s;
    };
    Interval s_lo, c_lo, s_hi, c_hi;
    at(y.hi, s_hi, c_hi);
    if (y.lo == -y.hi) {
        s_lo = -s_hi, c_lo = c_hi;
    } else {
        at(y.lo, s_lo, c_lo);
    }
    sinh = Interval(s_lo.lo, s_hi.hi);
    if (y.contains_zero())
        cosh = Interval(1.0, Interval::max(c_lo.hi, c_hi.hi));
    else
        cosh = std::fabs(y.lo) < std::fabs(y.hi) ? Interval(c_lo.lo, c_hi.hi) : Interval(c_hi.lo, c_lo.hi);
}

void sin_cos(const ComplexInterval& z, ComplexInterval& sin, ComplexInterval& cos) {
    Interval sx, cx;
    sin_cos(z.re, sx, cx);
    if (z.im.lo == 0 && z.im.hi == 0) {
        sin = ComplexInterval(sx), cos = ComplexInterval(cx);
        return;
    }
    Interval sh, ch;
    sinh_cosh(z.im, sh, ch);
    sin = ComplexInterval(sx * ch, cx * sh);
    cos = ComplexInterval(cx * ch, -(sx * sh));
}

}  // namespace ellvor
