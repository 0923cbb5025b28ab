// Deletion (DelaunayGraph::remove, CGAL's remove): after any removals the
// graph is the graph of the sites that remain.
//
// General position (random ellipses and circles, nested ones included): the
// graph after removing one site, 10 %, 90 % or all of them, in random order,
// equals the graph built from the remaining sites -- visible sites, [hidden,
// hiding] pairs, edges (a multiset), faces and hull -- and passes validate()
// (and brute_force_check() up to 150 sites). The sites a removed site hid come
// back. Degenerate inputs (cocircular rings, grids) may keep either diagonal
// of a degree-4 Voronoi vertex, so there only validity is required.
//
// A failure prints the sites (.ell lines) and the removals.
#include "graph/delaunay_graph.hpp"
#include "sites/ellipse.hpp"
#include "sites/site_generators.hpp"
#include "tests/support/ellipse_graph.hpp"
#include "tests/support/graph_shape.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <numeric>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

using namespace ellvor;
using test::GraphShape;
using test::Pairs;
using test::random_order;
using test::shape_of;

namespace {

// The graph of the sites not in `removed`, inserted largest first.
GraphShape rebuilt_without(const std::vector<Ellipse>& sites, const std::vector<SiteId>& removed) {
    std::vector<char> gone(sites.size(), 0);
    for (SiteId r : removed) gone[r] = 1;
    std::vector<SiteId> order;
    for (SiteId i = 0; i < sites.size(); ++i)
        if (!gone[i]) order.push_back(i);
    std::stable_sort(order.begin(), order.end(), [&](SiteId x, SiteId y) { return sites[x].a() * sites[x].b() > sites[y].a() * sites[y].b(); });
    DelaunayGraph g = test::ellipse_graph(sites);
    for (SiteId i : order) g.insert(i);
    return shape_of(g);
}

// Builds every site, removes `removed` in order, checks the graph after the
// last removal: valid, and (general position) equal to the rebuilt graph.
// Returns the graph's counters.
GraphStats check_removals(const std::vector<Ellipse>& sites, const std::vector<SiteId>& removed, bool general_position) {
    DelaunayGraph g = test::ellipse_graph(sites);
    g.insert_all();
    for (SiteId r : removed) g.remove(r);
    INFO(test::replay(sites, "removed, in order", removed));
    const std::string problem = sites.size() <= 150 ? g.brute_force_check() : g.validate();
    CHECK(problem == "");
    for (SiteId r : removed) CHECK_FALSE(g.contains(r));
    if (general_position) {
        const GraphShape got = shape_of(g), want = rebuilt_without(sites, removed);
        CHECK(got.visible == want.visible);
        CHECK(got.hidden == want.hidden);
        CHECK(got.edges == want.edges);
        CHECK(got.faces == want.faces);
        CHECK(got.hull == want.hull);
        CHECK(g.stats().removal_rebuilds == 0);
    }
    return g.stats();
}

std::vector<Ellipse> generated(SiteKind kind, long count, std::uint64_t seed) {
    GeneratorOptions o;
    o.kind = kind;
    o.count = count;
    o.seed = seed;
    o.nested_fraction = Rational(1, 8);
    o.box = Rational(std::max<long>(100, 8 * count));
    return generate_sites(o);
}

// The first `fraction` of a random order of the sites (at least one).
std::vector<SiteId> first_of(std::vector<SiteId> order, double fraction) {
    order.resize(std::max<std::size_t>(1, static_cast<std::size_t>(fraction * static_cast<double>(order.size()))));
    return order;
}

}  // namespace

TEST_CASE("removal: random sets, one site, 10%, 90% and all of them, equal the graph rebuilt", "[graph][removal]") {
    // 220 seeds: ellipses and circles, 10 to 58 sites, and four sets of 2000.
    std::mt19937_64 rng(61);
    std::size_t small_graph_removals = 0, seeds = 0;
    for (std::uint64_t seed = 1; seed <= 220; ++seed) {
        const SiteKind kind = seed % 2 ? SiteKind::ellipses : SiteKind::circles;
        long count = 10 + static_cast<long>(seed % 7) * 8;
        if (seed % 55 == 0) count = 2000;  // seeds 55, 165: 2000 ellipses; 110, 220: 2000 circles
        const std::vector<Ellipse> sites = generated(kind, count, seed);
        const std::vector<SiteId> order = random_order(sites.size(), rng);
        const double fraction = std::array<double, 4>{0.0, 0.1, 0.9, 1.0}[seed % 4];
        INFO(sites.size() << (kind == SiteKind::circles ? " circles" : " ellipses") << ", seed " << seed
                          << ", removing a fraction " << fraction);
        const GraphStats stats = check_removals(sites, fraction == 1.0 ? order : first_of(order, fraction), true);
        small_graph_removals += stats.small_graph_removals;
        ++seeds;
    }
    CHECK(seeds == 220);
    // Most removed vertices have degree > 3: the small-graph path is taken.
    CHECK(small_graph_removals > 1000);
}

