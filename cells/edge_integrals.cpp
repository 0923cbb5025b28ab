#include "cells/edge_integrals.hpp"

namespace ellvor {

void add_edge(const EdgeIntegrals& edge, bool forward, const BallPoint& c, long prec, CellIntegrals& cell) {
    using M = EdgeMeasure;
    const auto& m = edge.m;
    // u, v: the origin about c; the vertices about the origin.
    Ball u, v, xs, ys, xe, ye;
    arb_set_d(u.get(), edge.origin[0]);
    arb_set_d(v.get(), edge.origin[1]);
    arb_sub(xs.get(), edge.start.x.get(), u.get(), prec);
    arb_sub(ys.get(), edge.start.y.get(), v.get(), prec);
    arb_sub(xe.get(), edge.end.x.get(), u.get(), prec);
    arb_sub(ye.get(), edge.end.y.get(), v.get(), prec);
    arb_sub(u.get(), u.get(), c.x.get(), prec);
    arb_sub(v.get(), v.get(), c.y.get(), prec);
    Ball dx, dy, y_dy, u2, v2, t;
    arb_sub(dx.get(), xe.get(), xs.get(), prec);  // integral of dX
    arb_sub(dy.get(), ye.get(), ys.get(), prec);  // integral of dY
    arb_sqr(y_dy.get(), ye.get(), prec);          // integral of Y dY = (Ye^2 - Ys^2) / 2
    arb_submul(y_dy.get(), ys.get(), ys.get(), prec);
    arb_mul_2exp_si(y_dy.get(), y_dy.get(), -1);
    arb_sqr(u2.get(), u.get(), prec);
    arb_sqr(v2.get(), v.get(), prec);

    // sum of coefficient * term, then times `scale` (an exact dyadic or 1/3)
    // and the orientation, added to `out`.
    const auto add = [&](Ball& out, std::initializer_list<std::pair<const Ball*, const Ball*>> terms, long numerator,
                         unsigned long denominator) {
        Ball sum;
        for (const auto& [coefficient, term] : terms) {
            if (coefficient)
                arb_addmul(sum.get(), coefficient->get(), term->get(), prec);
            else
                arb_add(sum.get(), sum.get(), term->get(), prec);
        }
        arb_mul_si(sum.get(), sum.get(), forward ? numerator : -numerator, prec);
        arb_div_ui(sum.get(), sum.get(), denominator, prec);
        arb_add(out.get(), out.get(), sum.get(), prec);
    };
    // area = 1/2 ((X dY + u dY) - (Y dX + v dX))
    Ball minus_y_dx, minus_v;
    arb_neg(minus_y_dx.get(), m[M::y_dx].get());
    arb_neg(minus_v.get(), v.get());
    add(cell.area, {{nullptr, &m[M::x_dy]}, {&u, &dy}, {nullptr, &minus_y_dx}, {&minus_v, &dx}}, 1, 2);
    // x: 1/2 (X^2 dY + 2 u X dY + u^2 dY)
    Ball two_u, two_v, three_u, three_v, three_u2, three_v2, u3, v3, u2v, two_uv;
    arb_mul_2exp_si(two_u.get(), u.get(), 1);
    arb_mul_2exp_si(two_v.get(), v.get(), 1);
    add(cell.first[0], {{nullptr, &m[M::x2_dy]}, {&two_u, &m[M::x_dy]}, {&u2, &dy}}, 1, 2);
    // y: -1/2 (Y^2 dX + 2 v Y dX + v^2 dX)
    add(cell.first[1], {{nullptr, &m[M::y2_dx]}, {&two_v, &m[M::y_dx]}, {&v2, &dx}}, -1, 2);
    // x^2: 1/3 (X^3 dY + 3 u X^2 dY + 3 u^2 X dY + u^3 dY)
    arb_mul_ui(three_u.get(), u.get(), 3, prec);
    arb_mul_ui(three_v.get(), v.get(), 3, prec);
    arb_mul_ui(three_u2.get(), u2.get(), 3, prec);
    arb_mul_ui(three_v2.get(), v2.get(), 3, prec);
    arb_mul(u3.get(), u2.get(), u.get(), prec);
    arb_mul(v3.get(), v2.get(), v.get(), prec);
    add(cell.second[0], {{nullptr, &m[M::x3_dy]}, {&three_u, &m[M::x2_dy]}, {&three_u2, &m[M::x_dy]}, {&u3, &dy}}, 1, 3);
    // y^2: -1/3 (Y^3 dX + 3 v Y^2 dX + 3 v^2 Y dX + v^3 dX)
    add(cell.second[2], {{nullptr, &m[M::y3_dx]}, {&three_v, &m[M::y2_dx]}, {&three_v2, &m[M::y_dx]}, {&v3, &dx}}, -1,
        3);
    // x y: 1/2 (X^2 Y dY + 2 u X Y dY + u^2 Y dY + v X^2 dY + 2 u v X dY + u^2 v dY)
    arb_mul(u2v.get(), u2.get(), v.get(), prec);
    arb_mul(two_uv.get(), two_u.get(), v.get(), prec);
    add(cell.second[1],
        {{nullptr, &m[M::x2y_dy]}, {&two_u, &m[M::xy_dy]}, {&u2, &y_dy}, {&v, &m[M::x2_dy]}, {&two_uv, &m[M::x_dy]},
         {&u2v, &dy}},
        1, 2);
    arb_add(cell.perimeter.get(), cell.perimeter.get(), m[M::length].get(), prec);
}

}  // namespace ellvor
