#include "subdivision/voronoi_circle_search.hpp"

#include "subdivision/boundary_chart.hpp"
#include "util/error.hpp"
#include "util/precision.hpp"

#include <algorithm>
#include <deque>
#include <map>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace ellvor {

namespace {

// Precision rule (util/precision.hpp): prec = kGuardBits + magnitude bits + r
// for a box of resolution r (widest half-width 2^-r), at least one limb, so
// the precision grows with the data and with the depth and no box is ever too
// small for its arithmetic.
constexpr long kMinimumPrecision = precision::kStart;
constexpr long kGuardBits = precision::kSearchGuardBits;

constexpr int kCoordinates = 4;  // t1, t2, t3 (chart parameters) and s (radius)

Rational absolute(const Rational& q) { return q.sign() < 0 ? -q : q; }

// Smallest e with |q| < 2^e (q != 0), from a 64-bit ball of it.
long exponent_bound(const Rational& q) {
    const Ball b(q, kMinimumPrecision);
    Arf upper;
    arb_get_abs_ubound_arf(upper.get(), b.get(), kMinimumPrecision);
    return arf_abs_bound_lt_2exp_si(upper.get());
}

// Exponent of L: 2^(e-1) <= diameter of the sites' bounding box < 2^e.
long scale_exponent(const std::array<const Ellipse*, 3>& sites) {
    Rational x_min, x_max, y_min, y_max;
    for (int i = 0; i < 3; ++i) {
        const Ellipse& e = *sites[i];
        const Rational r = std::max(e.a(), e.b());
        if (i == 0 || e.xc() - r < x_min) x_min = e.xc() - r;
        if (i == 0 || e.xc() + r > x_max) x_max = e.xc() + r;
        if (i == 0 || e.yc() - r < y_min) y_min = e.yc() - r;
        if (i == 0 || e.yc() + r > y_max) y_max = e.yc() + r;
    }
    return exponent_bound(std::max(x_max - x_min, y_max - y_min));
}

// Exponent of L_in: 2^(e-1) <= the smallest semi-axis of the three < 2^e. A
// point at signed distance rho <= 0 from all three sites lies at depth -rho
// in each, and no point of an ellipse is deeper than its smaller semi-axis
// (the depth of the medial axis' middle), so branch (C) needs -rho < L_in.
long internal_scale_exponent(const std::array<const Ellipse*, 3>& sites) {
    Rational smallest = std::min(sites[0]->a(), sites[0]->b());
    for (const Ellipse* e : sites) smallest = std::min({smallest, e->a(), e->b()});
    return exponent_bound(smallest);
}

// Some two of the sites certainly share no point: their circumscribed
// circles (radius the larger semi-axis) are apart. Then no point has signed
// distance <= 0 from all three, and branch (C) holds no Voronoi circle.
bool some_pair_apart(const std::array<const Ellipse*, 3>& sites) {
    for (int i = 0; i < 3; ++i)
        for (int j = i + 1; j < 3; ++j) {
            const Ellipse &e = *sites[i], &f = *sites[j];
            const Rational dx = e.xc() - f.xc(), dy = e.yc() - f.yc();
            const Rational reach = std::max(e.a(), e.b()) + std::max(f.a(), f.b());
            if (dx * dx + dy * dy > reach * reach) return true;
        }
    return false;
}

Ball sub(const Ball& a, const Ball& b, long prec) {
    Ball r;
    arb_sub(r.get(), a.get(), b.get(), prec);
    return r;
}

// A boundary point and its outward normal.
struct PointNormal {
    Ball px, py, nx, ny;
};

enum class Branch {
    radius,          // (A) rho = s L
    inverse_radius,  // (B) rho = L / s
    internal,        // (C) rho = -s L_in
};

// A box of the search: chart flags, branch, and four coordinates as balls.
// The chart parameters have an exact dyadic midpoint and a power-of-two
// radius (bisection is exact), with the point and normal at both ends (a
// split evaluates the chart once, at the new end). s lies in [0, 1] and is
// narrowed by the equations (each is affine in s), so it is split only when
// they do not pin it down: the search is mostly over the 3 chart parameters.
struct Box {
    std::array<bool, 3> flipped{};
    Branch branch = Branch::radius;
    std::array<Ball, kCoordinates> coordinate;
    std::array<std::array<PointNormal, 2>, 3> ends;  // [site][low end, high end]
};

int widest_coordinate(const Box& box) {
    int widest = 0;
    for (int j = 1; j < kCoordinates; ++j)
        if (mag_cmp(arb_radref(box.coordinate[j].get()), arb_radref(box.coordinate[widest].get())) > 0) widest = j;
    return widest;
}

// -log2 of the widest half-width (rad < 2^exponent).
long resolution_bits(const Box& box) {
    const mag_struct* r = arb_radref(box.coordinate[widest_coordinate(box)].get());
    return std::max(0L, -fmpz_get_si(MAG_EXPREF(r)));
}

// Boundary points and outward normals of a site over an interval of a chart
// parameter, without overestimation: the hull of the values at the two ends
// and of the extremes reached inside. Inside, x of P is extreme exactly where
// the normal is horizontal (normal +x: x = xc + half-width, nx = 1; normal
// -x: the minimum, nx = -1), y where it is vertical; between those points
// both coordinates of P and of the normal are monotone (the normal turns
// monotonically on a convex curve). Ball arithmetic on the rational
// parametrization over the interval would overestimate the ranges about
// tenfold where exclusion starts, and the search would examine thousands of
// times more boxes.
class ArcRanges {
public:
    ArcRanges(const Ellipse& e, bool flipped) : site_(&e), chart_(e, flipped) {}

