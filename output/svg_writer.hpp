// An SVG drawing of the Voronoi diagram of ellipses (floating point, for the
// eye only): the sites (hidden ones dashed and grey), optionally their ids,
// the Delaunay edges (thin, light, between the centers), the Voronoi vertices
// (dots at the certified centers of the Voronoi circles) and every Voronoi
// edge as a traced bisector arc (output/bisector_trace.hpp), one <path> each;
// unbounded edges are clipped to the drawing box. Where two visible sites
// cross, their common part (the lens) is shaded translucently, one later site
// clipped to the earlier one per pair (so a part covered by more sites is
// darker). A title and a legend with the counts. World y points up (flipped
// by the group's transform). With cells (SvgOptions::cells), each bounded
// cell is filled on a colour scale by the midpoint of its certified packing
// fraction (for the eye; the tables give the intervals), with a colour bar in
// the legend; cells without rings (not computed by the library yet) colour
// their sites instead, and the legend says so.
//
// Tolerance: consecutive points of an arc are closer than
// tolerance_fraction (default 0.5%) of the drawing box's larger side; each
// point is equidistant from its two sites up to the floating-point root
// solve (about 1e-12 relative), far below that. The SVG states it in a
// comment and in the legend.
#pragma once

#include "cells/cell_tessellation.hpp"
#include "output/bisector_trace.hpp"
#include "graph/delaunay_graph.hpp"

#include <ostream>
#include <string>
#include <vector>

namespace ellvor {

struct SvgOptions {
    bool show_ids = false;            // write each site's id at its center
    double tolerance_fraction = 0.005;
    double margin_fraction = 0.08;    // of the sites' bounding box's larger side
    double pixels = 900;              // size in pixels of the box's larger side
    std::string title;                // "" = "Voronoi diagram of N ellipses"
    const CellTessellation* cells = nullptr;  // colour the cells by packing fraction (the same sites)
};

// Renders an already traced diagram.
void render_svg(std::ostream& out, const DelaunayGraph& graph, const std::vector<Ellipse>& sites,
                const TracedDiagram& diagram, const SvgOptions& options);

// Traces the diagram and renders it; returns what was traced (for counts).
TracedDiagram write_svg(std::ostream& out, const DelaunayGraph& graph, const std::vector<Ellipse>& sites,
                        const SvgOptions& options);

}  // namespace ellvor
