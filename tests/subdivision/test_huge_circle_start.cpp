// Voronoi circles 10^12 .. 10^40 times larger than their sites (nearly
// collinear sites), certified from the tangent-line start
// (huge_circle_start.hpp), against independent computations:
//  * circles: the closed-form Apollonius oracle at 4096 bits;
//  * ellipses: a family built on the line y = 1 (two sites tangent to it, the
//    third 10^-k below), solved by the test's own method -- a planar Newton
//    iteration for the point equidistant from the three ellipses, each
//    distance from its own nearest-point iteration, in Arb at 2048 bits,
//    started from the first-order circle derived by hand below.
// And InCircle against those circles, with queries 1 unit inside or outside
// a circle of radius up to 5 10^40. (Their time per decision is measured by
// experiments/near_degenerate.cpp.)
#include "predicates/incircle.hpp"
#include "subdivision/huge_circle_start.hpp"
#include "subdivision/voronoi_circle_enclosure.hpp"
#include "tests/support/apollonius_oracle.hpp"
#include "tests/support/random_sites.hpp"
#include "util/ball_arithmetic.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

using namespace ellvor;

namespace {

constexpr long kOraclePrecision = 2048;


bool overlaps(const Ball& a, const Ball& b) { return arb_overlaps(a.get(), b.get()) != 0; }

Ball widened(const Ball& b, long bits_below) {
    Ball r = b;
    Mag m;
    arb_get_mag(m.get(), b.get());
    mag_mul_2exp_si(m.get(), m.get(), -bits_below);
    mag_add(arb_radref(r.get()), arb_radref(r.get()), m.get());
    return r;
}

// ------------------------------------------------------------- the oracle --


// Distance from a far point V to E, and the unit vector from the nearest
// point to V: Newton on the nearest point's angle theta in E's frame,
// g(theta) = (a^2 - b^2) sin cos - a x sin + b y cos, from the support point
// in the direction of V (V is far, so that is close).
struct Foot {
    Ball distance, ux, uy;
};
Foot foot(const Ellipse& e, const Ball& vx, const Ball& vy) {
    const BallArithmetic A{kOraclePrecision};
    const Ball c = A.q(e.cos_rotation()), s = A.q(e.sin_rotation()), a = A.q(e.a()), b = A.q(e.b());
    const Ball dx = A.sub(vx, A.q(e.xc())), dy = A.sub(vy, A.q(e.yc()));
    const Ball x = A.add(A.mul(c, dx), A.mul(s, dy)), y = A.sub(A.mul(c, dy), A.mul(s, dx));
    Ball theta;
    arb_atan2(theta.get(), A.mul(b, y).get(), A.mul(a, x).get(), A.prec);
    theta = A.mid(theta);
    const Ball ab = A.sub(A.mul(a, a), A.mul(b, b));
    for (int it = 0; it < 40; ++it) {
        Ball sn, cs;
        arb_sin_cos(sn.get(), cs.get(), theta.get(), A.prec);
        const Ball g = A.add(A.sub(A.mul(A.mul(ab, sn), cs), A.mul(A.mul(a, x), sn)), A.mul(A.mul(b, y), cs));
        // g' = (a^2 - b^2) cos(2 theta) - a x cos - b y sin
        const Ball g1 = A.sub(A.sub(A.mul(ab, A.sub(A.mul(cs, cs), A.mul(sn, sn))), A.mul(A.mul(a, x), cs)),
                              A.mul(A.mul(b, y), sn));
        theta = A.mid(A.sub(theta, A.div(g, g1)));
    }
    Ball sn, cs;
    arb_sin_cos(sn.get(), cs.get(), theta.get(), A.prec);
    const Ball px = A.sub(x, A.mul(a, cs)), py = A.sub(y, A.mul(b, sn));  // V - P, local
    Foot f;
    arb_hypot(f.distance.get(), px.get(), py.get(), A.prec);
    f.ux = A.div(A.sub(A.mul(c, px), A.mul(s, py)), f.distance);
    f.uy = A.div(A.add(A.mul(s, px), A.mul(c, py)), f.distance);
    return f;
}

// Distance from an outside point V to E by the Lagrange multiplier of the
// nearest point P = (a^2 x / (a^2 + l), b^2 y / (b^2 + l)) in E's frame:
// F(l) = (a x / (a^2 + l))^2 + (b y / (b^2 + l))^2 - 1 decreases from
// F(0) > 0 to F(sqrt(a^2 x^2 + b^2 y^2)) <= 0, so bisection finds its one root
// whatever the aspect (the foot iteration above needs a start near P).
Ball distance_by_multiplier(const Ellipse& e, const Ball& vx, const Ball& vy) {
    const BallArithmetic A{kOraclePrecision};
    const Ball c = A.q(e.cos_rotation()), s = A.q(e.sin_rotation()), a = A.q(e.a()), b = A.q(e.b());
    const Ball dx = A.sub(vx, A.q(e.xc())), dy = A.sub(vy, A.q(e.yc()));
    const Ball x = A.add(A.mul(c, dx), A.mul(s, dy)), y = A.sub(A.mul(c, dy), A.mul(s, dx));
    const Ball a2 = A.mul(a, a), b2 = A.mul(b, b), ax = A.mul(a, x), by = A.mul(b, y);
    auto point = [&](const Ball& l, Ball& px, Ball& py) {
        px = A.div(A.mul(a2, x), A.add(a2, l));
        py = A.div(A.mul(b2, y), A.add(b2, l));
    };
    Ball lo = A.q(Rational(0)), hi;
    arb_hypot(hi.get(), ax.get(), by.get(), A.prec);
    hi = A.mid(hi);
    for (int it = 0; it < 2 * A.prec; ++it) {
        Ball l = A.mid(A.mul(A.add(lo, hi), A.q(Rational(1, 2UL)))), px, py;
        point(l, px, py);
        const Ball f = A.sub(A.add(A.mul(A.div(px, a), A.div(px, a)), A.mul(A.div(py, b), A.div(py, b))), A.q(1));
        (arf_sgn(arb_midref(f.get())) > 0 ? lo : hi) = l;
    }
    Ball px, py, d;
    point(lo, px, py);
    arb_hypot(d.get(), A.sub(x, px).get(), A.sub(y, py).get(), A.prec);
    return d;
}

// Newton for d1(V) = d2(V) = d3(V); returns V and the common distance, or
// false when it did not converge.
bool equidistant_point(const std::array<const Ellipse*, 3>& e, Ball& vx, Ball& vy, Ball& radius) {
    const BallArithmetic A{kOraclePrecision};
    for (int it = 0; it < 60; ++it) {
        const Foot f1 = foot(*e[0], vx, vy), f2 = foot(*e[1], vx, vy), f3 = foot(*e[2], vx, vy);
        const Ball g1 = A.sub(f1.distance, f2.distance), g2 = A.sub(f1.distance, f3.distance);
        const Ball a11 = A.sub(f1.ux, f2.ux), a12 = A.sub(f1.uy, f2.uy), a21 = A.sub(f1.ux, f3.ux),
                   a22 = A.sub(f1.uy, f3.uy);
        const Ball det = A.sub(A.mul(a11, a22), A.mul(a12, a21));
        const Ball sx = A.div(A.sub(A.mul(a22, g1), A.mul(a12, g2)), det);
        const Ball sy = A.div(A.sub(A.mul(a11, g2), A.mul(a21, g1)), det);
        vx = A.mid(A.sub(vx, sx));
        vy = A.mid(A.sub(vy, sy));
        radius = f1.distance;
        Mag step;
        arb_get_mag(step.get(), sx.get());
        Mag stepy;
        arb_get_mag(stepy.get(), sy.get());
        mag_max(step.get(), step.get(), stepy.get());
        if (mag_cmp_2exp_si(step.get(), -A.prec / 2) < 0 && it > 2) return true;
    }
    return false;
}

// The ellipse family on the line y = 1: E1 = (3/4, 4/3, w = 1/2) at the
// origin (cos = 3/5, sin = 4/5, so its top is at y = sqrt(16a^2 + 9b^2)/5 = 1,
// x = -7/12), E2 = (2, 1, 0) at (6, 0) (top (6, 1)), and E3 = (1/2, 1, 0) at
// (3, -10^-k) (top (3, 1 - 10^-k)). The counter-clockwise order along the
// circle above the line is E1, E3, E2. First order (huge_circle_start.hpp
// derives it): c = (x1 + x2)/2 = 65/24, R = (x3 - x1)(x3 - x2)/(2g) with g =
// -10^-k: R = 43/8 10^k, V = (c, 1 + R - (x1 - c)^2 / (2R)).
struct Family {
    Ellipse e1, e3, e2;
    Rational radius, cx, cy;
};
Family family(int k) {
    const Rational g = power_of_ten(-k), x1(-7, 12UL), x2(6), c(65, 24UL);
    const Rational R = Rational(43, 8UL) * power_of_ten(k);
    return {Ellipse(Rational(3, 4UL), Rational(4, 3UL), Rational(1, 2UL), 0, 0),
            Ellipse(Rational(1, 2UL), 1, 0, 3, -g), Ellipse(2, 1, 0, 6, 0), R, c,
            Rational(1) + R - (x1 - c) * (x1 - c) / (Rational(2) * R)};
}

// A unit circle at distance R + 1 + delta above V (a rational point within
// 2^-100 of it): it meets the open disk iff delta < 0.
Ellipse query_above(const Ball& vx, const Ball& vy, const Ball& radius, long delta) {
    const BallArithmetic A{kOraclePrecision};
    const Ball y = A.add(A.add(vy, radius), A.q(Rational(1 + delta)));
    Rational qx, qy, hi;
    Ball x = widened(vx, 0);
    arb_set_round(x.get(), vx.get(), 300);
    Ball yr;
    arb_set_round(yr.get(), y.get(), 300);
    ball_endpoints(x, qx, hi);
    ball_endpoints(yr, qy, hi);
    return Ellipse::circle(qx, qy, 1);
}

}  // namespace

