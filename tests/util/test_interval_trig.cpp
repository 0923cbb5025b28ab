// Sines and cosines in double intervals (util/interval_trig.hpp) against Arb
// at 256 bits: the split of pi/2, then containment (exact comparisons of
// Arb's ball ends with the interval's ends) at points of every magnitude and
// sign, at the doubles nearest k pi/4 and their neighbours, over intervals
// (their ends, middles, random points and the extrema inside) and complex
// rectangles (corners and random points); and the widths at points, a few
// ulps.
#include "util/interval_trig.hpp"

#include "util/complex_ball.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>

using namespace ellvor;

namespace {

constexpr long kPrec = 256;

// lo <= every point of the ball <= hi, compared exactly. With `unit`, an
// end at +-1 or beyond holds (|sin|, |cos| <= 1 on the reals), where a ball
// about cos(1e-300) reaches past 1.
bool contains(const Interval& x, const arb_struct* b, bool unit = false) {
    if (!arb_is_finite(b)) return false;
    Arf bound, end;
    arb_get_lbound_arf(bound.get(), b, kPrec);
    arf_set_d(end.get(), x.lo);
    if (!(unit && x.lo <= -1) && arf_cmp(end.get(), bound.get()) > 0) return false;
    arb_get_ubound_arf(bound.get(), b, kPrec);
    arf_set_d(end.get(), x.hi);
    return (unit && x.hi >= 1) || arf_cmp(bound.get(), end.get()) <= 0;
}

// Width in units of the last place at the interval's larger end.
double width_in_ulps(const Interval& x) {
    const double m = std::fmax(std::fabs(x.lo), std::fabs(x.hi));
    const double ulp = std::nextafter(m, INFINITY) - m;
    return (x.hi - x.lo) / ulp;
}

struct SinCos {
    Ball sin, cos;
};

SinCos arb_at(double x) {
    Ball b;
    SinCos r;
    arb_set_d(b.get(), x);
    arb_sin_cos(r.sin.get(), r.cos.get(), b.get(), kPrec);
    return r;
}

// Checks containment at the point x; returns the larger width in ulps.
double check_point(double x) {
    Interval s, c;
    sin_cos(Interval(x), s, c);
    const SinCos want = arb_at(x);
    INFO("x = " << x << " (" << std::hexfloat << x << std::defaultfloat << ") sin [" << s.lo << ", " << s.hi
                << "] cos [" << c.lo << ", " << c.hi << "]");
    CHECK(contains(s, want.sin.get(), true));
    CHECK(contains(c, want.cos.get(), true));
    return std::fmax(width_in_ulps(s), width_in_ulps(c));
}

}  // namespace

TEST_CASE("interval_trig: the split of pi/2 is within its stated error of Arb's pi/2", "[interval][trig]") {
    Ball half_pi, rest, c;
    arb_const_pi(half_pi.get(), 1024);
    arb_mul_2exp_si(half_pi.get(), half_pi.get(), -1);
    arb_set(rest.get(), half_pi.get());
    for (double part : {HalfPiSplit::c1, HalfPiSplit::c2, HalfPiSplit::c3}) {
        arb_set_d(c.get(), part);
        arb_sub(rest.get(), rest.get(), c.get(), 1024);
    }
    Mag bound;
    arb_get_mag(bound.get(), rest.get());
    CHECK(mag_cmp_2exp_si(bound.get(), -122) <= 0);
    CHECK(HalfPiSplit::error == std::ldexp(1.0, -122));
    // c1 and c2 have at most 33 significant bits: times |k| < 2^20 they are exact.
    for (double part : {HalfPiSplit::c1, HalfPiSplit::c2}) {
        int e;
        const double m = std::frexp(part, &e);
        CHECK(std::ldexp(m, 33) == std::floor(std::ldexp(m, 33)));
        for (double k : {HalfPiSplit::max_quadrants - 1, -(HalfPiSplit::max_quadrants - 1), 123457.0}) {
            Ball product, kb, pb;
            arb_set_d(kb.get(), k);
            arb_set_d(pb.get(), part);
            arb_mul(product.get(), kb.get(), pb.get(), kPrec);
            arb_set_d(kb.get(), k * part);
            CHECK(arb_equal(product.get(), kb.get()));
        }
    }
}

