// voronoi_circle_count(E1, E2, E3): none / ccw_only / cw_only / both, against
// an independent solution of the Apollonius problem for circles
// (circle_oracles.hpp) and hand cases, CGAL's collinear three-site tests
// among them.
#include "predicates/voronoi_circle_count.hpp"
#include "predicates/infinite_vertex_conflict.hpp"
#include "predicates/relative_position.hpp"
#include "sites/site_generators.hpp"
#include "tests/support/circle_oracles.hpp"

#include <catch2/catch.hpp>

#include <random>

using namespace ellvor;

namespace {

using oracle::circles_apart;
using oracle::rnd;
using oracle::rnd_pos;
using oracle::Rng;

const char* name(oracle::Count c) { return oracle::count_name(c); }
const char* name(VoronoiCircles v) {
    switch (v) {
        case VoronoiCircles::none: return "none";
        case VoronoiCircles::ccw_only: return "ccw_only";
        case VoronoiCircles::cw_only: return "cw_only";
        case VoronoiCircles::both: return "both";
    }
    return "?";
}

VoronoiCircles reversed(VoronoiCircles v) {
    if (v == VoronoiCircles::ccw_only) return VoronoiCircles::cw_only;
    if (v == VoronoiCircles::cw_only) return VoronoiCircles::ccw_only;
    return v;
}

void expect(const oracle::Circle& a, const oracle::Circle& b, const oracle::Circle& c, VoronoiCircles want) {
    const Ellipse e1 = a.ellipse(), e2 = b.ellipse(), e3 = c.ellipse();
    INFO("want " << name(want) << oracle::ell({&e1, &e2, &e3}));
    CHECK(name(*voronoi_circle_count(e1, e2, e3)) == std::string(name(want)));
    // Rotating the triple keeps the orientation, swapping two reverses it.
    CHECK(name(*voronoi_circle_count(e2, e3, e1)) == std::string(name(want)));
    CHECK(name(*voronoi_circle_count(e1, e3, e2)) == std::string(name(reversed(want))));
}

}  // namespace

TEST_CASE("voronoi circle count: hand cases", "[predicates][voronoi_circle_count]") {
    // Three small far-apart circles: one circle through (almost) the three centers, whose
    // tangency points follow the orientation of the centers.
    expect({0, 0, 1}, {100, 0, 1}, {0, 100, 1}, VoronoiCircles::ccw_only);
    expect({0, 0, 1}, {0, 100, 1}, {100, 0, 1}, VoronoiCircles::cw_only);
    // The oracle agrees.
    CHECK(oracle::voronoi_circles({0, 0, 1}, {100, 0, 1}, {0, 100, 1}) == oracle::Count::ccw_only);
    CHECK(oracle::voronoi_circles({0, 0, 1}, {0, 100, 1}, {100, 0, 1}) == oracle::Count::cw_only);
}

TEST_CASE("voronoi circle count: CGAL's collinear three-site configurations", "[predicates][voronoi_circle_count]") {
    // Centers (100,100), (150,150), (200,200). Along the center line, with p the
    // foot of the query point X and h its distance to the line, the weighted distance
    // g(t) = sqrt((t - p)^2 + h^2) - r(t) must take one value at the three sites.
    // Radii linear in t (5,10,15 or 20,20,20): g is strictly convex -> none (CGAL:
    // all faces infinite). Middle 25 (outer 20): symmetry forces p at the middle, where
    // g(middle) = h - 25 < sqrt(L^2 + h^2) - 20: none (CGAL: the middle site on the hull).
    // Middle 15: h + 5 = sqrt(L^2 + h^2) gives h = +-(L^2 - 25)/10 with L = 50 sqrt 2:
    // two circles, one each side -> both (CGAL: two finite faces, middle not on hull).
    const Rational x1(100), x2(150), x3(200);
    struct Case { long r1, r2, r3; VoronoiCircles want; };
    for (const Case& c : {Case{5, 10, 15, VoronoiCircles::none}, Case{20, 20, 20, VoronoiCircles::none},
                          Case{20, 25, 20, VoronoiCircles::none}, Case{20, 15, 20, VoronoiCircles::both},
                          Case{15, 10, 5, VoronoiCircles::none}}) {
        const oracle::Circle a{x1, x1, c.r1}, b{x2, x2, c.r2}, d{x3, x3, c.r3};
        INFO("radii " << c.r1 << " " << c.r2 << " " << c.r3);
        CHECK(name(oracle::voronoi_circles(a, b, d)) == std::string(name(c.want == VoronoiCircles::none ? oracle::Count::none : oracle::Count::both)));
        expect(a, b, d, c.want);
        expect(d, b, a, c.want);  // the other insertion order
        expect(b, a, d, c.want);  // the middle site first
    }
}

