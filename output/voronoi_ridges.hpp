// The Voronoi edges of a built graph in scipy.spatial.Voronoi's terms: each
// edge ("ridge") by the two sites it separates and the Voronoi vertices at
// its ends, a vertex being a finite face numbered in the order of
// DelaunayGraph::faces() and -1 standing for a vertex at infinity.
#pragma once

#include "graph/delaunay_graph.hpp"

#include <vector>

namespace ellvor {

struct VoronoiRidge {
    // The Delaunay edge p -> q; the Voronoi edge runs from the vertex of the
    // face on its left (`from`) to that of the face on its right (`to`).
    SiteId p = 0, q = 0;
    long from = -1, to = -1;
};

// The number of every finite face of the triangulation, indexed by
// FaceIndex::value(): its position in DelaunayGraph::faces() (faces listing
// the same triple, which have one Voronoi circle, are numbered in the
// triangulation's order); -1 for infinite faces and unused indices.
std::vector<long> face_numbers(const DelaunayGraph& graph);
// numbers[f], or -1 (an infinite face, or none).
long face_number(const std::vector<long>& numbers, FaceIndex f);

// One ridge per Voronoi edge (per finite Delaunay edge, so as many as
// DelaunayGraph::edges() lists), sorted by the pair (min(p, q), max(p, q)) as
// edges() is. Two visible sites alone give one ridge with both ends at
// infinity.
std::vector<VoronoiRidge> voronoi_ridges(const DelaunayGraph& graph, const std::vector<long>& numbers);

}  // namespace ellvor