TEST_CASE("huge circles of nearly collinear circles are certified from the tangent line, k = 12 .. 40",
          "[subdivision][huge-circle]") {
    for (int k : {12, 16, 20, 30, 40}) {
        const Rational lift = power_of_ten(-k);
        // Unit circles on the x-axis with the middle one lifted (the circle is
        // below), and the same on the tilted line through (0, 0) and (6, 8).
        const apollonius::Circle rows[2][3] = {
            {{Rational(0), Rational(0), Rational(1)}, {Rational(6), Rational(0), Rational(1)}, {Rational(3), lift, Rational(1)}},
            {{Rational(0), Rational(0), Rational(1)}, {Rational(6), Rational(8), Rational(1)}, {Rational(3), Rational(4) + lift, Rational(1)}}};
        for (const auto& c : rows) {
            const Ellipse e1 = c[0].ellipse(), e2 = c[1].ellipse(), e3 = c[2].ellipse();
            INFO("k " << k << apollonius::ell({&e1, &e2, &e3}));
            const apollonius::Result oracle = apollonius::voronoi_circles(c[0], c[1], c[2], 4096);
            REQUIRE(oracle.certain);
            REQUIRE(oracle.ccw());
            VoronoiCircleSolver solver(e1, e2, e3);
            REQUIRE(solver.refine(128));
            const VoronoiCircleEnclosure& found = solver.enclosure();
            CHECK(found.found_by == CircleStart::tangent_line);
            CHECK(overlaps(found.center_x, oracle.ccw()->x));
            CHECK(overlaps(found.center_y, oracle.ccw()->y));
            CHECK(overlaps(found.radius, oracle.ccw()->radius));
            CHECK(found.radius.mid_double() > 1e11 * std::pow(10.0, k - 12));
        }
    }
}

