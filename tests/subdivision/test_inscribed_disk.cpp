// disk_inside_ellipse: the certified test that an internal circle's disk lies
// in its site (docs/DESIGN.md §9, deep internal circles). Centers are placed
// on the inward normal at a fraction of the depth of the medial axis there;
// the oracle is a dense long-double search for the nearest boundary point,
// refined around every local minimum.
#include "subdivision/boundary_chart.hpp"
#include "subdivision/inscribed_disk.hpp"
#include "tests/support/random_sites.hpp"
#include "tests/support/signed_distance_oracle.hpp"
#include "tests/support/diagnostics.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

using namespace ellvor;
using ellvor::test::show;
using ellvor::test::verbose;

namespace {

using Rng = std::mt19937_64;


// A center at depth -rho on the inward normal at chart parameter t, as the
// solver's Krawczyk box would give it: t and rho exact (or widened by
// 2^-widen), V = P(t) + rho nu(t) in balls.
struct Case {
    Ellipse e;
    bool flipped;
    Ball t, rho, vx, vy;
    double theta;        // angle of P(t) in the ellipse's frame
    double medial_depth; // depth of the medial axis along the inward normal at P(t)
    double kappa;        // smallest radius of curvature
};

double angle_of(bool flipped, double t) { return flipped ? M_PI + 2 * std::atan(t) : 2 * std::atan(t); }

// Depth of the medial axis along the inward normal at (a cos theta, b sin
// theta): the normal meets the major axis there, after (min/max) sqrt(b^2
// cos^2 + a^2 sin^2).
double medial_depth(double a, double b, double theta) {
    const double n = std::hypot(b * std::cos(theta), a * std::sin(theta));
    return std::min(a, b) / std::max(a, b) * n;
}

Case make_case(const Ellipse& e, bool flipped, double t, double fraction, long prec, long widen = 0) {
    const double a = e.a().to_double(), b = e.b().to_double();
    const double theta = angle_of(flipped, t);
    const double depth = medial_depth(a, b, theta);
    Case c{e, flipped, Ball(), Ball(), Ball(), Ball(), theta, depth, std::min(a, b) * std::min(a, b) / std::max(a, b)};
    arb_set_d(c.t.get(), t);
    arb_set_d(c.rho.get(), -fraction * depth);
    const BoundaryChart chart(e, flipped);
    const BoundaryChart::Local p = chart.evaluate(c.t, prec, false);
    arb_mul(c.vx.get(), c.rho.get(), p.nx.get(), prec);
    arb_add(c.vx.get(), c.vx.get(), p.px.get(), prec);
    arb_mul(c.vy.get(), c.rho.get(), p.ny.get(), prec);
    arb_add(c.vy.get(), c.vy.get(), p.py.get(), prec);
    if (widen > 0)
        for (Ball* x : {&c.t, &c.rho, &c.vx, &c.vy}) arb_add_error_2exp_si(x->get(), -widen);
    return c;
}

// V in the ellipse's own frame (long double from the balls' midpoints).
void frame_point(const Case& c, long double& xi, long double& eta) {
    const long double dx = c.vx.mid_double() - c.e.xc().to_double(), dy = c.vy.mid_double() - c.e.yc().to_double();
    const long double co = c.e.cos_rotation().to_double(), si = c.e.sin_rotation().to_double();
    xi = co * dx + si * dy;
    eta = -si * dx + co * dy;
}

// Distance from V to the boundary, brute force: 8192 samples of the angle,
// then a golden-section search around each sampled local minimum.
long double nearest_distance(const Case& c) {
    long double xi, eta;
    frame_point(c, xi, eta);
    const long double a = c.e.a().to_double(), b = c.e.b().to_double();
    auto d2 = [&](long double phi) {
        const long double x = a * std::cos(phi) - xi, y = b * std::sin(phi) - eta;
        return x * x + y * y;
    };
    constexpr int n = 8192;
    const long double step = 2 * M_PIl / n;
    std::vector<long double> v(n);
    for (int i = 0; i < n; ++i) v[i] = d2(i * step);
    long double best = *std::min_element(v.begin(), v.end());
    for (int i = 0; i < n; ++i) {
        if (v[i] > v[(i + n - 1) % n] || v[i] > v[(i + 1) % n]) continue;
        long double lo = (i - 1) * step, hi = (i + 1) * step;
        const long double g = (std::sqrt(5.0L) - 1) / 2;
        for (int it = 0; it < 200 && hi - lo > 1e-18L; ++it) {
            const long double m1 = hi - g * (hi - lo), m2 = lo + g * (hi - lo);
            if (d2(m1) < d2(m2)) hi = m2; else lo = m1;
        }
        best = std::min(best, d2((lo + hi) / 2));
    }
    return std::sqrt(best);
}

bool strictly_inside(const Case& c) {
    long double xi, eta;
    frame_point(c, xi, eta);
    const long double a = c.e.a().to_double(), b = c.e.b().to_double();
    return xi * xi / (a * a) + eta * eta / (b * b) < 1 - 1e-6L;
}

// Semi-axes with aspect ratio 1 to 20 (the longer one a or b at random),
// any rotation, centers near the origin.
Ellipse random_ellipse(Rng& rng) {
    std::uniform_int_distribution<long> small(32, 64), aspect(16, 320), w(-39, 39), ctr(-14, 14);
    const Rational s(small(rng), 64UL), l = s * Rational(aspect(rng), 16UL);
    const bool swap = rng() % 2;
    return Ellipse(swap ? s : l, swap ? l : s, Rational(w(rng), 13UL), Rational(ctr(rng), 7UL), Rational(ctr(rng), 7UL));
}

double uniform(Rng& rng, double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }

double abs_rho(const Case& c) { return -c.rho.mid_double(); }

}  // namespace