TEST_CASE("removal: the sites a removed site hid come back, in every small case", "[graph][removal]") {
    // A big circle holding two small ones (one inside the other's host chain),
    // and three more circles around.
    const std::vector<Ellipse> sites = {
        Ellipse::circle(Rational(0), Rational(0), Rational(10)),  // 0: hides 1, 2, 3
        Ellipse::circle(Rational(3), Rational(0), Rational(4)),   // 1: hides 2
        Ellipse::circle(Rational(3), Rational(1), Rational(1)),   // 2
        Ellipse::circle(Rational(-5), Rational(-5), Rational(2)), // 3
        Ellipse::circle(Rational(40), Rational(0), Rational(3)),  // 4
        Ellipse::circle(Rational(0), Rational(40), Rational(5)),  // 5
        Ellipse::circle(Rational(-40), Rational(-3), Rational(4)),  // 6
    };
    DelaunayGraph g = test::ellipse_graph(sites);
    g.insert_all();
    REQUIRE(g.hidden() == Pairs{{1, 0}, {2, 0}, {3, 0}});
    g.remove(0);  // the host: 1 and 3 come back, 2 is hidden by 1 again
    CHECK(g.hidden() == Pairs{{2, 1}});
    CHECK(g.visible_sites() == std::vector<SiteId>{1, 3, 4, 5, 6});
    CHECK(g.brute_force_check() == "");
    CHECK(shape_of(g).edges == rebuilt_without(sites, {0}).edges);
    g.remove(2);  // a hidden site: only its host's list changes
    CHECK(g.hidden().empty());
    // Down to nothing, through three sites (the small cases) and back up.
    for (SiteId s : {4, 5, 6, 1}) {
        g.remove(s);
        CHECK(g.brute_force_check() == "");
    }
    CHECK(g.visible_sites() == std::vector<SiteId>{3});
    g.remove(3);
    CHECK(g.visible_sites().empty());
    CHECK(g.validate() == "");
    for (SiteId s = 0; s < sites.size(); ++s) g.insert(s);  // removed sites may come back
    CHECK(g.brute_force_check() == "");
    CHECK(g.hidden() == Pairs{{1, 0}, {2, 0}, {3, 0}});
    CHECK_THROWS_WITH(g.remove(7), Catch::Contains("no site 7"));
    g.remove(6);
    CHECK_THROWS_WITH(g.remove(6), Catch::Contains("not in the graph"));
}

TEST_CASE("removal: the center of a ring of 8 cocircular circles, and the ring around it", "[graph][removal]") {
    // 8 of the 12 integer points of x^2 + y^2 = 25, scaled by 20: the ring's
    // equal circles are tangent to one circle about the origin; the center
    // site's removal leaves a degree-8 Voronoi vertex.
    const std::vector<std::pair<long, long>> ring = {{5, 0}, {4, 3}, {0, 5}, {-3, 4}, {-5, 0}, {-4, -3}, {0, -5}, {3, -4}};
    std::vector<Ellipse> sites;
    for (const auto& [x, y] : ring) sites.push_back(Ellipse::circle(Rational(20 * x), Rational(20 * y), Rational(5)));
    sites.push_back(Ellipse::circle(Rational(0), Rational(0), Rational(7)));
    check_removals(sites, {8}, false);
    // The center stays; ring sites go, one by one, in two orders.
    check_removals(sites, {0, 1, 2, 3, 4}, false);
    check_removals(sites, {4, 2, 0, 6}, false);
    // A center touching every ring circle (radius 95 = 100 - 5).
    sites.back() = Ellipse::circle(Rational(0), Rational(0), Rational(95));
    check_removals(sites, {8}, false);
    check_removals(sites, {0, 1, 2, 3}, false);
    // The ring alone: its Voronoi vertex of degree 8 is six faces whose
    // diagonals are edges of length 0; removing ring sites flips them away.
    sites.pop_back();
    std::size_t flips = 0;
    for (SiteId first = 0; first < 8; ++first) flips += check_removals(sites, {first, (first + 3) % 8}, false).degenerate_flips;
    CHECK(flips > 0);
}

TEST_CASE("removal: sites of square grids of circles and of identical ellipses", "[graph][removal]") {
    // Every cell's four sites are tangent to one circle at its center.
    std::vector<Ellipse> circles, ellipses;
    for (long i = 0; i < 5; ++i)
        for (long j = 0; j < 5; ++j) circles.push_back(Ellipse::circle(Rational(100 * i), Rational(100 * j), Rational(10)));
    std::mt19937_64 rng(67);
    check_removals(circles, {12}, false);  // the middle
    check_removals(circles, {0, 6, 12, 18, 24, 4, 20}, false);
    check_removals(circles, random_order(circles.size(), rng), false);
    for (long i = 0; i < 3; ++i)
        for (long j = 0; j < 3; ++j)
            ellipses.push_back(Ellipse(Rational(6), Rational(4), Rational(0), Rational(20 * i), Rational(20 * j)));
    check_removals(ellipses, {4}, false);
    check_removals(ellipses, {0, 8, 2}, false);
}