TEST_CASE("voronoi circle count on 500 random disjoint circle triples agrees with the Apollonius oracle", "[predicates][voronoi_circle_count]") {
    Rng rng(6174);
    int n = 0, seen[4] = {};
    while (n < 600) {
        // Radii up to 4 in a [-10,10]^2 box: crowded triples, so all four answers occur.
        oracle::Circle c1{rnd(rng, -10, 10, 97), rnd(rng, -10, 10, 89), rnd_pos(rng, 4, 53)};
        oracle::Circle c2{rnd(rng, -10, 10, 83), rnd(rng, -10, 10, 79), rnd_pos(rng, 4, 47)};
        oracle::Circle c3{rnd(rng, -10, 10, 71), rnd(rng, -10, 10, 67), rnd_pos(rng, 4, 43)};
        if (!circles_apart(c1, c2) || !circles_apart(c1, c3) || !circles_apart(c2, c3)) continue;
        ++n;
        const Ellipse e1 = c1.ellipse(), e2 = c2.ellipse(), e3 = c3.ellipse();
        INFO(oracle::ell({&e1, &e2, &e3}));
        const oracle::Count want = oracle::voronoi_circles(c1, c2, c3);
        REQUIRE(want != oracle::Count::undecided);
        ++seen[static_cast<int>(want)];
        CHECK(name(*voronoi_circle_count(e1, e2, e3)) == std::string(name(want)));
    }
    INFO("none " << seen[0] << " ccw " << seen[1] << " cw " << seen[2] << " both " << seen[3]);
    for (int k = 0; k < 4; ++k) CHECK(seen[k] > 5);
}

TEST_CASE("has_both_voronoi_circles agrees with the count on random ellipse triples, early exits included",
          "[predicates][voronoi_circle_count]") {
    // Sites of very different sizes (a big one and two small ones) give
    // `both`; small ones apart mostly give none of the three conflicts, where
    // two signs settle it.
    Rng rng(20261127);
    auto q = [&](long lo, long hi, long den) { return Rational(std::uniform_int_distribution<long>(lo, hi)(rng), den); };
    int both = 0, early = 0, triples = 0;
    while (triples < 400) {
        std::vector<Ellipse> e;
        for (int i = 0; i < 3; ++i) {
            const long size = i == 0 && triples % 2 ? 200 : 20;
            e.emplace_back(q(5, size, 10), q(5, size, 10), q(-300, 300, 97), q(-600, 600, 10), q(-600, 600, 10));
        }
        bool apart = true;
        for (int i = 0; i < 3; ++i) apart = apart && *relative_position(e[i], e[(i + 1) % 3]) == RelativePosition::separated;
        if (!apart) continue;
        ++triples;
        for (int swap = 0; swap < 2; ++swap) {
            const Ellipse &e1 = e[0], &e2 = swap ? e[2] : e[1], &e3 = swap ? e[1] : e[2];
            INFO(oracle::ell({&e1, &e2, &e3}));
            const Decision<VoronoiCircles> count = voronoi_circle_count(e1, e2, e3);
            const Decision<bool> has_both = has_both_voronoi_circles(e1, e2, e3);
            REQUIRE(has_both.is_decided());
            CHECK(*has_both == (*count == VoronoiCircles::both));
            CHECK(static_cast<int>(has_both.stage) <= static_cast<int>(count.stage));  // fewer signs: no later stage
            both += *has_both;
            early += *infinite_vertex_conflict(e1, e2, e3) == Sign::positive &&
                     *infinite_vertex_conflict(e2, e3, e1) == Sign::positive;
        }
    }
    CHECK(both >= 20);
    CHECK(early >= 100);
}