TEST_CASE("inscribed disk: internal circles of random ellipses up to the medial axis are certified",
          "[subdivision][inscribed-disk]") {
    Rng rng(20240611);
    for (long prec : {128L, 64L}) {
        long interesting = 0, interesting_proven = 0, near = 0, near_proven = 0, shallow = 0, pieces_total = 0,
             calls = 0;
        double seconds = 0;
        for (int i = 0; i < 2000; ++i) {
            const Ellipse e = random_ellipse(rng);
            const bool flipped = rng() % 2;
            const double fraction = uniform(rng, 0.001, 0.98);
            // Half of the cases with balls as loose as a Krawczyk box's.
            const Case c = make_case(e, flipped, uniform(rng, -1, 1), fraction, prec, i % 2 ? prec - 12 : 0);
            long pieces = 0;
            const auto start = std::chrono::steady_clock::now();
            const bool proven = disk_inside_ellipse(c.e, c.flipped, c.t, c.rho, c.vx, c.vy, prec, &pieces);
            seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            pieces_total += pieces;
            ++calls;
            INFO("ellipse " << e.str() << " flipped " << flipped << " t " << c.t.str() << " fraction " << fraction
                            << " prec " << prec);
            if (proven) {
                // The truth: no boundary point nearer than |rho|.
                CHECK(nearest_distance(c) >= abs_rho(c) * (1 - 1e-9));
            }
            if (abs_rho(c) < c.kappa / 2) {
                ++shallow;
                CHECK(proven);
            } else if (fraction <= 0.9 && abs_rho(c) > c.kappa) {
                ++interesting;
                interesting_proven += proven;
            } else if (fraction > 0.9) {
                ++near;
                near_proven += proven;
            }
        }
        if (verbose())
            std::printf("inscribed disk, %ld bits: %ld/%ld proven beyond kappa (fraction <= 0.9), %ld/%ld in (0.9, "
                        "0.98], %ld shallow; %.1f us and %.1f pieces a call\n",
                        prec, interesting_proven, interesting, near_proven, near, shallow, 1e6 * seconds / calls,
                        static_cast<double>(pieces_total) / calls);
        CHECK(interesting > 500);
        CHECK(interesting_proven >= 0.95 * interesting);
    }
}

