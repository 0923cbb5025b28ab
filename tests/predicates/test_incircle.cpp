// kappa3 incircle(E1, E2, E3, Q): Q against the counter-clockwise Voronoi
// circle of (E1, E2, E3). Oracles: CGAL's Apollonius Vertex_conflict_2 on
// integer circles (exact in doubles), the closed-form Apollonius oracle
// (apollonius_oracle.hpp), exactly tangent configurations built by symmetry
// and their perturbations by 10^-k.
//
// CGAL's inversion-based code returns an artifact sign when the triple has
// no counter-clockwise circle; ellvor returns no_circle (NEGATIVE, docs/DESIGN.md §2)
// there. So CGAL is compared only where the CCW circle exists.
#include "predicates/incircle.hpp"
#include "predicates/voronoi_circle_count.hpp"
#include "tests/support/apollonius_oracle.hpp"

#include <CGAL/Apollonius_graph_filtered_traits_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include "tests/support/random_sites.hpp"
#include "tests/support/diagnostics.hpp"

#include <catch2/catch.hpp>

#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <tuple>

using namespace ellvor;
using ellvor::test::show;
using ellvor::test::verbose;

namespace {

using Rng = std::mt19937_64;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Traits = CGAL::Apollonius_graph_filtered_traits_2<Kernel>;
using CSite = Traits::Site_2;
using CPoint = Traits::Point_2;


bool apart(const apollonius::Circle& a, const apollonius::Circle& b) {
    const Rational dx = a.x - b.x, dy = a.y - b.y, r = a.r + b.r;
    return dx * dx + dy * dy > r * r;
}

CSite cgal_site(long x, long y, long r) { return CSite(CPoint(double(x), double(y)), double(r)); }

int cgal_sign(CGAL::Sign s) { return s == CGAL::NEGATIVE ? -1 : (s == CGAL::POSITIVE ? 1 : 0); }


bool has_ccw(VoronoiCircles v) { return v == VoronoiCircles::ccw_only || v == VoronoiCircles::both; }

}  // namespace