    const BoundaryChart& chart() const { return chart_; }

    PointNormal at(const Ball& chart_parameter, long prec) const {
        BoundaryChart::Local p = chart_.evaluate(chart_parameter, prec, false);
        return {std::move(p.px), std::move(p.py), std::move(p.nx), std::move(p.ny)};
    }

    PointNormal over(const Ball& chart_parameter, const std::array<PointNormal, 2>& ends, long prec) const {
        PointNormal r = ends[0];
        arb_union(r.px.get(), r.px.get(), ends[1].px.get(), prec);
        arb_union(r.py.get(), r.py.get(), ends[1].py.get(), prec);
        arb_union(r.nx.get(), r.nx.get(), ends[1].nx.get(), prec);
        arb_union(r.ny.get(), r.ny.get(), ends[1].ny.get(), prec);
        for (const Extreme& e : extremes(prec)) {
            if (!e.in_chart || !arb_overlaps(e.parameter.get(), chart_parameter.get())) continue;
            Ball& coordinate = e.horizontal ? r.px : r.py;
            Ball& normal = e.horizontal ? r.nx : r.ny;
            Ball unit;
            arb_set_si(unit.get(), e.sign);
            arb_union(coordinate.get(), coordinate.get(), e.coordinate.get(), prec);
            arb_union(normal.get(), normal.get(), unit.get(), prec);
        }
        return r;
    }

private:
    // Where the normal points along +x, -x, +y or -y, and P's coordinate there.
    struct Extreme {
        bool horizontal;  // normal along x (else along y)
        int sign;
        bool in_chart;  // the point lies in this chart's [-1, 1]
        Ball parameter, coordinate;
    };

