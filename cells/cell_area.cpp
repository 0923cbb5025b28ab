#include "cells/cell_area.hpp"

#include "cells/cell_chunks.hpp"
#include "cells/cell_vertex_angles.hpp"
#include "cells/edge_integrals.hpp"
#include "cells/edge_quadrature.hpp"
#include "cells/face_numbers.hpp"
#include "cells/normal_ray_bisector.hpp"
#include "cells/normal_ray_in_doubles.hpp"
#include "util/error.hpp"

#include <acb_calc.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <mutex>
#include <map>
#include <memory>
#include <optional>
#include <string>

namespace ellvor {
namespace {

constexpr double kTwoPi = 6.28318530717958647692;

// A double interval as a real ball.
ComplexBall to_ball(const Interval& x) {
    ComplexBall z;
    arb_set(z.real(), ball_of(x, 64).get());
    return z;
}

NormalRayBisector::Densities as_balls(const MeasureIntervals& I) {
    NormalRayBisector::Densities d;
    for (int j = 0; j < EdgeMeasure::count; ++j) d.m[j] = to_ball(I.m[j]);
    return d;
}

// Measure j (EdgeMeasure) is scaled by L^-kLengthPower[j] to area units (L
// the cell's length unit, about the square root of its area), so that one
// absolute tolerance serves every measure.
constexpr int kLengthPower[EdgeMeasure::count] = {0, 0, -1, 1, 1, 1, 2, 2, 2};
// Arb's integrator takes the measures in pairs f + i g, both real on the
// reals, so that the real and imaginary parts of the integral enclose the
// two integrals (-1: none).
constexpr int kMeasurePairs = 5;
constexpr int kPairs[kMeasurePairs][2] = {{EdgeMeasure::x_dy, EdgeMeasure::y_dx},
                                          {EdgeMeasure::x2_dy, EdgeMeasure::y2_dx},
                                          {EdgeMeasure::x3_dy, EdgeMeasure::y3_dx},
                                          {EdgeMeasure::x2y_dy, EdgeMeasure::xy_dy},
                                          {EdgeMeasure::length, -1}};

class DensityCache;

// The integrand of one pair of measures on one edge (kPairs), in area units.
struct EdgeIntegrand {
    NormalRayBisector* bisector;
    // Values at points (order 0) need only the goal's bits, not the working
    // precision of the holomorphy certificates on balls: a second solver at
    // point_precision spares the longer limbs.
    NormalRayBisector* point_bisector;
    long point_precision;
    int pair;          // kPairs
    long length_unit;  // L = 2^length_unit (exact scaling)
    DensityCache* cache;
};

// Arb evaluates the five pairs on mostly the same balls: the densities of
// each ball are kept for the next pair, found by the ball's midpoint and radii
// rounded to doubles and the precision, and used only for the very ball they
// were computed on (acb_equal): a rounded key can cost a recomputation, never
// a wrong value. At most kMaxEntries balls are kept (an edge Arb struggles on
// evaluates millions: unbounded, the cache took gigabytes); the others are
// computed in a scratch slot.
class DensityCache {
public:
    using Densities = std::optional<NormalRayBisector::Densities>;
    // The slot for `z`, and whether it must be (re)computed.
    std::pair<Densities*, bool> find(const acb_t z, slong prec) {
        const std::array<double, 5> key = {arf_get_d(arb_midref(acb_realref(z)), ARF_RND_NEAR),
                                           arf_get_d(arb_midref(acb_imagref(z)), ARF_RND_NEAR),
                                           mag_get_d(arb_radref(acb_realref(z))),
                                           mag_get_d(arb_radref(acb_imagref(z))), static_cast<double>(prec)};
        auto it = entries_.find(key);
        if (it == entries_.end()) {
            if (entries_.size() >= kMaxEntries) {
                scratch_.reset();
                return {&scratch_, true};
            }
            it = entries_.try_emplace(key).first;
        } else if (acb_equal(it->second.ball.get(), z)) {
            return {&it->second.densities, false};
        }
        Entry& e = it->second;
        acb_set(e.ball.get(), z);
        e.densities.reset();
        return {&e.densities, true};
    }

private:
    static constexpr std::size_t kMaxEntries = 1 << 15;  // some 30 MB at 128 bits
    struct Entry {
        ComplexBall ball;
        Densities densities;
    };
    std::map<std::array<double, 5>, Entry> entries_;
    Densities scratch_;
};

// f + i g of the pair from the densities (scaled as above).
void pair_value(const NormalRayBisector::Densities& d, int pair, long unit, slong prec, acb_t out) {
    ComplexBall f, g;
    const int j = kPairs[pair][0], k = kPairs[pair][1];
    acb_mul_2exp_si(f.get(), d.m[j].get(), -kLengthPower[j] * unit);
    if (k >= 0) {
        acb_mul_2exp_si(g.get(), d.m[k].get(), -kLengthPower[k] * unit);
        acb_mul_onei(g.get(), g.get());
    }
    acb_add(out, f.get(), g.get(), prec);
}

int edge_integrand(acb_ptr out, const acb_t in, void* param, slong order, slong prec) {
    // order 0: a value; order 1: a value and proof of holomorphy on the ball,
    // which a successful certificate gives (cells/normal_ray_bisector.hpp).
    if (order > 1) {
        acb_indeterminate(out);
        return 0;
    }
    auto* e = static_cast<EdgeIntegrand*>(param);
    try {
        auto [slot, fresh] = e->cache->find(in, prec);
        if (fresh) {
            ComplexBall theta;
            acb_set(theta.get(), in);
            NormalRayBisector::Densities d;
            const bool point = order == 0 && e->point_precision < prec;
            NormalRayBisector* bisector = point ? e->point_bisector : e->bisector;
            if (bisector->densities(theta, point ? e->point_precision : prec, d)) *slot = std::move(d);
        }
        if (*slot)
            pair_value(**slot, e->pair, e->length_unit, prec, out);
        else
            acb_indeterminate(out);
    } catch (...) {
        acb_indeterminate(out);  // nothing may cross Arb's C frames; an indeterminate value is always safe
    }
    return 0;
}

// The goals (bits) that the double-interval stage serves.
constexpr long kDoubleGoalBits = 44;

// Moves the ball's middle to the nearest double and widens it to still
// contain the ball; returns that double.
double centre_on_double(Ball& end) {
    const double c = arf_get_d(arb_midref(end.get()), ARF_RND_NEAR);
    Ball centre, difference;
    arb_set_d(centre.get(), c);
    arb_sub(difference.get(), end.get(), centre.get(), 64);
    Mag radius;
    arb_get_mag(radius.get(), difference.get());
    arb_set(end.get(), centre.get());
    mag_set(arb_radref(end.get()), radius.get());
    return c;
}

// Does p's normal line reach the bisector of p and q all along the angles
// [a, b] (floating point, 33 samples)? Where the edge of sites that meet runs
// through p's medial axis it does not (docs/DESIGN.md §10). A sample, not a
// proof: it only refuses early what the certificate would fail on.
bool normal_line_reaches(const Ellipse& p, const Ellipse& q, double a, double b) {
    const EllipseShape ps = EllipseShape::of(p), qs = EllipseShape::of(q);
    for (int i = 0; i <= 32; ++i)
        if (!equal_distance_on_normal(ps, qs, a + (b - a) * i / 32, INFINITY)) return false;
    return true;
}

// The edge k of a cell whose neighbour meets its site: an InputError naming
// both (as input ids) when the edge runs through either site's medial axis,
// seen from either side (normal_line_reaches).
void require_normal_lines_reach(const std::vector<Ellipse>& sites, const VoronoiCell& cell, std::size_t k,
                                const std::vector<Ball>& lifted, CellVertexAngles& angles,
                                const std::vector<SiteId>& input_ids, long prec) {
    const SiteId p = cell.site, q = cell.edges[k].neighbor;
    // Around q the edge runs from `to` to `from`.
    const double phi_lo = angles.angle(cell.edges[k].to, q, prec).mid_double();
    double phi_hi = angles.angle(cell.edges[k].from, q, prec).mid_double();
    phi_hi -= kTwoPi * std::floor((phi_hi - phi_lo + 1e-9) / kTwoPi);
    if (normal_line_reaches(sites[p], sites[q], lifted[k].mid_double(), lifted[k + 1].mid_double()) &&
        normal_line_reaches(sites[q], sites[p], phi_lo, phi_hi))
        return;
    const SiteId a = input_ids.empty() ? p : input_ids[p], b = input_ids.empty() ? q : input_ids[q];
    throw InputError("cells: sites " + std::to_string(std::min(a, b)) + " and " + std::to_string(std::max(a, b)) +
                         " cross so deeply that their Voronoi edge runs through a site's medial axis; cells of such "
                         "crossings are not supported",
                     InputError::SitePair{std::min(a, b), std::max(a, b)});
}

// What the first pass of a cell needs to know before it integrates: whether
// a neighbour meets the site, and the scale of its area (the site's, unless a
// neighbour meets it, or half an estimate of the cell's if larger).
struct FirstPassScale {
    bool meets = false;
    double area_floor = 0;
};

class CellAreaSolver {
public:
    CellAreaSolver(std::shared_ptr<const CellVertexAngles::Faces> faces, const std::vector<Ellipse>& sites,
                   const std::vector<VoronoiCell>& cells, double tolerance, bool arb_integrator_only)
        : sites_(sites),
          cells_(cells),
          tolerance_(tolerance),
          arb_integrator_only_(arb_integrator_only),
          angles_(std::move(faces), sites),
          scales_(cells.size()),
          pending_(cells.size(), 0) {}