TEST_CASE("incircle on 1200 random integer circle quadruples agrees with CGAL and the closed form",
          "[predicates][incircle]") {
    Rng rng(314159);
    std::uniform_int_distribution<long> coord(-25, 25), rad(1, 7);
    Traits traits;
    const auto cgal_conflict = traits.vertex_conflict_2_object();
    int total = 0, with_ccw = 0, no_circle = 0, undecided = 0, oracle_skipped = 0;
    int cgal_artifact_positive = 0, sign_count[3] = {};
    StageCounters stages;
    std::string undecided_cases;
    while (total < 1200) {
        long v[4][3];
        apollonius::Circle c[4];
        for (int i = 0; i < 4; ++i) {
            v[i][0] = coord(rng), v[i][1] = coord(rng), v[i][2] = rad(rng);
            c[i] = {v[i][0], v[i][1], v[i][2]};
        }
        bool ok = true;
        for (int i = 0; i < 4; ++i)
            for (int j = i + 1; j < 4; ++j) ok = ok && apart(c[i], c[j]);
        if (!ok) continue;
        ++total;
        const Ellipse e1 = c[0].ellipse(), e2 = c[1].ellipse(), e3 = c[2].ellipse(), q = c[3].ellipse();
        INFO(apollonius::ell({&e1, &e2, &e3, &q}));
        const Decision<VoronoiCircles> count = voronoi_circle_count(e1, e2, e3);
        const Decision<InCircle> got = incircle(e1, e2, e3, q);
        INFO(show(got) << " count " << voronoi_circles_name((*count)));
        stages.record(got.stage);
        const int cgal = cgal_sign(cgal_conflict(cgal_site(v[0][0], v[0][1], v[0][2]), cgal_site(v[1][0], v[1][1], v[1][2]),
                                                 cgal_site(v[2][0], v[2][1], v[2][2]), cgal_site(v[3][0], v[3][1], v[3][2])));
        INFO("CGAL " << cgal);
        const int want = apollonius::incircle(c[0], c[1], c[2], c[3]);
        INFO("oracle " << want);
        if (!has_ccw((*count))) {
            ++no_circle;
            CHECK((*got) == InCircle::no_circle);
            // Decided by the four-circle filter, or else by the closed form.
            CHECK((got.stage == Stage::filter || got.stage == Stage::exact));
            if (want == 3)
                ++oracle_skipped;
            else
                CHECK(want == -1);  // the oracle finds no CCW circle either
            if (cgal == 1) ++cgal_artifact_positive;
            continue;
        }
        ++with_ccw;
        CHECK((*got) != InCircle::no_circle);
        if (!got.is_decided()) {
            ++undecided;
            undecided_cases += apollonius::ell({&e1, &e2, &e3, &q});
            continue;
        }
        const int sign = to_int(incircle_sign(*got));
        ++sign_count[sign + 1];
        CHECK(sign == cgal);
        if (want == 3 || want == 2) {
            ++oracle_skipped;
        } else {
            CHECK(sign == want);
        }
    }
    if (verbose()) {
        std::printf("[incircle/circles] total %d, ccw %d (conflict %d, tangent %d, no_conflict %d), no_circle %d "
                    "(CGAL positive there %d), undecided %d, oracle skipped %d; stages filter %lu subdivision %lu exact %lu\n",
                    total, with_ccw, sign_count[0], sign_count[1], sign_count[2], no_circle, cgal_artifact_positive,
                    undecided, oracle_skipped, (unsigned long)stages[Stage::filter], (unsigned long)stages[Stage::subdivision],
                    (unsigned long)stages[Stage::exact]);
        if (!undecided_cases.empty()) std::printf("[incircle/circles] undecided:%s", undecided_cases.c_str());
    }
    INFO("undecided cases:" << undecided_cases);
    CHECK(undecided == 0);  // the certification of the circle is complete (exhaustive search)
    CHECK(with_ccw >= 400);
    CHECK(no_circle >= 100);
    CHECK(sign_count[0] >= 100);
    CHECK(sign_count[2] >= 100);
    CHECK(oracle_skipped == 0);
}

