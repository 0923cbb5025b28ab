#include "predicates/bisector_order.hpp"

#include "predicates/support_function.hpp"
#include "predicates/voronoi_vertex_equality.hpp"
#include "util/precision.hpp"

#include <algorithm>

namespace ellvor {

Ball parameter_angle(const Ball& parameter, bool flipped, long prec) {
    Ball theta;
    if (flipped) {
        Ball one(Rational(1), prec), minus_u;
        arb_neg(minus_u.get(), parameter.get());
        arb_atan2(theta.get(), one.get(), minus_u.get(), prec);
    } else {
        arb_atan(theta.get(), parameter.get(), prec);
    }
    arb_mul_2exp_si(theta.get(), theta.get(), 1);
    return theta;
}

BisectorFrame::BisectorFrame(const Ellipse& e1, const Ellipse& e2)
    : departure_(external_bitangent_on(e1, e2, HullSide::departure)) {}

Ball BisectorFrame::position(const Ball& parameter, bool flipped, long prec) {
    Ball start;
    if (departure_.at_infinity()) {
        arb_const_pi(start.get(), prec);  // the i-point, theta = pi
    } else {
        start = parameter_angle(departure_.value->to_ball(prec), false, prec);
    }
    Ball p = parameter_angle(parameter, flipped, prec), two_pi;
    arb_sub(p.get(), p.get(), start.get(), prec);
    arb_const_pi(two_pi.get(), prec);
    arb_mul_2exp_si(two_pi.get(), two_pi.get(), 1);
    // Reduce into (0, 2 pi): both angles lie in intervals of length 2 pi
    // around 0 or pi, so the raw difference lies in (-2 pi, 3 pi).
    if (arb_is_negative(p.get())) arb_add(p.get(), p.get(), two_pi.get(), prec);
    Ball excess;
    arb_sub(excess.get(), p.get(), two_pi.get(), prec);
    if (arb_is_nonnegative(excess.get())) p = excess;
    // A ball that still touches 0 or 2 pi may stand for either representative
    // (a tangency point just past the departure point, computed in the other
    // chart, is 2 pi + epsilon before the reduction): the position is then
    // anywhere in [0, 2 pi] at this precision. A finite vertex lies strictly
    // inside, so a higher precision decides.
    arb_sub(excess.get(), p.get(), two_pi.get(), prec);
    if (!arb_is_positive(p.get()) || !arb_is_negative(excess.get())) {
        arb_const_pi(p.get(), prec);
        arb_add_error(p.get(), p.get());
    }
    return p;
}

Ball vertex_position(BisectorFrame& frame, VoronoiCircleSolver& solver, int index, long prec) {
    solver.refine_existing(std::max(prec - precision::kEnclosureGuard, 1L));
    const auto& c = solver.enclosure();
    return frame.position(c.parameter[index], c.flipped[index], prec);
}

Decision<Sign> order_on_bisector(BisectorFrame& frame, VoronoiCircleSolver& a, int index_a, VoronoiCircleSolver& b,
                                 int index_b, const RefinementOptions& options) {
    return refine_then_exact(
        "order_on_bisector", options,
        [&](long prec) {
            const Ball pa = vertex_position(frame, a, index_a, prec), pb = vertex_position(frame, b, index_b, prec);
            Ball difference;
            arb_sub(difference.get(), pa.get(), pb.get(), prec);
            return difference.certain_sign();
        },
        [&](long prec) {
            return ContactComparison({a.sites(), &a, index_a}, {b.sites(), &b, index_b}).same_contact_point(prec);
        });
}

namespace {

// The pseudo-angle of BisectorFrameInDoubles for a parameter of its chart.
std::optional<Interval> pseudo_angle(const Interval& parameter, bool flipped) {
    if (!(parameter.lo >= -1 && parameter.hi <= 1)) return std::nullopt;
    return flipped ? parameter + Interval(2.0) : parameter;
}

}  // namespace

BisectorFrameInDoubles::BisectorFrameInDoubles(const Ellipse& e1, const Ellipse& e2) {
    const std::optional<NormalInterval> n = certified_bitangent_normal(e1, e2, false);
    if (!n) return;
    // The boundary point of E1 with outward normal n: (cos theta, sin theta)
    // is along (a m1, b m2), m = R^T n (the ellipse's frame).
    const Ellipse::Enclosure& k = e1.enclosure();
    const Interval nx = n->nx(), ny = n->ny();
    const Interval p = k.a * (k.cos * nx + k.sin * ny), q = k.b * (k.cos * ny - k.sin * nx);
    const Interval norm = (p.square() + q.square()).sqrt();
    // t = tan(theta / 2) = q / (|(p, q)| + p) where cos theta >= 0, else
    // u = -1/t = -q / (|(p, q)| - p); near the seam (p of either sign)
    // nothing is claimed.
    if (p.lo >= 0) departure_ = pseudo_angle(q / (norm + p), false);
    else if (p.hi <= 0) departure_ = pseudo_angle(-q / (norm - p), true);
}

std::optional<Interval> BisectorFrameInDoubles::position(const Interval& parameter, bool flipped) const {
    const std::optional<Interval> angle = pseudo_angle(parameter, flipped);
    if (!departure_ || !angle) return std::nullopt;
    // Both in [-1, 3]: the difference lies in [-4, 4]; reduce into (0, 4).
    Interval d = *angle - *departure_;
    if (d.hi < 0) d = d + Interval(4.0);
    if (!(d.lo > 0 && d.hi < 4)) return std::nullopt;
    return d;
}

std::optional<Sign> order_on_bisector_in_doubles(const BisectorFrameInDoubles& frame, const DoubleVoronoiCircle& a,
                                                 int index_a, const DoubleVoronoiCircle& b, int index_b) {
    const std::optional<Interval> pa = frame.position(a.parameter[index_a], a.flipped[index_a]);
    const std::optional<Interval> pb = frame.position(b.parameter[index_b], b.flipped[index_b]);
    if (!pa || !pb) return std::nullopt;
    if (pa->hi < pb->lo) return Sign::negative;
    if (pb->hi < pa->lo) return Sign::positive;
    return std::nullopt;
}

}  // namespace ellvor
