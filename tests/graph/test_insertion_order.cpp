// The Delaunay graph does not depend on the insertion order (Karavelas and
// Yvinec's incremental algorithm, as CGAL's Apollonius_graph_2): the sites
// are inserted one by one in random permutations instead of insert_all's
// bulk order.
//
// General position (random ellipses and circles, nested ones included): the
// whole graph must be the same for every order -- visible sites, [hidden,
// hiding] pairs, edges (a multiset), faces and hull. That includes the
// hiding site of a site nested in several: sites are disjoint or nested, so
// containment is a forest whose roots are the visible sites, and a hidden
// site is always recorded under a visible site containing it (validate()) --
// the root of its tree, whatever the order. Only identical sites, which hide
// each other, could swap roles; general position has none.
//
// Degenerate inputs (four or more sites tangent to one circle): the graph may
// keep either diagonal of a degree-4 Voronoi vertex depending on the order,
// so only validity is required: every order passes validate() and
// brute_force_check().
//
// A failure prints the sites (.ell lines) and the order.
#include "graph/delaunay_graph.hpp"
#include "graph/insertion_order.hpp"
#include "traits/ellipse_delaunay_traits.hpp"
#include "sites/ellipse.hpp"
#include "sites/site_generators.hpp"
#include "tests/support/ellipse_graph.hpp"
#include "tests/support/graph_shape.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <numeric>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

using namespace ellvor;
using test::GraphShape;
using test::random_order;
using test::shape_of;

namespace {

// The graph of `sites` inserted in `order`, checked by validate() and, with
// `brute_force`, by brute_force_check().
GraphShape build_in_order(const std::vector<Ellipse>& sites, const std::vector<SiteId>& order, bool brute_force) {
    DelaunayGraph g = test::ellipse_graph(sites);
    for (SiteId i : order) g.insert(i);
    const std::string problem = brute_force ? g.brute_force_check() : g.validate();
    INFO(test::replay(sites, "order", order));
    CHECK(problem == "");
    return shape_of(g);
}

// Nested chains: inside every site that holds no other site (every
// `every`-th one of the top-level sites) a concentric circle of a third of its
// smaller semi-axis, and inside that one a circle of a ninth. Each lies
// strictly inside the site's inscribed circle, hence inside the site and
// apart from every other site; the innermost circle of a chain in a nested
// site is nested in three sites.
std::vector<Ellipse> with_nested_chains(std::vector<Ellipse> sites, std::size_t every) {
    const std::size_t n = sites.size();
    std::vector<char> holds(n, 0), nested(n, 0);
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j)
            if (i != j && bounding_circle_inside_inscribed(sites[j], sites[i])) holds[i] = nested[j] = 1;
    std::size_t top_level = 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (holds[i] || (!nested[i] && top_level++ % every != 0)) continue;
        const Rational r = std::min(sites[i].a(), sites[i].b()) / Rational(3);
        sites.push_back(Ellipse::circle(sites[i].xc(), sites[i].yc(), r));
        sites.push_back(Ellipse::circle(sites[i].xc(), sites[i].yc(), r / Rational(3)));
    }
    return sites;
}

// Returns the graph of the bulk order.
GraphShape check_order_independence(const std::vector<Ellipse>& sites, std::mt19937_64& rng, int orders) {
    DelaunayGraph bulk = test::ellipse_graph(sites);
    bulk.insert_all();
    REQUIRE(bulk.validate() == "");
    const GraphShape want = shape_of(bulk);
    for (int k = 0; k < orders; ++k) {
        const std::vector<SiteId> order = random_order(sites.size(), rng);
        const GraphShape got = build_in_order(sites, order, false);
        INFO(test::replay(sites, "order", order));
        CHECK(got.visible == want.visible);
        CHECK(got.hidden == want.hidden);
        CHECK(got.edges == want.edges);
        CHECK(got.faces == want.faces);
        CHECK(got.hull == want.hull);
    }
    return want;
}

