// The certified cells of a set of sites, in the free plane, in a box (walls)
// or in a periodic box (the torus): per site its area, perimeter, centroid
// and second moments as Arb balls that provably contain the exact values,
// its neighbours counter-clockwise, and a ring (a closed polyline within a
// certified Hausdorff distance of the cell's boundary). docs/DESIGN.md §10.
//
// This is the one entry point of the cells layer; the CLI (`ellvor cells`),
// the Python `Diagram.cells()` and the benchmarks call it.
#pragma once

#include "cells/cell_chunks.hpp"
#include "cells/cell_domain.hpp"
#include "cells/quadrature_counts.hpp"
#include "decision/site_id.hpp"
#include "sites/ellipse.hpp"
#include "util/ball_arithmetic.hpp"
#include "util/flint_types.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <vector>

namespace ellvor {

struct CellOptions {
    // Every finite area is returned with hi - lo <= tolerance * lo, in (0, 1].
    double tolerance = 1e-9;
    // The rings' certified Hausdorff distance to the cell boundaries; 0: 1e-3
    // of the median site size (its larger semi-axis).
    double boundary_tolerance = 0;
    // False: no rings (the areas and the rest do not need them; they cost
    // about as much as the areas). The torus still covers the edges, coarsely,
    // for its certificate.
    bool rings = true;
    // The sites whose cells are computed (input ids); empty: every site. The
    // others are left as Cell{} (with their id: not visible, no sides). Every
    // site still shapes the wanted cells.
    std::vector<SiteId> only;
    // Every edge by Arb's integrator, which gives no reach (Cell::reach):
    // covers of the edges then give it (tests reach both so).
    bool arb_integrator_only = false;
    // Called after each cell's measures (done, total), from any of the
    // threads, one call at a time; may be empty.
    std::function<void(std::size_t done, std::size_t total)> progress;
    // Threads measuring the areas and making the rings (CellAreaOptions::threads);
    // 0: one per core. The result depends on the chunk size, not on them.
    unsigned threads = 1;
    std::size_t chunk = kCellChunk;
};

// One side of a cell: a Voronoi edge, or a piece of a wall.
struct CellSide {
    long neighbor = -1;                  // the site across the side (an input id); -1 for a wall
    Wall wall = Wall::none;              // the wall across the side, when neighbor is -1
    // periodic: the neighbour across is site `neighbor` shifted by shift * (box size), both
    // with their centers taken into the box first (cells/periodic_copies.hpp, wrap_into_box)
    std::array<long, 2> shift = {0, 0};
    long from = -1, to = -1;             // vertex numbers in CellTessellation::vertices, counter-clockwise; -1: infinity
};

// A site as a cell side or a vertex names it: an input id, and the wall of a
// mirror (box) or the shift in periods of a copy (torus).
struct CellSiteImage {
    long site = -1;
    Wall wall = Wall::none;
    std::array<long, 2> shift = {0, 0};
};

struct CellVertex {
    Ball x, y;  // contains the exact vertex
    // The three sites whose Voronoi circle it is, counter-clockwise as the
    // triangulation's face lists them: one triple, one circle (§2), so a key
    // for the same vertex seen from another site set.
    std::array<CellSiteImage, 3> face;
};

struct Cell {
    SiteId site = 0;
    bool visible = false;
    bool bounded = false;  // false: a visible cell reaching infinity (free plane only), or a hidden site
    Ball area;             // 0 for a hidden site, +inf for an unbounded cell
    Ball site_area;        // pi a b
    Ball perimeter;        // the length of the cell's boundary; 0 hidden, +inf unbounded
    // The centroid and the second moments about it, integrals of (x - cx)^2,
    // (x - cx)(y - cy), (y - cy)^2 over the cell (the cell's Minkowski tensor
    // W_0^{2,0} up to normalisation); indeterminate for hidden and unbounded cells.
    std::array<Ball, 2> centroid;
    std::array<Ball, 3> second_moments;
    std::vector<CellSide> sides;              // counter-clockwise around the site
    std::vector<std::array<double, 2>> ring;  // closed (first point not repeated); empty if unbounded or hidden
    long precision = 0;                       // Arb precision that met the tolerance
    std::size_t edges_in_doubles = 0, edges_by_nodes_in_arb = 0, edges_by_arb = 0;  // its integrals' stages (CellArea)
    std::size_t edges_from_neighbors = 0;  // integrated by a neighbour's cell for both (CellArea)
    QuadratureCounts quadrature;                         // CellArea's
    // Bounded cells: an upper bound (rounded up) of |x - c| over the points x
    // of the cell's boundary, c the site's center (for the periodic and the
    // tiled cells' certificates: docs/DESIGN.md §8, §10), from the areas'
    // quadrature, else from covers of the edges at the boundary tolerance;
    // +inf for unbounded or hidden cells.
    double reach = INFINITY;
};

struct CellTessellation {
    CellDomain domain;
    double boundary_tolerance = 0;  // the one actually used; 0 without rings
    // The plane: every Voronoi vertex, numbered as DelaunayGraph::faces(); a box or
    // a torus: the vertices of the cells (walls and corners included), in order of first use.
    std::vector<CellVertex> vertices;
    std::vector<Cell> cells;  // one per input site, in input order
    // How many times the mirrors (a box) or the copies (a torus) were made:
    // more than once when a cell reached past them.
    int attempts = 1;
    // The cells measured over all those tries: a try after the first
    // measures only the cells the earlier ones did not prove.
    std::size_t cells_measured = 0;
};

// Throws InputError for a tolerance outside (0, 1], a box with x0 >= x1 or
// y0 >= y1, a site not inside the box (box) or meeting one of its own
// periodic images (periodic), and for touching or crossing sites; Error if a
// cell cannot be certified within the precision limit.
CellTessellation cell_tessellation(const std::vector<Ellipse>& sites, const CellDomain& domain,
                                   const CellOptions& options = {});

}  // namespace ellvor
