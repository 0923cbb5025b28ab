// Predicates of overlapping circles (docs/DESIGN.md §2: signed distances
// |x - c| - r; a Voronoi circle has R + r_i > 0 for its sites, R < 0 when its
// center lies inside all three; InCircle compares Q's signed distance at V
// with R). Oracles: CGAL 5.5's exact Apollonius traits (Gmpq), which use
// signed distances, and the independent closed form of apollonius_oracle.hpp
// with signed radii. Each stage is reached and checked: the semi-static and
// interval filters, the exact closed form, and the certified Voronoi circle
// in doubles and in Arb balls (the signed-distance certificate, §4.1).
#include "circles/circle_incircle_filter.hpp"
#include "circles/circle_predicates.hpp"
#include "circles/circle_semi_static.hpp"
#include "predicates/incircle.hpp"
#include "predicates/infinite_vertex_conflict.hpp"
#include "predicates/relative_position.hpp"
#include "predicates/voronoi_circle_count.hpp"
#include "subdivision/voronoi_circle_enclosure.hpp"
#include "subdivision/voronoi_circle_in_doubles.hpp"
#include "tests/support/apollonius_oracle.hpp"

#include <CGAL/Apollonius_graph_traits_2.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>
#include <catch2/catch.hpp>

#include <array>
#include <random>
#include <vector>

using namespace ellvor;

namespace {

using ExactKernel = CGAL::Simple_cartesian<CGAL::Gmpq>;
using ExactTraits = CGAL::Apollonius_graph_traits_2<ExactKernel, CGAL::Integral_domain_without_division_tag>;

ExactTraits::Site_2 cgal_site(const Ellipse& e) {
    return ExactTraits::Site_2(ExactTraits::Point_2(CGAL::Gmpq(e.xc().str()), CGAL::Gmpq(e.yc().str())),
                               CGAL::Gmpq(e.a().str()));
}
int sign_of(CGAL::Sign s) { return s == CGAL::NEGATIVE ? -1 : s == CGAL::POSITIVE ? 1 : 0; }
int cgal_vertex_conflict(const Ellipse& a, const Ellipse& b, const Ellipse& c, const Ellipse& q) {
    return sign_of(ExactTraits().vertex_conflict_2_object()(cgal_site(a), cgal_site(b), cgal_site(c), cgal_site(q)));
}
int cgal_infinite_vertex_conflict(const Ellipse& a, const Ellipse& b, const Ellipse& q) {
    return sign_of(ExactTraits().vertex_conflict_2_object()(cgal_site(a), cgal_site(b), cgal_site(q)));
}

int sign_of_incircle(InCircle r) { return to_int(incircle_sign(r)); }

// Neither circle lies in the other (they may cross or be apart).
bool neither_inside(const Ellipse& a, const Ellipse& b) {
    const Rational dx = a.xc() - b.xc(), dy = a.yc() - b.yc(), d = a.a() - b.a();
    return dx * dx + dy * dy > d * d;
}

bool crossing(const Ellipse& a, const Ellipse& b) {
    const Rational dx = a.xc() - b.xc(), dy = a.yc() - b.yc(), s = a.a() + b.a();
    return neither_inside(a, b) && dx * dx + dy * dy < s * s;
}

apollonius::Circle oracle_circle(const Ellipse& e) { return {e.xc(), e.yc(), e.a()}; }

int oracle_incircle(const Ellipse& a, const Ellipse& b, const Ellipse& c, const Ellipse& q) {
    return apollonius::incircle(oracle_circle(a), oracle_circle(b), oracle_circle(c), oracle_circle(q), 1024, true);
}

// A random circle with dyadic data (k fraction bits) in a small box, so that
// most quadruples overlap.
Ellipse random_circle(std::mt19937_64& rng, int k) {
    auto draw = [&](long lo, long hi) { return lo + static_cast<long>(rng() % static_cast<std::uint64_t>(hi - lo + 1)); };
    const long unit = 1L << k;
    return Ellipse::circle(Rational(draw(-8 * unit, 8 * unit), unit), Rational(draw(-8 * unit, 8 * unit), unit),
                           Rational(draw(2 * unit, 10 * unit), unit));
}

}  // namespace