    // The cells still to be measured: the first pass of each integrates its
    // edges with those once for both (see measure()).
    void set_pending(SiteId s, bool pending) { pending_.at(s) = pending; }

    // The measures of a bounded cell at precision prec, or nothing when the
    // pass could not certify its area within the tolerance. Pass k asks Arb
    // for 6k more bits than the first.
    std::optional<CellArea> measure(const VoronoiCell& cell, long prec, int pass) {
        const Ellipse& site = sites_[cell.site];
        CellArea r;
        r.site_area = site_area(site, prec);
        const std::size_t m = cell.edges.size();
        const Goal goal = goal_of(pass);
        std::vector<Ball> lifted = lifted_angles(cell, goal, prec);
        const FirstPassScale& first = first_pass_scale(cell.site);
        // The scale of the tolerances and the length unit: the first pass's,
        // then the site's unless a neighbour meets it (the final check below,
        // not the estimate, decides).
        double area_floor = first.area_floor;
        if (pass > 0 && !first.meets) area_floor = r.site_area.mid_double();
        if (pass > 0 && first.meets) area_floor = std::max(0.0, 0.5 * estimated_area(cell, lifted));
        if (!(area_floor > 0)) area_floor = r.site_area.mid_double();
        const long unit = std::lround(0.5 * std::log2(area_floor));  // L = 2^unit, about sqrt(area)
        const double edge_tolerance = edge_area_tolerance(area_floor, m, pass);

        CellIntegrals sums;
        const BallPoint center{Ball(site.xc(), prec), Ball(site.yc(), prec)};
        double reach = 0;
        for (std::size_t k = 0; k < m; ++k) {
            const CellEdge& e = cell.edges[k];
            // The first pass takes an edge its neighbour integrated for both
            // (along the neighbour's angle, the edge runs from `to` to `from`).
            if (pass == 0) {
                const auto shared = shared_.find(edge_key(e.neighbor, cell.site, e.to, e.from));
                if (shared != shared_.end()) {
                    add_edge(shared->second.integrals, false, center, prec, sums);
                    reach = std::max(reach, shared->second.neighbor_reach);
                    ++r.edges_from_neighbors;
                    shared_.erase(shared);
                    continue;
                }
            }
            // The neighbour's first pass can take this edge when its cell is
            // still to be measured: integrated to the tighter of the two
            // cells' tolerances.
            const bool share = pass == 0 && pending_[e.neighbor];
            double tolerance = edge_tolerance;
            if (share) {
                const FirstPassScale& other = first_pass_scale(e.neighbor);
                tolerance = std::min(tolerance, edge_area_tolerance(other.area_floor,
                                                                    cells_[e.neighbor].edges.size(), 0));
            }
            EdgeIntegrals integrals;
            std::array<double, 2> edge_reach = {0, 0};
            if (!integrate_edge_of_cell(cell, k, lifted, goal, tolerance, unit, prec, r, integrals, edge_reach))
                return std::nullopt;
            add_edge(integrals, true, center, prec, sums);
            reach = std::max(reach, edge_reach[0]);
            if (share)
                shared_.emplace(edge_key(cell.site, e.neighbor, e.from, e.to),
                                SharedEdge{std::move(integrals), edge_reach[1]});
        }
        r.area = sums.area;
        Arf lo, width;
        arb_get_lbound_arf(lo.get(), r.area.get(), prec);
        arf_set_mag(width.get(), arb_radref(r.area.get()));
        const double w = 2 * arf_get_d(width.get(), ARF_RND_UP), l = arf_get_d(lo.get(), ARF_RND_DOWN);
        if (!(l > 0) || !(w <= tolerance_ * l)) return std::nullopt;
        finish_moments(center, sums, prec, r);
        r.reach = reach;
        return r;
    }