TEST_CASE("inscribed disk: centers beyond the medial axis are never certified", "[subdivision][inscribed-disk]") {
    Rng rng(77);
    const long prec = 128;
    int tested = 0;
    long pieces_total = 0;
    while (tested < 1000) {
        const Ellipse e = random_ellipse(rng);
        if (e.is_circle()) continue;
        const bool flipped = rng() % 2;
        const Case c = make_case(e, flipped, uniform(rng, -1, 1), uniform(rng, 1.05, 2), prec);
        if (!strictly_inside(c)) continue;
        ++tested;
        INFO("ellipse " << e.str() << " flipped " << flipped << " t " << c.t.str() << " rho " << c.rho.str());
        // The truth: a boundary point nearer than |rho| (the disk pokes out).
        CHECK(nearest_distance(c) < abs_rho(c) * (1 - 1e-9));
        long pieces = 0;
        CHECK_FALSE(disk_inside_ellipse(c.e, c.flipped, c.t, c.rho, c.vx, c.vy, prec, &pieces));
        pieces_total += pieces;
    }
    if (verbose()) std::printf("beyond the medial axis: %.1f pieces a call\n", pieces_total / 1000.0);
}

TEST_CASE("inscribed disk: circles, every depth below the radius", "[subdivision][inscribed-disk]") {
    Rng rng(5);
    for (int i = 0; i < 500; ++i) {
        std::uniform_int_distribution<long> r(8, 400), ctr(-30, 30);
        const Ellipse e = Ellipse::circle(Rational(ctr(rng), 7UL), Rational(ctr(rng), 11UL), Rational(r(rng), 64UL));
        const bool flipped = rng() % 2;
        const double fraction = uniform(rng, 0.001, 0.98);
        const Case c = make_case(e, flipped, uniform(rng, -1, 1), fraction, 128, i % 2 ? 116 : 0);
        INFO("circle " << e.str() << " flipped " << flipped << " t " << c.t.str() << " fraction " << fraction);
        CHECK(disk_inside_ellipse(c.e, c.flipped, c.t, c.rho, c.vx, c.vy, 128));
    }
}

TEST_CASE("inscribed disk: the i-point and the ends of the charts", "[subdivision][inscribed-disk]") {
    const Ellipse e(Rational(5), Rational(1, 2), Rational(1, 3), Rational(1, 7), Rational(-2, 3));
    for (double t : {0.0, 1.0, -1.0, 0.999, -0.999}) {
        for (bool flipped : {false, true}) {
            // 0.9 of the medial depth: beyond kappa except near the vertices.
            const Case c = make_case(e, flipped, t, 0.9, 128, 100);
            INFO("flipped " << flipped << " t " << t);
            const bool proven = disk_inside_ellipse(c.e, c.flipped, c.t, c.rho, c.vx, c.vy, 128);
            CHECK(proven);
            if (proven) CHECK(nearest_distance(c) >= abs_rho(c) * (1 - 1e-9));
        }
    }
    // A chart parameter a little outside [-1, 1], as a Krawczyk box may have.
    const Case c = make_case(e, false, 1.01, 0.9, 128, 100);
    CHECK(disk_inside_ellipse(c.e, c.flipped, c.t, c.rho, c.vx, c.vy, 128));
}

TEST_CASE("inscribed disk: rho not certainly negative is not this test's case", "[subdivision][inscribed-disk]") {
    const Ellipse e(Rational(3), Rational(1), Rational(0), Rational(0), Rational(0));
    const Case outside = make_case(e, false, 0.3, -0.5, 128);  // rho > 0: V outside
    CHECK_FALSE(disk_inside_ellipse(e, false, outside.t, outside.rho, outside.vx, outside.vy, 128));
    Case zero = make_case(e, false, 0.3, 0.0, 128);  // rho = 0: V = P(t)
    CHECK_FALSE(disk_inside_ellipse(e, false, zero.t, zero.rho, zero.vx, zero.vy, 128));
    arb_add_error_2exp_si(zero.rho.get(), -60);  // a ball around 0
    CHECK_FALSE(disk_inside_ellipse(e, false, zero.t, zero.rho, zero.vx, zero.vy, 128));
}

