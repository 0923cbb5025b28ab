#include "cells/cell_tessellation.hpp"

#include "cells/box_mirrors.hpp"
#include "cells/cell_area.hpp"
#include "cells/cell_chunks.hpp"
#include "cells/cell_vertex_angles.hpp"
#include "cells/face_numbers.hpp"
#include "cells/normal_ray_bisector.hpp"
#include "cells/periodic_copies.hpp"
#include "cells/voronoi_cells.hpp"
#include "cells/voronoi_edge_cover.hpp"
#include "graph/delaunay_graph.hpp"
#include "traits/ellipse_delaunay_traits.hpp"
#include "util/error.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <string>

namespace ellvor {
namespace {

// 1e-3 of the median larger semi-axis (the default boundary tolerance).
double default_boundary_tolerance(const std::vector<Ellipse>& sites) {
    if (sites.empty()) return 1e-3;
    std::vector<double> sizes;
    for (const Ellipse& e : sites) sizes.push_back(std::max(e.a().to_double(), e.b().to_double()));
    std::nth_element(sizes.begin(), sizes.begin() + static_cast<long>(sizes.size() / 2), sizes.end());
    return 1e-3 * sizes[sizes.size() / 2];
}

// The sites of a plane diagram whose first `originals` cells are wanted:
// the input sites, with mirrors (box) or periodic copies (torus) after them.
struct PlaneSites {
    std::vector<Ellipse> sites;
    std::size_t originals = 0;
    std::vector<SiteId> original;              // per site: the input site it copies
    std::vector<Wall> wall;                    // per site: the wall a mirror mirrors across; none otherwise
    std::vector<std::array<long, 2>> shift;    // per site: a periodic copy's shift in periods
};

PlaneSites plane_sites(const std::vector<Ellipse>& sites) {
    PlaneSites out;
    out.sites = sites;
    out.originals = sites.size();
    for (SiteId s = 0; s < sites.size(); ++s) out.original.push_back(s);
    out.wall.assign(sites.size(), Wall::none);
    out.shift.assign(sites.size(), {0, 0});
    return out;
}

PlaneSites plane_sites(const MirroredSites& m) {
    PlaneSites out;
    out.sites = m.sites;
    out.originals = m.originals;
    out.original = m.original;
    out.wall = m.wall;
    out.shift.assign(m.sites.size(), {0, 0});
    return out;
}

PlaneSites plane_sites(const PeriodicCopies& c) {
    PlaneSites out;
    out.sites = c.sites;
    out.originals = c.originals;
    out.original = c.original;
    out.wall.assign(c.sites.size(), Wall::none);
    out.shift = c.shift;
    return out;
}

std::unique_ptr<DelaunayGraph> built_graph(const std::vector<Ellipse>& sites) {
    auto graph = std::make_unique<DelaunayGraph>(std::make_unique<EllipseDelaunayTraits>(sites));
    graph->insert_all();
    return graph;
}

// The originals, the neighbours and the hosts of the wanted ones: each wanted
// original's cell among these is its cell among all (docs/DESIGN.md §5: a
// cell is its cell among its neighbours), and few of the others have a
// bounded cell to integrate. Originals keep their ids.
PlaneSites neighbourhood_of_originals(const PlaneSites& all, const std::vector<char>& wanted) {
    const std::unique_ptr<DelaunayGraph> graph = built_graph(all.sites);
    const std::vector<VoronoiCell> cells = voronoi_cells(*graph, face_numbers(*graph));
    std::vector<char> keep(all.sites.size(), 0);
    for (SiteId s = 0; s < all.originals; ++s) {
        keep[s] = 1;
        if (wanted[s])
            for (const CellEdge& e : cells[s].edges) keep[e.neighbor] = 1;
    }
    for (const auto& [hidden, host] : graph->hidden())
        if (hidden < all.originals && wanted[hidden]) keep[host] = 1;
    PlaneSites out;
    out.originals = all.originals;
    for (SiteId s = 0; s < all.sites.size(); ++s)
        if (keep[s]) {
            out.sites.push_back(all.sites[s]);
            out.original.push_back(all.original[s]);
            out.wall.push_back(all.wall[s]);
            out.shift.push_back(all.shift[s]);
        }
    return out;
}

// The covers of cells' edges (cells/voronoi_edge_cover.hpp): their rings and
// reach. A cell still to be covered (pending) takes the boxes of an edge its
// neighbour covered, backwards: each edge between two pending cells is covered
// once, along the angle of the first.
class CellCovers {
public:
    CellCovers(const PlaneSites& sites, const std::vector<VoronoiCell>& cells,
               std::shared_ptr<const CellVertexAngles::Faces> faces, const EdgeCoverOptions& cover)
        : sites_(sites), cells_(cells), angles_(std::move(faces), sites.sites), cover_(cover),
          // The vertices and their angles to 24 bits beyond the covers' radius
          // relative to the sites (cover.prec is 64 bits beyond it), at least
          // to the 44 bits the circles certified in doubles give
          // (cells/cell_vertex_angles.hpp): the covers need them well within
          // their radius (the angles' widths are the covers' overshoot).
          vertex_precision_(std::max(44L, cover.prec - 64 + 24) + 24),
          pending_(cells.size(), 0) {}