    static Ball site_area(const Ellipse& e, long prec) {
        Ball area, a(e.a(), prec), b(e.b(), prec);
        arb_const_pi(area.get(), prec);
        arb_mul(area.get(), area.get(), a.get(), prec);
        arb_mul(area.get(), area.get(), b.get(), prec);
        return area;
    }

private:
    // The bits a pass asks of its integrals, and the stage that serves them.
    struct Goal {
        long bits;
        // Below 45 bits the edges go to the double-interval quadrature first,
        // beyond to its pieces with the nodes in Arb; Arb's integrator takes
        // what they cannot certify.
        bool in_doubles, nodes_in_arb;
    };
    Goal goal_of(int pass) const {
        const long bits = static_cast<long>(std::ceil(-std::log2(tolerance_))) + 4 + 6 * pass;
        const bool in_doubles = !arb_integrator_only_ && bits <= kDoubleGoalBits;
        return {bits, in_doubles, !arb_integrator_only_ && !in_doubles};
    }

    // Per edge half the area tolerance's share: with the ends' terms the
    // area's width stays well below T * area (at most 0.24 T on 10^4
    // random, packed and circle cells at 1e-9, 0.18 T at 1e-15; an eighth
    // cost 2-3% more instructions, for widths of 0.05 T).
    double edge_area_tolerance(double area_floor, std::size_t edges, int pass) const {
        return std::ldexp(tolerance_ * area_floor / static_cast<double>(edges), -1 - 6 * pass);
    }