TEST_CASE("overlapping circles: the exact closed form against CGAL and a signed-radius oracle; the filters agree",
          "[circle-predicates][overlap]") {
    std::mt19937_64 rng(2026);
    int n = 0, internal = 0, crossing_triples = 0, oracle_compared = 0, semi_static = 0, interval = 0;
    int signs[3] = {};
    while (n < 1500) {
        const int k = static_cast<int>(rng() % 4);
        std::array<Ellipse, 4> s = {random_circle(rng, k), random_circle(rng, k), random_circle(rng, k),
                                    random_circle(rng, k)};
        bool ok = true;
        for (int i = 0; i < 4; ++i)
            for (int j = i + 1; j < 4; ++j) ok = ok && neither_inside(s[i], s[j]);
        if (!ok) continue;
        ++n;
        const Ellipse &a = s[0], &b = s[1], &c = s[2], &q = s[3];
        INFO(apollonius::ell({&a, &b, &c, &q}));
        crossing_triples += crossing(a, b) && crossing(b, c) && crossing(c, a);
        const CircleVoronoiVertex vertex(a, b, c);
        const int exact = circle_vertex_conflict(vertex, q);
        ++signs[exact + 1];
        if (vertex.exists()) {
            CHECK(exact == cgal_vertex_conflict(a, b, c, q));
            internal += vertex.radius().sign() < 0;
        } else {
            CHECK(exact == -1);
        }
        const int oracle = oracle_incircle(a, b, c, q);
        if (oracle <= 1) {
            ++oracle_compared;
            CHECK(exact == oracle);
        }
        CHECK(circle_infinite_vertex_conflict(a, b, q) == cgal_infinite_vertex_conflict(a, b, q));
        // The filters never contradict the exact stage.
        const Decision<InCircle> fast = circle_incircle_semi_static(a, b, c, q);
        if (fast.is_decided()) {
            ++semi_static;
            CHECK(sign_of_incircle(*fast) == exact);
        }
        const Decision<InCircle> filtered = circle_incircle_interval_filter(a, b, c, q);
        if (filtered.is_decided()) {
            ++interval;
            CHECK(sign_of_incircle(*filtered) == exact);
        }
        const Decision<VoronoiCircles> count = circle_voronoi_circle_count_semi_static(a, b, c);
        if (count.is_decided()) CHECK(*count == circle_voronoi_circle_count(a, b, c));
        const Decision<InCircle> cascade = incircle(a, b, c, q);
        REQUIRE(cascade.is_decided());
        CHECK(sign_of_incircle(*cascade) == exact);
    }
    INFO("internal circles " << internal << ", pairwise crossing triples " << crossing_triples << ", signs "
                             << signs[0] << " " << signs[1] << " " << signs[2] << ", oracle " << oracle_compared
                             << ", semi-static " << semi_static << ", interval " << interval);
    CHECK(internal >= 100);
    CHECK(crossing_triples >= 300);
    CHECK(signs[0] >= 200);
    CHECK(signs[2] >= 200);
    CHECK(oracle_compared >= n * 9 / 10);
    CHECK(semi_static >= n * 9 / 10);
    CHECK(interval >= n / 2);
}

