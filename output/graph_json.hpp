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
#include <ostream>
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

// The Voronoi vertices of graph.faces(), in that order.
std::vector<VoronoiVertexValue> voronoi_vertex_values(const DelaunayGraph& graph, const std::vector<Ellipse>& sites);

// Writes the whole document (one line, no newline); `sites` are the graph's
// sites, `stats` the build's statistics (build_stats_json taken right after
// the build: validation asks predicates too), `vertices` one per face of
// graph.faces(), in that order. An element at a time: the bytes of
// nlohmann's dump of the whole (its members in order) without the document
// held whole (10^5 random ellipses: 335 MB at the peak, 83 MB for the build).
void write_graph_json(std::ostream& out, const DelaunayGraph& graph, const std::vector<Ellipse>& sites,
                      const nlohmann::json& stats, const std::vector<VoronoiVertexValue>& vertices);

}  // namespace ellvor