    // The cell's vertex angles, lifted (cells/cell_vertex_angles.hpp).
    std::vector<Ball> lifted_angles(const VoronoiCell& cell, const Goal& goal, long prec) {
        // The double quadrature reads the ends as doubles and adds their
        // radii times the density: goal + 8 bits of angle leave those terms
        // far below the tolerance (the circles certified in doubles give
        // them); the other stages take the angles at the working precision.
        // (A zero-length edge, four cocircular sites as at a wall's mirror
        // images, may get ends a rounding apart in either order: the
        // quadrature takes them reversed.)
        return angles_.lifted(cell, goal.in_doubles ? goal.bits + 8 + 24 : prec);
    }

    const FirstPassScale& first_pass_scale(SiteId s) {
        std::optional<FirstPassScale>& scale = scales_[s];
        if (scale) return *scale;
        const VoronoiCell& cell = cells_[s];
        const Ellipse& site = sites_[s];
        FirstPassScale f;
        for (const CellEdge& e : cell.edges)
            f.meets = f.meets || (NormalRayBisector::uses_signed_tie(site, sites_[e.neighbor]) &&
                                  NormalRayBisector::meet(site, sites_[e.neighbor]));
        const double own = site_area(site, 64).mid_double();
        f.area_floor = std::max(f.meets ? 0.0 : own, 0.5 * vertex_polygon_area(cell));
        if (!(f.area_floor > 0)) f.area_floor = own;
        scale = f;
        return *scale;
    }