    // In the site's frame the normal at angle theta is along
    // (cos theta / a, sin theta / b), so the point with normal d has
    // (cos theta, sin theta) = (p, q) / |(p, q)|, (p, q) = (a d'x, b d'y), d'
    // = d rotated into the frame; then t = tan(theta/2) = q / (|(p, q)| + p),
    // in [-1, 1] iff p >= 0, and u = -1/t = -q / (|(p, q)| - p), in [-1, 1]
    // iff p <= 0 (exact rational signs). P's coordinate there is the center's
    // plus or minus the half-width of the site, |(a cos w, b sin w)| for x.
    const std::array<Extreme, 4>& extremes(long prec) const {
        auto found = cache_.find(prec);
        if (found != cache_.end()) return found->second;
        const Ellipse& e = *site_;
        const Rational &c = e.cos_rotation(), &s = e.sin_rotation();
        std::array<Extreme, 4> out;
        int n = 0;
        for (bool horizontal : {true, false})
            for (int sign : {1, -1}) {
                Extreme& x = out[n++];
                x.horizontal = horizontal, x.sign = sign;
                const Rational dx = horizontal ? sign : 0, dy = horizontal ? 0 : sign;
                const Rational p = e.a() * (c * dx + s * dy), q = e.b() * (c * dy - s * dx);
                x.in_chart = chart_.flipped() ? p.sign() <= 0 : p.sign() >= 0;
                Ball norm(p * p + q * q, prec), denominator;
                arb_sqrt(norm.get(), norm.get(), prec);
                const Ball pb(p, prec), qb(q, prec);
                if (chart_.flipped()) {
                    arb_sub(denominator.get(), norm.get(), pb.get(), prec);
                    arb_div(x.parameter.get(), qb.get(), denominator.get(), prec);
                    arb_neg(x.parameter.get(), x.parameter.get());
                } else {
                    arb_add(denominator.get(), norm.get(), pb.get(), prec);
                    arb_div(x.parameter.get(), qb.get(), denominator.get(), prec);
                }
                const Rational along = horizontal ? e.a() * c : e.a() * s;
                const Rational across = horizontal ? e.b() * s : e.b() * c;
                Ball half_width(along * along + across * across, prec);
                arb_sqrt(half_width.get(), half_width.get(), prec);
                x.coordinate = Ball(horizontal ? e.xc() : e.yc(), prec);
                if (sign > 0)
                    arb_add(x.coordinate.get(), x.coordinate.get(), half_width.get(), prec);
                else
                    arb_sub(x.coordinate.get(), x.coordinate.get(), half_width.get(), prec);
            }
        return cache_.emplace(prec, std::move(out)).first->second;
    }

    const Ellipse* site_;
    BoundaryChart chart_;
    mutable std::map<long, std::array<Extreme, 4>> cache_;  // by precision: few distinct ones per search
};

// The equations of pair (i, j), all branches in one form, affine in s:
//   (A) (Pi - Pj) + s L (nui - nuj) = 0,  (B) (nui - nuj) + s (Pi - Pj) / L = 0,
//   (C) (Pi - Pj) - s L_in (nui - nuj) = 0,
// i.e. constant + s slope = 0 per coordinate.
struct PairEquations {
    Ball constant_x, constant_y, slope_x, slope_y;
};

class SearchSystem {
public:
    explicit SearchSystem(const std::array<const Ellipse*, 3>& sites)
        : sites_(sites), scale_(scale_exponent(sites)), internal_scale_(internal_scale_exponent(sites)),
          internal_possible_(!some_pair_apart(sites)) {
        for (const Ellipse* e : sites)
            for (bool flipped : {false, true}) arcs_.emplace_back(*e, flipped);
    }

    // Whether branch (C) needs searching: the three sites may share a point.
    bool internal_possible() const { return internal_possible_; }

    // Charts (bit i of `charts`: site i flipped) x [-1, 1]^3 x s in [0, 1].
    Box root_box(int charts, Branch branch, long prec) const {
        Box box;
        box.branch = branch;
        for (int i = 0; i < 3; ++i) {
            box.flipped[i] = (charts >> i) & 1;
            arb_zero(box.coordinate[i].get());
            mag_one(arb_radref(box.coordinate[i].get()));
            for (int end : {0, 1}) {
                Ball t;
                arb_set_si(t.get(), end ? 1 : -1);
                box.ends[i][end] = arcs(i, box.flipped[i]).at(t, prec);
            }
        }
        arb_set_d(box.coordinate[3].get(), 0.5);
        mag_set_ui_2exp_si(arb_radref(box.coordinate[3].get()), 1, -1);
        return box;
    }

    // The two halves of a box along its widest coordinate (exact).
    std::pair<Box, Box> bisect(Box box, long prec) const {
        const int j = widest_coordinate(box);
        arb_struct* c = box.coordinate[j].get();
        Ball split;
        arb_get_mid_arb(split.get(), c);
        mag_mul_2exp_si(arb_radref(c), arb_radref(c), -1);
        Arf offset;
        arf_set_mag(offset.get(), arb_radref(c));
        Box low = box;
        arf_sub(arb_midref(low.coordinate[j].get()), arb_midref(c), offset.get(), ARF_PREC_EXACT, ARF_RND_DOWN);
        arf_add(arb_midref(c), arb_midref(c), offset.get(), ARF_PREC_EXACT, ARF_RND_DOWN);
        if (j < 3) {
            low.ends[j][1] = arcs(j, box.flipped[j]).at(split, prec);
            box.ends[j][0] = low.ends[j][1];
        }
        return {std::move(low), std::move(box)};
    }

