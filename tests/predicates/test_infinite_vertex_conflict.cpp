// kappa2 infinite_vertex_conflict(E1, E2, Q): NEGATIVE (-1) iff Q meets the
// open half-plane H beyond the external bitangent L of (E1, E2) (E1, E2 on the
// right of L directed from T1 to T2); ties (Q touching L from the sites' side)
// broken as in CGAL. Oracles: CGAL's test vectors, the closed form for circles
// at 256 bits, constructed tangencies, support-function numerics for ellipses.
#include "circles/circle_predicates.hpp"
#include "predicates/infinite_vertex_conflict.hpp"
#include "predicates/relative_position.hpp"
#include "tests/support/circle_oracles.hpp"
#include "util/error.hpp"

#include <catch2/catch.hpp>

#include <random>

using namespace ellvor;

namespace {

using oracle::circles_apart;
using oracle::rnd;
using oracle::rnd_pos;
using oracle::Rng;


void expect(const Ellipse& e1, const Ellipse& e2, const Ellipse& q, int want, const char* why = "") {
    INFO(why << oracle::ell({&e1, &e2, &q}));
    const Decision<Sign> got = infinite_vertex_conflict(e1, e2, q);
    INFO("stage " << stage_name(got.stage) << " precision " << got.precision);
    CHECK(to_int(*got) == want);
}

}  // namespace

TEST_CASE("kappa2 CGAL test vectors", "[predicates][infinite_vertex_conflict]") {
    // p1 = (1,100,49), p2 = (0,-100,50): L is exactly the line x = 50 (the normal
    // n = (1,0) solves n.(c1 - c2) = r2 - r1), tangent at (50,100) and (50,-100);
    // H = {x > 50}.
    const oracle::Circle p1{1, 100, 49}, p2{0, -100, 50};
    struct V { oracle::Circle q; int want; const char* why; };
    // Radius 0 is not a site: 1/1000 instead. h_q(n) = x_q + r_q stays far below 50
    // for the first two, so the answer does not change.
    const std::vector<V> vectors = {
        {{0, 0, Rational(1, 1000)}, 1, "q = (0,0,0)"},
        {{-100000, 0, Rational(1, 1000)}, 1, "q = (-100000,0,0)"},
        {{100000, 0, 1000}, -1, "q = (100000,0,1000)"},
        {{-1, 0, 51}, -1, "q = (-1,0,51): touches L at (50,0), between the contacts"},
        {{-1, 200, 51}, 1, "q = (-1,200,51): touches L at (50,200), outside"},
        {{-1, -200, 51}, 1, "q = (-1,-200,51): touches L at (50,-200), outside"},
    };
    for (const V& v : vectors) {
        const oracle::InfiniteConflict o = oracle::infinite_vertex_conflict(p1, p2, v.q);
        INFO(v.why);
        CHECK(o.sign == v.want);  // the oracle reproduces CGAL's expectations
        expect(p1.ellipse(), p2.ellipse(), v.q.ellipse(), v.want, v.why);
    }
}