    // The integrals of the cell's edge k along the site's angle, about the
    // middle of its vertices, between its true vertices; false when the last
    // stage fails on the area. `reach` gets upper bounds of the distance of
    // the edge from the site's and the neighbour's centers (+inf when Arb's
    // integrator, which gives none, took the edge).
    bool integrate_edge_of_cell(const VoronoiCell& cell, std::size_t k, const std::vector<Ball>& lifted,
                                const Goal& goal, double area_tolerance, long unit, long prec, CellArea& r,
                                EdgeIntegrals& out, std::array<double, 2>& reach) {
        const Ellipse& site = sites_[cell.site];
        const CellEdge& e = cell.edges[k];
        const long vertex_prec = goal.in_doubles ? goal.bits + 8 + 24 : prec;
        out.start = angles_.vertex(e.from, vertex_prec);
        out.end = angles_.vertex(e.to, vertex_prec);
        for (int i = 0; i < 2; ++i) {
            const Ball& a = i == 0 ? out.start.x : out.start.y;
            const Ball& b = i == 0 ? out.end.x : out.end.y;
            out.origin[i] = 0.5 * (a.mid_double() + b.mid_double());
        }
        NormalRayBisector bisector(site, sites_[e.neighbor]);
        NormalRayInDoubles bisector_in_doubles(site, sites_[e.neighbor], bisector.signed_tie());
        bisector.set_origin(out.origin[0], out.origin[1]);
        bisector_in_doubles.set_origin(out.origin[0], out.origin[1]);
        bisector_in_doubles.start_near(lifted[k].mid_double(), out.start.x.mid_double(), out.start.y.mid_double());
        Ball ends[2] = {lifted[k], lifted[k + 1]};
        double tolerances[EdgeMeasure::count];
        // The perimeter, about 4 L, at the area's relative accuracy: 4 L times
        // the area tolerance over L^2. (It decided the rule size on nearly
        // every piece at L; 2% fewer instructions.)
        for (int j = 0; j < EdgeMeasure::count; ++j)
            tolerances[j] = std::ldexp(area_tolerance, static_cast<int>(kLengthPower[j] * unit) +
                                                           (j == EdgeMeasure::length ? 2 : 0));
        bool integrated = false;
        reach = {0, 0};
        if (goal.in_doubles) {
            const double a = centre_on_double(ends[0]), b = centre_on_double(ends[1]);
            if (const std::optional<MeasureIntervals> I =
                    integrate_edge(bisector_in_doubles, rules_, a, b, tolerances, &r.quadrature, &reach)) {
                for (int j = 0; j < EdgeMeasure::count; ++j) out.m[j] = ball_of(I->m[j], 64);
                integrated = true;
                ++r.edges_in_doubles;
            } else {
                ends[0] = lifted[k], ends[1] = lifted[k + 1];
            }
        } else if (goal.nodes_in_arb) {
            Ball middles[2];
            for (int i = 0; i < 2; ++i) arb_get_mid_arb(middles[i].get(), ends[i].get());
            if (const std::optional<NormalRayBisector::Densities> I = integrate_edge_in_arb(
                    bisector_in_doubles, bisector, rules_, middles, tolerances, prec, &r.quadrature, &reach)) {
                for (int j = 0; j < EdgeMeasure::count; ++j) arb_set(out.m[j].get(), acb_realref(I->m[j].get()));
                integrated = true;
                ++r.edges_by_nodes_in_arb;
            }
        }
        if (!integrated) {
            if (!integrate_with_arb(bisector, ends, goal.bits, area_tolerance, unit, prec, out)) return false;
            ++r.edges_by_arb;
            reach = {INFINITY, INFINITY};
        }
        // The pieces between the certified end angles and their midpoints:
        // at most the radius times a bound of the density on the ball (in
        // double intervals over the ball's real interval when the edge was
        // integrated so, else, or if that fails, by Arb).
        for (const Ball* end : {&ends[0], &ends[1]}) {
            NormalRayBisector::Densities d;
            const std::optional<MeasureIntervals> fast =
                integrated ? bisector_in_doubles.densities(enclose(*end)) : std::nullopt;
            if (fast) {
                d = as_balls(*fast);
            } else {
                ComplexBall theta(*end);
                if (!bisector.densities(theta, prec, d)) return false;
            }
            Mag radius;
            mag_set(radius.get(), arb_radref(end->get()));
            for (int j = 0; j < EdgeMeasure::count; ++j) {
                Mag bound;
                acb_get_mag(bound.get(), d.m[j].get());
                mag_mul(bound.get(), bound.get(), radius.get());
                arb_add_error_mag(out.m[j].get(), bound.get());
            }
            // The edge moves at most the radius times |V'| (the length density).
            Mag moved;
            acb_get_mag(moved.get(), d.m[EdgeMeasure::length].get());
            mag_mul(moved.get(), moved.get(), radius.get());
            for (double& x : reach) x = std::nextafter(x + mag_get_d(moved.get()), INFINITY);
        }
        return true;
    }