    // Narrows s to the solutions of each equation (s = -constant / slope
    // where the slope excludes 0), then tests the ranges over the box: every
    // equation (all three pairs: they are not implied for ranges), the
    // consequence (Pi - Pj).(nui + nuj) = 0 of each pair (it holds for every
    // rho and, unlike the (B) equations, does not vanish on all of s = 0),
    // and the orientation. True: no counter-clockwise solution in the box.
    bool excluded_by_ranges(Box& box, long prec) const {
        std::array<PointNormal, 3> q;
        for (int i = 0; i < 3; ++i) q[i] = arcs(i, box.flipped[i]).over(box.coordinate[i], box.ends[i], prec);
        constexpr int kPairs[3][2] = {{0, 1}, {0, 2}, {1, 2}};
        std::array<PairEquations, 3> pairs;
        Ball& s = box.coordinate[3];
        if (box.branch == Branch::internal && !narrow_to_medial_depth(q, s, prec)) return true;
        for (int k = 0; k < 3; ++k) {
            pairs[k] = pair_equations(box, q[kPairs[k][0]], q[kPairs[k][1]], prec);
            for (const auto& [constant, slope] : {std::make_pair(&pairs[k].constant_x, &pairs[k].slope_x),
                                                  std::make_pair(&pairs[k].constant_y, &pairs[k].slope_y)}) {
                if (arb_contains_zero(slope->get())) continue;
                Ball root;
                arb_div(root.get(), constant->get(), slope->get(), prec);
                arb_neg(root.get(), root.get());
                if (!arb_intersection(s.get(), s.get(), root.get(), prec)) return true;
            }
        }
        Ball value;
        for (const PairEquations& e : pairs)
            for (const auto& [constant, slope] :
                 {std::make_pair(&e.constant_x, &e.slope_x), std::make_pair(&e.constant_y, &e.slope_y)}) {
                arb_mul(value.get(), slope->get(), s.get(), prec);
                arb_add(value.get(), value.get(), constant->get(), prec);
                if (!arb_contains_zero(value.get())) return true;
            }
        Ball g, sum;
        for (const auto& pair : kPairs) {
            const PointNormal &pi = q[pair[0]], &pj = q[pair[1]];
            arb_add(sum.get(), pi.nx.get(), pj.nx.get(), prec);
            arb_mul(g.get(), sub(pi.px, pj.px, prec).get(), sum.get(), prec);
            arb_add(sum.get(), pi.ny.get(), pj.ny.get(), prec);
            arb_addmul(g.get(), sub(pi.py, pj.py, prec).get(), sum.get(), prec);
            if (!arb_contains_zero(g.get())) return true;
        }
        if (box.branch == Branch::internal && !center_inside_sites(q, s, prec)) return true;
        // Orientation. At a solution P_i - P_1 = -rho (nu_i - nu_1), so
        // det(P2 - P1, P3 - P1) = rho^2 det(nu2 - nu1, nu3 - nu1): a
        // counter-clockwise solution (normals' determinant > 0, DESIGN.md §2)
        // makes neither negative, whatever the sign of rho. The points' form
        // is the sharper one for large rho (the normals' shrinks like their
        // spread squared); the normals' is the only one that tells near rho =
        // 0, where the points' is rho^2 times it.
        return arb_is_negative(orientation(q, &PointNormal::px, &PointNormal::py, prec).get()) ||
               arb_is_negative(orientation(q, &PointNormal::nx, &PointNormal::ny, prec).get());
    }