void check_every_order_valid(const std::vector<Ellipse>& sites, std::mt19937_64& rng, int orders) {
    std::vector<SiteId> order(sites.size());
    std::iota(order.begin(), order.end(), 0);
    build_in_order(sites, order, true);
    std::reverse(order.begin(), order.end());
    build_in_order(sites, order, true);
    for (int k = 0; k < orders; ++k) build_in_order(sites, random_order(sites.size(), rng), true);
}

// `count` generated sites, round(count / 8) of them nested, then the chains.
std::vector<Ellipse> generated(SiteKind kind, long count, std::uint64_t seed) {
    GeneratorOptions o;
    o.kind = kind;
    o.count = count;
    o.seed = seed;
    o.nested_fraction = Rational(1, 8);
    return with_nested_chains(generate_sites(o), 10);
}

// k^2 copies of `site` translated to the points of a k x k square grid of step `step`.
std::vector<Ellipse> square_grid(const Ellipse& site, long k, long step) {
    std::vector<Ellipse> out;
    for (long i = 0; i < k; ++i)
        for (long j = 0; j < k; ++j)
            out.push_back(Ellipse(site.a(), site.b(), site.w(), site.xc() + Rational(i * step), site.yc() + Rational(j * step)));
    return out;
}

}  // namespace

TEST_CASE("insertion order: random ellipses, nested ones included, give one graph", "[graph][order]") {
    std::mt19937_64 rng(41);
    for (const auto& [count, seed] : std::vector<std::pair<long, std::uint64_t>>{{50, 1}, {100, 2}, {150, 3}}) {
        const std::vector<Ellipse> sites = generated(SiteKind::ellipses, count, seed);
        INFO(sites.size() << " ellipses and circles, seed " << seed);
        const GraphShape graph = check_order_independence(sites, rng, 3);
        // Every nested site is hidden: the generated ones and both circles of each chain.
        CHECK(graph.hidden.size() == (count + 4) / 8 + (sites.size() - count));
    }
}

TEST_CASE("insertion order: random circles, nested ones included, give one graph", "[graph][order]") {
    std::mt19937_64 rng(43);
    for (const auto& [count, seed] : std::vector<std::pair<long, std::uint64_t>>{{60, 4}, {120, 5}, {160, 6}}) {
        const std::vector<Ellipse> sites = generated(SiteKind::circles, count, seed);
        INFO(sites.size() << " circles, seed " << seed);
        const GraphShape graph = check_order_independence(sites, rng, 3);
        // Every nested site is hidden: the generated ones and both circles of each chain.
        CHECK(graph.hidden.size() == (count + 4) / 8 + (sites.size() - count));
    }
}

TEST_CASE("insertion order: a ring of 8 equal cocircular circles, with and without its center", "[graph][order]") {
    // 8 of the 12 integer points of x^2 + y^2 = 25, scaled by 20: the 8 equal
    // circles are tangent to one circle centered at the origin.
    const std::vector<std::pair<long, long>> ring = {{5, 0}, {4, 3}, {0, 5}, {-3, 4}, {-5, 0}, {-4, -3}, {0, -5}, {3, -4}};
    std::vector<Ellipse> sites;
    for (const auto& [x, y] : ring) sites.push_back(Ellipse::circle(Rational(20 * x), Rational(20 * y), Rational(5)));
    std::mt19937_64 rng(47);
    check_every_order_valid(sites, rng, 6);
    sites.push_back(Ellipse::circle(Rational(0), Rational(0), Rational(7)));
    check_every_order_valid(sites, rng, 6);
}

TEST_CASE("insertion order: a square grid of equal circles", "[graph][order]") {
    // Every cell's four circles are tangent to one circle at its center.
    std::mt19937_64 rng(53);
    check_every_order_valid(square_grid(Ellipse::circle(Rational(0), Rational(0), Rational(10)), 3, 100), rng, 6);
}