    // The area of the polygon of the cell's vertices, in doubles about the
    // site's center, not certified: the first pass's scale. (Within a few
    // percent of the cell's where its edges are nearly straight, as between
    // sites far apart; the curved edges of close sites move it by less than
    // the floor's factor 2. estimated_area's quadrature, the first scale, cost
    // 8% of a run.)
    double vertex_polygon_area(const VoronoiCell& cell) {
        const Ellipse& site = sites_[cell.site];
        const EllipseShape shape = EllipseShape::of(site);
        const std::size_t m = cell.edges.size();
        std::vector<std::array<double, 2>> corner(m);
        for (std::size_t k = 0; k < m; ++k) {
            const BallPoint v = angles_.vertex(cell.edges[k].from, 64);
            corner[k] = {v.x.mid_double() - shape.xc, v.y.mid_double() - shape.yc};
        }
        double twice = 0;
        for (std::size_t k = 0; k < m; ++k) {
            const std::array<double, 2>&a = corner[k], &b = corner[(k + 1) % m];
            twice += a[0] * b[1] - a[1] * b[0];
        }
        return std::isfinite(twice) ? 0.5 * twice : 0;
    }

    // The cell's area by 8 Gauss nodes an edge in floating point (Green's
    // formula about the site's center), or 0 when a node fails: a scale, not
    // a bound.
    double estimated_area(const VoronoiCell& cell, const std::vector<Ball>& lifted) {
        const Ellipse& site = sites_[cell.site];
        const GaussLegendreRule& rule = rules_.rule(8);
        const EllipseShape shape = EllipseShape::of(site);
        double area = 0;
        for (std::size_t k = 0; k < cell.edges.size(); ++k) {
            NormalRayInDoubles nodes(site, sites_[cell.edges[k].neighbor]);
            nodes.set_origin(shape.xc, shape.yc);
            const double a = arf_get_d(arb_midref(lifted[k].get()), ARF_RND_NEAR);
            const double b = arf_get_d(arb_midref(lifted[k + 1].get()), ARF_RND_NEAR);
            const double half = 0.5 * (b - a), mid = 0.5 * (a + b);
            const BallPoint v = angles_.vertex(cell.edges[k].from, 64);
            nodes.start_near(a, v.x.mid_double(), v.y.mid_double());
            for (std::size_t i = 0; i < rule.nodes.size(); ++i) {
                const std::optional<double> density = nodes.area_density_estimate(mid + half * rule.nodes[i].mid());
                if (!density) return 0;
                area += half * rule.weights[i].mid() * *density;
            }
        }
        return std::isfinite(area) ? area : 0;
    }