    // The Krawczyk operator of the reduced system (pairs (1, 2), (1, 3)),
    //   K = m - Y F(m) + (I - Y J(box)) (box - m),   Y ~ mid(J(box))^-1:
    // every root in the box lies in K, so K missing the box excludes it --
    // what the range tests cannot do near roots just outside the box or the
    // domain (rho < 0 for (A): circles around the sites, or internal ones).
    bool excluded_by_krawczyk(const Box& box, long prec) const {
        BallMatrix midpoint(kCoordinates, 1), F(kCoordinates, 1), J(kCoordinates, kCoordinates),
            Fm(kCoordinates, 1), Jmid(kCoordinates, kCoordinates), Y(kCoordinates, kCoordinates);
        std::array<BoundaryChart::Local, 3> q, qm;
        for (int i = 0; i < 3; ++i) {
            const BoundaryChart& chart = arcs(i, box.flipped[i]).chart();
            q[i] = chart.evaluate(box.coordinate[i], prec, true);
            Ball t;
            arb_get_mid_arb(t.get(), box.coordinate[i].get());
            arb_set(midpoint.at(i, 0), t.get());
            qm[i] = chart.evaluate(t, prec, false);
        }
        Ball s_mid;
        arb_get_mid_arb(s_mid.get(), box.coordinate[3].get());
        arb_set(midpoint.at(3, 0), s_mid.get());
        reduced_system(box, box.coordinate[3], q, F, &J, prec);
        reduced_system(box, s_mid, qm, Fm, nullptr, prec);
        arb_mat_get_mid(Jmid.get(), J.get());
        if (!arb_mat_approx_inv(Y.get(), Jmid.get(), prec)) return false;
        BallMatrix M(kCoordinates, kCoordinates), D(kCoordinates, 1), K(kCoordinates, 1), YF(kCoordinates, 1);
        arb_mat_mul(M.get(), Y.get(), J.get(), prec);
        arb_mat_neg(M.get(), M.get());
        for (int j = 0; j < kCoordinates; ++j) {
            arb_add_si(M.at(j, j), M.at(j, j), 1, prec);
            arb_sub(D.at(j, 0), box.coordinate[j].get(), midpoint.at(j, 0), prec);
        }
        arb_mat_mul(K.get(), M.get(), D.get(), prec);
        arb_mat_mul(YF.get(), Y.get(), Fm.get(), prec);
        arb_mat_sub(K.get(), K.get(), YF.get(), prec);
        arb_mat_add(K.get(), K.get(), midpoint.get(), prec);
        for (int j = 0; j < kCoordinates; ++j)
            if (!arb_overlaps(K.at(j, 0), box.coordinate[j].get())) return true;
        return false;
    }

    // The box's midpoint as a start: rho from s, V = P1 + rho nu1.
    VoronoiCircleStart start_of(const Box& box, long prec) const {
        VoronoiCircleStart start;
        start.flipped = box.flipped;
        start.precision = prec;
        for (int i = 0; i < 3; ++i) arb_get_mid_arb(start.parameter[i].get(), box.coordinate[i].get());
        Ball s;
        arb_get_mid_arb(s.get(), box.coordinate[3].get());
        switch (box.branch) {
            case Branch::radius:
                arb_mul_2exp_si(start.radius.get(), s.get(), scale_);
                break;
            case Branch::inverse_radius:
                arb_inv(start.radius.get(), s.get(), prec);
                arb_mul_2exp_si(start.radius.get(), start.radius.get(), scale_);
                break;
            case Branch::internal:
                arb_neg(start.radius.get(), s.get());
                arb_mul_2exp_si(start.radius.get(), start.radius.get(), internal_scale_);
                break;
        }
        arb_get_mid_arb(start.radius.get(), start.radius.get());
        const PointNormal p = arcs(0, box.flipped[0]).at(start.parameter[0], prec);
        for (auto [center, point, normal] : {std::make_tuple(&start.center_x, &p.px, &p.nx),
                                             std::make_tuple(&start.center_y, &p.py, &p.ny)}) {
            arb_mul(center->get(), start.radius.get(), normal->get(), prec);
            arb_add(center->get(), center->get(), point->get(), prec);
            arb_get_mid_arb(center->get(), center->get());
        }
        return start;
    }

private:
    const ArcRanges& arcs(int site, bool flipped) const { return arcs_[2 * site + (flipped ? 1 : 0)]; }