TEST_CASE("insertion order: a square grid of identical ellipses", "[graph][order]") {
    // Axis-aligned: the reflections of a cell map its four ellipses onto each
    // other, so a circle at the cell's center tangent to one is tangent to
    // all four. These ties go to the exact stage (tens of ms a call), so one
    // cell and few orders: a 3 x 3 grid takes seconds per order.
    std::mt19937_64 rng(59);
    const Ellipse site(Rational(6), Rational(4), Rational(0), Rational(0), Rational(0));
    check_every_order_valid(square_grid(site, 2, 20), rng, 2);
}

TEST_CASE("insertion order: the Hilbert index runs through adjacent cells", "[graph][order]") {
    // On the grid of unit cells (side 2^16), the first 16 positions fill the
    // 4 x 4 corner block, one cell each, every step to a neighbouring cell;
    // so do the first 4096 in the 64 x 64 block.
    for (int block : {4, 64}) {
        std::vector<std::pair<std::uint32_t, std::pair<int, int>>> cells;
        for (int i = 0; i < block; ++i)
            for (int j = 0; j < block; ++j) cells.push_back({hilbert_index(i + 0.5, j + 0.5, 0, 0, 65536), {i, j}});
        std::sort(cells.begin(), cells.end());
        for (std::size_t k = 0; k < cells.size(); ++k) {
            INFO("block " << block << " position " << k);
            REQUIRE(cells[k].first == k);
            if (k > 0) {
                const int step = std::abs(cells[k].second.first - cells[k - 1].second.first) +
                                 std::abs(cells[k].second.second - cells[k - 1].second.second);
                CHECK(step == 1);
            }
        }
    }
    CHECK(hilbert_index(-5, -5, 0, 0, 1) == 0);  // clamped
    CHECK(bulk_insertion_rounds(0).empty());
    CHECK(bulk_insertion_rounds(10) == std::vector<std::size_t>{10});
    CHECK(bulk_insertion_rounds(5000) == std::vector<std::size_t>{1024, 1024, 2048, 904});
}

TEST_CASE("insertion order: compare_weight on circles of doubles (their radii's doubles) is the exact order of a b",
          "[graph][order]") {
    // Radii with 0 to 60 fraction bits, many equal, against the rationals'
    // products; and a circle against an ellipse and a non-double circle.
    std::mt19937_64 rng(27);
    std::vector<Ellipse> sites;
    for (int i = 0; i < 300; ++i) {
        const long bits = static_cast<long>(rng() % 61), num = 1 + static_cast<long>(rng() % 40);
        const Rational r = i % 3 == 0 ? Rational(num % 5 + 1) : Rational(num, 1UL << bits);
        sites.push_back(Ellipse::circle(Rational(static_cast<long>(rng() % 100)), Rational(i), r));
    }
    sites.push_back(Ellipse(Rational(3), Rational(1, 3), Rational(0), Rational(0), Rational(-5)));
    sites.push_back(Ellipse::circle(Rational(0), Rational(-9), Rational(1, 3)));
    const EllipseDelaunayTraits traits(sites);
    int dyadic_pairs = 0, ties = 0;
    for (SiteId x = 0; x < sites.size(); ++x)
        for (SiteId y = 0; y < sites.size(); y += 7) {
            const Rational wx = sites[x].a() * sites[x].b(), wy = sites[y].a() * sites[y].b();
            const Sign want = wx > wy ? Sign::positive : wx < wy ? Sign::negative : Sign::zero;
            INFO(sites[x].str() << " / " << sites[y].str());
            CHECK(traits.compare_weight(x, y) == want);
            dyadic_pairs += sites[x].is_dyadic_circle() && sites[y].is_dyadic_circle();
            ties += want == Sign::zero && x != y;
        }
    CHECK(dyadic_pairs > 10000);
    CHECK(ties > 100);
    // The bulk order sorts through weight_bounds (up to 1024 sites it is the
    // weight order): the same order as compare_weight alone, ties and all.
    std::vector<SiteId> by_weight(sites.size());
    std::iota(by_weight.begin(), by_weight.end(), 0);
    std::stable_sort(by_weight.begin(), by_weight.end(),
                     [&](SiteId x, SiteId y) { return traits.compare_weight(x, y) == Sign::positive; });
    for (SiteId x = 0; x < sites.size(); ++x) {
        const std::optional<DelaunayTraits::WeightBounds> b = traits.weight_bounds(x);
        REQUIRE(b);
        CHECK(b->lo <= b->hi);
    }
    CHECK(bulk_insertion_order(traits) == by_weight);
}