    // The edge's measures between the midpoints of its end balls by Arb's
    // integrator, in `out`; false when the area's are not finite.
    bool integrate_with_arb(NormalRayBisector& bisector, const Ball (&ends)[2], long goal, double area_tolerance,
                            long unit, long prec, EdgeIntegrals& out) {
        acb_calc_integrate_opt_t options;
        acb_calc_integrate_opt_init(options);
        // 20 bits beyond the goal, in whole limbs.
        const long point_precision = 64 * ((goal + 20 + 63) / 64);
        NormalRayBisector point_bisector(bisector.first(), bisector.second(), bisector.signed_tie());
        point_bisector.set_origin(out.origin[0], out.origin[1]);
        DensityCache cache;
        ComplexBall a, b;
        arb_get_mid_arb(a.real(), ends[0].get());
        arb_get_mid_arb(b.real(), ends[1].get());
        Mag tol;
        mag_set_d(tol.get(), area_tolerance);
        for (int pair = 0; pair < kMeasurePairs; ++pair) {
            EdgeIntegrand integrand{&bisector, &point_bisector, point_precision, pair, unit, &cache};
            ComplexBall integral;
            acb_calc_integrate(integral.get(), edge_integrand, &integrand, a.get(), b.get(), goal, tol.get(), options,
                               prec);
            if (!acb_is_finite(integral.get())) {
                if (pair == 0) return false;
                acb_indeterminate(integral.get());
            }
            for (int part = 0; part < 2; ++part) {
                const int j = kPairs[pair][part];
                if (j < 0) continue;
                const arb_struct* value = part == 0 ? acb_realref(integral.get()) : acb_imagref(integral.get());
                arb_mul_2exp_si(out.m[j].get(), value, kLengthPower[j] * unit);
            }
        }
        return true;
    }

    // Area, perimeter, centroid and central second moments from the sums
    // about the site's center.
    static void finish_moments(const BallPoint& center, const CellIntegrals& sums, long prec, CellArea& r) {
        const Ball& area = r.area;
        r.perimeter = sums.perimeter;
        // Centroid C + first / area; central moments second - first first^T / area.
        const Ball* c[2] = {&center.x, &center.y};
        Ball d[2], t;
        for (int i = 0; i < 2; ++i) {
            arb_div(d[i].get(), sums.first[i].get(), area.get(), prec);
            arb_add(r.centroid[i].get(), c[i]->get(), d[i].get(), prec);
        }
        const int pairs[3][2] = {{0, 0}, {0, 1}, {1, 1}};
        for (int k = 0; k < 3; ++k) {
            arb_mul(t.get(), sums.first[pairs[k][0]].get(), d[pairs[k][1]].get(), prec);
            arb_sub(r.second_moments[k].get(), sums.second[k].get(), t.get(), prec);
        }
    }

    static std::array<long, 4> edge_key(SiteId owner, SiteId neighbor, long from, long to) {
        return {static_cast<long>(owner), static_cast<long>(neighbor), from, to};
    }
    // An edge integrated by one cell's first pass for its neighbour's.
    struct SharedEdge {
        EdgeIntegrals integrals;
        double neighbor_reach;  // of the edge from the neighbour's center
    };