    template <class Point>
    PairEquations pair_equations(const Box& box, const Point& pi, const Point& pj, long prec) const {
        Ball dpx = sub(pi.px, pj.px, prec), dpy = sub(pi.py, pj.py, prec);
        Ball dnx = sub(pi.nx, pj.nx, prec), dny = sub(pi.ny, pj.ny, prec);
        PairEquations e;
        switch (box.branch) {
            case Branch::radius:
                e.constant_x = std::move(dpx), e.constant_y = std::move(dpy);
                arb_mul_2exp_si(e.slope_x.get(), dnx.get(), scale_);
                arb_mul_2exp_si(e.slope_y.get(), dny.get(), scale_);
                break;
            case Branch::inverse_radius:
                e.constant_x = std::move(dnx), e.constant_y = std::move(dny);
                arb_mul_2exp_si(e.slope_x.get(), dpx.get(), -scale_);
                arb_mul_2exp_si(e.slope_y.get(), dpy.get(), -scale_);
                break;
            case Branch::internal:
                e.constant_x = std::move(dpx), e.constant_y = std::move(dpy);
                arb_mul_2exp_si(e.slope_x.get(), dnx.get(), internal_scale_);
                arb_mul_2exp_si(e.slope_y.get(), dny.get(), internal_scale_);
                arb_neg(e.slope_x.get(), e.slope_x.get());
                arb_neg(e.slope_y.get(), e.slope_y.get());
                break;
        }
        return e;
    }

    // The reduced system F = (pair (1, 2) x, y; pair (1, 3) x, y) at s and
    // the chart values q, and its Jacobian in (t1, t2, t3, s) when J is given
    // (q with derivatives): d/dt_i = +-(alpha P_i' + beta nu_i') with
    // (alpha, beta) = (1, s L) in (A), (s / L, 1) in (B), (1, -s L_in) in (C);
    // d/ds = slope.
    void reduced_system(const Box& box, const Ball& s, const std::array<BoundaryChart::Local, 3>& q, BallMatrix& F,
                        BallMatrix* J, long prec) const {
        Ball alpha, beta;
        arb_one(alpha.get());
        switch (box.branch) {
            case Branch::radius: arb_mul_2exp_si(beta.get(), s.get(), scale_); break;
            case Branch::inverse_radius:
                arb_mul_2exp_si(alpha.get(), s.get(), -scale_);
                arb_one(beta.get());
                break;
            case Branch::internal:
                arb_mul_2exp_si(beta.get(), s.get(), internal_scale_);
                arb_neg(beta.get(), beta.get());
                break;
        }
        for (int pair = 0; pair < 2; ++pair) {
            const int j = pair + 1;
            const PairEquations e = pair_equations(box, q[0], q[j], prec);
            arb_mul(F.at(2 * pair, 0), e.slope_x.get(), s.get(), prec);
            arb_add(F.at(2 * pair, 0), F.at(2 * pair, 0), e.constant_x.get(), prec);
            arb_mul(F.at(2 * pair + 1, 0), e.slope_y.get(), s.get(), prec);
            arb_add(F.at(2 * pair + 1, 0), F.at(2 * pair + 1, 0), e.constant_y.get(), prec);
            if (!J) continue;
            for (int i : {0, j}) {
                arb_struct* jx = J->at(2 * pair, i);
                arb_struct* jy = J->at(2 * pair + 1, i);
                arb_mul(jx, alpha.get(), q[i].dpx.get(), prec);
                arb_addmul(jx, beta.get(), q[i].dnx.get(), prec);
                arb_mul(jy, alpha.get(), q[i].dpy.get(), prec);
                arb_addmul(jy, beta.get(), q[i].dny.get(), prec);
                if (i == j) arb_neg(jx, jx), arb_neg(jy, jy);
            }
            arb_set(J->at(2 * pair, 3), e.slope_x.get());
            arb_set(J->at(2 * pair + 1, 3), e.slope_y.get());
        }
    }

    // det(q1 - q0, q2 - q0) = det(q0 - q1, q0 - q2) of the points (or the
    // normals) over the box.
    static Ball orientation(const std::array<PointNormal, 3>& q, Ball PointNormal::*x, Ball PointNormal::*y,
                            long prec) {
        const Ball ux = sub(q[0].*x, q[1].*x, prec), uy = sub(q[0].*y, q[1].*y, prec);
        const Ball vx = sub(q[0].*x, q[2].*x, prec), vy = sub(q[0].*y, q[2].*y, prec);
        Ball d;
        arb_mul(d.get(), ux.get(), vy.get(), prec);
        arb_submul(d.get(), uy.get(), vx.get(), prec);
        return d;
    }

