#include "subdivision/point_ellipse_distance.hpp"

#include "subdivision/boundary_chart.hpp"
#include "subdivision/nearest_point.hpp"

#include <cmath>

namespace ellvor {

int certified_side(const Ellipse& q, const Ball& x, const Ball& y, long prec) {
    const auto& k = q.conic();
    Ball v, term, two(Rational(2), prec);
    // A x^2 + 2B xy + C y^2 + 2D x + 2E y + F
    arb_sqr(term.get(), x.get(), prec);
    arb_mul(v.get(), term.get(), Ball(k[0], prec).get(), prec);
    arb_mul(term.get(), x.get(), y.get(), prec);
    arb_mul(term.get(), term.get(), Ball(k[1] * Rational(2), prec).get(), prec);
    arb_add(v.get(), v.get(), term.get(), prec);
    arb_sqr(term.get(), y.get(), prec);
    arb_addmul(v.get(), term.get(), Ball(k[2], prec).get(), prec);
    arb_addmul(v.get(), x.get(), Ball(k[3] * Rational(2), prec).get(), prec);
    arb_addmul(v.get(), y.get(), Ball(k[4] * Rational(2), prec).get(), prec);
    arb_add(v.get(), v.get(), Ball(k[5], prec).get(), prec);
    return v.certain_sign();
}

namespace {

// h(t) = (V - P(t)) x nu(t): zero iff V is on the normal at P(t); and h'(t).
void normal_condition(const BoundaryChart::Local& p, const Ball& x, const Ball& y, Ball& h, Ball* dh, long prec) {
    Ball dx, dy, tmp;
    arb_sub(dx.get(), x.get(), p.px.get(), prec);
    arb_sub(dy.get(), y.get(), p.py.get(), prec);
    arb_mul(h.get(), dx.get(), p.ny.get(), prec);
    arb_submul(h.get(), dy.get(), p.nx.get(), prec);
    if (!dh) return;
    // h' = -(P' x nu) + (V - P) x nu'
    arb_mul(dh->get(), p.dpy.get(), p.nx.get(), prec);
    arb_submul(dh->get(), p.dpx.get(), p.ny.get(), prec);
    arb_addmul(dh->get(), dx.get(), p.dny.get(), prec);
    arb_submul(dh->get(), dy.get(), p.dnx.get(), prec);
}

}  // namespace

bool certified_outside_distance(const Ellipse& q, const Ball& x, const Ball& y, long prec, Ball& distance) {
    // Floating-point nearest point, then its chart.
    const auto& k = q.enclosure();
    const double dx = x.mid_double() - k.xc.mid(), dy = y.mid_double() - k.yc.mid();
    double theta = approximate_nearest_angle(k.a.mid(), k.b.mid(), k.cos.mid() * dx + k.sin.mid() * dy,
                                             k.cos.mid() * dy - k.sin.mid() * dx);
    if (!std::isfinite(theta)) return false;
    theta = std::remainder(theta, 2 * M_PI);
    const bool flipped = std::fabs(theta) > M_PI / 2;
    const BoundaryChart chart(q, flipped);
    Ball t;
    arb_set_d(t.get(), flipped ? -1 / std::tan(theta / 2) : std::tan(theta / 2));

    // Newton on the midpoints up to the rounding level of prec.
    Ball xm, ym, h, dh, step;
    arb_get_mid_arb(xm.get(), x.get());
    arb_get_mid_arb(ym.get(), y.get());
    for (int it = 0; it < 64; ++it) {
        normal_condition(chart.evaluate(t, prec), xm, ym, h, &dh, prec);
        arb_div(step.get(), h.get(), dh.get(), prec);
        arb_get_mid_arb(step.get(), step.get());
        arb_sub(t.get(), t.get(), step.get(), prec);
        if (arf_is_zero(arb_midref(step.get())) ||
            arf_cmpabs_2exp_si(arb_midref(step.get()), -prec + 8) < 0)
            break;
    }
    // Interval Newton on T = t +- r, for every V in the balls.
    // The box must hold the foot points of all of V's balls: its radius is
    // well above both the rounding level and V's own radius.
    Ball T = t, r;
    mag_set_ui_2exp_si(arb_radref(r.get()), 1, -prec + 24);
    Mag spread;
    mag_add(spread.get(), arb_radref(x.get()), arb_radref(y.get()));
    mag_mul_2exp_si(spread.get(), spread.get(), 6);
    mag_add(arb_radref(r.get()), arb_radref(r.get()), spread.get());
    arb_add_error(T.get(), r.get());
    normal_condition(chart.evaluate(t, prec, false), x, y, h, nullptr, prec);
    normal_condition(chart.evaluate(T, prec), x, y, step, &dh, prec);
    Ball N;
    arb_div(N.get(), h.get(), dh.get(), prec);
    arb_sub(N.get(), t.get(), N.get(), prec);
    if (!arb_contains_interior(T.get(), N.get())) return false;
    // Length along the outward normal at the foot point.
    const BoundaryChart::Local p = chart.evaluate(N, prec, false);
    Ball ddx, ddy;
    arb_sub(ddx.get(), x.get(), p.px.get(), prec);
    arb_sub(ddy.get(), y.get(), p.py.get(), prec);
    arb_mul(distance.get(), ddx.get(), p.nx.get(), prec);
    arb_addmul(distance.get(), ddy.get(), p.ny.get(), prec);
    return arb_is_positive(distance.get());
}

}  // namespace ellvor