    void set_pending(SiteId s, bool pending) { pending_.at(s) = pending; }

    // The largest distance from the site's center to its bounded cell (an
    // upper bound, rounded up), by covering the cell's edges; their points
    // appended to `ring` when given.
    double cover(SiteId s, std::vector<std::array<double, 2>>* ring) {
        const VoronoiCell& cell = cells_[s];
        const Ellipse& site = sites_.sites[s];
        pending_[s] = 0;
        std::vector<Ball> lifted;
        double reach = 0;
        for (std::size_t k = 0; k < cell.edges.size(); ++k) {
            const CellEdge& e = cell.edges[k];
            if (sites_.wall[e.neighbor] != Wall::none) {
                // The wall is a straight side between two vertices: its first
                // vertex stands for it (the next side starts at the second),
                // and its farthest point from the center is one of them.
                if (ring) ring->push_back(vertex_point(e.from));
                for (long face : {e.from, e.to}) {
                    const BallPoint v = angles_.vertex(face, vertex_precision_);
                    reach = std::max(reach, distance_bound(EdgeCoverBox{v.x, v.y, {}}, site.xc(), site.yc(), cover_.prec));
                }
                continue;
            }
            // Along the neighbour's angle the edge runs from `to` to `from`.
            CoveredEdge edge;
            const auto shared = shared_.find({static_cast<long>(e.neighbor), static_cast<long>(s), e.to, e.from});
            if (shared != shared_.end()) {
                edge = std::move(shared->second);
                shared_.erase(shared);
                std::reverse(edge.boxes.begin(), edge.boxes.end());
                for (EdgeCoverBox& box : edge.boxes) std::reverse(box.points.begin(), box.points.end());
                std::reverse(edge.polyline.begin(), edge.polyline.end());
            } else {
                if (lifted.empty()) lifted = lifted_angles(cell);
                NormalRayBisector bisector(site, sites_.sites[e.neighbor]);
                edge.boxes = voronoi_edge_cover(bisector, lifted[k], lifted[k + 1], cover_);
                // Made once, so that both cells' rings have the same points along it.
                edge.polyline = simplified_polyline(edge.boxes, cover_.radius);
                if (pending_[e.neighbor])
                    shared_.emplace(std::array<long, 4>{static_cast<long>(s), static_cast<long>(e.neighbor), e.from, e.to},
                                    edge);
            }
            if (ring) ring->insert(ring->end(), edge.polyline.begin(), edge.polyline.end());
            for (const EdgeCoverBox& box : edge.boxes) {
                reach = std::max(reach, std::min(distance_bound(box, site.xc(), site.yc(), cover_.prec),
                                                 polyline_distance_bound(box, site)));
            }
        }
        return reach;
    }

private:
    // The cell's vertex angles (CellVertexAngles::lifted) at vertex_precision_,
    // or at the covers' when the ends of an edge to be covered are less than
    // a thousand times their radii apart (a very short edge: its end pieces
    // must hold the vertex balls). (A wall's sides are not covered: the
    // zero-length side between two mirrors' vertices had sent a third of a
    // box's cells to Arb, a tenth of a JSON run.)
    std::vector<Ball> lifted_angles(const VoronoiCell& cell) {
        std::vector<Ball> lifted = angles_.lifted(cell, vertex_precision_);
        for (std::size_t k = 0; k + 1 < lifted.size(); ++k) {
            if (sites_.wall[cell.edges[k].neighbor] != Wall::none) continue;
            const double gap = lifted[k + 1].mid_double() - lifted[k].mid_double();
            if (!(gap > 1024 * (lifted[k].radius_double() + lifted[k + 1].radius_double())))
                return angles_.lifted(cell, cover_.prec + 24);
        }
        return lifted;
    }

