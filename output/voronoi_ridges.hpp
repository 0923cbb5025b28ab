// The Voronoi edges of a built graph in scipy.spatial.Voronoi's terms: each
// edge ("ridge") by the two sites it separates and the Voronoi vertices at
// its ends, a vertex being a finite face numbered in the order of
// DelaunayGraph::faces() and -1 standing for a vertex at infinity.
#pragma once

#include "cells/face_numbers.hpp"
#include "graph/delaunay_graph.hpp"

#include <vector>

namespace ellvor {

struct VoronoiRidge {
    // The Delaunay edge p -> q; the Voronoi edge runs from the vertex of the
    // face on its left (`from`) to that of the face on its right (`to`).
    SiteId p = 0, q = 0;
    long from = -1, to = -1;
};

// One ridge per Voronoi edge (per finite Delaunay edge, so as many as
// DelaunayGraph::edges() lists), sorted by the pair (min(p, q), max(p, q)) as
// edges() is. Two visible sites alone give one ridge with both ends at
// infinity.
std::vector<VoronoiRidge> voronoi_ridges(const DelaunayGraph& graph, const std::vector<long>& numbers);

}  // namespace ellvor
