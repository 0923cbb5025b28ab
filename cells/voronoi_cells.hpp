// The cells of a built diagram, combinatorially: for every visible site the
// counter-clockwise cyclic sequence of its Voronoi edges, each by the
// neighbour across it and its two Voronoi vertices (numbered as in
// DelaunayGraph::faces(), cells/face_numbers.hpp; -1 for a vertex at
// infinity). A hidden site has an empty cell and no edges (docs/DESIGN.md §2).
#pragma once

#include "graph/delaunay_graph.hpp"

#include <vector>

namespace ellvor {

struct CellEdge {
    SiteId neighbor = 0;
    // The edge runs counter-clockwise around the site from `from` to `to`;
    // along it the site's tangency angle increases (output/bisector_trace.hpp).
    long from = -1, to = -1;
};

struct VoronoiCell {
    SiteId site = 0;
    bool visible = false;
    std::vector<CellEdge> edges;  // counter-clockwise; empty for a hidden site and for a site alone
    // A visible site's cell is bounded iff it has an edge and no vertex at infinity.
    bool bounded() const;
};

// One cell per site, indexed by site id.
std::vector<VoronoiCell> voronoi_cells(const DelaunayGraph& graph, const std::vector<long>& numbers);

}  // namespace ellvor