TEST_CASE("incircle on random ellipse quadruples: which stage decided", "[predicates][incircle]") {
    // A random non-degenerate case is decided by the subdivision stage at the
    // start precision; no_circle cases report the stage of the kappa2 calls.
    Rng rng(2718);
    auto rnd = [&](long lo, long hi, long den) { return ellvor::test::random_fraction(rng, lo * den, hi * den, den); };
    auto rnd_pos = [&](long lo_num, long hi_num, long den) { return ellvor::test::random_fraction(rng, lo_num, hi_num, den); };
    const auto bounding_apart = ellvor::test::bounding_circles_apart;
    int total = 0, decided_at_start = 0, decided_higher = 0, undecided = 0, no_circle = 0;
    StageCounters stages, no_circle_stages;
    while (total < 200) {
        std::vector<Ellipse> e;
        for (int i = 0; i < 4; ++i)
            e.emplace_back(rnd_pos(2, 30, 10), rnd_pos(2, 30, 10), rnd(-3, 3, 11), rnd(-10, 10, 13), rnd(-10, 10, 7));
        bool ok = true;
        for (int i = 0; i < 4; ++i)
            for (int j = i + 1; j < 4; ++j) ok = ok && bounding_apart(e[i], e[j]);
        if (!ok) continue;
        ++total;
        INFO(apollonius::ell({&e[0], &e[1], &e[2], &e[3]}));
        const Decision<VoronoiCircles> count = voronoi_circle_count(e[0], e[1], e[2]);
        VoronoiCircle circle(e[0], e[1], e[2]);
        const Decision<InCircle> got = incircle(e[0], e[1], e[2], e[3], {}, &circle);
        INFO(show(got) << " count " << voronoi_circles_name((*count)));
        stages.record(got.stage);
        if (!has_ccw((*count))) {
            ++no_circle;
            no_circle_stages.record(got.stage);
            CHECK((*got) == InCircle::no_circle);
            CHECK(got.stage == count.stage);
            CHECK(circle.in_doubles() == nullptr);  // nothing to certify
            continue;
        }
        if (!got.is_decided()) {
            ++undecided;
            if (verbose()) std::printf("[incircle/ellipses] undecided (%s):%s", show(got).c_str(),
                                       apollonius::ell({&e[0], &e[1], &e[2], &e[3]}).c_str());
            continue;
        }
        CHECK(((*got) == InCircle::conflict || (*got) == InCircle::no_conflict));
        CHECK((got.stage == Stage::filter || got.stage == Stage::subdivision));
        // The Arb stage alone (no double-interval filter) agrees.
        InCircleOptions arb;
        arb.use_filter = false;
        VoronoiCircle arb_circle(e[0], e[1], e[2]);
        const Decision<InCircle> by_arb = incircle(e[0], e[1], e[2], e[3], arb, &arb_circle);
        INFO("Arb alone: " << show(by_arb));
        CHECK((*by_arb) == (*got));
        CHECK(by_arb.stage == Stage::subdivision);
        CHECK(arb_circle.solver().enclosure().newton_steps > 0);
        if (by_arb.precision <= 64)
            ++decided_at_start;
        else
            ++decided_higher;
        // The same answer without a given circle, and a second call with the
        // cached one.
        const Decision<InCircle> a = incircle(e[0], e[1], e[2], e[3]);
        const Decision<InCircle> b = incircle(e[0], e[1], e[2], e[3], {}, &circle);
        CHECK((*a) == (*got));
        CHECK((*b) == (*got));
    }
    if (verbose())
        std::printf("[incircle/ellipses] total %d, Arb at 64 bits %d, higher %d, undecided %d, no_circle %d (filter %lu "
                    "subdivision %lu exact %lu); all: filter %lu subdivision %lu\n",
                    total, decided_at_start, decided_higher, undecided, no_circle,
                    (unsigned long)no_circle_stages[Stage::filter], (unsigned long)no_circle_stages[Stage::subdivision],
                    (unsigned long)no_circle_stages[Stage::exact], (unsigned long)stages[Stage::filter],
                    (unsigned long)stages[Stage::subdivision]);
    CHECK(decided_at_start >= 9 * (total - no_circle) / 10);
    // The double-interval stage decides nearly every query that has a circle.
    CHECK(stages[Stage::filter] - no_circle_stages[Stage::filter] >= static_cast<std::uint64_t>(9 * (total - no_circle) / 10));
    CHECK(undecided == 0);  // the certification of the circle is complete (exhaustive search)
    CHECK(no_circle >= 20);
}