TEST_CASE("interval_trig: the series' coefficients are 1/n! rounded to nearest", "[interval][trig]") {
    const auto check = [](double c, unsigned long n) {
        // |c - 1/n!| <= 2^-53 / n!, i.e. |c n! - 1| <= 2^-53.
        Ball x, f;
        arb_fac_ui(f.get(), n, kPrec);
        arb_set_d(x.get(), c);
        arb_mul(x.get(), x.get(), f.get(), kPrec);
        arb_sub_ui(x.get(), x.get(), 1, kPrec);
        Mag bound;
        arb_get_mag(bound.get(), x.get());
        INFO("1/" << n << "! as " << c);
        CHECK(mag_cmp_2exp_si(bound.get(), -53) <= 0);
    };
    for (int k = 0; k < SeriesCoefficients::kOddTerms; ++k) check(SeriesCoefficients::odd[k], 2 * k + 3);
    for (int k = 0; k < SeriesCoefficients::kEvenTerms; ++k) check(SeriesCoefficients::even[k], 2 * k + 2);
}

TEST_CASE("interval_trig: sin and cos at points contain Arb's, a few ulps wide", "[interval][trig]") {
    std::mt19937_64 rng(20261127);
    double widest = 0;
    for (double x : {0.0, -0.0, 1.0, -1.0, 0.785, -0.785, 0.78539816339744828, 1e-300, -1e-300,
                     std::numeric_limits<double>::denorm_min(), std::numeric_limits<double>::min(), 1e5, 524287.9,
                     524288.0, -524288.0, 524289.0, 1e6, 1e22, -1e300, std::numeric_limits<double>::max()})
        widest = std::fmax(widest, check_point(x));
    // Near and at the doubles nearest k pi/4.
    for (int k = -400; k <= 400; ++k) {
        Ball b;
        arb_const_pi(b.get(), kPrec);
        arb_mul_si(b.get(), b.get(), k, kPrec);
        arb_mul_2exp_si(b.get(), b.get(), -2);
        const double x = arf_get_d(arb_midref(b.get()), ARF_RND_NEAR);
        double y = x;
        for (int step = 0; step < 3; ++step) y = std::nextafter(y, INFINITY);
        for (int step = 0; step < 6; ++step) {
            check_point(y);
            y = std::nextafter(y, -INFINITY);
        }
    }
    // Uniform in [-10, 10] and [-2^19, 2^19]; log-uniform magnitudes 2^-1074 .. 2^30, both signs.
    std::uniform_real_distribution<double> small(-10, 10), large(-524288, 524288), exponent(-1074, 30);
    for (int n = 0; n < 20000; ++n) {
        widest = std::fmax(widest, check_point(small(rng)));
        const double x = large(rng);
        if (std::fabs(x) > 1) widest = std::fmax(widest, check_point(x));
        const double y = std::ldexp(1 + std::generate_canonical<double, 53>(rng), static_cast<int>(exponent(rng)));
        check_point(n % 2 ? y : -y);
    }
    // Reduced arguments are enclosed to a few ulps of the result where it is
    // not tiny (the Taylor sum's outward roundings).
    INFO("widest " << widest << " ulps");
    CHECK(widest <= 16);
}

TEST_CASE("interval_trig: sin and cos over intervals contain Arb's at the ends, inside and at the extrema",
          "[interval][trig]") {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> centre(-50, 50), unit(0, 1);
    const double half_pi = 1.5707963267948966;
    for (int n = 0; n < 5000; ++n) {
        const double c = centre(rng), width = std::ldexp(unit(rng), -static_cast<int>(60 * unit(rng)));
        const Interval x(c - width, c + width * (1 + unit(rng)));
        Interval s, c_;
        sin_cos(x, s, c_);
        INFO("x [" << x.lo << ", " << x.hi << "] sin [" << s.lo << ", " << s.hi << "] cos [" << c_.lo << ", "
                   << c_.hi << "]");
        std::vector<double> points = {x.lo, x.hi, x.mid()};
        for (int k = 0; k < 4; ++k) points.push_back(x.lo + (x.hi - x.lo) * unit(rng));
        for (double p : points) {
            const SinCos want = arb_at(std::fmin(std::fmax(p, x.lo), x.hi));
            CHECK(contains(s, want.sin.get(), true));
            CHECK(contains(c_, want.cos.get(), true));
        }
        // An extremum k pi/2 inside: its value +-1 or 0 must be in the enclosure.
        for (double k = std::ceil(x.lo / half_pi - 1); k <= std::floor(x.hi / half_pi + 1); ++k) {
            Ball e, sn, cs;
            arb_const_pi(e.get(), kPrec);
            arb_mul_si(e.get(), e.get(), static_cast<long>(k), kPrec);
            arb_mul_2exp_si(e.get(), e.get(), -1);
            Arf lo, hi;
            arf_set_d(lo.get(), x.lo);
            arf_set_d(hi.get(), x.hi);
            if (arf_cmp(arb_midref(e.get()), lo.get()) < 0 || arf_cmp(arb_midref(e.get()), hi.get()) > 0) continue;
            arb_sin_cos(sn.get(), cs.get(), e.get(), kPrec);
            CHECK(contains(s, sn.get(), true));
            CHECK(contains(c_, cs.get(), true));
        }
        // Not much wider than the range: the widening is about the radius.
        CHECK(s.hi - s.lo <= 2.1 * (x.hi - x.lo) + 1e-14);
        CHECK(c_.hi - c_.lo <= 2.1 * (x.hi - x.lo) + 1e-14);
    }
    Interval s, c;
    sin_cos(Interval(-1, 7), s, c);
    CHECK((s.lo == -1 && s.hi == 1 && c.lo == -1 && c.hi == 1));
    sin_cos(Interval(-INFINITY, 0), s, c);
    CHECK((s.lo == -1 && s.hi == 1));
    sin_cos(Interval(NAN, 0), s, c);
    CHECK((std::isnan(s.lo) && std::isnan(c.hi)));
}