TEST_CASE("huge circles of nearly collinear ellipses match an independent high-precision computation",
          "[subdivision][huge-circle]") {
    for (int k : {12, 16, 20, 30, 40}) {
        const Family f = family(k);
        INFO("k " << k << apollonius::ell({&f.e1, &f.e3, &f.e2}));
        // The oracle, from the hand-derived first-order circle.
        Ball vx = Ball(f.cx, kOraclePrecision), vy = Ball(f.cy, kOraclePrecision), radius;
        REQUIRE(equidistant_point({&f.e1, &f.e3, &f.e2}, vx, vy, radius));
        // ellvor.
        VoronoiCircleSolver solver(f.e1, f.e3, f.e2);
        REQUIRE(solver.refine(160));
        const VoronoiCircleEnclosure& found = solver.enclosure();
        CHECK(found.found_by == CircleStart::tangent_line);
        // The oracle is good to far more than 160 bits: its midpoint must lie
        // in ellvor's (widened by 2^-150 of the value, for the oracle's own
        // rounding) balls.
        CHECK(overlaps(widened(found.center_x, 150), vx));
        CHECK(overlaps(widened(found.center_y, 150), vy));
        CHECK(overlaps(widened(found.radius, 150), radius));

        // InCircle: a unit circle 1 unit outside or inside the circle of
        // radius ~5.4 10^k, above it.
        for (long delta : {1L, -1L}) {
            const Ellipse q = query_above(vx, vy, radius, delta);
            const Decision<InCircle> d = incircle(f.e1, f.e3, f.e2, q);
            INFO("delta " << delta << " stage " << stage_name(d.stage) << " precision " << d.precision);
            CHECK(*d == (delta > 0 ? InCircle::no_conflict : InCircle::conflict));
        }
    }
}