TEST_CASE("kappa2 on 1000 random disjoint circle triples agrees with the closed form", "[predicates][infinite_vertex_conflict]") {
    Rng rng(31337);
    int n = 0, conflicts = 0;
    StageCounters counters;
    while (n < 1000) {
        oracle::Circle c1{rnd(rng, -10, 10, 97), rnd(rng, -10, 10, 89), rnd_pos(rng, 2, 53)};
        oracle::Circle c2{rnd(rng, -10, 10, 83), rnd(rng, -10, 10, 79), rnd_pos(rng, 2, 47)};
        oracle::Circle q{rnd(rng, -10, 10, 71), rnd(rng, -10, 10, 67), rnd_pos(rng, 2, 43)};
        if (!circles_apart(c1, c2) || !circles_apart(c1, q) || !circles_apart(c2, q)) continue;
        ++n;
        const Ellipse e1 = c1.ellipse(), e2 = c2.ellipse(), eq = q.ellipse();
        INFO(oracle::ell({&e1, &e2, &eq}));
        const oracle::InfiniteConflict o = oracle::infinite_vertex_conflict(c1, c2, q);
        REQUIRE(o.sign != 2);
        // The general cascade (filter, then exact), and the closed form that
        // circles take by default.
        InfiniteVertexConflictOptions general;
        general.use_circle_closed_form = false;
        const Decision<Sign> got = infinite_vertex_conflict(e1, e2, eq, general);
        INFO("stage " << stage_name(got.stage));
        CHECK(to_int(*got) == o.sign);
        const Decision<Sign> closed = infinite_vertex_conflict(e1, e2, eq);
        CHECK(to_int(*closed) == o.sign);
        CHECK(closed.stage == Stage::exact);
        counters.record(got.stage);
        conflicts += o.sign < 0;
    }
    INFO("conflicts " << conflicts << "; filter " << counters[Stage::filter] << " subdivision " << counters[Stage::subdivision]
                      << " exact " << counters[Stage::exact]);
    CHECK(conflicts > 200);
    CHECK(conflicts < 800);
    CHECK(counters[Stage::filter] > 950);  // random triples: the filter decides almost all
}

TEST_CASE("kappa2's exact stage alone agrees with the closed form", "[predicates][infinite_vertex_conflict]") {
    Rng rng(4242);
    InfiniteVertexConflictOptions exact_only;
    exact_only.use_filter = false;
    int n = 0;
    while (n < 200) {
        oracle::Circle c1{rnd(rng, -10, 10, 97), rnd(rng, -10, 10, 89), rnd_pos(rng, 2, 53)};
        oracle::Circle c2{rnd(rng, -10, 10, 83), rnd(rng, -10, 10, 79), rnd_pos(rng, 2, 47)};
        oracle::Circle q{rnd(rng, -10, 10, 71), rnd(rng, -10, 10, 67), rnd_pos(rng, 2, 43)};
        if (!circles_apart(c1, c2) || !circles_apart(c1, q) || !circles_apart(c2, q)) continue;
        ++n;
        const Ellipse e1 = c1.ellipse(), e2 = c2.ellipse(), eq = q.ellipse();
        INFO(oracle::ell({&e1, &e2, &eq}));
        const Decision<Sign> got = infinite_vertex_conflict(e1, e2, eq, exact_only);
        CHECK(got.stage == Stage::exact);
        CHECK(to_int(*got) == oracle::infinite_vertex_conflict(c1, c2, q).sign);
    }
}