TEST_CASE("incircle on an exactly tangent ellipse quadruple and its perturbations", "[predicates][incircle]") {
    // E = (2, 1, 0, (5, 0)) and its rotations by 90, 180, 270 degrees about the
    // origin; each has the origin on its a-axis at distance 5, nearest point the
    // vertex at distance 3: all four touch the circle |x| = 3 from outside,
    // at (3,0), (0,3), (-3,0), (0,-3), counter-clockwise.
    const Ellipse e1(2, 1, 0, 5, 0), e2(2, 1, 1, 0, 5), e3(2, 1, 0, -5, 0), e4(2, 1, 1, 0, -5);
    const Ellipse* s[4] = {&e1, &e2, &e3, &e4};
    InCircleOptions capped;
    capped.use_circle_closed_form = false;  // the general path on circles
    capped.refinement.cap = 512;
    for (int rot = 0; rot < 4; ++rot) {
        const Ellipse &a = *s[rot], &b = *s[(rot + 1) % 4], &c = *s[(rot + 2) % 4], &q = *s[(rot + 3) % 4];
        INFO(apollonius::ell({&a, &b, &c, &q}));
        const Decision<InCircle> d = incircle(a, b, c, q, capped);
        if (verbose()) std::printf("[incircle/tangent ellipses] rotation %d: %s\n", rot, show(d).c_str());
        INFO(show(d));
        // Past the cap the exact stage proves it (undecided only without it).
        CHECK((*d) == InCircle::tangent);
        CHECK(d.stage == Stage::exact);
        CHECK(d.precision >= 512);
    }
    // The fourth site moved by 10^-k: away from the circle -> no_conflict,
    // toward it -> conflict; the precision Arb needs grows with k (the double
    // filter decides k = 6, and must agree).
    InCircleOptions arb;
    arb.use_filter = false;
    long previous = 0;
    for (int k : {6, 30, 100}) {
        const Rational eps = power_of_ten(-k);
        const Ellipse away(2, 1, 1, 0, Rational(-5) - eps), toward(2, 1, 1, 0, Rational(-5) + eps);
        long used = 0;
        for (const Ellipse* q : {&away, &toward}) {
            INFO("k " << k << apollonius::ell({&e1, &e2, &e3, q}));
            const Decision<InCircle> d = incircle(e1, e2, e3, *q, arb);
            INFO(show(d));
            CHECK((*d) == (q == &away ? InCircle::no_conflict : InCircle::conflict));
            CHECK(d.stage == Stage::subdivision);
            const Decision<InCircle> filtered = incircle(e1, e2, e3, *q);
            CHECK((*filtered) == (*d));
            CHECK((filtered.stage == Stage::filter) == (k == 6));
            used = std::max(used, d.precision);
        }
        if (verbose()) std::printf("[incircle/tangent ellipses] k %d precision %ld\n", k, used);
        INFO("k " << k << " precision " << used << " previous " << previous);
        CHECK(used > previous);
        CHECK(used > 3.33 * k);  // 10^-k needs more than k log2(10) bits
        previous = used;
    }
}

TEST_CASE("incircle on an exactly tangent circle quadruple, CGAL's ZERO, and perturbations", "[predicates][incircle]") {
    // Unit circles centered at distance 6 from the origin at rational points
    // (6,0), (0,6), (-6,0), 6 (3/5, -4/5): all tangent to the circle of radius 5.
    const apollonius::Circle c1{6, 0, 1}, c2{0, 6, 1}, c3{-6, 0, 1}, cq{Rational(18, 5UL), Rational(-24, 5UL), 1};
    const Ellipse e1 = c1.ellipse(), e2 = c2.ellipse(), e3 = c3.ellipse(), q = cq.ellipse();
    INFO(apollonius::ell({&e1, &e2, &e3, &q}));
    InCircleOptions capped;
    capped.use_circle_closed_form = false;  // the general path on circles
    capped.refinement.cap = 512;
    const Decision<InCircle> d = incircle(e1, e2, e3, q, capped);
    INFO(show(d));
    CHECK((*d) == InCircle::tangent);  // by the exact stage past the cap
    CHECK(d.precision >= 512);
    // The closed form cannot certify a sign either.
    const int o = apollonius::incircle(c1, c2, c3, cq);
    CHECK((o == 0 || o == 2));
    // CGAL (its input is exact here except 18/5, -24/5: use the integer point (0,-6)).
    Traits traits;
    const auto cgal_conflict = traits.vertex_conflict_2_object();
    CHECK(cgal_conflict(cgal_site(6, 0, 1), cgal_site(0, 6, 1), cgal_site(-6, 0, 1), cgal_site(0, -6, 1)) == CGAL::ZERO);
    {
        const Ellipse q2 = Ellipse::circle(0, -6, 1);
        INFO(apollonius::ell({&e1, &e2, &e3, &q2}));
        const Decision<InCircle> d2 = incircle(e1, e2, e3, q2, capped);
        INFO(show(d2));
        CHECK((*d2) == InCircle::tangent);
    }
    // CGAL with a larger / smaller fourth radius.
    CHECK(cgal_conflict(cgal_site(6, 0, 1), cgal_site(0, 6, 1), cgal_site(-6, 0, 1), cgal_site(0, -6, 2)) == CGAL::NEGATIVE);
    // Radius of Q changed by 10^-k: larger -> conflict, smaller -> no_conflict.
    // The subdivision's precision must grow with k (the circle filter, which
    // would decide k = 6 in doubles, is switched off to watch it).
    InCircleOptions subdivision_only;
    subdivision_only.use_circle_closed_form = false;  // the general path on circles
    subdivision_only.use_filter = false;
    long previous = 0;
    for (int k : {6, 30, 100}) {
        const Rational eps = power_of_ten(-k);
        long used = 0;
        for (int dir : {1, -1}) {
            const apollonius::Circle cp{cq.x, cq.y, dir > 0 ? Rational(1) + eps : Rational(1) - eps};
            const Ellipse qp = cp.ellipse();
            INFO("k " << k << apollonius::ell({&e1, &e2, &e3, &qp}));
            const Decision<InCircle> dp = incircle(e1, e2, e3, qp, subdivision_only);
            INFO(show(dp));
            CHECK((*dp) == (dir > 0 ? InCircle::conflict : InCircle::no_conflict));
            CHECK(*incircle(e1, e2, e3, qp) == (*dp));  // with the filter
            CHECK(apollonius::incircle(c1, c2, c3, cp) == (dir > 0 ? -1 : 1));
            used = std::max(used, dp.precision);
        }
        if (verbose()) std::printf("[incircle/tangent circles] k %d precision %ld\n", k, used);
        INFO("k " << k << " precision " << used);
        CHECK(used > previous);
        CHECK(used > 3.33 * k);
        previous = used;
    }
}

