#include "predicates/side_of_bisector.hpp"

#include "exact/algebraic_real.hpp"
#include "exact/real_roots.hpp"
#include "sites/ellipse_polynomials.hpp"
#include "subdivision/nearest_point.hpp"
#include "util/error.hpp"
#include "util/interval.hpp"

#include <cmath>
#include <optional>
#include <vector>

namespace ellvor {

namespace {

// ---------------------------------------------------------------- filter --

// The point p in the ellipse's own frame (xi along the a-axis), enclosed.
struct LocalPoint {
    Interval x, y, a, b;
};

LocalPoint to_local(const Ellipse& e, const Point& p) {
    const Ellipse::Enclosure& k = e.enclosure();
    const Interval dx = enclose(p.x) - k.xc, dy = enclose(p.y) - k.yc;
    return {k.cos * dx + k.sin * dy, k.cos * dy - k.sin * dx, k.a, k.b};
}

// Sign of (x/a)^2 + (y/b)^2 - 1, or 0 when the filter cannot tell.
int filtered_side(const LocalPoint& q) {
    const Interval v = (q.x / q.a).square() + (q.y / q.b).square() - Interval(1.0);
    if (!v.finite()) return 0;
    return v.positive() ? 1 : v.negative() ? -1 : 0;
}

// Certified bounds on the distance from an outside point to the ellipse:
// the distance to a boundary point is an upper bound, the distance to the
// tangent line there (the ellipse lies on one side of it) a lower bound.
// Both meet at the foot point, so a good guess gives a tight interval.
Interval outside_distance_bounds(const LocalPoint& q) {
    double theta = approximate_nearest_angle(q.a.mid(), q.b.mid(), q.x.mid(), q.y.mid());
    // A boundary point through the rational parametrization at an exact double
    // u = tan(theta/2), in the chart where |u| <= 1 (flip by pi otherwise).
    double sign = 1.0;
    if (std::cos(theta) < 0) {
        theta = theta > 0 ? theta - M_PI : theta + M_PI;
        sign = -1.0;
    }
    const Interval u(std::tan(theta / 2));
    const Interval den = Interval(1.0) + u.square();
    const Interval c = (Interval(1.0) - u.square()) / den * Interval(sign);
    const Interval s = (Interval(2.0) * u) / den * Interval(sign);
    const Interval bx = q.a * c, by = q.b * s;
    const Interval dx = q.x - bx, dy = q.y - by;
    const Interval upper = (dx.square() + dy.square()).sqrt();
    const Interval nx = c / q.a, ny = s / q.b;
    const Interval lower = (nx * dx + ny * dy) / (nx.square() + ny.square()).sqrt();
    const Interval d(std::fmax(lower.lo, 0.0), upper.hi);
    return d.finite() ? d : Interval(0.0, INFINITY);
}

// +1 / -1 when decided, 0 when undecided.
int filter_stage(const LocalPoint& q1, const LocalPoint& q2, int side1, int side2) {
    if (side1 != 1 || side2 != 1) return 0;  // the inside case goes to Arb
    const Interval d1 = outside_distance_bounds(q1);
    const Interval d2 = outside_distance_bounds(q2);
    if (d1.hi < d2.lo) return 1;
    if (d2.hi < d1.lo) return -1;
    return 0;
}

// ------------------------------------------------------ Arb and exact --

// The candidates for the nearest boundary point: the real foot points, and the
// i-point when the foot-point quartic loses degree (it is a foot point then).
struct FootPoints {
    std::vector<AlgebraicReal> parameters;
    bool i_point = false;
};

FootPoints foot_points(const Ellipse& e, const Point& p) {
    const IntPolynomial f = foot_point_quartic(e, p);
    // At the center of a circle every boundary point is a foot point; the
    // point at t = 0 stands for all of them.
    if (f.is_zero()) return {{AlgebraicReal::from_rational(Rational(0))}, false};
    return {real_roots(f), f.degree() < 4};
}

// Enclosure of the squared distance from p to the ellipse: the minimum over
// the foot points.
Ball squared_distance(const Ellipse& e, const Point& p, FootPoints& feet, long prec) {
    Ball best, d2, dx, dy;
    const Ball px(p.x, prec), py(p.y, prec);
    bool first = true;
    auto consider = [&](const Ball& x, const Ball& y) {
        arb_sub(dx.get(), x.get(), px.get(), prec);
        arb_sub(dy.get(), y.get(), py.get(), prec);
        arb_sqr(dx.get(), dx.get(), prec);
        arb_sqr(dy.get(), dy.get(), prec);
        arb_add(d2.get(), dx.get(), dy.get(), prec);
        if (first) best = d2;
        else arb_min(best.get(), best.get(), d2.get(), prec);
        first = false;
    };
    for (auto& t : feet.parameters) {
        const BallPoint q = e.point_at(t.to_ball(prec), prec);
        consider(q.x, q.y);
    }
    if (feet.i_point) {
        const Point ip = e.i_point();
        consider(Ball(ip.x, prec), Ball(ip.y, prec));
    }
    return best;
}

// Balls of the squared distances shrink to points, so isolation succeeds long
// before this; reaching it means an inconsistency, reported rather than looped.
constexpr long kExactPrecisionLimit = 1L << 16;

// The root of p inside the ball, if the ball isolates exactly one.
std::optional<AlgebraicReal> unique_root_in(const IntPolynomial& p, const Ball& b) {
    Rational lo, hi;
    ball_endpoints(b, lo, hi);
    const IntPolynomial sq = squarefree_part(p);
    if (lo == hi) {
        if (sign_at_rational(sq, lo) == 0) return AlgebraicReal::from_rational(lo);
        return std::nullopt;
    }
    if (sign_at_rational(sq, lo) == 0 || sign_at_rational(sq, hi) == 0) return std::nullopt;
    if (count_real_roots(sq, lo, hi) != 1) return std::nullopt;
    return AlgebraicReal::from_interval(sq, lo, hi);
}

}  // namespace

SignDecision side_of_bisector(const Ellipse& e1, const Ellipse& e2, const Point& p,
                              const SideOfBisectorOptions& options) {
    // Which side of each boundary p is on: inside one and outside the other
    // decides at once (signed distances).
    const LocalPoint q1 = to_local(e1, p), q2 = to_local(e2, p);
    int side1 = filtered_side(q1), side2 = filtered_side(q2);
    Stage side_stage = Stage::filter;
    if (side1 == 0 || side2 == 0) {
        side_stage = Stage::exact;
        side1 = e1.side_of_point(p.x, p.y);
        side2 = e2.side_of_point(p.x, p.y);
    }
    if (side1 != side2) return {side1 < side2 ? 1 : -1, side_stage, 0};
    if (side1 == 0) return {0, Stage::exact, 0};  // on both boundaries

    if (options.use_filter)
        if (int s = filter_stage(q1, q2, side1, side2)) return {s, Stage::filter, 53};

    // Both outside: nearer means smaller squared distance; both inside: the
    // signed distance is -d, so nearer means larger d.
    const int orientation = side1 > 0 ? 1 : -1;
    FootPoints feet1 = foot_points(e1, p), feet2 = foot_points(e2, p);
    long prec = options.start_precision;
    for (; prec <= options.max_precision; prec *= 2) {
        Ball diff;
        arb_sub(diff.get(), squared_distance(e2, p, feet2, prec).get(),
                squared_distance(e1, p, feet1, prec).get(), prec);
        if (int s = diff.certain_sign()) return {orientation * s, Stage::subdivision, prec};
    }
    // Exact: each squared distance is the root of its squared-distance quartic
    // isolated by its ball; compare the two algebraic numbers.
    const IntPolynomial delta1 = squared_distance_quartic(e1, p), delta2 = squared_distance_quartic(e2, p);
    for (; prec <= kExactPrecisionLimit; prec *= 2) {
        auto d1 = unique_root_in(delta1, squared_distance(e1, p, feet1, prec));
        auto d2 = unique_root_in(delta2, squared_distance(e2, p, feet2, prec));
        if (d1 && d2) return {orientation * compare(*d2, *d1), Stage::exact, prec};
    }
    throw Error("side_of_bisector: no squared-distance root isolated (internal error)");
}

}  // namespace ellvor
