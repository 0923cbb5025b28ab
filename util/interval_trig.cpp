#include "util/interval_trig.hpp"

#include "util/flint_types.hpp"

#include <cmath>
#include <limits>

namespace ellvor {
namespace {

// Beyond these the argument goes to Arb.
constexpr double kMaxReduced = 0x1p19;
constexpr double kMaxHyperbolic = 16;
constexpr long kFallbackPrecision = 128;
// |x| below this needs no reduction (pi/4 = 0.78539...).
constexpr double kNoReduction = 0.785;
// The series' domain: |r| <= pi/4 + 2^-31 after reduction; z = r^2 <= 0.618.
constexpr double kMaxSeries = 0.786;
// Below this the series' first term and a cubic bound suffice (and r^2
// cannot underflow above it).
constexpr double kTiny = 0x1p-26;
// Intervals narrower than this (radius) take the first-order widening.
constexpr double kNarrow = 0x1p-20;
// Hyperbolic arguments are halved to at most this.
constexpr double kMaxHalved = 0.5;
// 2/pi rounded: only chooses k; any k gives a correct (if larger) r.
constexpr double kTwoOverPi = 0x1.45f306dc9c883p-1;
// The unit roundoff of doubles.
constexpr double kU = 0x1p-53;

double up_product(double a, double b) { return Interval::up(a * b); }  // a, b >= 0
double up_sum(double a, double b) { return Interval::up(a + b); }

// The odd and even parts of the series at a double r, |r| <= kMaxSeries:
// sin r = r - r z A(-z), cos r = 1 - z B(-z) (z = r^2), or sinh r = r + r z
// A(z), cosh r = 1 + z B(z) (hyperbolic), each enclosed with the bound of
// interval_trig.hpp on its rounding errors and Taylor remainder.
void series(double r, bool hyperbolic, Interval& odd, Interval& even) {
    const double m = std::fabs(r);
    if (m < kTiny) {
        // |sin r - r|, |sinh r - r| <= |r|^3; |cos r - 1|, |cosh r - 1| <= r^2.
        const double z_up = up_product(m, m), cube = up_product(m, z_up);
        odd = Interval(Interval::down(r - cube), Interval::up(r + cube));
        even = hyperbolic ? Interval(1.0, up_sum(1.0, z_up)) : Interval(Interval::down(1.0 - z_up), 1.0);
        return;
    }
    using A = SeriesCoefficients;
    const double z = r * r, w = hyperbolic ? z : -z;
    double a = A::odd[A::kOddTerms - 1], b = A::even[A::kEvenTerms - 1];
    for (int k = A::kOddTerms - 2; k >= 0; --k) a = a * w + A::odd[k];
    for (int k = A::kEvenTerms - 2; k >= 0; --k) b = b * w + A::even[k];
    const double t = (r * z) * a, u = z * b;
    const double s = hyperbolic ? r + t : r - t, c = hyperbolic ? 1.0 + u : 1.0 - u;
    const double z_up = Interval::up(z);
    const double odd_error = up_product(up_product(kU * m, z_up), up_sum(0.84, up_product(0.07, z_up)));
    const double even_error = up_product(kU * z_up, up_sum(2.01, up_product(0.31, z_up)));
    odd = Interval(Interval::down(Interval::down(s) - odd_error), Interval::up(Interval::up(s) + odd_error));
    even = Interval(Interval::down(Interval::down(c) - even_error), Interval::up(Interval::up(c) + even_error));
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
    if (std::fabs(x) <= kNoReduction) return series(x, false, sin, cos);
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
    // The series at r's middle, widened by r's radius (|sin'|, |cos'| <= 1).
    const double middle = r.mid();
    if (!(std::fabs(middle) <= kMaxSeries)) return sin_cos_by_arb(x, sin, cos);
    Interval s, c;
    series(middle, false, s, c);
    const double h = Interval::max(Interval::up(r.hi - middle), Interval::up(middle - r.lo));
    s = s + Interval(-h, h);
    c = c + Interval(-h, h);
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
    // y = 2^k t with t <= 1/2 (exact).
    int k = 0;
    double t = y;
    while (t > kMaxHalved) t *= 0.5, ++k;
    series(t, true, sinh, cosh);
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
    if (h <= kNarrow) {
        // |sin'|, |cos'| <= 1; the second-order form below gains nothing here.
        sin = clamp_unit(sm + Interval(-h, h));
        cos = clamp_unit(cm + Interval(-h, h));
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