    // V(J) lies within the cover radius of the piece's polyline, whose
    // farthest point from the center is one of its points: often tighter than
    // the box V(J) (rounded up; +inf without points).
    double polyline_distance_bound(const EdgeCoverBox& box, const Ellipse& site) const {
        if (box.points.empty()) return INFINITY;
        // In double intervals (in Arb, with the center converted at each
        // point, this was a sixth of a JSON run).
        const Interval cx = enclose(site.xc()), cy = enclose(site.yc());
        double far = 0;
        for (const auto& q : box.points) {
            const double d = ((Interval(q[0]) - cx).square() + (Interval(q[1]) - cy).square()).sqrt().hi;
            if (std::isnan(d)) return INFINITY;
            far = std::max(far, d);
        }
        return std::nextafter(far + cover_.radius, INFINITY);
    }

    // A Voronoi vertex as a ring point within the cover radius of the true one
    // (at the covers' precision when vertex_precision_ is not enough: a vertex
    // far out).
    std::array<double, 2> vertex_point(long face) {
        for (long prec : {vertex_precision_, cover_.prec + 24}) {
            const BallPoint v = angles_.vertex(face, prec);
            if (std::hypot(v.x.radius_double(), v.y.radius_double()) <= cover_.radius / 2)
                return {v.x.mid_double(), v.y.mid_double()};
        }
        throw Error("cell_tessellation: a Voronoi vertex is not known to the ring's tolerance");
    }

    const PlaneSites& sites_;
    const std::vector<VoronoiCell>& cells_;
    CellVertexAngles angles_;
    EdgeCoverOptions cover_;
    long vertex_precision_;
    std::vector<char> pending_;
    // An edge's boxes (for the reach) and its ring points.
    struct CoveredEdge {
        std::vector<EdgeCoverBox> boxes;
        std::vector<std::array<double, 2>> polyline;
    };
    // By (covered cell, neighbour, from, to): an edge's cover until the neighbour takes it.
    std::map<std::array<long, 4>, CoveredEdge> shared_;
};

// The cells of the originals of a plane diagram: sides, vertices, rings, and
// for the torus the certificate; areas come after (cell_areas).
class OriginalCells {
public:
    // Edges are covered to boundary_tolerance: for the rings when `rings`,
    // else for the reach of the cells whose areas gave none.
    OriginalCells(const PlaneSites& sites, double boundary_tolerance, bool rings)
        : rings_(rings), sites_(sites), graph_(built_graph(sites.sites)),
          cells_(voronoi_cells(*graph_, face_numbers(*graph_))),
          faces_(std::make_shared<const CellVertexAngles::Faces>(graph_->faces())), angles_(faces_, sites_.sites) {
        double size = 0;
        for (const Ellipse& e : sites.sites) size = std::max(size, std::max(e.a().to_double(), e.b().to_double()));
        cover_.radius = boundary_tolerance / 2;
        cover_.prec = 64 + std::max(0L, static_cast<long>(std::ceil(std::log2(size / boundary_tolerance))));
    }

    const DelaunayGraph& graph() const { return *graph_; }
    const VoronoiCell& cell(SiteId s) const { return cells_[s]; }

