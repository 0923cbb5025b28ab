// The JSON document of `ellvor build --json`: the sites (null for removed
// ones), the removed ids in the order of removal, the [hidden, hiding]
// pairs, the finite edges and faces by site id, the Voronoi vertex of every
// face (center and radius of its certified Voronoi circle, in doubles, each
// within `error`) and the build statistics.
#pragma once

#include "graph/delaunay_graph.hpp"
#include "sites/ellipse.hpp"

#include <nlohmann/json.hpp>

#include <array>
#include <vector>

namespace ellvor {

// The Voronoi vertex of a finite face (i, j, k) as the JSON gives it: the
// center and radius of its certified Voronoi circle (voronoi_circle_box:
// within about 2^-40 of the circle's magnitude, usually 2^-50) as doubles in
// the boxes, and `error`, a bound on each one's distance to the exact value.
struct VoronoiVertexValue {
    double x = 0, y = 0, radius = 0, error = 0;
};
VoronoiVertexValue voronoi_vertex_value(const std::vector<Ellipse>& sites, const std::array<SiteId, 3>& face);

// {"seconds", "inserted", "predicates": {name: {"calls", one count per stage}}}.
nlohmann::json build_stats_json(const DelaunayGraph& graph, double seconds);

// The whole document; `sites` are the graph's sites, `stats` the build's
// statistics (build_stats_json taken right after the build: validation asks
// predicates too).
nlohmann::json graph_json(const DelaunayGraph& graph, const std::vector<Ellipse>& sites, const nlohmann::json& stats);
// The same with the Voronoi vertices already computed, one per face of
// graph.faces(), in that order (the Python module keeps them as arrays too).
nlohmann::json graph_json(const DelaunayGraph& graph, const std::vector<Ellipse>& sites, const nlohmann::json& stats,
                          const std::vector<VoronoiVertexValue>& vertices);

}  // namespace ellvor
