// Voronoi vertices by number: a finite face of the triangulation is numbered
// by its position in DelaunayGraph::faces(), the order the JSON document, the
// ridges and the cells all use.
#pragma once

#include "graph/delaunay_graph.hpp"

#include <vector>

namespace ellvor {

// The number of every finite face of the triangulation, indexed by
// FaceIndex::value(): its position in DelaunayGraph::faces() (faces listing
// the same triple, which have one Voronoi circle, are numbered in the
// triangulation's order); -1 for infinite faces and unused indices.
std::vector<long> face_numbers(const DelaunayGraph& graph);
// numbers[f], or -1 (an infinite face, or none).
long face_number(const std::vector<long>& numbers, FaceIndex f);

}  // namespace ellvor