TEST_CASE("an internal Voronoi circle: exact values, each stage, and Q deeper than its own radius",
          "[circle-predicates][overlap]") {
    // Radius-10 circles about (0, 0), (12, 0), (6, 10): the point (6, 16/5)
    // lies 34/5 from each center, so the counter-clockwise circle of the
    // triple has center (6, 16/5) and radius 34/5 - 10 = -16/5.
    const Ellipse a = Ellipse::circle(0, 0, 10), b = Ellipse::circle(12, 0, 10), c = Ellipse::circle(6, 10, 10);
    const CircleVoronoiVertex v(a, b, c);
    REQUIRE(v.exists());
    CHECK(v.center_x() == QuadraticNumber(Rational(6)));
    CHECK(v.center_y() == QuadraticNumber(Rational(16, 5UL)));
    CHECK(v.radius() == QuadraticNumber(Rational(-16, 5UL)));
    CHECK(circle_voronoi_circle_count(a, b, c) == VoronoiCircles::ccw_only);
    CHECK(*circle_voronoi_circle_count_semi_static(a, b, c) == VoronoiCircles::ccw_only);

    // Q about (6, 3) of radius 1 contains V, yet its signed distance there,
    // 1/5 - 1 = -4/5, exceeds R = -16/5: no conflict. Comparing squares
    // (|V - C_Q|^2 < (R + r_Q)^2) would say "conflict".
    const Ellipse deep = Ellipse::circle(6, 3, 1);
    CHECK(circle_vertex_conflict(v, deep) == 1);
    const Decision<InCircle> fast = circle_incircle_semi_static(a, b, c, deep);
    REQUIRE(fast.is_decided());
    CHECK(*fast == InCircle::no_conflict);
    const Decision<InCircle> filtered = circle_incircle_interval_filter(a, b, c, deep);
    REQUIRE(filtered.is_decided());
    CHECK(*filtered == InCircle::no_conflict);
    // Q of radius 4 about (6, 3): -4 + 1/5 < -16/5, a conflict.
    const Ellipse deeper = Ellipse::circle(6, 3, 4);
    CHECK(circle_vertex_conflict(v, deeper) == -1);
    CHECK(*circle_incircle_semi_static(a, b, c, deeper) == InCircle::conflict);
    // Q through V at depth exactly 16/5: radius 16/5 + 1/5 about (6, 3).
    const Ellipse touching = Ellipse::circle(6, 3, Rational(17, 5UL));
    CHECK(circle_vertex_conflict(v, touching) == 0);
    CHECK(!circle_incircle_semi_static(a, b, c, touching).is_decided());
    const Decision<InCircle> exact = incircle(a, b, c, touching);
    CHECK(*exact == InCircle::tangent);
    CHECK(exact.stage == Stage::exact);

    // The certified circle: in doubles, then in Arb balls (the general path
    // of ellipses, which circles reach only when a caller asks for the
    // circle itself, e.g. the JSON's Voronoi vertices).
    const auto in_doubles = certify_voronoi_circle_in_doubles(a, b, c);
    REQUIRE(in_doubles);
    CHECK(in_doubles->radius.lo <= -3.2);
    CHECK(in_doubles->radius.hi >= -3.2);
    CHECK(in_doubles->radius.negative());
    VoronoiCircleSolver solver(a, b, c);
    REQUIRE(solver.certify());
    solver.refine(200);
    const VoronoiCircleEnclosure& e = solver.enclosure();
    Ball want;
    arb_set_fmpq(want.get(), Rational(-16, 5UL).get(), 256);
    CHECK(arb_overlaps(e.radius.get(), want.get()));
    CHECK(arb_is_negative(e.radius.get()));
    CHECK(e.correct_bits() >= 200);
    // The clockwise order has no circle; the count says so and the solver's
    // search proves it.
    CHECK(circle_voronoi_circle_count(a, c, b) == VoronoiCircles::cw_only);
    VoronoiCircleSolver clockwise(a, c, b);
    CHECK(!clockwise.certify());
}

