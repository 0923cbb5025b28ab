#include "predicates/infinite_vertex_conflict.hpp"

#include "circles/circle_predicates.hpp"
#include "circles/circle_semi_static.hpp"
#include "predicates/external_bitangent.hpp"
#include "predicates/support_function.hpp"
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
// L is the common external tangent where the hull arrives on E1; Q meets the
// open half-plane beyond L iff h_Q(n) > h_1(n) at L's normal n, proven over
// an enclosure of n. First over the wide box of ArrivalNormalBox (no
// search: decides Q far from L, most calls on sparse sites), then over a
// tiny interval of normals where h1 - h2 is proven to change sign
// (support_function.hpp). +1 / -1 when proved, 0 when undecided.
int sign_beyond(const Ellipse::Enclosure& kq, const Ellipse::Enclosure& k1, const Interval& nx, const Interval& ny) {
    const Interval beyond = support_value(kq, nx, ny) - support_value(k1, nx, ny);
    return beyond.positive() ? -1 : beyond.negative() ? 1 : 0;
}

// sign_beyond for a box that holds the UNIT normal n (ArrivalNormalBox's):
// there h(n) = n.C + rho(n) with rho(n) between the inscribed and the
// circumscribed radius, and for small sites far apart (most calls) that
// bound decides in a third of the operations. 0 when it does not.
int sign_beyond_by_disks(const Ellipse::Enclosure& kq, const Ellipse::Enclosure& k1, const Interval& nx,
                         const Interval& ny) {
    const Interval radius_q(Interval::min(kq.a.lo, kq.b.lo), Interval::max(kq.a.hi, kq.b.hi));
    const Interval radius_1(Interval::min(k1.a.lo, k1.b.lo), Interval::max(k1.a.hi, k1.b.hi));
    const Interval beyond = nx * (kq.xc - k1.xc) + ny * (kq.yc - k1.yc) + (radius_q - radius_1);
    return beyond.positive() ? -1 : beyond.negative() ? 1 : 0;
}

int filter_stage(const Ellipse& e1, const Ellipse& e2, const Ellipse& q) {
    const Ellipse::Enclosure& kq = q.enclosure();
    if (!(kq.a.finite() && kq.b.finite() && kq.xc.finite() && kq.yc.finite())) return 0;
    if (int s = infinite_vertex_conflict_in_normal_box(e1, e2, q)) return s;
    const std::optional<NormalInterval> n = certified_bitangent_normal(e1, e2, true);
    if (!n) return 0;
    return sign_beyond(kq, e1.enclosure(), n->nx(), n->ny());
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

constexpr int kNormalBoxContractions = 2;

int infinite_vertex_conflict_in_normal_box(const Ellipse& e1, const Ellipse& e2, const Ellipse& q) {
    const Ellipse::Enclosure& kq = q.enclosure();
    if (!(kq.a.finite() && kq.b.finite() && kq.xc.finite() && kq.yc.finite())) return 0;
    const Ellipse::Enclosure k1 = e1.enclosure(), k2 = e2.enclosure();  // made once (sites/ellipse.hpp)
    std::optional<ArrivalNormalBox> box = ArrivalNormalBox::of(k1, k2);
    if (!box) return 0;
    // Q far from L is decided on the first box; each contraction costs about
    // as much as a test, and two take most of the rest. The support functions
    // are tried on the last box only: a contraction keeps the box inside the
    // last one, so what they prove on a box they prove on the next (interval
    // operations are inclusion monotone), and on close sites (dense
    // packings) they rarely prove anything before.
    for (int contractions = 0;; ++contractions) {
        if (int s = sign_beyond_by_disks(kq, k1, box->nx(), box->ny())) return s;
        const bool last = contractions == kNormalBoxContractions || !box->contract();
        if (!last) continue;
        return sign_beyond(kq, k1, box->nx(), box->ny());
    }
}

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