TEST_CASE("kappa2 constructed tangencies on the bitangents y = 1 and y = -1, i-points included", "[predicates][infinite_vertex_conflict]") {
    // E1 centered (0,0), E2 centered (10,0), semi-axis 1 vertical: the external
    // bitangents are y = 1 and y = -1 with contacts above/below the centers. For
    // (E1, E2), T1 -> T2 points to +x and H (on the left) is y > 1: L is y = 1. For
    // (E2, E1) it is y = -1, H = {y < -1}.
    // The same point sets three ways: w = 0; w = 1 (a-axis vertical, i-point at the
    // bottom); w = -1 (a-axis pointing down, i-point at the top).
    const std::vector<std::pair<Ellipse, Ellipse>> sites = {
        {Ellipse(2, 1, 0, 0, 0), Ellipse(3, 1, 0, 10, 0)},
        {Ellipse(1, 2, 1, 0, 0), Ellipse(1, 3, 1, 10, 0)},
        {Ellipse(1, 2, -1, 0, 0), Ellipse(1, 3, -1, 10, 0)},
        {Ellipse(2, 1, 0, 0, 0), Ellipse(1, 3, -1, 10, 0)},
    };
    REQUIRE(sites[1].first.i_point().y == Rational(-1));
    REQUIRE(sites[2].first.i_point().y == Rational(1));
    struct Q { Ellipse q; int want12, want21; const char* why; };
    const Rational h(1, 2);
    const std::vector<Q> queries = {
        {Ellipse::circle(5, 0, 1), -1, -1, "touches both lines between the contacts"},
        {Ellipse::circle(20, 0, 1), 1, 1, "touches both lines beyond E2"},
        {Ellipse::circle(-5, 0, 1), 1, 1, "touches both lines before E1"},
        {Ellipse(1, h, 0, 5, h), -1, 1, "touches y = 1 between"},
        {Ellipse(h, 1, -1, 5, h), -1, 1, "touches y = 1 between at its i-point"},
        {Ellipse(h, 1, 1, 5, -h), 1, -1, "touches y = -1 between at its i-point"},
        {Ellipse(h, 1, -1, 20, h), 1, 1, "touches y = 1 beyond E2 at its i-point"},
        {Ellipse(h, 1, 1, -4, -h), 1, 1, "touches y = -1 before E1 at its i-point"},
        {Ellipse::circle(5, 1, 1), -1, 1, "crosses y = 1"},
        {Ellipse::circle(5, 3, h), -1, 1, "inside H of (E1, E2)"},
        {Ellipse::circle(5, -10, 1), 1, -1, "inside H of (E2, E1)"},
        {Ellipse::circle(20, h, h), 1, 1, "touches y = 1 beyond E2, above the center line"},
        {Ellipse(2, h, Rational(1, 3), 5, 0), -1, -1, "a tilted flat ellipse crossing both lines"},
    };
    for (const auto& s : sites)
        for (const Q& q : queries) {
            REQUIRE(*relative_position(s.first, q.q) == RelativePosition::separated);
            REQUIRE(*relative_position(s.second, q.q) == RelativePosition::separated);
            expect(s.first, s.second, q.q, q.want12, q.why);
            expect(s.second, s.first, q.q, q.want21, q.why);
        }
}

TEST_CASE("kappa2 constructed tangencies on circles agree with the oracle's exact tie", "[predicates][infinite_vertex_conflict]") {
    // Circles (-2,0),(2,0) r = 1 (the paper's kappa2 family): L of (E1, E2) is y = 1.
    const oracle::Circle c1{-2, 0, 1}, c2{2, 0, 1};
    for (int k = -8; k <= 8; ++k) {
        // Query of radius 1/2 touching y = 1 from below at x = k, and disjoint from the sites
        // when |k| is not close to 2.
        const oracle::Circle q{Rational(k), Rational(1, 2), Rational(1, 2)};
        if (!circles_apart(q, c1) || !circles_apart(q, c2)) continue;
        const oracle::InfiniteConflict o = oracle::infinite_vertex_conflict(c1, c2, q);
        REQUIRE(o.tie);
        CHECK(o.sign == (k > -2 && k < 2 ? -1 : 1));
        expect(c1.ellipse(), c2.ellipse(), q.ellipse(), o.sign, "tangent to y = 1");
    }
}

TEST_CASE("kappa2's exact stage rejects nested E1, E2", "[predicates][infinite_vertex_conflict]") {
    // No external bitangent at all; the filter cannot decide either.
    CHECK_THROWS_AS(infinite_vertex_conflict(Ellipse::circle(0, 0, 3), Ellipse::circle(1, 0, 1),
                                             Ellipse::circle(10, 10, 1)),
                    Error);
}

