#include "cells/cell_area.hpp"

#include "cells/cell_vertex_angles.hpp"
#include "cells/edge_quadrature.hpp"
#include "cells/face_numbers.hpp"
#include "cells/normal_ray_bisector.hpp"
#include "cells/normal_ray_in_doubles.hpp"
#include "util/error.hpp"

#include <acb_calc.h>

#include <algorithm>
#include <array>
#include <cmath>
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
    d.area = to_ball(I.m[MeasureIntervals::area]);
    d.length = to_ball(I.m[MeasureIntervals::length]);
    for (int i = 0; i < 2; ++i) d.first[i] = to_ball(I.m[MeasureIntervals::first_x + i]);
    for (int k = 0; k < 3; ++k) d.second[k] = to_ball(I.m[MeasureIntervals::second_xx + k]);
    return d;
}

class DensityCache;

// The integrand of one pair of measures on one edge: f + i g, both real on
// the reals, so that the real and imaginary parts of the integral enclose
// the two integrals. Each measure is scaled by the cell's length unit L to a
// power (area units), so that one absolute tolerance serves both.
struct EdgeIntegrand {
    NormalRayBisector* bisector;
    // Values at points (order 0) need only the goal's bits, not the working
    // precision of the holomorphy certificates on balls: a second solver at
    // point_precision spares the longer limbs.
    NormalRayBisector* point_bisector;
    long point_precision;
    int pair;  // 0: area + i L length, 1: first / L (x + i y), 2: second / L^2 (xx + i yy), 3: second / L^2 (xy)
    long length_unit;  // L = 2^length_unit (exact scaling)
    DensityCache* cache;
};

constexpr int kMeasurePairs = 4;

// Arb evaluates the four pairs on mostly the same balls: the densities of
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
    switch (pair) {
        case 0: f = d.area; acb_mul_2exp_si(g.get(), d.length.get(), unit); break;
        case 1: acb_mul_2exp_si(f.get(), d.first[0].get(), -unit); acb_mul_2exp_si(g.get(), d.first[1].get(), -unit); break;
        case 2: acb_mul_2exp_si(f.get(), d.second[0].get(), -2 * unit); acb_mul_2exp_si(g.get(), d.second[2].get(), -2 * unit); break;
        default: acb_mul_2exp_si(f.get(), d.second[1].get(), -2 * unit); break;
    }
    acb_mul_onei(g.get(), g.get());
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

// Everything a cell's integrals add up, in area units (see EdgeIntegrand).
struct MeasureSums {
    std::array<ComplexBall, kMeasurePairs> pairs;
};

// The goals (bits) that the double-interval stage serves.
constexpr long kDoubleGoalBits = 44;
// Measure j is scaled by L^-kLengthPower[j] to area units in the pairs (as
// pair_value does): its tolerance is the area's times L^kLengthPower[j].
constexpr int kLengthPower[MeasureIntervals::count] = {0, -1, 1, 1, 2, 2, 2};

void add_to_pairs(const NormalRayBisector::Densities& d, long unit, long prec, MeasureSums& sums) {
    for (int pair = 0; pair < kMeasurePairs; ++pair) {
        ComplexBall v;
        pair_value(d, pair, unit, prec, v.get());
        acb_add(sums.pairs[pair].get(), sums.pairs[pair].get(), v.get(), prec);
    }
}

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

class CellAreaSolver {
public:
    CellAreaSolver(const DelaunayGraph& graph, const std::vector<Ellipse>& sites, double tolerance,
                   bool arb_integrator_only)
        : sites_(sites), tolerance_(tolerance), arb_integrator_only_(arb_integrator_only), angles_(graph, sites) {}

