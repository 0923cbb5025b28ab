#include "cells/cell_area.hpp"

#include "cells/face_numbers.hpp"
#include "cells/normal_ray_bisector.hpp"
#include "predicates/relative_position.hpp"
#include "subdivision/voronoi_circle_enclosure.hpp"
#include "util/error.hpp"

#include <acb_calc.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

namespace ellvor {
namespace {

constexpr double kTwoPi = 6.28318530717958647692;

// Cells assume that every visible site lies in its own cell (docs/DESIGN.md
// §10): no two sites may touch or cross; nesting is fine (the inner site is
// hidden). A sweep over the bounding circles finds the candidate pairs.
void require_disjoint_or_nested(const std::vector<Ellipse>& sites) {
    struct Disk {
        double x, r;  // the center's abscissa and max(a, b), widened below
        SiteId id;
    };
    std::vector<Disk> disks;
    for (SiteId i = 0; i < sites.size(); ++i) {
        const EllipseShape e = EllipseShape::of(sites[i]);
        // The slack covers the rounding of x and r to doubles many times over;
        // the pairs it admits are decided by the proved test below.
        const double r = std::max(e.a, e.b);
        disks.push_back({e.xc, r + 1e-9 * (std::fabs(e.xc) + r), i});
    }
    std::sort(disks.begin(), disks.end(), [](const Disk& p, const Disk& q) { return p.x - p.r < q.x - q.r; });
    for (std::size_t i = 0; i < disks.size(); ++i)
        for (std::size_t j = i + 1; j < disks.size() && disks[j].x - disks[j].r <= disks[i].x + disks[i].r; ++j) {
            const Disk &p = disks[i], &q = disks[j];
            if (bounding_circles_apart_in_doubles(sites[p.id], sites[q.id])) continue;  // proved apart
            const SiteId a = std::min(p.id, q.id), b = std::max(p.id, q.id);
            const RelativePosition rp = *relative_position(sites[a], sites[b]);
            if (rp == RelativePosition::intersecting || rp == RelativePosition::externally_tangent)
                throw InputError("cells: sites " + std::to_string(a) + " and " + std::to_string(b) + " " +
                                     (rp == RelativePosition::intersecting ? "cross" : "touch") +
                                     "; cells of touching or crossing sites are not supported yet",
                                 InputError::SitePair{a, b});
        }
}

int area_density_function(acb_ptr out, const acb_t in, void* param, slong order, slong prec) {
    // order 0: a value; order 1: a value and proof of holomorphy on the ball,
    // which a successful certificate gives (cells/normal_ray_bisector.hpp).
    if (order > 1) {
        acb_indeterminate(out);
        return 0;
    }
    auto* bisector = static_cast<NormalRayBisector*>(param);
    ComplexBall theta, density;
    acb_set(theta.get(), in);
    bool ok = false;
    try {
        ok = bisector->area_density(theta, prec, density);
    } catch (...) {
        ok = false;  // nothing may cross Arb's C frames; an indeterminate value is always safe
    }
    if (ok)
        acb_set(out, density.get());
    else
        acb_indeterminate(out);
    return 0;
}

class CellAreaSolver {
public:
    CellAreaSolver(const DelaunayGraph& graph, const std::vector<Ellipse>& sites, double tolerance)
        : sites_(sites), faces_(graph.faces()), tolerance_(tolerance), solvers_(faces_.size()) {}

    // The area of a bounded cell at precision prec, or nothing when the pass
    // could not certify it within the tolerance.
    std::optional<Ball> area(const VoronoiCell& cell, long prec) {
        const Ellipse& site = sites_[cell.site];
        Ball total = site_area(site, prec);
        const std::size_t m = cell.edges.size();
        // Vertex angles, lifted so that they increase counter-clockwise
        // (docs/DESIGN.md §10: consecutive differences in [0, 2 pi), sum 2 pi).
        std::vector<Ball> lifted(m + 1);
        Ball two_pi;
        arb_const_pi(two_pi.get(), prec);
        arb_mul_2exp_si(two_pi.get(), two_pi.get(), 1);
        for (std::size_t k = 0; k < m; ++k)
            if (cell.edges[k].to != cell.edges[(k + 1) % m].from) throw Error("cell_areas: cell edges do not chain");
        lifted[0] = vertex_angle(cell.edges[0].from, cell.site, prec);
        for (std::size_t k = 0; k < m; ++k) {
            Ball next = vertex_angle(cell.edges[k].to, cell.site, prec);
            const double d = next.mid_double() - lifted[k].mid_double();
            const double eps = next.radius_double() + lifted[k].radius_double() + 1e-9;
            const double j = std::floor((d + eps) / kTwoPi);
            Ball shift;
            arb_mul_si(shift.get(), two_pi.get(), static_cast<slong>(j), prec);
            arb_sub(lifted[k + 1].get(), next.get(), shift.get(), prec);
        }
        // The lifts telescope to the first angle plus 2 pi times an integer,
        // which must be one turn (then each difference is its true value).
        if (std::lround((lifted[m].mid_double() - lifted[0].mid_double()) / kTwoPi) != 1)
            throw Error("cell_areas: the vertex angles of cell " + std::to_string(cell.site) + " do not make one turn");

        const long goal = static_cast<long>(std::ceil(-std::log2(tolerance_))) + 10;
        Mag tol;
        // Arb holds each subinterval to the absolute tolerance (or the relative
        // goal): a few hundred of them must still add up to far below T * area,
        // and the area is at least the site's, pi a b.
        mag_set_d(tol.get(), std::ldexp(tolerance_ * total.mid_double() / static_cast<double>(m), -16));
        acb_calc_integrate_opt_t options;
        acb_calc_integrate_opt_init(options);
        for (std::size_t k = 0; k < m; ++k) {
            NormalRayBisector bisector(site, sites_[cell.edges[k].neighbor]);
            ComplexBall a, b, integral;
            arb_get_mid_arb(a.real(), lifted[k].get());
            arb_get_mid_arb(b.real(), lifted[k + 1].get());
            acb_calc_integrate(integral.get(), area_density_function, &bisector, a.get(), b.get(), goal, tol.get(),
                               options, prec);
            if (!arb_is_finite(integral.real())) return std::nullopt;
            arb_add(total.get(), total.get(), integral.real(), prec);
            // The pieces between the certified end angles and their midpoints:
            // at most the radius times a bound of the density on the ball.
            for (const Ball* end : {&lifted[k], &lifted[k + 1]}) {
                ComplexBall theta(*end), density;
                if (!bisector.area_density(theta, prec, density)) return std::nullopt;
                Mag bound, radius;
                acb_get_mag(bound.get(), density.get());
                mag_set(radius.get(), arb_radref(end->get()));
                mag_mul(bound.get(), bound.get(), radius.get());
                arb_add_error_mag(total.get(), bound.get());
            }
        }
        Arf lo, width;
        arb_get_lbound_arf(lo.get(), total.get(), prec);
        arf_set_mag(width.get(), arb_radref(total.get()));
        const double w = 2 * arf_get_d(width.get(), ARF_RND_UP), l = arf_get_d(lo.get(), ARF_RND_DOWN);
        if (!(l > 0) || !(w <= tolerance_ * l)) return std::nullopt;
        return total;
    }

