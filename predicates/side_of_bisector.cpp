#include "predicates/side_of_bisector.hpp"

#include "circles/circle_semi_static.hpp"
#include "exact/algebraic_real.hpp"
#include "exact/real_roots.hpp"
#include "sites/ellipse_polynomials.hpp"
#include "predicates/distance_filter.hpp"
#include "util/error.hpp"
#include "util/interval.hpp"

#include <cmath>
#include <optional>
#include <vector>

namespace ellvor {

namespace {

// ---------------------------------------------------------------- filter --

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



// Two circles: the signed distances are |p - c| - r in closed form.
int circle_filter(const Ellipse& e1, const Ellipse& e2, Interval px, Interval py) {
    auto signed_distance = [&](const Ellipse& e) {
        const auto& k = e.enclosure();
        return ((px - k.xc).square() + (py - k.yc).square()).sqrt() - k.a;
    };
    const Interval d1 = signed_distance(e1), d2 = signed_distance(e2);
    if (!d1.finite() || !d2.finite()) return 0;
    return d1.hi < d2.lo ? 1 : d2.hi < d1.lo ? -1 : 0;
}

// sign(sqrt(A) - sqrt(B) - delta) for rationals A, B >= 0, exactly: the sign
// of sqrt(A) - sqrt(B) is that of A - B; when it and delta have the same sign,
// compare the squares (A + B - delta^2)^2 and 4AB.
int sign_of_root_difference(const Rational& A, const Rational& B, const Rational& delta) {
    const int u = (A - B).sign(), d = delta.sign();
    if (d == 0) return u;
    if (u != d) return u != 0 ? u : -d;
    const Rational M = A + B - delta * delta;
    // |sqrt(A) - sqrt(B)|^2 - delta^2 = M - 2 sqrt(AB)
    const int magnitude = M.sign() <= 0 ? (M.is_zero() && (A * B).is_zero() ? 0 : -1)
                                        : (M * M - Rational(4) * A * B).sign();
    return u * magnitude;
}

// Two circles, exactly: d_i = |p - c_i| - r_i, and the sign of d2 - d1.
int circle_exact(const Ellipse& e1, const Ellipse& e2, const Point& p) {
    auto squared = [&](const Ellipse& e) {
        const Rational dx = p.x - e.xc(), dy = p.y - e.yc();
        return dx * dx + dy * dy;
    };
    return sign_of_root_difference(squared(e2), squared(e1), e2.a() - e1.a());
}

// The point p = (x, y), enclosed in (px, py); p itself is made only for the
// exact stages.
Decision<Sign> decide_side(const Ellipse& e1, const Ellipse& e2, const Rational& x, const Rational& y,
                           const Interval& px, const Interval& py, const SideOfBisectorOptions& options) {
    auto decided = [](int s, Stage stage, long prec = 0) { return Decision<Sign>::decided(sign_of(s), stage, prec); };
    if (e1.is_circle() && e2.is_circle()) {
        if (options.use_filter)
            if (int s = circle_filter(e1, e2, px, py)) return decided(s, Stage::filter);
        return decided(circle_exact(e1, e2, Point{x, y}), Stage::exact);
    }
    // The sites' inscribed and circumscribed disks bound both signed
    // distances: decides most points whose distances differ by more than the
    // sites' R - r (the walk's points are other sites' centers).
    if (options.use_filter) {
        const Interval d1 = signed_distance_disk_bounds(e1.enclosure(), px, py),
                       d2 = signed_distance_disk_bounds(e2.enclosure(), px, py);
        if (d1.finite() && d2.finite()) {
            if (d1.hi < d2.lo) return decided(1, Stage::filter);
            if (d2.hi < d1.lo) return decided(-1, Stage::filter);
        }
    }
    // Which side of each boundary p is on: inside one and outside the other
    // decides at once (signed distances).
    const LocalPoint q1 = to_local(e1, px, py), q2 = to_local(e2, px, py);
    int side1 = filtered_side(q1), side2 = filtered_side(q2);
    Stage side_stage = Stage::filter;
    if (side1 == 0 || side2 == 0) {
        side_stage = Stage::exact;
        side1 = e1.side_of_point(x, y);
        side2 = e2.side_of_point(x, y);
    }
    if (side1 != side2) return decided(side1 < side2 ? 1 : -1, side_stage);
    if (side1 == 0) return decided(0, Stage::exact);  // on both boundaries

    if (options.use_filter)
        if (int s = filter_stage(q1, q2, side1, side2)) return decided(s, Stage::filter);

    // Both outside: nearer means smaller squared distance; both inside: the
    // signed distance is -d, so nearer means larger d.
    const Point p{x, y};
    const int orientation = side1 > 0 ? 1 : -1;
    FootPoints feet1 = foot_points(e1, p), feet2 = foot_points(e2, p);
    long prec = precision::kStart;
    for (; prec <= options.max_precision; prec *= 2) {
        Ball diff;
        arb_sub(diff.get(), squared_distance(e2, p, feet2, prec).get(),
                squared_distance(e1, p, feet1, prec).get(), prec);
        if (int s = diff.certain_sign()) return decided(orientation * s, Stage::subdivision, prec);
    }
    // Exact: each squared distance is the root of its squared-distance quartic
    // isolated by its ball (the balls shrink to points, so isolation succeeds;
    // the limit reports an inconsistency rather than looping); compare the
    // two algebraic numbers.
    const IntPolynomial delta1 = squared_distance_quartic(e1, p), delta2 = squared_distance_quartic(e2, p);
    for (; prec <= precision::kExactIsolationLimit; prec *= 2) {
        auto d1 = unique_root_in(delta1, squared_distance(e1, p, feet1, prec));
        auto d2 = unique_root_in(delta2, squared_distance(e2, p, feet2, prec));
        if (d1 && d2) return decided(orientation * compare(*d2, *d1), Stage::exact, prec);
    }
    throw Error("side_of_bisector: no squared-distance root isolated (internal error)");
}

}  // namespace

Decision<Sign> side_of_bisector(const Ellipse& e1, const Ellipse& e2, const Point& p,
                                const SideOfBisectorOptions& options) {
    return decide_side(e1, e2, p.x, p.y, enclose(p.x), enclose(p.y), options);
}

Decision<Sign> side_of_bisector_at_center(const Ellipse& e1, const Ellipse& e2, const Ellipse& site,
                                          const SideOfBisectorOptions& options) {
    // The walk's calls on circles of doubles: one semi-static sign, no interval.
    if (options.use_filter && e1.is_dyadic_circle() && e2.is_dyadic_circle() && site.is_dyadic_circle()) {
        const Decision<Sign> fast = circle_side_of_bisector_at_center_semi_static(e1, e2, site);
        if (fast.is_decided()) return fast;
    }
    const Ellipse::Enclosure& k = site.enclosure();
    return decide_side(e1, e2, site.xc(), site.yc(), k.xc, k.yc, options);
}

}  // namespace ellvor