    // Branch (C): V = P_i - s L_in nu_i is a Voronoi circle's center only if
    // it has not crossed E_i's medial axis (beyond it the mirror image of P_i
    // is nearer, so rho is not the signed distance). For a >= b the inward
    // normal at the frame point (x, y) = (a cos theta, b sin theta) meets the
    // major axis at depth (b / a) sqrt(b^2 cos^2 theta + a^2 sin^2 theta) =
    // sqrt((b^2 / a^2)^2 x^2 + y^2), inside the medial axis |x| <= (a^2 -
    // b^2) / a; at most b; for a circle r. Narrows s to [0, max depth / L_in]
    // with an upper bound of that depth over the box's arc of each site;
    // false: s is empty (every point of the box lies beyond a medial axis).
    // The solutions of the algebraic system beyond the axis are no Voronoi
    // circles, and boxes around them could never be excluded otherwise.
    bool narrow_to_medial_depth(const std::array<PointNormal, 3>& q, Ball& s, long prec) const {
        for (int i = 0; i < 3; ++i) {
            const Ellipse& e = *sites_[i];
            const Rational& minor = std::min(e.a(), e.b());
            Ball depth(minor, prec);
            if (e.a() != e.b()) {
                const Ball dx = sub(q[i].px, Ball(e.xc(), prec), prec), dy = sub(q[i].py, Ball(e.yc(), prec), prec);
                const Ball c(e.cos_rotation(), prec), sn(e.sin_rotation(), prec);
                Ball along, across;  // along the a-axis, along the b-axis
                arb_mul(along.get(), dx.get(), c.get(), prec);
                arb_addmul(along.get(), dy.get(), sn.get(), prec);
                arb_mul(across.get(), dy.get(), c.get(), prec);
                arb_submul(across.get(), dx.get(), sn.get(), prec);
                const bool a_major = e.a() > e.b();
                const Rational& major = a_major ? e.a() : e.b();
                Ball& x = a_major ? along : across;
                Ball& y = a_major ? across : along;
                const Rational ratio = minor * minor / (major * major);
                arb_mul(x.get(), x.get(), Ball(ratio, prec).get(), prec);
                Ball squared;
                arb_sqr(squared.get(), x.get(), prec);
                arb_addmul(squared.get(), y.get(), y.get(), prec);
                Ball over_arc;
                arb_sqrt(over_arc.get(), squared.get(), prec);
                if (arb_is_finite(over_arc.get())) arb_min(depth.get(), depth.get(), over_arc.get(), prec);
            }
            Arf upper;
            arb_get_ubound_arf(upper.get(), depth.get(), prec);
            arf_mul_2exp_si(upper.get(), upper.get(), -internal_scale_);
            Ball range;
            arb_set_interval_arf(range.get(), Arf().get(), upper.get(), prec);
            if (!arb_intersection(s.get(), s.get(), range.get(), prec)) return false;
        }
        return true;
    }