TEST_CASE("kappa2 on crossing E1, E2: the crossing points stand for the internal tangents",
          "[predicates][infinite_vertex_conflict][overlap]") {
    // Circles: the exact stage of the general path (the bitangent quartic,
    // the crossing points from the intersection quartic) against the closed
    // form. Ellipses: the filter and the exact stage against support-function
    // numerics.
    Rng rng(1124);
    InfiniteVertexConflictOptions exact_only;
    exact_only.use_filter = false;
    exact_only.use_circle_closed_form = false;
    int circles = 0, ellipses = 0, conflicts = 0, tries = 0;
    while (circles < 200 && ++tries < 10000) {
        const Ellipse e1 = Ellipse::circle(rnd(rng, -3, 3, 7), rnd(rng, -3, 3, 5), rnd_pos(rng, 4, 3));
        const Ellipse e2 = Ellipse::circle(rnd(rng, -3, 3, 7), rnd(rng, -3, 3, 5), rnd_pos(rng, 4, 3));
        const Ellipse q = Ellipse::circle(rnd(rng, -8, 8, 7), rnd(rng, -8, 8, 5), rnd_pos(rng, 2, 3));
        if (*relative_position(e1, e2) != RelativePosition::intersecting) continue;
        ++circles;
        INFO(oracle::ell({&e1, &e2, &q}));
        const Decision<Sign> got = infinite_vertex_conflict(e1, e2, q, exact_only);
        CHECK(got.stage == Stage::exact);
        CHECK(to_int(*got) == circle_infinite_vertex_conflict(e1, e2, q));
        conflicts += to_int(*got) < 0;
    }
    while (ellipses < 200 && ++tries < 20000) {
        auto random_ellipse = [&] {
            return Ellipse(rnd_pos(rng, 4, 7), rnd_pos(rng, 4, 5), rnd(rng, -4, 4, 19), rnd(rng, -3, 3, 7), rnd(rng, -3, 3, 9));
        };
        const Ellipse e1 = random_ellipse(), e2 = random_ellipse();
        const Ellipse q(rnd_pos(rng, 2, 7), rnd_pos(rng, 2, 5), rnd(rng, -4, 4, 3), rnd(rng, -9, 9, 7), rnd(rng, -9, 9, 5));
        if (*relative_position(e1, e2) != RelativePosition::intersecting || boundary_meeting_points(e1, e2) != 2) continue;
        const oracle::NumEllipse n1 = oracle::num(e1), n2 = oracle::num(e2), nq = oracle::num(q);
        oracle::LD phi = 0;
        INFO(oracle::ell({&e1, &e2, &q}));
        REQUIRE(oracle::bitangent_normal(n1, n2, phi));
        const oracle::LD margin = oracle::support(nq, phi) - oracle::support(n1, phi);
        if (std::fabs(static_cast<double>(margin)) < 1e-9) continue;
        ++ellipses;
        const int want = margin > 0 ? -1 : 1;
        CHECK(to_int(*infinite_vertex_conflict(e1, e2, q, exact_only)) == want);
        CHECK(to_int(*infinite_vertex_conflict(e1, e2, q)) == want);
    }
    CHECK(circles == 200);
    CHECK(ellipses == 200);
    CHECK(conflicts > 20);
}

TEST_CASE("kappa2 on 300+ random disjoint ellipse triples agrees with support-function numerics", "[predicates][infinite_vertex_conflict]") {
    Rng rng(8080);
    int compared = 0, skipped = 0, conflicts = 0, tries = 0;
    StageCounters counters;
    while (compared < 320 && tries < 5000) {
        ++tries;
        auto random_ellipse = [&] {
            return Ellipse(rnd_pos(rng, 3, 17), rnd_pos(rng, 3, 13), rnd(rng, -4, 4, 19), rnd(rng, -10, 10, 7), rnd(rng, -10, 10, 9));
        };
        const Ellipse e1 = random_ellipse(), e2 = random_ellipse(), q = random_ellipse();
        if (*relative_position(e1, e2) != RelativePosition::separated || *relative_position(e1, q) != RelativePosition::separated ||
            *relative_position(e2, q) != RelativePosition::separated)
            continue;
        const oracle::NumEllipse n1 = oracle::num(e1), n2 = oracle::num(e2), nq = oracle::num(q);
        oracle::LD phi = 0;
        INFO(oracle::ell({&e1, &e2, &q}));
        REQUIRE(oracle::bitangent_normal(n1, n2, phi));
        const oracle::LD margin = oracle::support(nq, phi) - oracle::support(n1, phi);
        if (std::fabs(static_cast<double>(margin)) < 1e-9) { ++skipped; continue; }
        const int want = margin > 0 ? -1 : 1;
        INFO("numeric margin h_Q - h_1 = " << static_cast<double>(margin) << " at normal angle " << static_cast<double>(phi));
        const Decision<Sign> got = infinite_vertex_conflict(e1, e2, q);
        INFO("stage " << stage_name(got.stage));
        CHECK(to_int(*got) == want);
        counters.record(got.stage);
        conflicts += want < 0;
        ++compared;
    }
    INFO("compared " << compared << " skipped " << skipped << " conflicts " << conflicts << "; filter " << counters[Stage::filter]
                     << " subdivision " << counters[Stage::subdivision] << " exact " << counters[Stage::exact]);
    CHECK(compared >= 300);
    CHECK(conflicts > 50);
    CHECK(conflicts < compared - 50);
}