TEST_CASE("incircle: triples without a counter-clockwise circle give no_circle", "[predicates][incircle]") {
    // The three circles of the tangent configuration in clockwise order: the
    // only tangent circle (equal radii: the circumcenter) is clockwise.
    const Ellipse e1 = Ellipse::circle(6, 0, 1), e2 = Ellipse::circle(0, 6, 1), e3 = Ellipse::circle(-6, 0, 1);
    for (const Ellipse& q : {Ellipse::circle(0, 0, 1), Ellipse::circle(0, -6, 1), Ellipse::circle(100, 100, 1)}) {
        INFO(apollonius::ell({&e3, &e2, &e1, &q}));
        const Decision<InCircle> d = incircle(e3, e2, e1, q);
        INFO(show(d));
        CHECK((*d) == InCircle::no_circle);
        CHECK(to_int(incircle_sign(*d)) == -1);
        CHECK(d.is_decided());
    }
    // An undecided answer cannot be read as one.
    CHECK_THROWS(*Decision<InCircle>::undecided(Stage::subdivision, 64));
}

// Regression (found by this suite before 978734a, which made the
// certification escalate its precision): well-separated integer circle
// quadruples whose counter-clockwise Voronoi circle is large (radius ~900 ..
// 15000, tangency points close together) came back `undecided` at precision
// 64 although the cap is 4096: certify() ran Krawczyk at 64 bits only. The
// closed form and CGAL decide every one with a wide margin.
TEST_CASE("incircle decides well-separated quadruples with a large Voronoi circle", "[predicates][incircle]") {
    struct Case { long v[4][3]; int want; };
    const Case cases[] = {
        {{{17, -12, 7}, {-3, -9, 4}, {-20, -4, 4}, {8, 9, 7}}, 1},        // CCW radius ~1604
        {{{1, 15, 1}, {-5, 20, 5}, {20, 14, 3}, {-5, -20, 6}}, -1},       // CCW radius ~15249
        {{{-9, 2, 7}, {22, -23, 3}, {12, -14, 5}, {-18, 16, 4}}, 1},      // CCW radius ~2367
        {{{16, 1, 6}, {-1, -7, 6}, {-14, -19, 1}, {19, 17, 1}}, 1},       // CCW radius ~933
    };
    Traits traits;
    const auto cgal_conflict = traits.vertex_conflict_2_object();
    for (const Case& k : cases) {
        apollonius::Circle c[4];
        for (int i = 0; i < 4; ++i) c[i] = {k.v[i][0], k.v[i][1], k.v[i][2]};
        const Ellipse e1 = c[0].ellipse(), e2 = c[1].ellipse(), e3 = c[2].ellipse(), q = c[3].ellipse();
        INFO(apollonius::ell({&e1, &e2, &e3, &q}));
        REQUIRE(apollonius::incircle(c[0], c[1], c[2], c[3]) == k.want);
        REQUIRE(cgal_sign(cgal_conflict(cgal_site(k.v[0][0], k.v[0][1], k.v[0][2]), cgal_site(k.v[1][0], k.v[1][1], k.v[1][2]),
                                        cgal_site(k.v[2][0], k.v[2][1], k.v[2][2]), cgal_site(k.v[3][0], k.v[3][1], k.v[3][2]))) ==
                k.want);
        const Decision<InCircle> d = incircle(e1, e2, e3, q);
        INFO(show(d));
        CHECK(d.is_decided());
        if (d.is_decided()) CHECK(to_int(incircle_sign(*d)) == k.want);
        VoronoiCircleSolver solver(e1, e2, e3);
        CHECK(solver.certify());
    }
}

