// The JSON document of `ellvor build --json`: the sites (null for removed
// ones), the removed ids in the order of removal, the [hidden, hiding]
// pairs, the finite edges and faces by site id, the Voronoi vertex of every
// face (center and radius of its certified Voronoi circle, in doubles, each
// within `error`) and the build statistics.
#pragma once

#include "graph/delaunay_graph.hpp"
#include "sites/ellipse.hpp"

#include <nlohmann/json.hpp>

#include <vector>

namespace ellvor {

// {"seconds", "inserted", "predicates": {name: {"calls", one count per stage}}}.
nlohmann::json build_stats_json(const DelaunayGraph& graph, double seconds);

// The whole document; `sites` are the graph's sites, `stats` the build's
// statistics (build_stats_json taken right after the build: validation asks
// predicates too).
nlohmann::json graph_json(const DelaunayGraph& graph, const std::vector<Ellipse>& sites, const nlohmann::json& stats);

}  // namespace ellvor