TEST_CASE("kappa2's normal-box filter step agrees with the exact stage and decides Q far from L",
          "[predicates][infinite_vertex_conflict]") {
    // infinite_vertex_conflict_in_normal_box, the filter's first step: every
    // sign it proves is the exact stage's; it decides most triples of small
    // sites far apart (sparse random data), is undecided for Q touching L,
    // and the whole predicate then reports the filter stage.
    Rng rng(5151);
    int compared = 0, decided = 0, conflicts = 0;
    const InfiniteVertexConflictOptions exact_only{false, true};
    while (compared < 400) {
        auto small_ellipse = [&] {
            return Ellipse(rnd_pos(rng, 1, 9), rnd_pos(rng, 1, 7), rnd(rng, -4, 4, 19),
                           rnd(rng, -30, 30, 7), rnd(rng, -30, 30, 9));
        };
        const Ellipse e1 = small_ellipse(), e2 = small_ellipse(), q = small_ellipse();
        if (*relative_position(e1, e2) != RelativePosition::separated || *relative_position(e1, q) != RelativePosition::separated ||
            *relative_position(e2, q) != RelativePosition::separated)
            continue;
        ++compared;
        INFO(oracle::ell({&e1, &e2, &q}));
        const int box = infinite_vertex_conflict_in_normal_box(e1, e2, q);
        if (!box) continue;
        ++decided;
        const Decision<Sign> exact = infinite_vertex_conflict(e1, e2, q, exact_only);
        REQUIRE(exact.stage == Stage::exact);
        CHECK(box == to_int(*exact));
        conflicts += box < 0;
        const Decision<Sign> full = infinite_vertex_conflict(e1, e2, q);
        CHECK(full.stage == Stage::filter);
        CHECK(to_int(*full) == box);
    }
    INFO("decided " << decided << " of " << compared << ", conflicts " << conflicts);
    CHECK(decided > compared / 2);
    CHECK(conflicts > 20);
    CHECK(conflicts < decided - 20);

    // Q tangent to L from the sites' side (E1, E2 and Q touching y = 1 from
    // below): the box cannot prove a sign.
    const Ellipse a(Rational(2), Rational(1), Rational(0), Rational(-10), Rational(0));
    const Ellipse b(Rational(1), Rational(1, 2), Rational(0), Rational(10), Rational(1, 2));
    const Ellipse touching(Rational(1), Rational(1, 2), Rational(0), Rational(0), Rational(1, 2));
    CHECK(infinite_vertex_conflict_in_normal_box(a, b, touching) == 0);
    // Overlapping circumscribed disks: no box.
    const Ellipse near_a(Rational(2), Rational(1), Rational(0), Rational(-10), Rational(5, 2));
    CHECK(infinite_vertex_conflict_in_normal_box(a, near_a, b) == 0);
}