    const std::vector<Ellipse>& sites_;
    const std::vector<VoronoiCell>& cells_;
    double tolerance_;
    bool arb_integrator_only_;
    CellVertexAngles angles_;
    GaussLegendreRules rules_;
    std::vector<std::optional<FirstPassScale>> scales_;
    std::vector<char> pending_;
    // By (owner, neighbour, from, to): the owner's edge from face `from` to
    // face `to`, until the neighbour's first pass takes it.
    std::map<std::array<long, 4>, SharedEdge> shared_;
};

}  // namespace

void require_followable_edges(const DelaunayGraph& graph, const std::vector<Ellipse>& sites,
                              const std::vector<SiteId>& which, const std::vector<SiteId>& input_ids) {
    const std::vector<VoronoiCell> cells = voronoi_cells(graph, face_numbers(graph));
    std::vector<char> wanted(cells.size(), which.empty());
    for (SiteId s : which) wanted.at(s) = 1;
    std::unique_ptr<CellVertexAngles> angles;  // made at the first pair that meets
    const long prec = 64;
    for (SiteId s = 0; s < cells.size(); ++s) {
        if (!wanted[s]) continue;
        const VoronoiCell& cell = cells[s];
        if (!cell.visible || !cell.bounded()) continue;
        std::vector<Ball> lifted;
        for (std::size_t k = 0; k < cell.edges.size(); ++k) {
            if (!NormalRayBisector::meet(sites[s], sites[cell.edges[k].neighbor])) continue;
            if (!angles) angles = std::make_unique<CellVertexAngles>(graph, sites);
            if (lifted.empty()) lifted = angles->lifted(cell, prec);
            require_normal_lines_reach(sites, cell, k, lifted, *angles, input_ids, prec);
        }
    }
}

long cell_area_precision(double tolerance) { return 64 + static_cast<long>(std::ceil(-std::log2(tolerance))); }

namespace {

// The measures of one cell (left at their defaults unless visible and bounded).
void measure_cell(CellAreaSolver& solver, const VoronoiCell& cell, const Ellipse& site, long start, CellArea& r) {
    r.site = cell.site;
    r.visible = cell.visible;
    r.bounded = cell.bounded();
    r.site_area = CellAreaSolver::site_area(site, start);
    for (Ball* b : {&r.perimeter, &r.centroid[0], &r.centroid[1], &r.second_moments[0], &r.second_moments[1],
                    &r.second_moments[2]})
        arb_indeterminate(b->get());
    if (!cell.visible) {
        arb_zero(r.area.get());
        arb_zero(r.perimeter.get());
        return;
    }
    if (!r.bounded) {
        arb_pos_inf(r.area.get());
        arb_pos_inf(r.perimeter.get());
        return;
    }
    // Each pass doubles the precision: the vertex angles, the certificates
    // and the quadrature all tighten with it.
    for (long prec = start, pass = 0; !r.precision; prec *= 2, ++pass) {
        if (prec > 16 * start)
            throw Error("cell_areas: the area of cell " + std::to_string(cell.site) +
                        " could not be certified to the tolerance below " + std::to_string(prec / 2) + " bits");
        std::optional<CellArea> m = solver.measure(cell, prec, static_cast<int>(pass));
        if (pass == 0) solver.set_pending(cell.site, false);
        if (m) {
            m->site = cell.site;
            m->visible = true;
            m->bounded = true;
            m->precision = prec;
            r = std::move(*m);
        }
    }
}

}  // namespace

std::vector<CellArea> cell_areas(const DelaunayGraph& graph, const std::vector<Ellipse>& sites,
                                 const CellAreaOptions& options) {
    const double T = options.tolerance;
    if (!(T > 0 && T <= 1)) throw InputError("cell_areas: the tolerance must be in (0, 1]");
    const std::vector<VoronoiCell> cells = voronoi_cells(graph, face_numbers(graph));
    std::vector<CellArea> out(cells.size());
    const long start = cell_area_precision(T);
    std::vector<SiteId> which = options.only;
    if (which.empty())
        for (SiteId s = 0; s < cells.size(); ++s) which.push_back(s);
    for (SiteId s : which) cells.at(s);  // out of range: an Error before any thread
    require_followable_edges(graph, sites, which, options.input_ids);
    // In chunks along a Hilbert curve (cells/cell_chunks.hpp), each by a
    // solver of its own: an edge one cell integrated for its neighbour waits
    // only a short while (CellAreaSolver::measure).
    const std::vector<SiteId> order = hilbert_order(sites, std::move(which));
    const auto faces = std::make_shared<const CellVertexAngles::Faces>(graph.faces());
    std::size_t done = 0;
    std::mutex progress_lock;
    for_each_chunk(order, options.chunk, options.threads, [&](const SiteId* begin, const SiteId* end) {
        CellAreaSolver solver(faces, sites, cells, T, options.arb_integrator_only);
        for (const SiteId* s = begin; s != end; ++s)
            if (cells[*s].visible && cells[*s].bounded()) solver.set_pending(*s, true);
        for (const SiteId* s = begin; s != end; ++s) {
            measure_cell(solver, cells[*s], sites[*s], start, out[*s]);
            const std::lock_guard<std::mutex> lock(progress_lock);
            if (options.progress && ++done < order.size()) options.progress(done, order.size());
        }
    });
    if (options.progress) options.progress(order.size(), order.size());
    return out;
}

}  // namespace ellvor
