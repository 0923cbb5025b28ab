#include "predicates/bisector_order.hpp"

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

}  // namespace ellvor