    static Ball site_area(const Ellipse& e, long prec) {
        Ball area, a(e.a(), prec), b(e.b(), prec);
        arb_const_pi(area.get(), prec);
        arb_mul(area.get(), area.get(), a.get(), prec);
        arb_mul(area.get(), area.get(), b.get(), prec);
        return area;
    }

private:
    // The tangency angle on `site` of the Voronoi circle of face `face`, its
    // radius about 2^(24 - prec) (the certified circle refined to prec - 24 bits).
    Ball vertex_angle(long face, SiteId site, long prec) {
        const auto f = static_cast<std::size_t>(face);
        if (!solvers_[f]) solvers_[f] = std::make_unique<VoronoiCircleSolver>(sites_[faces_[f][0]], sites_[faces_[f][1]], sites_[faces_[f][2]]);
        VoronoiCircleSolver& solver = *solvers_[f];
        solver.refine_existing(prec - 24);
        const VoronoiCircleEnclosure& c = solver.enclosure();
        const int i = static_cast<int>(std::find(faces_[f].begin(), faces_[f].end(), site) - faces_[f].begin());
        if (i == 3) throw Error("cell_areas: a cell's vertex misses its site");
        // theta = 2 atan(t), or pi + 2 atan(u) in the flipped chart u = -1/t.
        Ball theta;
        arb_atan(theta.get(), c.parameter[i].get(), prec);
        arb_mul_2exp_si(theta.get(), theta.get(), 1);
        if (c.flipped[i]) {
            Ball pi;
            arb_const_pi(pi.get(), prec);
            arb_add(theta.get(), theta.get(), pi.get(), prec);
        }
        solver.release_charts();
        return theta;
    }

    const std::vector<Ellipse>& sites_;
    std::vector<std::array<SiteId, 3>> faces_;
    double tolerance_;
    std::vector<std::unique_ptr<VoronoiCircleSolver>> solvers_;
};

}  // namespace

long cell_area_precision(double tolerance) { return 64 + static_cast<long>(std::ceil(-std::log2(tolerance))); }

std::vector<CellArea> cell_areas(const DelaunayGraph& graph, const std::vector<Ellipse>& sites,
                                 const CellAreaOptions& options) {
    const double T = options.tolerance;
    if (!(T > 0 && T <= 1)) throw InputError("cell_areas: the tolerance must be in (0, 1]");
    require_disjoint_or_nested(sites);
    const std::vector<VoronoiCell> cells = voronoi_cells(graph, face_numbers(graph));
    CellAreaSolver solver(graph, sites, T);
    std::vector<CellArea> out(cells.size());
    const long start = cell_area_precision(T);
    for (const VoronoiCell& cell : cells) {
        CellArea& r = out[cell.site];
        r.site = cell.site;
        r.visible = cell.visible;
        r.bounded = cell.bounded();
        r.site_area = CellAreaSolver::site_area(sites[cell.site], start);
        if (!cell.visible) {
            arb_zero(r.area.get());
            continue;
        }
        if (!r.bounded) {
            arb_pos_inf(r.area.get());
            continue;
        }
        // Each pass doubles the precision: the vertex angles, the certificates
        // and the quadrature all tighten with it.
        for (long prec = start; !r.precision; prec *= 2) {
            if (prec > 16 * start)
                throw Error("cell_areas: the area of cell " + std::to_string(cell.site) +
                            " could not be certified to the tolerance below " + std::to_string(prec / 2) + " bits");
            if (std::optional<Ball> area = solver.area(cell, prec)) {
                r.area = *area;
                r.precision = prec;
            }
        }
    }
    return out;
}

}  // namespace ellvor