TEST_CASE("incircle: the four-circle filter agrees with the general cascade", "[predicates][incircle]") {
    // Rational (non-dyadic) circles, so the filter's double enclosures are wide
    // enough to matter; every answer it gives must be the cascade's.
    std::mt19937_64 rng(909);
    InCircleOptions no_filter;
    no_filter.use_circle_closed_form = false;  // the general path on circles
    no_filter.use_filter = false;
    int n = 0, by_filter = 0;
    while (n < 400) {
        std::array<apollonius::Circle, 4> c;
        for (auto& k : c) {
            k = {Rational(std::uniform_int_distribution<long>(-1000, 1000)(rng), 7UL),
                 Rational(std::uniform_int_distribution<long>(-1000, 1000)(rng), 3UL),
                 Rational(std::uniform_int_distribution<long>(1, 400)(rng), 11UL)};
        }
        bool ok = true;
        for (int i = 0; i < 4; ++i)
            for (int j = i + 1; j < 4; ++j) ok = ok && apart(c[i], c[j]);
        if (!ok) continue;
        ++n;
        const Ellipse e1 = c[0].ellipse(), e2 = c[1].ellipse(), e3 = c[2].ellipse(), q = c[3].ellipse();
        INFO(apollonius::ell({&e1, &e2, &e3, &q}));
        const Decision<InCircle> fast = incircle(e1, e2, e3, q), slow = incircle(e1, e2, e3, q, no_filter);
        CHECK((*fast) == (*slow));
        by_filter += fast.stage == Stage::filter;
    }
    CHECK(by_filter > 350);
}

TEST_CASE("incircle: a Voronoi center exactly on Q's boundary is a conflict", "[predicates][incircle]") {
    // The paper's InCircle set (1) at y = 1: the Voronoi circle of the three
    // circles is the unit circle at the origin, and Q = circle (0, 1) r 1 passes
    // through its center: no precision can place the center inside or outside
    // Q, but d(V, Q) = 0 < rho. (The four-circle filter is off so that the
    // general path is the one tested.)
    const Ellipse e1 = Ellipse::circle(-3, 0, 2), e2 = Ellipse::circle(0, -2, 1), e3 = Ellipse::circle(Rational(3, 2), 0, Rational(1, 2));
    const Ellipse q = Ellipse::circle(0, 1, 1);
    InCircleOptions general;
    general.use_circle_closed_form = false;  // the general path on circles
    general.use_filter = false;
    for (const auto& [a, b, c] : {std::tuple{&e1, &e2, &e3}, {&e1, &e3, &e2}}) {
        const Decision<InCircle> d = incircle(*a, *b, *c, q, general);
        INFO(apollonius::ell({a, b, c, &q}) << show(d));
        if ((*d) == InCircle::no_circle) continue;  // the clockwise order
        CHECK((*d) == InCircle::conflict);
        CHECK(d.stage == Stage::subdivision);
        CHECK(d.precision == 64);
    }
}