TEST_CASE("interval_trig: sinh and cosh contain Arb's", "[interval][trig]") {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> y(-20, 20), unit(0, 1);
    double widest = 0;
    for (int n = 0; n < 5000; ++n) {
        double lo = y(rng), hi = lo;
        if (n % 3 == 1) hi = lo + unit(rng);
        if (n % 3 == 2) lo = -(hi = std::ldexp(unit(rng), -static_cast<int>(30 * unit(rng))));
        Interval sh, ch;
        sinh_cosh(Interval(lo, hi), sh, ch);
        INFO("y [" << lo << ", " << hi << "] sinh [" << sh.lo << ", " << sh.hi << "] cosh [" << ch.lo << ", "
                   << ch.hi << "]");
        for (double p : {lo, hi, 0.5 * (lo + hi), lo + (hi - lo) * unit(rng)}) {
            Ball b, s, c;
            arb_set_d(b.get(), p);
            arb_sinh_cosh(s.get(), c.get(), b.get(), kPrec);
            CHECK(contains(sh, s.get()));
            CHECK(contains(ch, c.get()));
        }
        if (lo == hi && std::fabs(lo) <= 16) widest = std::fmax(widest, std::fmax(width_in_ulps(sh), width_in_ulps(ch)));
        if (lo <= 0 && 0 <= hi) CHECK(ch.lo == 1);
    }
    // Up to 16 the doublings cost a few ulps each.
    INFO("widest " << widest << " ulps");
    CHECK(widest <= 4096);
}

TEST_CASE("interval_trig: sin and cos over complex rectangles contain Arb's", "[interval][trig]") {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> centre(-20, 20), unit(0, 1);
    for (int n = 0; n < 3000; ++n) {
        const double re = centre(rng), im = 3 * (2 * unit(rng) - 1);
        const double wr = n % 4 == 0 ? 0 : std::ldexp(unit(rng), -static_cast<int>(40 * unit(rng)));
        const double wi = n % 4 == 1 ? 0 : std::ldexp(unit(rng), -static_cast<int>(40 * unit(rng)));
        // Symmetric about the real axis every third time (the quadrature's boxes).
        const ComplexInterval z(Interval(re - wr, re + wr), n % 3 ? Interval(im - wi, im + wi) : Interval(-wi, wi));
        ComplexInterval s, c;
        sin_cos(z, s, c);
        INFO("z [" << z.re.lo << ", " << z.re.hi << "] + i [" << z.im.lo << ", " << z.im.hi << "]");
        for (int k = 0; k < 8; ++k) {
            const double x = k < 4 ? (k & 1 ? z.re.hi : z.re.lo) : z.re.lo + (z.re.hi - z.re.lo) * unit(rng);
            const double y = k < 4 ? (k & 2 ? z.im.hi : z.im.lo) : z.im.lo + (z.im.hi - z.im.lo) * unit(rng);
            ComplexBall w, ws, wc;
            arb_set_d(acb_realref(w.get()), std::fmin(std::fmax(x, z.re.lo), z.re.hi));
            arb_set_d(acb_imagref(w.get()), std::fmin(std::fmax(y, z.im.lo), z.im.hi));
            acb_sin_cos(ws.get(), wc.get(), w.get(), kPrec);
            CHECK(contains(s.re, ws.real()));
            CHECK(contains(s.im, ws.imag()));
            CHECK(contains(c.re, wc.real()));
            CHECK(contains(c.im, wc.imag()));
        }
    }
}