TEST_CASE("bounding disks of one orientation: the three kappa2 signs agree, and has_both says no by that filter",
          "[predicates][voronoi_circle_count]") {
    // Sites up to 20 across, centers within 60 of the origin: many triples
    // near the filter's bound (its spread about its orientation).
    Rng rng(20261130);
    auto q = [&](long lo, long hi, long den) { return Rational(std::uniform_int_distribution<long>(lo, hi)(rng), den); };
    int uniform = 0, mixed = 0, near_bound = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        std::vector<Ellipse> e;
        for (int i = 0; i < 3; ++i)
            e.emplace_back(q(5, 200, 20), q(5, 200, 20), q(-300, 300, 97), q(-600, 600, 10), q(-600, 600, 10));
        if (!bounding_disks_uniformly_oriented(e[0], e[1], e[2])) {
            ++mixed;
            continue;
        }
        ++uniform;
        INFO(oracle::ell({&e[0], &e[1], &e[2]}));
        // Invariant under rotation and swaps of the triple.
        CHECK(bounding_disks_uniformly_oriented(e[1], e[2], e[0]));
        CHECK(bounding_disks_uniformly_oriented(e[0], e[2], e[1]));
        const Sign first = *infinite_vertex_conflict(e[0], e[1], e[2]);
        CHECK(first != Sign::zero);
        CHECK(*infinite_vertex_conflict(e[1], e[2], e[0]) == first);
        CHECK(*infinite_vertex_conflict(e[2], e[0], e[1]) == first);
        const VoronoiCircles count = *voronoi_circle_count(e[0], e[1], e[2]);
        // Exactly one circle, whose tangency points have the disks' orientation.
        CHECK(count == (bounding_disks_orientation(e[0], e[1], e[2]) > 0 ? VoronoiCircles::ccw_only
                                                                          : VoronoiCircles::cw_only));
        const Decision<bool> both = has_both_voronoi_circles(e[0], e[1], e[2]);
        CHECK(!*both);
        CHECK(both.stage == Stage::filter);
        // Sites larger than a third of their mutual distances (where the
        // bound's quadratic term counts).
        double largest = 0, closest = HUGE_VAL;
        for (int i = 0; i < 3; ++i) {
            const Ellipse &a = e[i], &b = e[(i + 1) % 3];
            largest = std::max({largest, a.a().to_double(), a.b().to_double()});
            closest = std::min(closest, std::hypot(a.xc().to_double() - b.xc().to_double(), a.yc().to_double() - b.yc().to_double()));
        }
        near_bound += 3 * largest > closest;
    }
    CHECK(uniform >= 300);
    CHECK(mixed >= 300);
    CHECK(near_bound >= 30);
}

TEST_CASE("none_inside_another agrees with the pairs' relative positions, nested and crossing sites included",
          "[predicates][voronoi_circle_count]") {
    // Triples with a pair of nearby sites (nested, crossing or close): the
    // filter (bounding circles apart or centers outside each other) must not
    // change the answer relative_position gives pair by pair.
    GeneratorOptions options;
    options.count = 150;
    options.seed = 11;
    options.box = Rational(30);
    options.nested_fraction = Rational(1, 3);
    options.crossing_fraction = Rational(1, 4);
    const std::vector<Ellipse> sites = generate_sites(options);
    auto not_nested = [](const Ellipse& p, const Ellipse& q) {
        const RelativePosition r = *relative_position(p, q);
        return r == RelativePosition::separated || r == RelativePosition::externally_tangent ||
               r == RelativePosition::intersecting;
    };
    int triples = 0, with_nested = 0;
    for (std::size_t i = 0; i < sites.size(); ++i)
        for (std::size_t j = i + 1; j < sites.size(); ++j) {
            if (bounding_circles_apart_in_doubles(sites[i], sites[j])) continue;
            // A near pair and a third site, in both orders.
            const std::size_t k = (i + j + 1) % sites.size() == i ? (i + 1) % sites.size() : (i + j + 1) % sites.size();
            if (k == j) continue;
            for (int order = 0; order < 2; ++order) {
                const Ellipse &e1 = sites[i], &e2 = sites[order ? k : j], &e3 = sites[order ? j : k];
                INFO(oracle::ell({&e1, &e2, &e3}));
                const bool want = not_nested(e1, e2) && not_nested(e2, e3) && not_nested(e3, e1);
                const Decision<bool> got = none_inside_another(e1, e2, e3);
                REQUIRE(got.is_decided());
                CHECK(*got == want);
                ++triples;
                with_nested += !want;
            }
        }
    CHECK(triples >= 100);
    CHECK(with_nested >= 40);
    CHECK(triples - with_nested >= 20);
}