TEST_CASE("insertion order: the bulk order is largest first by rounds, local within them, and gives the weight order's graph",
          "[graph][order]") {
    const std::vector<Ellipse> sites = generated(SiteKind::ellipses, 2400, 11);
    const EllipseDelaunayTraits traits(sites);
    const std::vector<SiteId> order = bulk_insertion_order(traits);
    INFO(sites.size() << " sites");
    std::vector<SiteId> sorted = order;
    std::sort(sorted.begin(), sorted.end());
    std::vector<SiteId> identity(sites.size());
    std::iota(identity.begin(), identity.end(), 0);
    REQUIRE(sorted == identity);
    // Every site of a round weighs at least as much as every later site
    // (so a container precedes the sites it holds unless both share a round).
    std::vector<SiteId> by_weight = identity;
    std::stable_sort(by_weight.begin(), by_weight.end(),
                     [&](SiteId x, SiteId y) { return traits.compare_weight(x, y) == Sign::positive; });
    std::size_t begin = 0;
    for (std::size_t size : bulk_insertion_rounds(order.size())) {
        for (std::size_t k = begin; k < begin + size; k += 3)
            for (std::size_t later = begin + size; later < order.size(); later += 37)
                CHECK(traits.compare_weight(order[k], order[later]) != Sign::negative);
        begin += size;
    }
    // Within the last round consecutive sites are near: a much shorter path
    // through the centers than the weight order's.
    const std::size_t last = bulk_insertion_rounds(order.size()).back(), first = order.size() - last;
    auto path = [&](const std::vector<SiteId>& o) {
        double length = 0;
        for (std::size_t k = first + 1; k < o.size(); ++k) {
            const LocationHint a = traits.location_hint(o[k - 1]), b = traits.location_hint(o[k]);
            length += std::hypot(a.x - b.x, a.y - b.y);
        }
        return length;
    };
    INFO("path through the last round: bulk " << path(order) << ", weight order " << path(by_weight));
    CHECK(path(order) < 0.25 * path(by_weight));
    // insert_all (the bulk order) and the weight order give one graph.
    DelaunayGraph bulk = test::ellipse_graph(sites);
    bulk.insert_all();
    REQUIRE(bulk.validate() == "");
    const GraphShape want = shape_of(bulk);
    const GraphShape got = build_in_order(sites, by_weight, false);
    CHECK(got.visible == want.visible);
    CHECK(got.hidden == want.hidden);
    CHECK(got.edges == want.edges);
    CHECK(got.faces == want.faces);
    CHECK(got.hull == want.hull);
    CHECK(want.hidden.size() > 300);  // the nested sites and chains are hidden in both
    // Up to 1024 sites the bulk order is the weight order.
    const std::vector<Ellipse> few(sites.begin(), sites.begin() + 1000);
    const EllipseDelaunayTraits few_traits(few);
    std::vector<SiteId> few_by_weight(few.size());
    std::iota(few_by_weight.begin(), few_by_weight.end(), 0);
    std::stable_sort(few_by_weight.begin(), few_by_weight.end(),
                     [&](SiteId x, SiteId y) { return few_traits.compare_weight(x, y) == Sign::positive; });
    CHECK(bulk_insertion_order(few_traits) == few_by_weight);
}