TEST_CASE("three circle boundaries through one point: a Voronoi circle of radius 0, decided exactly",
          "[circle-predicates][overlap]") {
    // Radius-5 circles about (-5, 0), (0, -5), (5, 0) all pass through the
    // origin: their counter-clockwise circle is the point (0, 0), R = 0. A
    // fourth circle through the origin is tangent to it (ZERO); one that
    // covers the origin conflicts; one that misses it does not.
    const Ellipse a = Ellipse::circle(-5, 0, 5), b = Ellipse::circle(0, -5, 5), c = Ellipse::circle(5, 0, 5);
    const CircleVoronoiVertex v(a, b, c);
    REQUIRE(v.exists());
    CHECK(v.radius() == QuadraticNumber(Rational(0)));
    CHECK(v.center_x() == QuadraticNumber(Rational(0)));
    CHECK(v.center_y() == QuadraticNumber(Rational(0)));
    const Ellipse through = Ellipse::circle(0, 5, 5), covering = Ellipse::circle(0, 4, 5),
                  missing = Ellipse::circle(0, 6, 5);
    CHECK(circle_vertex_conflict(v, through) == 0);
    CHECK(circle_vertex_conflict(v, covering) == -1);
    CHECK(circle_vertex_conflict(v, missing) == 1);
    for (const Ellipse* q : {&through, &covering, &missing}) {
        INFO(apollonius::ell({&a, &b, &c, q}));
        CHECK(circle_vertex_conflict(v, *q) == cgal_vertex_conflict(a, b, c, *q));
    }
    CHECK(!circle_incircle_semi_static(a, b, c, through).is_decided());
    CHECK(!circle_incircle_interval_filter(a, b, c, through).is_decided());
    const Decision<InCircle> exact = incircle(a, b, c, through);
    CHECK(*exact == InCircle::tangent);
    CHECK(exact.stage == Stage::exact);
    // The Arb certificate at R = 0: the tangency points coincide, so the
    // orientation is that of the normals (§4.1).
    VoronoiCircleSolver solver(a, b, c);
    REQUIRE(solver.certify());
    CHECK(arb_contains_zero(solver.enclosure().radius.get()));
}

TEST_CASE("crossing pairs: which are accepted, and how many points the boundaries share", "[relative-position][overlap]") {
    const Ellipse circle = Ellipse::circle(0, 0, 1);
    SECTION("two circles crossing: accepted") {
        const Ellipse other = Ellipse::circle(1, 0, 1);
        CHECK(*relative_position(circle, other) == RelativePosition::intersecting);
        CHECK(boundary_meeting_points(circle, other) == 2);
        CHECK(crossing_pair_problem(circle, other).empty());
    }
    SECTION("an ellipse crossing in two points: accepted") {
        const Ellipse e(Rational(2), Rational(1), Rational(0), Rational(1), Rational(1));
        CHECK(boundary_meeting_points(circle, e) == 2);
        CHECK(crossing_pair_problem(circle, e).empty());
        CHECK(crossing_pair_problem(e, Ellipse(Rational(2), Rational(1), Rational(1, 2UL), Rational(0), Rational(1))).empty());
    }
    SECTION("a tangency and two crossings: three points") {
        // x^2 + y^2 = 1 against x^2 + (y + 1/2)^2 / (9/4) = 1: y = 1 (double)
        // and y = -1/5 (two points).
        const Ellipse e(Rational(1), Rational(3, 2UL), Rational(0), Rational(0), Rational(-1, 2UL));
        CHECK(*relative_position(circle, e) == RelativePosition::intersecting);
        CHECK(boundary_meeting_points(circle, e) == 3);
        CHECK(crossing_pair_problem(circle, e) == "their boundaries meet in 3 points (sites may cross in at most two)");
    }
    SECTION("a cross: four points; a point at the i-point (t = infinity) counts too") {
        const Ellipse wide(Rational(3), Rational(1), Rational(0), Rational(0), Rational(0)),
            tall(Rational(1), Rational(3), Rational(0), Rational(0), Rational(0));
        CHECK(boundary_meeting_points(wide, tall) == 4);
        CHECK(crossing_pair_problem(wide, tall) == "their boundaries meet in 4 points (sites may cross in at most two)");
        // The unit circle's i-point is (-1, 0): the circle about (-1, 1) of
        // radius 1 crosses it there and at (0, 1).
        CHECK(boundary_meeting_points(circle, Ellipse::circle(-1, 1, 1)) == 2);
        // Tangent there from outside: one point.
        CHECK(boundary_meeting_points(circle, Ellipse::circle(-2, 0, 1)) == 1);
    }
}