TEST_CASE("inside_distance_minus: the depth of a point inside an ellipse against a radius", "[inscribed-disk][crossing]") {
    const long prec = 128;
    auto ball = [](double x) {  // exact
        Ball b;
        arb_set_d(b.get(), x);
        return b;
    };
    // The center of an ellipse lies at depth b (its smaller semi-axis); a
    // point of a circle at distance d from its center, at depth r - d.
    const Ellipse e(Rational(5), Rational(2), Rational(1, 3UL), Rational(1), Rational(-2));
    CHECK(inside_distance_minus(e, ball(2 * (1 - 1e-9)), ball(1), ball(-2), prec) == 1);
    CHECK(inside_distance_minus(e, ball(2 * (1 + 1e-9)), ball(1), ball(-2), prec) == -1);
    CHECK(inside_distance_minus(e, ball(2), ball(1), ball(-2), prec) == 0);  // equal: never decided
    const Ellipse c = Ellipse::circle(3, 4, 10);
    // (6, 8) lies 5 from the center (3, 4): depth 5.
    CHECK(inside_distance_minus(c, ball(5 - 1e-12), ball(6), ball(8), prec) == 1);
    CHECK(inside_distance_minus(c, ball(5 + 1e-12), ball(6), ball(8), prec) == -1);
    CHECK(inside_distance_minus(c, ball(-1), ball(6), ball(8), prec) == 0);  // r must be positive

    // Random points inside random ellipses against the MPFR signed distance
    // (tests/support/signed_distance_oracle.hpp): r a little below and above
    // the depth.
    Rng rng(5);
    int decided = 0;
    for (int k = 0; k < 200; ++k) {
        const Ellipse f(test::random_fraction(rng, 10, 100, 10), test::random_fraction(rng, 1, 100, 10),
                        test::random_fraction(rng, -99, 99, 100), test::random_fraction(rng, -100, 100, 10),
                        test::random_fraction(rng, -100, 100, 10));
        const double x = f.xc().to_double() + test::random_fraction(rng, -50, 50, 10).to_double(),
                     y = f.yc().to_double() + test::random_fraction(rng, -50, 50, 10).to_double();
        const double depth = -test::OracleEllipse(f).signed_distance_value({test::Real(x), test::Real(y)}).to_double();
        if (!(depth > 1e-6)) continue;  // outside, or too near the boundary
        for (double factor : {0.999, 1.001}) {
            const int got = inside_distance_minus(f, ball(depth * factor), ball(x), ball(y), prec);
            CHECK(got == (factor < 1 ? 1 : -1));
            decided += got != 0;
        }
    }
    CHECK(decided >= 100);
}