    // Sides (neighbours as input ids, walls merged) and, with rings, the ring
    // and the cell's reach (+inf without, or unless bounded).
    void describe(SiteId s, Cell& out, std::map<long, long>& vertex_ids) {
        const VoronoiCell& cell = cells_[s];
        for (const CellEdge& e : cell.edges) {
            CellSide side;
            side.from = vertex_id(e.from, vertex_ids);
            side.to = vertex_id(e.to, vertex_ids);
            if (sites_.wall[e.neighbor] != Wall::none) {
                side.wall = sites_.wall[e.neighbor];
                // A side with another site's mirror has length 0 (docs/DESIGN.md §10):
                // it joins the wall side next to it.
                if (!out.sides.empty() && out.sides.back().wall == side.wall) {
                    out.sides.back().to = side.to;
                    continue;
                }
            } else {
                side.neighbor = static_cast<long>(sites_.original[e.neighbor]);
                side.shift = sites_.shift[e.neighbor];
            }
            out.sides.push_back(side);
        }
        if (out.sides.size() > 1 && out.sides.front().wall != Wall::none && out.sides.front().wall == out.sides.back().wall) {
            out.sides.front().from = out.sides.back().from;
            out.sides.pop_back();
        }
    }

    // The rings of the wanted bounded cells and their reach, in chunks along
    // a Hilbert curve (cells/cell_chunks.hpp) on `threads` threads: the same
    // rings whatever the threads.
    void rings(const std::vector<SiteId>& wanted, unsigned threads, std::size_t chunk, CellTessellation& out) {
        std::vector<SiteId> which;
        for (SiteId s : wanted)
            if (out.cells[s].bounded) which.push_back(s);
        for_each_chunk(hilbert_order(sites_.sites, std::move(which)), chunk, threads,
                       [&](const SiteId* begin, const SiteId* end) {
                           CellCovers covers(sites_, cells_, faces_, cover_);
                           for (const SiteId* s = begin; s != end; ++s) covers.set_pending(*s, true);
                           for (const SiteId* s = begin; s != end; ++s)
                               out.cells[*s].reach = covers.cover(*s, &out.cells[*s].ring);
                       });
    }

    // A bounded cell's reach by covering its edges (cells whose areas gave none).
    double reach(SiteId s) { return CellCovers(sites_, cells_, faces_, cover_).cover(s, nullptr); }

    // The vertices at precision prec (CellVertexAngles::vertex), or 8 bits
    // finer than the rings' tolerance relative to the sites' size when that
    // is finer (cover_.prec is 64 bits beyond those bits).
    std::vector<CellVertex> vertices(const std::map<long, long>& vertex_ids, long prec) {
        std::vector<CellVertex> out(vertex_ids.size());
        if (rings_) prec = std::max(prec, cover_.prec - 64 + 8 + 24);
        const CellVertexAngles::Faces& faces = *faces_;
        for (const auto& [face, id] : vertex_ids) {
            BallPoint v = angles_.vertex(face, prec);
            CellVertex& w = out[static_cast<std::size_t>(id)];
            w.x = v.x, w.y = v.y;
            for (int k = 0; k < 3; ++k) {
                const SiteId s = faces[static_cast<std::size_t>(face)][static_cast<std::size_t>(k)];
                w.face[static_cast<std::size_t>(k)] = {static_cast<long>(sites_.original[s]), sites_.wall[s], sites_.shift[s]};
            }
        }
        return out;
    }

private:
    static long vertex_id(long face, std::map<long, long>& ids) {
        if (face < 0) return -1;
        return ids.emplace(face, static_cast<long>(ids.size())).first->second;
    }

