#include "predicates/infinite_vertex_conflict.hpp"

#include "predicates/circle_predicates.hpp"
#include "predicates/circle_semi_static.hpp"
#include "predicates/external_bitangent.hpp"
#include "sites/ellipse_polynomials.hpp"
#include "util/error.hpp"
#include "util/interval.hpp"
#include "util/precision.hpp"

#include <arb_fmpz_poly.h>

#include <cmath>
#include <vector>

namespace ellvor {

namespace {

constexpr long kBitangentFormalDegree = 4;
constexpr long kIntersectionFormalDegree = 4;

// ---------------------------------------------------------------- filter --
//
// With a direction n (not necessarily unit), the support function of an
// ellipse is h(n) = n.C + sqrt(a^2 (n.u)^2 + b^2 (n.v)^2): the sites' common
// external tangent lines are the directions where h1 = h2, and Q meets the
// open half-plane beyond L iff h_Q(n) > h_1(n). The filter finds the right
// root in floating point, then proves with interval arithmetic that a tiny
// parameter interval holds exactly one root (a sign change: there are only two
// external tangents), that it is the tangent with the sites on the right, and
// the sign of h_Q - h_1 over the whole interval.

// Support value h(n) and its derivative along the unit circle, h'(phi) =
// S(phi) . (-sin phi, cos phi) with S the support point, in plain doubles.
struct SupportDouble {
    double value, slope;
};
SupportDouble support_double(const Ellipse::Enclosure& k, double c, double s) {
    const double cw = k.cos.mid(), sw = k.sin.mid(), a2 = k.a.mid() * k.a.mid(), b2 = k.b.mid() * k.b.mid();
    const double nu = c * cw + s * sw, nv = s * cw - c * sw;
    const double norm = std::sqrt(a2 * nu * nu + b2 * nv * nv);
    const double lu = a2 * nu / norm, lv = b2 * nv / norm;
    const double x = k.xc.mid() + cw * lu - sw * lv, y = k.yc.mid() + sw * lu + cw * lv;
    return {c * k.xc.mid() + s * k.yc.mid() + norm, -x * s + y * c};
}

// Support value and support point of an ellipse, enclosed, for an enclosed
// direction n.
struct SupportEnclosure {
    Interval value, x, y;
};
SupportEnclosure support_enclosure(const Ellipse::Enclosure& k, Interval nx, Interval ny) {
    const Interval nu = nx * k.cos + ny * k.sin, nv = ny * k.cos - nx * k.sin;
    const Interval a2 = k.a.square(), b2 = k.b.square();
    const Interval norm = (a2 * nu.square() + b2 * nv.square()).sqrt();
    const Interval lu = a2 * nu / norm, lv = b2 * nv / norm;  // local support point
    const Interval x = k.xc + k.cos * lu - k.sin * lv, y = k.yc + k.sin * lu + k.cos * lv;
    return {nx * k.xc + ny * k.yc + norm, x, y};
}

// The direction of angle phi in the rational chart n = +-(1 - tau^2, 2 tau),
// |tau| <= 1, evaluated for an enclosed tau.
struct Chart {
    double sign;
    Interval nx(Interval tau) const { return (Interval(1.0) - tau.square()) * Interval(sign); }
    Interval ny(Interval tau) const { return Interval(2.0) * tau * Interval(sign); }
};

// +1 / -1 when proved, 0 when undecided.
// Certifies a floating-point root phi of h1 - h2 (see above): +1 / -1 when it
// is the tangent L and Q's side of it is proven, 0 when undecided, and
// kOtherTangent when phi is proven to be the other external tangent.
constexpr int kOtherTangent = 2;
int certify_tangent(const Ellipse::Enclosure& k1, const Ellipse::Enclosure& k2, const Ellipse::Enclosure& kq,
                    double phi) {
    double sign = 1.0;
    if (std::cos(phi) < 0) {
        phi = phi > 0 ? phi - M_PI : phi + M_PI;
        sign = -1.0;
    }
    const Chart chart{sign};
    for (double width : {1e-13, 1e-10, 1e-7}) {
        const double tau_lo = std::tan(0.5 * (phi - width)), tau_hi = std::tan(0.5 * (phi + width));
        auto difference = [&](Interval tau) {
            const Interval nx = chart.nx(tau), ny = chart.ny(tau);
            return support_enclosure(k1, nx, ny).value - support_enclosure(k2, nx, ny).value;
        };
        const Interval at_lo = difference(Interval(tau_lo)), at_hi = difference(Interval(tau_hi));
        const bool sign_change = (at_lo.negative() && at_hi.positive()) || (at_lo.positive() && at_hi.negative());
        if (!sign_change) continue;
        // Exactly one external tangent in the interval: is it L?
        const Interval tau(tau_lo, tau_hi);
        const Interval nx = chart.nx(tau), ny = chart.ny(tau);
        const SupportEnclosure s1 = support_enclosure(k1, nx, ny), s2 = support_enclosure(k2, nx, ny);
        // d = n turned clockwise; L has E1's contact before E2's along d.
        const Interval along = (s2.x - s1.x) * ny - (s2.y - s1.y) * nx;
        if (along.negative()) return kOtherTangent;
        if (!along.positive()) return 0;
        const Interval beyond = support_enclosure(kq, nx, ny).value - s1.value;
        return beyond.positive() ? -1 : beyond.negative() ? 1 : 0;
    }
    return 0;
}

// +1 / -1 when proved, 0 when undecided.
int filter_stage(const Ellipse& e1, const Ellipse& e2, const Ellipse& q) {
    const auto &k1 = e1.enclosure(), &k2 = e2.enclosure(), &kq = q.enclosure();
    if (!(k1.a.finite() && k1.xc.finite() && k2.a.finite() && k2.xc.finite() && kq.a.finite() && kq.xc.finite()))
        return 0;
    auto f = [&](double phi) {
        const double c = std::cos(phi), s = std::sin(phi);
        const SupportDouble h1 = support_double(k1, c, s), h2 = support_double(k2, c, s);
        return SupportDouble{h1.value - h2.value, h1.slope - h2.slope};
    };
    // Newton refinement of a root of h1 - h2 inside [lo, hi] (bisection when a
    // step leaves the bracket; plain Newton when there is none).
    auto refine = [&](double x, double lo, double hi, bool bracketed, bool rising) {
        for (int it = 0; it < 40; ++it) {
            const SupportDouble v = f(x);
            if (bracketed) ((v.value < 0) == rising ? lo : hi) = x;
            double next = x - v.value / v.slope;
            if (bracketed && !(next > lo && next < hi)) next = 0.5 * (lo + hi);
            if (!std::isfinite(next)) return x;
            if (std::fabs(next - x) <= 1e-15 * (1 + std::fabs(x))) return next;
            x = next;
        }
        return x;
    };
    // First guess: the same tangent of the circles with the sites' centers and
    // mean radii, in closed form: n.(C2 - C1) = r1 - r2 with d = n turned
    // clockwise pointing from E1 to E2.
    {
        const double dx = k2.xc.mid() - k1.xc.mid(), dy = k2.yc.mid() - k1.yc.mid(), length = std::hypot(dx, dy);
        const double r1 = 0.5 * (k1.a.mid() + k1.b.mid()), r2 = 0.5 * (k2.a.mid() + k2.b.mid());
        const double c = (r1 - r2) / length;
        if (length > 0 && std::fabs(c) < 1) {
            const double ex = dx / length, ey = dy / length, root = std::sqrt(1 - c * c);
            const double phi = refine(std::atan2(c * ey + root * ex, c * ex - root * ey), 0, 0, false, false);
            const int s = certify_tangent(k1, k2, kq, phi);
            if (s == 1 || s == -1) return s;
        }
    }
    // Otherwise bracket the roots of h1 - h2 by sampling.
    constexpr int kSamples = 16;
    double prev_phi = -M_PI, prev = f(prev_phi).value;
    for (int i = 1; i <= kSamples; ++i) {
        const double phi = -M_PI + 2 * M_PI * i / kSamples, value = f(phi).value;
        if ((prev < 0) != (value < 0)) {
            const int s = certify_tangent(k1, k2, kq, refine(0.5 * (prev_phi + phi), prev_phi, phi, true, prev < 0));
            if (s == 1 || s == -1) return s;
        }
        prev_phi = phi, prev = value;
    }
    return 0;
}

// ------------------------------------------------------------- exact --

// Outward normal of E at boundary parameter t (the gradient of its conic,
// i.e. the first two coefficients of the tangent line), enclosed.
BallPoint outward_normal(const Ellipse& e, BoundaryParameter& t, long prec) {
    const LinePolynomials l = tangent_line(e);
    BallPoint n;
    if (t.at_infinity()) {  // the coefficients of t^2 give the line at the i-point
        n.x = Ball(Rational(l.l1.coeff(2)), prec);
        n.y = Ball(Rational(l.l2.coeff(2)), prec);
        return n;
    }
    const Ball tb = t.value->to_ball(prec);
    arb_fmpz_poly_evaluate_arb(n.x.get(), l.l1.get(), tb.get(), prec);
    arb_fmpz_poly_evaluate_arb(n.y.get(), l.l2.get(), tb.get(), prec);
    return n;
}

// Position along the direction d of the point where a line with normal n
// touches E, for a line supporting E on the side n points to:
//   support point = C + R (a^2 m1, b^2 m2) / sqrt(a^2 m1^2 + b^2 m2^2), m = R^T n.
Ball support_position(const Ellipse& e, const BallPoint& n, const BallPoint& d, long prec) {
    Ball c(e.cos_rotation(), prec), s(e.sin_rotation(), prec), a2(e.a() * e.a(), prec), b2(e.b() * e.b(), prec);
    Ball m1, m2, t, u, norm, px, py, result;
    arb_mul(m1.get(), c.get(), n.x.get(), prec);  // m1 = c nx + s ny
    arb_addmul(m1.get(), s.get(), n.y.get(), prec);
    arb_mul(m2.get(), c.get(), n.y.get(), prec);  // m2 = c ny - s nx
    arb_submul(m2.get(), s.get(), n.x.get(), prec);
    arb_sqr(t.get(), m1.get(), prec);
    arb_mul(norm.get(), t.get(), a2.get(), prec);
    arb_sqr(t.get(), m2.get(), prec);
    arb_addmul(norm.get(), t.get(), b2.get(), prec);
    arb_sqrt(norm.get(), norm.get(), prec);
    arb_mul(m1.get(), m1.get(), a2.get(), prec);  // local support point (a^2 m1, b^2 m2)/norm
    arb_mul(m2.get(), m2.get(), b2.get(), prec);
    arb_div(m1.get(), m1.get(), norm.get(), prec);
    arb_div(m2.get(), m2.get(), norm.get(), prec);
    arb_mul(px.get(), c.get(), m1.get(), prec);  // R (m1, m2) + C
    arb_submul(px.get(), s.get(), m2.get(), prec);
    arb_add(px.get(), px.get(), Ball(e.xc(), prec).get(), prec);
    arb_mul(py.get(), s.get(), m1.get(), prec);
    arb_addmul(py.get(), c.get(), m2.get(), prec);
    arb_add(py.get(), py.get(), Ball(e.yc(), prec).get(), prec);
    arb_mul(result.get(), px.get(), d.x.get(), prec);
    arb_addmul(result.get(), py.get(), d.y.get(), prec);
    return result;
}

// CGAL's tie-break: Q touches L from the sites' side; NEGATIVE iff its contact
// point is strictly between those of E1 and E2 along L. The contact points
// coincide only when Q passes through a site's contact point, which is
// checked exactly; otherwise Arb separates them at some precision (distinct
// algebraic numbers of degree 4: reaching the limit is an internal error).
Decision<Sign> break_tangency_tie(const Ellipse& e1, const Ellipse& e2, const Ellipse& q, BoundaryParameter& t1) {
    BoundaryParameter t2 = external_bitangent_on(e2, e1, HullSide::departure);
    const bool at_first = sign_at(intersection_quartic(e1, q), kIntersectionFormalDegree, t1) == 0;
    const bool at_second = sign_at(intersection_quartic(e2, q), kIntersectionFormalDegree, t2) == 0;
    if (at_first || at_second) return Decision<Sign>::decided(Sign::positive, Stage::exact);
    for (long prec = precision::kStart; prec <= precision::kResumeLimit; prec *= 2) {
        const BallPoint n = outward_normal(e1, t1, prec);
        BallPoint d;  // the direction of L from E1's contact to E2's: n turned clockwise
        d.x = n.y;
        arb_neg(d.y.get(), n.x.get());
        const Ball s1 = support_position(e1, n, d, prec), s2 = support_position(e2, n, d, prec),
                   sq = support_position(q, n, d, prec);
        Ball after_first, before_second;
        arb_sub(after_first.get(), sq.get(), s1.get(), prec);
        arb_sub(before_second.get(), s2.get(), sq.get(), prec);
        const int a = after_first.certain_sign(), b = before_second.certain_sign();
        if (a < 0 || b < 0) return Decision<Sign>::decided(Sign::positive, Stage::exact, prec);
        if (a > 0 && b > 0) return Decision<Sign>::decided(Sign::negative, Stage::exact, prec);
    }
    throw Error("infinite_vertex_conflict: contact points on the bitangent not separated within " +
                std::to_string(precision::kResumeLimit) + " bits (internal error)");
}

}  // namespace

Decision<Sign> infinite_vertex_conflict(const Ellipse& e1, const Ellipse& e2, const Ellipse& q,
                                        const InfiniteVertexConflictOptions& options) {
    auto exactly = [](Sign s) { return Decision<Sign>::decided(s, Stage::exact); };
    // L is tangent to E1 where the counter-clockwise hull of E1 and E2 arrives
    // on E1: directed from E1's contact to E2's, both sites lie on its right.
    // Three circles: the closed form, in doubles with a static error bound,
    // else exactly; both cost less than the general filter.
    if (options.use_circle_closed_form && e1.is_circle() && e2.is_circle() && q.is_circle()) {
        if (options.use_filter) {
            const Decision<Sign> fast = circle_infinite_vertex_conflict_semi_static(e1, e2, q);
            if (fast.is_decided()) return fast;
        }
        return exactly(sign_of(circle_infinite_vertex_conflict(e1, e2, q)));
    }
    if (options.use_filter)
        if (int s = filter_stage(e1, e2, q)) return Decision<Sign>::decided(sign_of(s), Stage::filter);
    BoundaryParameter t1 = external_bitangent_on(e1, e2, HullSide::arrival);
    // Does L (the tangent of E1 at t1) cross Q, touch it, or miss it?
    const int meets = sign_at(bitangent_quartic(e1, q), kBitangentFormalDegree, t1);
    if (meets < 0) return exactly(Sign::negative);
    // Q on the sites' side of L (negative) or beyond it, judged by its center.
    const int side = sign_at(tangent_side_quadratic(e1, q.center()), 2, t1);
    if (side > 0) return exactly(Sign::negative);
    if (meets > 0) return exactly(Sign::positive);
    return break_tangency_tie(e1, e2, q, t1);
}

}  // namespace ellvor
