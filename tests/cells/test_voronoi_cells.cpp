// Cell topology: every visible site's edges chain counter-clockwise, each
// edge is seen from both sides with its ends swapped, and the cells hold
// exactly the ridges of output/voronoi_ridges (p's cell runs a ridge p -> q
// from its right face to its left face).
#include "cells/voronoi_cells.hpp"
#include "cells/face_numbers.hpp"
#include "output/voronoi_ridges.hpp"
#include "sites/site_generators.hpp"
#include "tests/support/ellipse_graph.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <tuple>
#include <vector>

using namespace ellvor;

TEST_CASE("voronoi_cells: chained counter-clockwise, the ridges seen from both sides", "[cells]") {
    GeneratorOptions o;
    o.count = GENERATE(2, 3, 40);
    o.seed = GENERATE(1, 2);
    o.nested_fraction = o.count > 3 ? Rational(1, 5) : Rational(0);
    const std::vector<Ellipse> sites = generate_sites(o);
    DelaunayGraph graph = test::ellipse_graph(sites);
    graph.insert_all();
    const std::vector<long> numbers = face_numbers(graph);
    const std::vector<VoronoiCell> cells = voronoi_cells(graph, numbers);
    REQUIRE(cells.size() == sites.size());

    std::vector<std::tuple<SiteId, SiteId, long, long>> from_cells, from_ridges;
    const std::vector<SiteId> visible = graph.visible_sites();
    for (const VoronoiCell& c : cells) {
        CHECK(c.visible == std::binary_search(visible.begin(), visible.end(), c.site));
        if (!c.visible) CHECK(c.edges.empty());
        if (c.visible && visible.size() > 1) CHECK(!c.edges.empty());
        for (std::size_t k = 0; k < c.edges.size(); ++k) {
            const CellEdge& e = c.edges[k];
            CHECK(e.to == c.edges[(k + 1) % c.edges.size()].from);
            from_cells.emplace_back(c.site, e.neighbor, e.from, e.to);
            // The same edge in the neighbour's cell, reversed.
            const auto& other = cells[e.neighbor].edges;
            CHECK(std::count_if(other.begin(), other.end(), [&](const CellEdge& f) {
                      return f.neighbor == c.site && f.from == e.to && f.to == e.from;
                  }) >= 1);
        }
    }
    for (const VoronoiRidge& r : voronoi_ridges(graph, numbers)) {
        from_ridges.emplace_back(r.p, r.q, r.to, r.from);
        from_ridges.emplace_back(r.q, r.p, r.from, r.to);
    }
    std::sort(from_cells.begin(), from_cells.end());
    std::sort(from_ridges.begin(), from_ridges.end());
    CHECK(from_cells == from_ridges);
    // Hull sites have unbounded cells, the others bounded ones.
    std::vector<SiteId> on_hull;
    for (const auto& [i, j] : graph.hull()) on_hull.push_back(i), on_hull.push_back(j);
    for (const VoronoiCell& c : cells)
        if (c.visible && visible.size() >= 3)
            CHECK(c.bounded() == (std::find(on_hull.begin(), on_hull.end(), c.site) == on_hull.end()));
}