    bool rings_;
    const PlaneSites& sites_;
    std::unique_ptr<DelaunayGraph> graph_;
    std::vector<VoronoiCell> cells_;
    std::shared_ptr<const CellVertexAngles::Faces> faces_;
    CellVertexAngles angles_;
    EdgeCoverOptions cover_;
};

// A cell's measures into its description, from cell_areas' CellArea or
// from the cell's description in an earlier try (the same names); its reach
// the lesser of the two.
template <class Measures>
void take_measures(const Measures& a, Cell& c) {
    c.area = a.area;
    c.site_area = a.site_area;
    c.precision = a.precision;
    c.edges_in_doubles = a.edges_in_doubles;
    c.edges_by_nodes_in_arb = a.edges_by_nodes_in_arb;
    c.edges_by_arb = a.edges_by_arb;
    c.edges_from_neighbors = a.edges_from_neighbors;
    c.quadrature = a.quadrature;
    c.perimeter = a.perimeter;
    c.centroid = a.centroid;
    c.second_moments = a.second_moments;
    c.reach = std::min(c.reach, a.reach);
}

// The areas of the originals in `which` (the mirrors' and copies' are not
// wanted), by site.
std::vector<CellArea> measured_areas(const PlaneSites& sites, const DelaunayGraph& graph, const CellOptions& options,
                                     const std::vector<char>& which) {
    CellAreaOptions o;
    o.tolerance = options.tolerance;
    o.arb_integrator_only = options.arb_integrator_only;
    for (SiteId s = 0; s < sites.originals; ++s)
        if (which[s]) o.only.push_back(s);
    o.progress = options.progress;
    o.threads = options.threads;
    o.chunk = options.chunk;
    o.input_ids = sites.original;
    return cell_areas(graph, sites.sites, o);
}

// The cells of sites whose centers are near the origin (cell_tessellation moves them there).
CellTessellation cells_near_origin(const std::vector<Ellipse>& input, const CellDomain& domain,
                                   const CellOptions& options) {
    if (!(options.tolerance > 0 && options.tolerance <= 1))
        throw InputError("cells: the tolerance must be in (0, 1]");
    if (!(options.boundary_tolerance >= 0)) throw InputError("cells: the boundary tolerance must be positive");
    require_proper_rectangle(domain);
    CellTessellation out;
    out.domain = domain;
    const double boundary_tolerance =
        options.boundary_tolerance > 0 ? options.boundary_tolerance : default_boundary_tolerance(input);
    out.boundary_tolerance = options.rings ? boundary_tolerance : 0;

    std::vector<Ellipse> sites = input;
    if (domain.kind == CellDomain::Kind::periodic) {
        for (Ellipse& e : sites) e = wrap_into_box(e, domain);
        require_sites_fit_periodic_box(sites, domain);
    } else if (domain.kind == CellDomain::Kind::box) {
        require_sites_inside_box(sites, domain);
    }
    std::vector<char> wanted(sites.size(), options.only.empty() ? 1 : 0);
    for (SiteId s : options.only) {
        if (s >= sites.size()) throw InputError("cells: asked for the cell of site " + std::to_string(s) + " of " + std::to_string(sites.size()));
        wanted[s] = 1;
    }
    std::unique_ptr<PlaneSites> plane;
    std::unique_ptr<OriginalCells> cells;
    std::map<long, long> vertex_ids;
    auto describe_all = [&]() {
        std::vector<SiteId> originals;
        for (SiteId s = 0; s < plane->originals; ++s)
            if (wanted[s]) originals.push_back(s);
        require_followable_edges(cells->graph(), plane->sites, originals, plane->original);
        out.cells.assign(sites.size(), Cell{});
        vertex_ids.clear();
        // In the plane the vertices are the diagram's, numbered as DelaunayGraph::faces()
        // (the ridges, regions and JSON use those numbers); with mirrors or copies, those
        // of the originals' cells, numbered in order of first use.
        // (With `only`, in order of first use in the plane too.)
        if (domain.kind == CellDomain::Kind::plane && options.only.empty())
            for (long f = 0; f < static_cast<long>(cells->graph().faces().size()); ++f) vertex_ids.emplace(f, f);
        for (SiteId s = 0; s < sites.size(); ++s) {
            Cell& c = out.cells[s];
            c.site = s;
            if (!wanted[s]) continue;
            c.visible = cells->cell(s).visible;
            c.bounded = c.visible && cells->cell(s).bounded();
            cells->describe(s, c, vertex_ids);
            if (domain.kind != CellDomain::Kind::plane && c.visible && !c.bounded)
                throw Error("cell_tessellation: the cell of site " + std::to_string(s) + " in a box is unbounded");
        }
        if (options.rings) cells->rings(originals, options.threads, options.chunk, out);
    };
    // A visible cell proven in a try (its cell among the sites and the
    // mirrors or copies then is the box's or the torus's: docs/DESIGN.md §10)
    // is final: more mirrors or copies leave it as it is, so a later try
    // keeps its measures (and reach) and measures only the others.
    // (Kept aside only before a retry, which replaces out.cells, and behind
    // pointers: a Cell is half a kilobyte, an optional one a tenth of the
    // peak memory at 10^5 sites.)
    std::vector<std::unique_ptr<Cell>> final_cells(sites.size());
    const auto keep_final = [&](const std::vector<SiteId>& proven) {
        for (SiteId s : proven) final_cells[s] = std::make_unique<Cell>(std::move(out.cells[s]));
    };
    // The areas, and each bounded cell's reach: the areas' (or the rings',
    // the less), else by covering the cell's edges.
    auto measure_all = [&]() {
        std::vector<char> which(sites.size());
        for (SiteId s = 0; s < sites.size(); ++s) which[s] = wanted[s] && !final_cells[s];
        const std::vector<CellArea> areas = measured_areas(*plane, cells->graph(), options, which);
        for (SiteId s = 0; s < sites.size(); ++s) {
            if (!wanted[s]) continue;
            if (final_cells[s]) {
                take_measures(*final_cells[s], out.cells[s]);
                continue;
            }
            take_measures(areas[s], out.cells[s]);
            ++out.cells_measured;
            if (out.cells[s].bounded && std::isinf(out.cells[s].reach)) out.cells[s].reach = cells->reach(s);
        }
    };
    switch (domain.kind) {
        case CellDomain::Kind::plane:
            plane = std::make_unique<PlaneSites>(plane_sites(sites));
            cells = std::make_unique<OriginalCells>(*plane, boundary_tolerance, options.rings);
            describe_all();
            measure_all();
            break;
        case CellDomain::Kind::box: {
            // Mirrors across the walls near each site, a guess of where the
            // cells reach (four times the spacing of sites spread evenly:
            // twice made 10^4 random cells twice, for two cells); a wanted
            // cell that reaches a wall its site has no mirror across
            // (unbounded, or its reach, proven, not below the wall's distance)
            // gets its site's four mirrors, and the cells are made again; the
            // third try mirrors every site (docs/DESIGN.md §10). (Every site's
            // four mirrors made a five times larger diagram.)
            const double area = ((domain.x1 - domain.x0) * (domain.y1 - domain.y0)).to_double();
            std::vector<WallMirrors> across =
                walls_near(sites, domain, 4 * std::sqrt(area / static_cast<double>(std::max<std::size_t>(1, sites.size()))));
            for (out.attempts = 1;; ++out.attempts) {
                if (out.attempts == 3) across.assign(sites.size(), {true, true, true, true});
                PlaneSites mirrored = plane_sites(with_box_mirrors(sites, domain, across));
                plane = std::make_unique<PlaneSites>(options.only.empty() ? std::move(mirrored)
                                                                          : neighbourhood_of_originals(mirrored, wanted));
                cells = std::make_unique<OriginalCells>(*plane, boundary_tolerance, options.rings);
                const auto all_walls = [](const WallMirrors& w) { return w[0] && w[1] && w[2] && w[3]; };
                bool past_the_walls = false;
                for (SiteId s = 0; s < sites.size(); ++s)
                    if (wanted[s] && cells->cell(s).visible && !cells->cell(s).bounded() && !all_walls(across[s])) {
                        across[s] = {true, true, true, true};
                        past_the_walls = true;
                    }
                if (past_the_walls) continue;
                describe_all();
                measure_all();
                std::vector<SiteId> proven_now;
                for (SiteId s = 0; s < sites.size(); ++s) {
                    if (!wanted[s] || !out.cells[s].visible || final_cells[s]) continue;
                    bool proven = true;
                    for (int k = 0; k < 4; ++k)
                        proven = proven && (across[s][static_cast<std::size_t>(k)] ||
                                            out.cells[s].reach < distance_to_wall(sites[s], kWalls[k], domain));
                    if (proven) {
                        proven_now.push_back(s);
                    } else {
                        across[s] = {true, true, true, true};
                        past_the_walls = true;
                    }
                }
                if (!past_the_walls) break;
                keep_final(proven_now);
            }
            break;
        }
        case CellDomain::Kind::periodic: {
            Rational e_max(0);
            for (const Ellipse& e : sites) e_max = std::max({e_max, e.a(), e.b()});
            const long first = starting_rings(sites, domain);
            // Without rings the certificate needs only coarse covers (for
            // the cells whose areas give no reach): an eighth of the smaller
            // period.
            const double cover_tolerance =
                options.rings ? boundary_tolerance
                              : std::min((domain.x1 - domain.x0).to_double(), (domain.y1 - domain.y0).to_double()) / 8;
            // The copies: first those within four even spacings plus twice the
            // largest semi-axis of the box (as a box's mirrors; beyond it every
            // copy is apart from every site in the box), the margin doubled
            // while a cell is not proven; then whole rings of copies, each a
            // period farther out; a cell that still reaches the missing copies
            // after three rings more than the first is an Error. (Each try
            // measures the cells the earlier ones did not prove: the first
            // nearly always proves every cell. Whole rings from the start made
            // a graph of nine times the sites: a third of 10^4 packed cells.)
            const CopyMargin rings = ring_margin(domain, first);
            std::vector<CopyMargin> margins;
            const double spacing = std::sqrt((domain.x1 - domain.x0).to_double() * (domain.y1 - domain.y0).to_double() /
                                             static_cast<double>(std::max<std::size_t>(sites.size(), 1)));
            if (std::isfinite(spacing))  // (a box beyond the doubles' range: whole rings only)
                for (Rational d = Rational(2) * e_max + Rational::of_double(4 * spacing); d < std::min(rings[0], rings[1]);
                     d = Rational(2) * d)
                    margins.push_back({d, d});
            for (long k = first; k <= first + 3; ++k) margins.push_back(ring_margin(domain, k));
            for (std::size_t m = 0;; ++m) {
                out.attempts = static_cast<int>(m + 1);
                if (m == margins.size())
                    throw Error("cell_tessellation: the periodic cells could not be proven with " +
                                std::to_string(first + 3) + " rings of copies");
                // Cut down to the originals' neighbourhood (a graph more) only
                // where it pays: whole rings, or some cells wanted.
                PlaneSites copies = plane_sites(periodic_copies(sites, domain, margins[m]));
                plane = std::make_unique<PlaneSites>(options.only.empty() && copies.sites.size() < 2 * sites.size()
                                                         ? std::move(copies)
                                                         : neighbourhood_of_originals(copies, wanted));
                cells = std::make_unique<OriginalCells>(*plane, cover_tolerance, options.rings);
                describe_all();
                measure_all();
                bool proven = true;
                std::vector<SiteId> proven_now;
                for (SiteId s = 0; s < sites.size(); ++s) {
                    if (!wanted[s] || !out.cells[s].visible || final_cells[s]) continue;
                    if (periodic_cell_is_proven(out.cells[s].reach, sites[s],
                                                distance_to_missing_copies(sites[s], domain, margins[m]), e_max))
                        proven_now.push_back(s);
                    else
                        proven = false;
                }
                if (proven) break;
                keep_final(proven_now);
            }
            break;
        }
    }
    // The vertices to 12 bits beyond the tolerance's (as the areas' end
    // angles): at 1e-9 what the circles certified in doubles give.
    out.vertices = cells->vertices(vertex_ids, static_cast<long>(std::ceil(-std::log2(options.tolerance))) + 12 + 24);
    return out;
}

// The integer vector nearest the middle of the domain (the plane: of the
// sites' centers), or zero when a double could not hold it exactly.
std::array<long, 2> translation_to_origin(const std::vector<Ellipse>& sites, const CellDomain& domain) {
    double middle[2] = {0, 0};
    if (domain.kind != CellDomain::Kind::plane) {
        middle[0] = 0.5 * (domain.x0.to_double() + domain.x1.to_double());
        middle[1] = 0.5 * (domain.y0.to_double() + domain.y1.to_double());
    } else if (!sites.empty()) {
        double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
        for (const Ellipse& e : sites)
            for (int i = 0; i < 2; ++i) {
                const double c = (i == 0 ? e.xc() : e.yc()).to_double();
                lo[i] = std::min(lo[i], c), hi[i] = std::max(hi[i], c);
            }
        for (int i = 0; i < 2; ++i) middle[i] = 0.5 * (lo[i] + hi[i]);
    }
    std::array<long, 2> t = {0, 0};
    for (int i = 0; i < 2; ++i)
        if (std::fabs(middle[i]) < 0x1p50) t[i] = std::lround(middle[i]);
    return t;
}

std::string number(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", x);
    return text;
}

// Ring points (doubles) near coordinates of modulus `extent` are 2^-52 extent
// apart: the rings' tolerance must leave its free half for that rounding.
bool rings_fit_in_doubles(double extent, double boundary_tolerance) {
    return std::ldexp(extent, -52) <= 0.5 * boundary_tolerance;
}

// x + t for an integer t, in a ball that contains the exact sum.
void add_integer(Ball& x, long t) { arb_add_si(x.get(), x.get(), t, std::max(64L, arb_bits(x.get()) + 64)); }

}  // namespace

// The double stages certify in double intervals, whose roundings grow with
// the coordinates: sites of size 1 at 10^7 took 300 times as long as at the
// origin, their edges falling to Arb. So the cells are computed about the
// integer point nearest the domain's (or the centers') middle, an exact
// translation, and moved back: areas, perimeters, second moments and reaches
// do not move; vertices and centroids are balls plus an integer; a ring
// point is rounded once, by at most 2^-52 of its modulus, which must stay
// within the half of the boundary tolerance that the covers leave free (their
// radius is the other half).
CellTessellation cell_tessellation(const std::vector<Ellipse>& input, const CellDomain& domain,
                                   const CellOptions& options) {
    // The input errors that name coordinates, before the translation.
    require_proper_rectangle(domain);
    if (domain.kind == CellDomain::Kind::box) require_sites_inside_box(input, domain);
    if (options.rings && domain.kind != CellDomain::Kind::plane) {
        // The rings stay within the box (the torus: within a period of it).
        const double tolerance =
            options.boundary_tolerance > 0 ? options.boundary_tolerance : default_boundary_tolerance(input);
        const double x0 = domain.x0.to_double(), x1 = domain.x1.to_double(), y0 = domain.y0.to_double(),
                     y1 = domain.y1.to_double();
        const double extent = std::max({std::fabs(x0), std::fabs(x1), std::fabs(y0), std::fabs(y1)}) +
                              std::max(x1 - x0, y1 - y0);
        if (!rings_fit_in_doubles(extent, tolerance))
            throw InputError("cells: the boundary tolerance " + number(tolerance) +
                             (options.boundary_tolerance > 0 ? "" : " (the default, 1e-3 of the median site size)") +
                             " is finer than doubles can hold at coordinates near " + number(extent) +
                             " (at least " + number(std::ldexp(extent, -51)) + ")");
    }
    const std::array<long, 2> t = translation_to_origin(input, domain);
    if (t[0] == 0 && t[1] == 0) return cells_near_origin(input, domain, options);
    const Rational tx(t[0]), ty(t[1]);
    std::vector<Ellipse> sites;
    sites.reserve(input.size());
    for (const Ellipse& e : input) sites.emplace_back(e.a(), e.b(), e.w(), e.xc() - tx, e.yc() - ty);
    CellDomain moved = domain;
    moved.x0 = domain.x0 - tx, moved.x1 = domain.x1 - tx;
    moved.y0 = domain.y0 - ty, moved.y1 = domain.y1 - ty;
    CellTessellation out = cells_near_origin(sites, moved, options);
    out.domain = domain;
    for (CellVertex& v : out.vertices) add_integer(v.x, t[0]), add_integer(v.y, t[1]);
    for (Cell& c : out.cells) {
        if (arb_is_finite(c.centroid[0].get())) add_integer(c.centroid[0], t[0]), add_integer(c.centroid[1], t[1]);
        for (std::array<double, 2>& q : c.ring) {
            q[0] += static_cast<double>(t[0]), q[1] += static_cast<double>(t[1]);
            if (!rings_fit_in_doubles(std::max(std::fabs(q[0]), std::fabs(q[1])), out.boundary_tolerance))
                throw Error("cell_tessellation: a ring point at (" + number(q[0]) + ", " + number(q[1]) +
                            ") cannot be held in doubles within the boundary tolerance " +
                            number(out.boundary_tolerance));
        }
    }
    return out;
}

}  // namespace ellvor