// Why an internal Voronoi circle centered exactly on a site's medial axis ends
// at the search's cap (docs/DESIGN.md §4.2, what still ends with an Error): a
// needle between two circles, symmetric about its axis, has its vertex there.
// The disk of radius dist(V, boundary) about such a V touches the needle at two
// mirror feet, so the test proves the disk inside from neither foot, while
// the same disk moved along one foot's normal, off the axis, is proved.
TEST_CASE("inscribed disk: a center exactly on the medial axis touches two mirror feet, certified with the mirror only",
          "[subdivision][inscribed-disk]") {
    const long prec = 256;
    const Ellipse needle(Rational(11, 30UL), Rational(10), Rational(0), Rational(6), Rational(10));
    const Ball a(needle.a(), prec), b(needle.b(), prec), vx(Rational(6), prec), vy(Rational(15, 2UL), prec);
    const Ball y(Rational(-5, 2UL), prec);  // V's height over the center, on the major (vertical) axis
    // Feet (a cos th, b sin th) with sin th = b y / (b^2 - a^2): cos th > 0 on the right (chart t =
    // tan(th/2) = sin / (1 + cos)), its mirror pi - th on the left (flipped chart u = -1/tan((pi - th)/2) = -t).
    Ball s, c, t, u, rho, x;
    arb_sqr(c.get(), b.get(), prec);
    arb_submul(c.get(), a.get(), a.get(), prec);
    arb_mul(s.get(), b.get(), y.get(), prec);
    arb_div(s.get(), s.get(), c.get(), prec);
    arb_sqr(c.get(), s.get(), prec);
    arb_sub_ui(c.get(), c.get(), 1, prec);
    arb_neg(c.get(), c.get());
    arb_sqrt(c.get(), c.get(), prec);
    arb_add_ui(t.get(), c.get(), 1, prec);
    arb_div(t.get(), s.get(), t.get(), prec);
    arb_neg(u.get(), t.get());
    arb_mul(x.get(), a.get(), c.get(), prec);
    arb_sqr(rho.get(), x.get(), prec);
    arb_mul(x.get(), b.get(), s.get(), prec);
    arb_sub(x.get(), x.get(), y.get(), prec);
    arb_addmul(rho.get(), x.get(), x.get(), prec);
    arb_sqrt(rho.get(), rho.get(), prec);
    arb_neg(rho.get(), rho.get());
    INFO("t " << t.str() << " rho " << rho.str());
    // Both feet put V on their inward normal at depth |rho|: consistent balls, as a Krawczyk box would give.
    for (bool flipped : {false, true}) {
        const BoundaryChart::Local p = BoundaryChart(needle, flipped).evaluate(flipped ? u : t, prec, false);
        Ball wx, wy;
        arb_set(wx.get(), p.px.get());
        arb_addmul(wx.get(), rho.get(), p.nx.get(), prec);
        arb_set(wy.get(), p.py.get());
        arb_addmul(wy.get(), rho.get(), p.ny.get(), prec);
        CHECK(arb_overlaps(wx.get(), vx.get()));
        CHECK(arb_overlaps(wy.get(), vy.get()));
        CHECK_FALSE(disk_inside_ellipse(needle, flipped, flipped ? u : t, rho, vx, vy, prec));
        // V on the needle's axis x = 6, which holds its b-axis: the mirror maps t to -t in the
        // other chart (P(t) -> P(1/t)). Told so, the test skips the mirror foot and proves the
        // disk inside; told the wrong mirror (the same chart), it still meets the other foot.
        CHECK(disk_inside_ellipse(needle, flipped, flipped ? u : t, rho, vx, vy, prec, nullptr, AxisMirror::other_chart));
        CHECK_FALSE(disk_inside_ellipse(needle, flipped, flipped ? u : t, rho, vx, vy, prec, nullptr, AxisMirror::same_chart));
    }
    // The distance from V to the boundary is |rho| within 2^-100: the disk touches both feet.
    for (int side : {-1, 1}) {
        Ball r, factor;
        arb_one(factor.get());
        arb_mul_2exp_si(factor.get(), factor.get(), -100);
        if (side < 0) arb_neg(factor.get(), factor.get());
        arb_add_ui(factor.get(), factor.get(), 1, prec);
        arb_neg(r.get(), rho.get());
        arb_mul(r.get(), r.get(), factor.get(), prec);
        CHECK(inside_distance_minus(needle, r, vx, vy, prec) == -side);
    }
    // Moved along the right foot's normal to 0.999 |rho|, off the axis: that foot alone is nearest.
    const BoundaryChart::Local p = BoundaryChart(needle, false).evaluate(t, prec, false);
    Ball shallower, wx, wy;
    arb_mul_ui(shallower.get(), rho.get(), 999, prec);
    arb_div_ui(shallower.get(), shallower.get(), 1000, prec);
    arb_set(wx.get(), p.px.get());
    arb_addmul(wx.get(), shallower.get(), p.nx.get(), prec);
    arb_set(wy.get(), p.py.get());
    arb_addmul(wy.get(), shallower.get(), p.ny.get(), prec);
    CHECK(disk_inside_ellipse(needle, false, t, shallower, wx, wy, prec));
}