    // The measures of a bounded cell at precision prec, or nothing when the
    // pass could not certify its area within the tolerance. Pass k asks Arb
    // for 6k more bits than the first.
    std::optional<CellArea> measure(const VoronoiCell& cell, long prec, int pass) {
        const Ellipse& site = sites_[cell.site];
        CellArea r;
        r.site_area = site_area(site, prec);
        const std::size_t m = cell.edges.size();
        const long goal = static_cast<long>(std::ceil(-std::log2(tolerance_))) + 4 + 6 * pass;
        // Below 45 bits the edges go to the double-interval quadrature first,
        // beyond to its pieces with the nodes in Arb; Arb's integrator takes
        // what they cannot certify.
        const bool in_doubles = !arb_integrator_only_ && goal <= kDoubleGoalBits;
        const bool nodes_in_arb = !arb_integrator_only_ && !in_doubles;
        // The double quadrature reads the ends as doubles and adds their
        // radii times the density: goal + 8 bits of angle leave those terms
        // far below the tolerance (the circles certified in doubles give
        // them); the other stages take the angles at the working precision.
        std::vector<Ball> lifted = angles_.lifted(cell, in_doubles ? goal + 8 + 24 : prec);
        // A zero-length edge (four cocircular sites, as at a wall's mirror
        // images) needs its two equal ends to round to the same double,
        // which takes the working precision.
        const auto nearest_double = [](const Ball& x) { return arf_get_d(arb_midref(x.get()), ARF_RND_NEAR); };
        for (std::size_t k = 0; in_doubles && k + 1 < lifted.size(); ++k)
            if (!(nearest_double(lifted[k]) < nearest_double(lifted[k + 1]))) {
                lifted = angles_.lifted(cell, prec);
                break;
            }
        std::vector<std::unique_ptr<NormalRayBisector>> bisectors;
        bool meets = false;  // a neighbour crosses or touches the site
        for (const CellEdge& e : cell.edges) {
            bisectors.push_back(std::make_unique<NormalRayBisector>(site, sites_[e.neighbor]));
            meets = meets || (bisectors.back()->signed_tie() && NormalRayBisector::meet(site, sites_[e.neighbor]));
        }

        // The scale of the tolerances and the length unit: the cell is at
        // least the site unless a neighbour meets it; on the first pass (on
        // every pass when a neighbour meets the site) half an estimate of its
        // area (the final check below, not the estimate, decides).
        double area_floor = meets ? 0.0 : r.site_area.mid_double();
        if (pass == 0 || meets) area_floor = std::max(area_floor, 0.5 * estimated_area(cell, lifted, bisectors));
        if (!(area_floor > 0)) area_floor = r.site_area.mid_double();
        const long unit = std::lround(0.5 * std::log2(area_floor));  // L = 2^unit, about sqrt(area)
        Mag tol;
        // Per edge and pair an eighth of the tolerance's share: with the ends'
        // terms the area's width stays well below T * area.
        mag_set_d(tol.get(), std::ldexp(tolerance_ * area_floor / static_cast<double>(m), -3 - 6 * pass));
        MeasureSums sums;
        // The edges' pieces bound their distance from the center between the
        // midpoints of the end balls; beyond, up to the true end angles, V
        // moves at most the ball's radius times |V'| (the length density).
        double reach = 0;
        bool reach_known = true;
        for (std::size_t k = 0; k < m; ++k) {
            NormalRayBisector& bisector = *bisectors[k];
            NormalRayInDoubles bisector_in_doubles(site, sites_[cell.edges[k].neighbor], bisector.signed_tie());
            Ball ends[2] = {lifted[k], lifted[k + 1]};
            double tolerances[MeasureIntervals::count];
            for (int j = 0; j < MeasureIntervals::count; ++j)
                tolerances[j] = std::ldexp(mag_get_d(tol.get()), static_cast<int>(kLengthPower[j] * unit));
            bool integrated = false;
            double edge_reach = 0;
            if (in_doubles) {
                const double a = centre_on_double(ends[0]), b = centre_on_double(ends[1]);
                if (const std::optional<MeasureIntervals> I =
                        integrate_edge(bisector_in_doubles, rules_, a, b, tolerances, &r.quadrature, &edge_reach)) {
                    add_to_pairs(as_balls(*I), unit, prec, sums);
                    integrated = true;
                    ++r.edges_in_doubles;
                } else {
                    ends[0] = lifted[k], ends[1] = lifted[k + 1];
                }
            } else if (nodes_in_arb) {
                Ball middles[2];
                for (int i = 0; i < 2; ++i) arb_get_mid_arb(middles[i].get(), ends[i].get());
                if (const std::optional<NormalRayBisector::Densities> I = integrate_edge_in_arb(
                        bisector_in_doubles, bisector, rules_, middles, tolerances, prec, &r.quadrature, &edge_reach)) {
                    add_to_pairs(*I, unit, prec, sums);
                    integrated = true;
                    ++r.edges_by_nodes_in_arb;
                }
            }
            if (!integrated) {
                if (!integrate_with_arb(bisector, ends, goal, tol, unit, prec, sums)) return std::nullopt;
                ++r.edges_by_arb;
                reach_known = false;
            }
            // The pieces between the certified end angles and their midpoints:
            // at most the radius times a bound of the density on the ball
            // (in double intervals over the ball's real interval when the
            // edge was integrated so, else, or if that fails, by Arb).
            for (const Ball* end : {&ends[0], &ends[1]}) {
                NormalRayBisector::Densities d;
                const std::optional<MeasureIntervals> fast =
                    integrated ? bisector_in_doubles.densities(enclose(*end)) : std::nullopt;
                if (fast) {
                    d = as_balls(*fast);
                } else {
                    ComplexBall theta(*end);
                    if (!bisector.densities(theta, prec, d)) return std::nullopt;
                }
                Mag radius;
                mag_set(radius.get(), arb_radref(end->get()));
                for (int pair = 0; pair < kMeasurePairs; ++pair) {
                    ComplexBall v;
                    pair_value(d, pair, unit, prec, v.get());
                    Mag bound;
                    acb_get_mag(bound.get(), v.get());
                    mag_mul(bound.get(), bound.get(), radius.get());
                    acb_add_error_mag(sums.pairs[pair].get(), bound.get());
                }
                Mag moved;
                acb_get_mag(moved.get(), d.length.get());
                mag_mul(moved.get(), moved.get(), radius.get());
                reach = std::max(reach, std::nextafter(edge_reach + mag_get_d(moved.get()), INFINITY));
            }
        }
        arb_add(r.area.get(), r.site_area.get(), acb_realref(sums.pairs[0].get()), prec);
        Arf lo, width;
        arb_get_lbound_arf(lo.get(), r.area.get(), prec);
        arf_set_mag(width.get(), arb_radref(r.area.get()));
        const double w = 2 * arf_get_d(width.get(), ARF_RND_UP), l = arf_get_d(lo.get(), ARF_RND_DOWN);
        if (!(l > 0) || !(w <= tolerance_ * l)) return std::nullopt;
        finish_moments(site, sums, unit, prec, r);
        r.reach = reach_known ? reach : INFINITY;
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
    // The cell's area by 8 Gauss nodes an edge in floating point, or 0 when
    // a node fails: a scale, not a bound.
    double estimated_area(const VoronoiCell& cell, const std::vector<Ball>& lifted,
                          const std::vector<std::unique_ptr<NormalRayBisector>>& bisectors) {
        const Ellipse& site = sites_[cell.site];
        const GaussLegendreRule& rule = rules_.rule(8);
        double area = site_area(site, 64).mid_double();
        for (std::size_t k = 0; k < cell.edges.size(); ++k) {
            NormalRayInDoubles nodes(site, sites_[cell.edges[k].neighbor], bisectors[k]->signed_tie());
            const double a = arf_get_d(arb_midref(lifted[k].get()), ARF_RND_NEAR);
            const double b = arf_get_d(arb_midref(lifted[k + 1].get()), ARF_RND_NEAR);
            const double half = 0.5 * (b - a), mid = 0.5 * (a + b);
            for (std::size_t i = 0; i < rule.nodes.size(); ++i) {
                const std::optional<MeasureIntervals> d = nodes.densities(Interval(mid + half * rule.nodes[i].mid()));
                if (!d) return 0;
                area += half * rule.weights[i].mid() * d->m[MeasureIntervals::area].mid();
            }
        }
        return std::isfinite(area) ? area : 0;
    }

    // The edge's measures between the midpoints of its end balls by Arb's
    // integrator, added to the sums; false when the area's is not finite.
    bool integrate_with_arb(NormalRayBisector& bisector, const Ball (&ends)[2], long goal, Mag& tol, long unit,
                            long prec, MeasureSums& sums) {
        acb_calc_integrate_opt_t options;
        acb_calc_integrate_opt_init(options);
        // 20 bits beyond the goal, in whole limbs.
        const long point_precision = 64 * ((goal + 20 + 63) / 64);
        NormalRayBisector point_bisector(bisector.first(), bisector.second(), bisector.signed_tie());
        DensityCache cache;
        ComplexBall a, b;
        arb_get_mid_arb(a.real(), ends[0].get());
        arb_get_mid_arb(b.real(), ends[1].get());
        for (int pair = 0; pair < kMeasurePairs; ++pair) {
            EdgeIntegrand integrand{&bisector, &point_bisector, point_precision, pair, unit, &cache};
            ComplexBall integral;
            acb_calc_integrate(integral.get(), edge_integrand, &integrand, a.get(), b.get(), goal, tol.get(), options,
                               prec);
            if (!acb_is_finite(integral.get())) {
                if (pair == 0) return false;
                acb_indeterminate(integral.get());
            }
            acb_add(sums.pairs[pair].get(), sums.pairs[pair].get(), integral.get(), prec);
        }
        return true;
    }

    // Perimeter, centroid and central second moments from the sums (about
    // the site's center C; the site adds pi a b / 4 R diag(a^2, b^2) R^T to
    // the second moments and nothing to the first).
    static void finish_moments(const Ellipse& site, const MeasureSums& sums, long unit, long prec, CellArea& r) {
        const Ball& area = r.area;
        arb_mul_2exp_si(r.perimeter.get(), acb_imagref(sums.pairs[0].get()), -unit);
        Ball first[2];
        arb_mul_2exp_si(first[0].get(), acb_realref(sums.pairs[1].get()), unit);
        arb_mul_2exp_si(first[1].get(), acb_imagref(sums.pairs[1].get()), unit);
        Ball second[3];
        arb_mul_2exp_si(second[0].get(), acb_realref(sums.pairs[2].get()), 2 * unit);
        arb_mul_2exp_si(second[1].get(), acb_realref(sums.pairs[3].get()), 2 * unit);
        arb_mul_2exp_si(second[2].get(), acb_imagref(sums.pairs[2].get()), 2 * unit);
        Ball a2(site.a(), prec), b2(site.b(), prec), c(site.cos_rotation(), prec), s(site.sin_rotation(), prec), t, u;
        arb_sqr(a2.get(), a2.get(), prec);
        arb_sqr(b2.get(), b2.get(), prec);
        Ball quarter_area;  // pi a b / 4
        arb_mul_2exp_si(quarter_area.get(), r.site_area.get(), -2);
        const Ball* own_axes[3][2] = {{&c, &c}, {&c, &s}, {&s, &s}};  // a^2 u_i u_j + b^2 v_i v_j, u = (c, s), v = (-s, c)
        const Ball* other_axes[3][2] = {{&s, &s}, {&s, &c}, {&c, &c}};
        for (int k = 0; k < 3; ++k) {
            arb_mul(t.get(), own_axes[k][0]->get(), own_axes[k][1]->get(), prec);
            arb_mul(t.get(), t.get(), a2.get(), prec);
            arb_mul(u.get(), other_axes[k][0]->get(), other_axes[k][1]->get(), prec);
            arb_mul(u.get(), u.get(), b2.get(), prec);
            if (k == 1) arb_neg(u.get(), u.get());
            arb_add(t.get(), t.get(), u.get(), prec);
            arb_addmul(second[k].get(), t.get(), quarter_area.get(), prec);
        }
        // Centroid C + first / area; central moments second - first first^T / area.
        Ball center[2] = {Ball(site.xc(), prec), Ball(site.yc(), prec)};
        Ball d[2];
        for (int i = 0; i < 2; ++i) {
            arb_div(d[i].get(), first[i].get(), area.get(), prec);
            arb_add(r.centroid[i].get(), center[i].get(), d[i].get(), prec);
        }
        const int pairs[3][2] = {{0, 0}, {0, 1}, {1, 1}};
        for (int k = 0; k < 3; ++k) {
            arb_mul(t.get(), first[pairs[k][0]].get(), d[pairs[k][1]].get(), prec);
            arb_sub(r.second_moments[k].get(), second[k].get(), t.get(), prec);
        }
    }

    const std::vector<Ellipse>& sites_;
    double tolerance_;
    bool arb_integrator_only_;
    CellVertexAngles angles_;
    GaussLegendreRules rules_;
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

std::vector<CellArea> cell_areas(const DelaunayGraph& graph, const std::vector<Ellipse>& sites,
                                 const CellAreaOptions& options) {
    const double T = options.tolerance;
    if (!(T > 0 && T <= 1)) throw InputError("cell_areas: the tolerance must be in (0, 1]");
    const std::vector<VoronoiCell> cells = voronoi_cells(graph, face_numbers(graph));
    CellAreaSolver solver(graph, sites, T, options.arb_integrator_only);
    std::vector<CellArea> out(cells.size());
    const long start = cell_area_precision(T);
    std::vector<SiteId> which = options.only;
    if (which.empty())
        for (SiteId s = 0; s < cells.size(); ++s) which.push_back(s);
    require_followable_edges(graph, sites, which, options.input_ids);
    std::size_t done = 0;
    for (SiteId s : which) {
        if (options.progress && done) options.progress(done, which.size());
        ++done;
        const VoronoiCell& cell = cells.at(s);
        CellArea& r = out[s];
        r.site = s;
        r.visible = cell.visible;
        r.bounded = cell.bounded();
        r.site_area = CellAreaSolver::site_area(sites[s], start);
        for (Ball* b : {&r.perimeter, &r.centroid[0], &r.centroid[1], &r.second_moments[0], &r.second_moments[1],
                        &r.second_moments[2]})
            arb_indeterminate(b->get());
        if (!cell.visible) {
            arb_zero(r.area.get());
            arb_zero(r.perimeter.get());
            continue;
        }
        if (!r.bounded) {
            arb_pos_inf(r.area.get());
            arb_pos_inf(r.perimeter.get());
            continue;
        }
        // Each pass doubles the precision: the vertex angles, the certificates
        // and the quadrature all tighten with it.
        for (long prec = start, pass = 0; !r.precision; prec *= 2, ++pass) {
            if (prec > 16 * start)
                throw Error("cell_areas: the area of cell " + std::to_string(s) +
                            " could not be certified to the tolerance below " + std::to_string(prec / 2) + " bits");
            if (std::optional<CellArea> m = solver.measure(cell, prec, static_cast<int>(pass))) {
                m->site = s;
                m->visible = true;
                m->bounded = true;
                m->precision = prec;
                r = std::move(*m);
            }
        }
    }
    if (options.progress) options.progress(which.size(), which.size());
    return out;
}

}  // namespace ellvor