TEST_CASE("huge circles of a close pair and a far circle are certified from the tangent line, 10^12 .. 10^40 away",
          "[subdivision][huge-circle]") {
    // Two unit circles 3 apart, the third 10^k away: straight out from the
    // pair's common tangent, obliquely, and nearly along the pair's axis.
    for (int k : {12, 20, 30, 40}) {
        const Rational far = power_of_ten(k);
        const apollonius::Circle triples[3][3] = {
            {{Rational(0), Rational(0), Rational(1)}, {Rational(3), Rational(0), Rational(1)}, {Rational(1), -far, Rational(2)}},
            {{Rational(0), Rational(0), Rational(1)}, {Rational(3), Rational(0), Rational(1)}, {far, -far, Rational(1)}},
            {{Rational(0), Rational(0), Rational(1)}, {Rational(3), Rational(1, 2UL), Rational(1)}, {far, Rational(5), Rational(3)}}};
        // Both orientations, each in its three rotations: the far site first
        // once made the pair's bitangents round away (a fuzz finding).
        constexpr int kOrders[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
        for (const auto& c : triples) {
            for (const auto& order : kOrders) {
                const apollonius::Circle &c1 = c[order[0]], &c2 = c[order[1]], &c3 = c[order[2]];
                const Ellipse e1 = c1.ellipse(), e2 = c2.ellipse(), e3 = c3.ellipse();
                INFO("k " << k << apollonius::ell({&e1, &e2, &e3}));
                const apollonius::Result oracle = apollonius::voronoi_circles(c1, c2, c3, 4096);
                REQUIRE(oracle.certain);
                VoronoiCircleSolver solver(e1, e2, e3);
                REQUIRE(solver.refine(128) == bool(oracle.ccw()));
                if (!oracle.ccw()) continue;
                const VoronoiCircleEnclosure& found = solver.enclosure();
                CHECK(found.found_by != CircleStart::search);
                CHECK(overlaps(found.center_x, oracle.ccw()->x));
                CHECK(overlaps(found.center_y, oracle.ccw()->y));
                CHECK(overlaps(found.radius, oracle.ccw()->radius));
                CHECK(found.radius.mid_double() > 1e11 * std::pow(10.0, k - 12));
            }
        }
    }
}

TEST_CASE("huge circles of a needle, a small circle past its side and a far site match independent distances",
          "[subdivision][huge-circle]") {
    // The needle's external bitangents with the circle pass within ~10^-6
    // radians of the needle's minor axis (a fuzz finding: the uniform samples
    // of the bitangent directions missed them, and the search gave up).
    for (int aspect : {3, 6, 9, 12}) {
        for (int k : {12, 16, 20, 30}) {
            const Ellipse needle(1, power_of_ten(aspect), 0, 5, 1), small = Ellipse::circle(2, 6, 1),
                          far(2, 1, 1, -power_of_ten(k), -5);
            for (const auto& triple : {std::array<const Ellipse*, 3>{&needle, &small, &far},
                                       std::array<const Ellipse*, 3>{&far, &needle, &small},
                                       std::array<const Ellipse*, 3>{&needle, &far, &small},
                                       std::array<const Ellipse*, 3>{&far, &small, &needle}}) {
                INFO("aspect 10^" << aspect << " k " << k << apollonius::ell({triple[0], triple[1], triple[2]}));
                VoronoiCircleSolver solver(*triple[0], *triple[1], *triple[2]);
                REQUIRE(solver.refine(128));
                const VoronoiCircleEnclosure& found = solver.enclosure();
                CHECK(found.found_by != CircleStart::search);
                // The test's own nearest-point computation from the certified
                // center: every site at the certified radius.
                const Ball vx = BallArithmetic::mid(found.center_x), vy = BallArithmetic::mid(found.center_y);
                for (const Ellipse* e : triple)
                    CHECK(arb_contains(widened(found.radius, 100).get(), distance_by_multiplier(*e, vx, vy).get()));
            }
        }
    }
}

TEST_CASE("huge circle starts in doubles agree with the Arb starts from 2^3 to 2^20 sizes",
          "[subdivision][huge-circle]") {
    // Random triples of small ellipses nearly on a line (the third lifted by
    // 2^-2 .. 2^-14 of the spacing, so that R runs over 2^3 .. 2^20 sizes):
    // every Arb start in the doubles' range has a doubles start of the same
    // charts within 1e-3 of it (the first-order circle's own error is
    // O(size / R); the doubles add rounding only). Both are only starts: the
    // certificate judges them (test_voronoi_circle_in_doubles.cpp).
    std::mt19937_64 rng(20261127);
    int compared = 0;
    for (int trial = 0; trial < 60; ++trial) {
        auto axis = [&] { return test::random_fraction(rng, 20, 60, 100); };
        auto angle = [&] { return test::random_fraction(rng, -99, 99, 100); };
        const long lift_den = 1L << (2 + trial % 13);
        const Ellipse e1(axis(), axis(), angle(), Rational(0), Rational(0));
        const Ellipse e2(axis(), axis(), angle(), Rational(10), Rational(0));
        const Ellipse e3(axis(), axis(), angle(), Rational(5), test::random_fraction(rng, -10, 10, lift_den));
        std::vector<VoronoiCircleStart> arb;
        for_each_huge_circle_start(e1, e2, e3, 3, [&](const VoronoiCircleStart& s) {
            arb.push_back(s);
            return false;
        });
        std::vector<DoubleCircleStart> doubles;
        for_each_huge_circle_start_in_doubles(e1, e2, e3, 3, [&](const DoubleCircleStart& s) {
            doubles.push_back(s);
            return false;
        });
        for (const VoronoiCircleStart& a : arb) {
            const double radius = a.radius.mid_double();
            if (radius > std::ldexp(0.2, kMaxRatioBitsInDoubles)) continue;
            INFO("trial " << trial << " radius " << radius);
            const auto same = [&](const DoubleCircleStart& d) {
                if (d.flipped != a.flipped) return false;
                for (int i = 0; i < 3; ++i)
                    if (!(std::fabs(d.x[i] - a.parameter[i].mid_double()) <= 1e-3 * (1 + std::fabs(d.x[i]))))
                        return false;
                return std::fabs(d.x[3] - radius) <= 1e-3 * radius &&
                       std::hypot(d.x[4] - a.center_x.mid_double(), d.x[5] - a.center_y.mid_double()) <= 1e-3 * radius;
            };
            CHECK(std::any_of(doubles.begin(), doubles.end(), same));
            ++compared;
        }
    }
    CHECK(compared >= 40);
}

TEST_CASE("huge circles of an ellipse, its copy moved by 10^-20 .. 10^-30 and a far circle are certified from the "
          "pair's exact bitangent (fuzz F9)",
          "[subdivision][huge-circle][near-duplicate]") {
    // The pair's bitangent is the tangent line parallel to the move (here
    // the x-axis): the support values differ by n.(move) only, which rounding
    // lost when added to the shapes' parts first. The circle touches the pair
    // where the normal is perpendicular to the move, up to ~h / R (the pair
    // decides it), and the far circle 10^20 away: R ~ 10^39.
    for (const Rational& x : {Rational(0), power_of_ten(20)}) {
        for (int k : {20, 30}) {
            const Rational h = power_of_ten(-k);
            const Ellipse e(2, 1, Rational(1, 3UL), x, 0), copy(2, 1, Rational(1, 3UL), x + h, 0),
                far = Ellipse::circle(x - power_of_ten(20), 3, 1);
            INFO("at x = " << x.to_double() << ", moved by 10^-" << k);
            VoronoiCircleSolver solver(e, copy, far);
            REQUIRE(solver.refine(128));
            const VoronoiCircleEnclosure& found = solver.enclosure();
            CHECK(found.found_by == CircleStart::tangent_line);
            CHECK(found.radius.mid_double() > 1e38);
            // The test's own feet from the certified center: every site at the
            // certified radius, and the pair's feet with normals perpendicular
            // to the move (a circle of the pair's first-order bitangent alone
            // has them 10^-20 off).
            const Ball vx = BallArithmetic::mid(found.center_x), vy = BallArithmetic::mid(found.center_y);
            for (const Ellipse* site : {&e, &copy, &far})
                CHECK(arb_contains(widened(found.radius, 100).get(), distance_by_multiplier(*site, vx, vy).get()));
            for (const Ellipse* site : {&e, &copy}) {
                const Foot f = foot(*site, vx, vy);
                Ball bound;
                arb_set(bound.get(), BallArithmetic::mid(BallArithmetic{kOraclePrecision}.q(h)).get());
                arb_mul_2exp_si(bound.get(), bound.get(), -20);
                CHECK(arb_lt(f.ux.get(), bound.get()));
                arb_neg(bound.get(), bound.get());
                CHECK(arb_gt(f.ux.get(), bound.get()));
            }
        }
    }
}

TEST_CASE("huge circles of an ellipse, its copy turned by 10^-20 .. 10^-30 and a circle 10^20 away along its axis are "
          "certified from the pair's bitangent found in balls",
          "[subdivision][huge-circle][near-duplicate]") {
    // The copy differs in shape only: in doubles its support values equal the ellipse's, so the
    // pair's bitangents (along its axes) are found in balls at 2 log2(1/h) bits more. Before, the
    // turn by 10^-30 ended at the search's cap.
    for (int k : {20, 30}) {
        const Ellipse e(2, 1, Rational(1, 3UL), 0, 0), turned(2, 1, Rational(1, 3UL) + power_of_ten(-k), 0, 0);
        // The major axis is along (4/5, 3/5), the minor along (-3/5, 4/5).
        const Rational d = power_of_ten(20);
        const Ellipse far = Ellipse::circle(d * Rational(4, 5UL) - Rational(9, 5UL), d * Rational(3, 5UL) + Rational(12, 5UL), 1);
        INFO("turned by 10^-" << k);
        VoronoiCircleSolver solver(e, turned, far);
        REQUIRE(solver.refine(128));
        const VoronoiCircleEnclosure& found = solver.enclosure();
        CHECK(found.found_by == CircleStart::tangent_line);
        CHECK(found.radius.mid_double() > 1e38);
        const Ball vx = BallArithmetic::mid(found.center_x), vy = BallArithmetic::mid(found.center_y);
        for (const Ellipse* site : {&e, &turned, &far})
            CHECK(arb_contains(widened(found.radius, 100).get(), distance_by_multiplier(*site, vx, vy).get()));
    }
}
