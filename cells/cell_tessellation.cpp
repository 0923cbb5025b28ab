#include "cells/cell_tessellation.hpp"

#include "cells/cell_area.hpp"
#include "cells/face_numbers.hpp"
#include "cells/voronoi_cells.hpp"
#include "graph/delaunay_graph.hpp"
#include "subdivision/voronoi_circle_enclosure.hpp"
#include "traits/ellipse_delaunay_traits.hpp"
#include "util/error.hpp"

#include <algorithm>
#include <memory>

namespace ellvor {

const char* wall_name(Wall w) {
    switch (w) {
        case Wall::left: return "left";
        case Wall::bottom: return "bottom";
        case Wall::right: return "right";
        case Wall::top: return "top";
        case Wall::none: break;
    }
    return "";
}

namespace {

// 1e-3 of the median larger semi-axis (the default boundary tolerance).
double default_boundary_tolerance(const std::vector<Ellipse>& sites) {
    if (sites.empty()) return 1e-3;
    std::vector<double> sizes;
    for (const Ellipse& e : sites) sizes.push_back(std::max(e.a().to_double(), e.b().to_double()));
    std::nth_element(sizes.begin(), sizes.begin() + static_cast<long>(sizes.size() / 2), sizes.end());
    return 1e-3 * sizes[sizes.size() / 2];
}

}  // namespace

CellTessellation cell_tessellation(const std::vector<Ellipse>& sites, const CellDomain& domain,
                                   const CellOptions& options) {
    if (!(options.tolerance > 0 && options.tolerance <= 1))
        throw InputError("cells: the tolerance must be in (0, 1]");
    if (!(options.boundary_tolerance >= 0)) throw InputError("cells: the boundary tolerance must be positive");
    if (domain.kind != CellDomain::Kind::plane) throw Error("cells: boxes are not implemented yet");
    CellTessellation out;
    out.domain = domain;
    out.boundary_tolerance =
        options.boundary_tolerance > 0 ? options.boundary_tolerance : default_boundary_tolerance(sites);

    DelaunayGraph graph(std::make_unique<EllipseDelaunayTraits>(sites));
    graph.insert_all();
    const std::vector<long> numbers = face_numbers(graph);
    const std::vector<VoronoiCell> cells = voronoi_cells(graph, numbers);
    const std::vector<CellArea> areas = cell_areas(graph, sites, {options.tolerance, {}, options.progress});

    const long prec = cell_area_precision(options.tolerance);
    for (const auto& f : graph.faces()) {
        // The vertices to the precision of the areas' end angles (cell_area.cpp).
        VoronoiCircleSolver solver(sites[f[0]], sites[f[1]], sites[f[2]]);
        solver.refine_existing(prec - 24);
        out.vertices.push_back({solver.enclosure().center_x, solver.enclosure().center_y});
    }
    out.cells.resize(sites.size());
    for (SiteId s = 0; s < sites.size(); ++s) {
        Cell& c = out.cells[s];
        c.site = s;
        c.visible = cells[s].visible;
        c.bounded = cells[s].visible && cells[s].bounded();
        c.area = areas[s].area;
        c.site_area = areas[s].site_area;
        c.precision = areas[s].precision;
        c.perimeter = areas[s].perimeter;
        c.centroid = areas[s].centroid;
        c.second_moments = areas[s].second_moments;
        for (const CellEdge& e : cells[s].edges) c.sides.push_back({static_cast<long>(e.neighbor), Wall::none, {0, 0}, e.from, e.to});
    }
    return out;
}

}  // namespace ellvor
