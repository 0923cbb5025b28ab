// Certified measures of the Voronoi cells of sites in the free plane (disjoint,
// nested, crossing or touching: signed distances, docs/DESIGN.md §9 and §10):
// area, perimeter, centroid and second
// moments, each an Arb ball that provably contains the exact value; the area
// includes the site's own (the set-Voronoi convention: the cells tile the
// plane).
#pragma once

#include "cells/cell_chunks.hpp"
#include "cells/quadrature_counts.hpp"
#include "cells/voronoi_cells.hpp"
#include "graph/delaunay_graph.hpp"
#include "sites/ellipse.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <vector>

namespace ellvor {

struct CellAreaOptions {
    // Every finite area is returned with hi - lo <= tolerance * lo, in (0, 1];
    // the working precision grows with -log2(tolerance). The other measures
    // are integrated to the same relative accuracy in the cell's own units
    // (length sqrt(area)), which is asked of Arb but not checked: their balls
    // are proofs at whatever width they come out.
    double tolerance = 1e-9;
    // The sites whose cells are measured (the others are left at their
    // defaults); empty: every site.
    std::vector<SiteId> only;
    // The input id of each site in the errors (the originals of mirrors and
    // periodic copies); empty: the ids themselves.
    std::vector<SiteId> input_ids;
    // Called after each measured cell (done, total), from any of the threads,
    // one call at a time; may be empty.
    std::function<void(std::size_t done, std::size_t total)> progress;
    // Threads measuring cells; 0: one per core. The cells are measured in
    // chunks of `chunk` cells along a Hilbert curve, each chunk by itself (an
    // edge is integrated once for both its cells only within a chunk:
    // docs/DESIGN.md §10), so the result depends on the chunk size, not on
    // the threads.
    unsigned threads = 1;
    std::size_t chunk = kCellChunk;
    // Every edge by Arb's integrator, the last stage (tests reach it so).
    bool arb_integrator_only = false;
};

struct CellArea {
    SiteId site = 0;
    bool visible = false;
    bool bounded = false;    // false: the area is +infinity (a vertex at infinity), or 0 (hidden)
    Ball area;               // [lo, hi]; exactly 0 for a hidden site; +inf for an unbounded cell
    Ball site_area;          // pi a b
    // Bounded cells only (else left indeterminate): the length of the
    // boundary, the centroid, and the second moments about the centroid
    // (integrals of (x - cx)^2, (x - cx)(y - cy), (y - cy)^2).
    Ball perimeter;
    std::array<Ball, 2> centroid;
    std::array<Ball, 3> second_moments;
    // Bounded cells: an upper bound (rounded up) of |x - the site's center|
    // over the cell's boundary, from the certificates of the quadrature's
    // pieces (cells/edge_quadrature.hpp); +inf when an edge went to Arb's
    // integrator, which gives none.
    double reach = INFINITY;
    long precision = 0;      // Arb precision of the pass that met the tolerance (0: none was needed)
    // The stages that integrated the edges in that pass
    // (cells/edge_quadrature.hpp): Gauss-Legendre in double intervals (goals
    // up to 44 bits), its pieces with the nodes in Arb (beyond), or Arb's
    // integrator (edges neither certifies).
    std::size_t edges_in_doubles = 0, edges_by_nodes_in_arb = 0, edges_by_arb = 0;
    // The edges whose integrals the neighbour's cell took for both (its first
    // pass; docs/DESIGN.md §10): counted there, in its stages and quadrature.
    std::size_t edges_from_neighbors = 0;
    // What the double-interval stage did on those edges (every attempt of that pass).
    QuadratureCounts quadrature;
};

// Throws InputError naming the pair (as input_ids, or the ids themselves when
// it is empty) when two sites cross so deeply that their edge, on a bounded
// cell of `which` (empty: every site), runs through a site's medial axis: the
// normal-line parametrization cannot follow it (docs/DESIGN.md §10). Decided
// by floating-point samples of the edge, before any integral: cell_areas
// asks it first; cell_tessellation before its rings.
void require_followable_edges(const DelaunayGraph& graph, const std::vector<Ellipse>& sites,
                              const std::vector<SiteId>& which, const std::vector<SiteId>& input_ids);

// The working precision for a tolerance: 64 bits beyond its own bits.
long cell_area_precision(double tolerance);

// Every cell's area, indexed by site id. Throws InputError when the
// tolerance is not in (0, 1], or when two sites cross so deeply that their
// edge runs through a site's medial axis (the normal-line parametrization
// cannot follow it: docs/DESIGN.md §10), naming the pair; Error if a cell
// cannot be certified within the precision limit.
std::vector<CellArea> cell_areas(const DelaunayGraph& graph, const std::vector<Ellipse>& sites,
                                 const CellAreaOptions& options = {});

}  // namespace ellvor