    // Branch (C): rho <= 0 is the signed distance to all three only at a
    // point V inside all three (closed). V = P_i - s L_in nu_i for each i:
    // false when those ranges are disjoint or when their intersection lies
    // certainly outside some site (its quadratic form exceeds 1). For sites
    // that come near one another without a common point the pair equations
    // exclude most boxes of (C) at once; this excludes about a quarter of the
    // rest (60 close disjoint ellipse triples: 494 boxes of (C) instead of
    // 660, 8 of them the roots of each triple).
    bool center_inside_sites(const std::array<PointNormal, 3>& q, const Ball& s, long prec) const {
        Ball depth;
        arb_mul_2exp_si(depth.get(), s.get(), internal_scale_);
        Ball vx, vy, x, y;
        for (int i = 0; i < 3; ++i) {
            arb_set(x.get(), q[i].px.get());
            arb_submul(x.get(), depth.get(), q[i].nx.get(), prec);
            arb_set(y.get(), q[i].py.get());
            arb_submul(y.get(), depth.get(), q[i].ny.get(), prec);
            if (i == 0) {
                vx = x, vy = y;
            } else if (!arb_intersection(vx.get(), vx.get(), x.get(), prec) ||
                       !arb_intersection(vy.get(), vy.get(), y.get(), prec)) {
                return false;
            }
        }
        for (const Ellipse* e : sites_) {
            const Ball dx = sub(vx, Ball(e->xc(), prec), prec), dy = sub(vy, Ball(e->yc(), prec), prec);
            const Ball c(e->cos_rotation(), prec), sn(e->sin_rotation(), prec);
            Ball along, across, form, term;
            arb_mul(along.get(), dx.get(), c.get(), prec);
            arb_addmul(along.get(), dy.get(), sn.get(), prec);
            arb_mul(across.get(), dy.get(), c.get(), prec);
            arb_submul(across.get(), dx.get(), sn.get(), prec);
            arb_sqr(form.get(), along.get(), prec);
            arb_div(form.get(), form.get(), Ball(e->a() * e->a(), prec).get(), prec);
            arb_sqr(term.get(), across.get(), prec);
            arb_div(term.get(), term.get(), Ball(e->b() * e->b(), prec).get(), prec);
            arb_add(form.get(), form.get(), term.get(), prec);
            arb_sub_ui(form.get(), form.get(), 1, prec);
            if (arb_is_positive(form.get())) return false;
        }
        return true;
    }

    std::array<const Ellipse*, 3> sites_;
    long scale_;           // L = 2^scale_
    long internal_scale_;  // L_in = 2^internal_scale_
    bool internal_possible_;
    std::vector<ArcRanges> arcs_;  // site i, flipped f at 2 i + f
};

}  // namespace

long site_magnitude_bits(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3) {
    Rational magnitude = 0, size = e1.a();
    for (const Ellipse* e : {&e1, &e2, &e3}) {
        magnitude = std::max(magnitude, std::max(absolute(e->xc()), absolute(e->yc())) + std::max(e->a(), e->b()));
        size = std::min({size, e->a(), e->b()});
    }
    return std::max(0L, exponent_bound(magnitude / size));
}

VoronoiCircleSearchResult search_voronoi_circle(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3,
                                                const std::function<bool(const VoronoiCircleStart&)>& try_start,
                                                const VoronoiCircleSearchOptions& options) {
    const SearchSystem system({&e1, &e2, &e3});
    const long magnitude = site_magnitude_bits(e1, e2, e3);
    auto precision_of = [&](const Box& box) {
        return std::max(kMinimumPrecision, kGuardBits + magnitude + resolution_bits(box));
    };
    // Breadth-first: every box of a level is examined before a finer one, so
    // the work spreads evenly over the domain and the search cannot dive
    // into a region of near-solutions (a clockwise circle, a near-tangent
    // line) while the circle waits elsewhere.
    std::deque<Box> queue;
    for (Branch branch : {Branch::radius, Branch::inverse_radius, Branch::internal}) {
        if (branch == Branch::internal && !system.internal_possible()) continue;
        for (int charts = 0; charts < 8; ++charts)
            queue.push_back(system.root_box(charts, branch, kMinimumPrecision + magnitude));
    }
    VoronoiCircleSearchResult result;
    while (!queue.empty()) {
        if (result.boxes >= options.max_boxes)
            throw Error("Voronoi circle search: " + std::to_string(result.boxes) +
                        " boxes neither certified nor excluded the circle of the triple (degenerate: a line "
                        "tangent to all three sites? or an internal circle centered on a site's medial axis?)");
        Box box = std::move(queue.front());
        queue.pop_front();
        ++result.boxes;
        const long prec = precision_of(box);
        if (system.excluded_by_ranges(box, prec)) continue;
        // Newton from the midpoint of a box that merely lies near the circle
        // often reaches it: every box that survives the range tests offers its
        // midpoint, before the costlier Krawczyk exclusion.
        if (try_start(system.start_of(box, prec))) {
            result.found = true;
            return result;
        }
        if (system.excluded_by_krawczyk(box, prec)) continue;
        auto halves = system.bisect(std::move(box), prec + 1);  // the halves are one bit finer
        queue.push_back(std::move(halves.first));
        queue.push_back(std::move(halves.second));
    }
    return result;
}

}  // namespace ellvor
