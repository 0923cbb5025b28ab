#include "subdivision/medial_axis_circle.hpp"

#include "sites/medial_axis.hpp"
#include "util/precision.hpp"

#include <arb_mat.h>

#include <optional>

namespace ellvor {
namespace {

constexpr long kGuardBits = precision::kSolverGuardBits;
constexpr int kNewtonSteps = 12;

// The medial axis of E_i in balls: center, direction, m^2 and m^2 / c^2.
struct AxisBalls {
    Ball cx, cy, dx, dy, minor2, curvature;
    AxisBalls(const MedialAxis& a, long prec)
        : cx(a.cx, prec), cy(a.cy, prec), dx(a.dx, prec), dy(a.dy, prec), minor2(a.minor2, prec),
          curvature(a.minor2 / a.focal2, prec) {}
};

// The system in X = (t, rho, h):
//   P(t) + rho nu(t) - (C + h d) = 0,  rho^2 - m^2 + (m^2/c^2) h^2 = 0.
void axis_tangency_system(const BoundaryChart& chart, const AxisBalls& axis, const BallMatrix& X, BallMatrix& F,
                          BallMatrix* J, long prec) {
    Ball t, tmp;
    arb_set(t.get(), X.at(0, 0));
    const arb_struct *rho = X.at(1, 0), *h = X.at(2, 0);
    const BoundaryChart::Local q = chart.evaluate(t, prec, J != nullptr);
    const std::array<const Ball*, 2> p{&q.px, &q.py}, n{&q.nx, &q.ny}, c{&axis.cx, &axis.cy}, d{&axis.dx, &axis.dy};
    for (int r = 0; r < 2; ++r) {
        arb_mul(tmp.get(), rho, n[r]->get(), prec);
        arb_add(F.at(r, 0), p[r]->get(), tmp.get(), prec);
        arb_sub(F.at(r, 0), F.at(r, 0), c[r]->get(), prec);
        arb_mul(tmp.get(), h, d[r]->get(), prec);
        arb_sub(F.at(r, 0), F.at(r, 0), tmp.get(), prec);
    }
    arb_sqr(F.at(2, 0), rho, prec);
    arb_sub(F.at(2, 0), F.at(2, 0), axis.minor2.get(), prec);
    arb_sqr(tmp.get(), h, prec);
    arb_addmul(F.at(2, 0), tmp.get(), axis.curvature.get(), prec);
    if (!J) return;
    const std::array<const Ball*, 2> dp{&q.dpx, &q.dpy}, dn{&q.dnx, &q.dny};
    for (int r = 0; r < 2; ++r) {
        arb_mul(tmp.get(), rho, dn[r]->get(), prec);
        arb_add(J->at(r, 0), dp[r]->get(), tmp.get(), prec);
        arb_set(J->at(r, 1), n[r]->get());
        arb_neg(J->at(r, 2), d[r]->get());
    }
    arb_zero(J->at(2, 0));
    arb_mul_2exp_si(J->at(2, 1), rho, 1);
    arb_mul(J->at(2, 2), h, axis.curvature.get(), prec);
    arb_mul_2exp_si(J->at(2, 2), J->at(2, 2), 1);
}

// Newton from `start`, then Krawczyk on a box inflated from the last
// correction: its image, holding exactly one root, or nothing.
std::optional<BallMatrix> certify_axis_tangency(const BoundaryChart& chart, const AxisBalls& axis, BallMatrix m,
                                                long prec) {
    constexpr int n = 3;
    BallMatrix F(n, 1), J(n, n), step(n, 1), Y(n, n), YF(n, 1);
    for (int k = 0; k < kNewtonSteps; ++k) {
        axis_tangency_system(chart, axis, m, F, &J, prec);
        if (!arb_mat_approx_solve(step.get(), J.get(), F.get(), prec)) return std::nullopt;
        for (int j = 0; j < n; ++j) {
            arb_sub(m.at(j, 0), m.at(j, 0), step.at(j, 0), prec);
            mag_zero(arb_radref(m.at(j, 0)));
        }
    }
    axis_tangency_system(chart, axis, m, F, &J, prec);
    if (!arb_mat_approx_inv(Y.get(), J.get(), prec)) return std::nullopt;
    arb_mat_mul(YF.get(), Y.get(), F.get(), prec);
    BallMatrix X = m;
    for (int j = 0; j < n; ++j) {
        Mag r, floor;
        arb_get_mag(r.get(), YF.at(j, 0));
        mag_mul_2exp_si(r.get(), r.get(), 2);
        mag_set_ui_2exp_si(floor.get(), 1, kGuardBits - prec);
        mag_add(arb_radref(X.at(j, 0)), r.get(), floor.get());
    }
    BallMatrix M(n, n), D(n, 1), K(n, 1);
    axis_tangency_system(chart, axis, X, F, &J, prec);
    arb_mat_mul(M.get(), Y.get(), J.get(), prec);
    arb_mat_neg(M.get(), M.get());
    for (int j = 0; j < n; ++j) arb_add_si(M.at(j, j), M.at(j, j), 1, prec);
    arb_mat_sub(D.get(), X.get(), m.get(), prec);
    arb_mat_mul(K.get(), M.get(), D.get(), prec);
    arb_mat_sub(K.get(), K.get(), YF.get(), prec);
    arb_mat_add(K.get(), K.get(), m.get(), prec);
    for (int j = 0; j < n; ++j)
        if (!arb_contains_interior(X.at(j, 0), K.at(j, 0))) return std::nullopt;
    return K;
}

// A ball's open rational neighbourhood (its radius doubled, plus 2^-prec):
// the exact test counts roots in open intervals.
void open_hull(const arb_struct* b, long prec, Rational& lo, Rational& hi) {
    Ball w;
    arb_set(w.get(), b);
    arb_add_error_mag(w.get(), arb_radref(b));
    arb_add_error_2exp_si(w.get(), -prec);
    ball_endpoints(w, lo, hi);
}

// The chart parameter of the boundary point at angle theta (cos c, sin s):
// t = tan(theta/2) = s/(1 + c) = (1 - c)/s, or u = -1/t, each by the form
// whose denominator is away from 0.
Ball chart_parameter(bool flipped, const Ball& c, const Ball& s, long prec) {
    Ball num, den, r;
    const bool c_nonnegative = arf_sgn(arb_midref(c.get())) >= 0;
    if (!flipped) {
        if (c_nonnegative) {
            arb_set(num.get(), s.get());
            arb_add_si(den.get(), c.get(), 1, prec);
        } else {
            arb_sub_si(num.get(), c.get(), 1, prec);
            arb_neg(num.get(), num.get());
            arb_set(den.get(), s.get());
        }
    } else if (!c_nonnegative) {
        arb_neg(num.get(), s.get());
        arb_sub_si(den.get(), c.get(), 1, prec);
        arb_neg(den.get(), den.get());
    } else {
        arb_add_si(num.get(), c.get(), 1, prec);
        arb_neg(num.get(), num.get());
        arb_set(den.get(), s.get());
    }
    arb_div(r.get(), num.get(), den.get(), prec);
    return r;
}

// A foot of the medial-axis circle about C + h d (h in a ball) on E, one of
// the two mirror images, lies in the ball t of the chart?
bool foot_in(const Ellipse& e, const MedialAxis& axis, const BoundaryChart& chart, const Ball& h, const arb_struct* t,
             long prec) {
    Ball along, across, tmp, c, s;
    const Ball stretch(axis.major2 / axis.focal2, prec), major2(axis.major2, prec), minor2(axis.minor2, prec),
        a(e.a(), prec), b(e.b(), prec);
    arb_mul(along.get(), h.get(), stretch.get(), prec);
    // across^2 = m^2 (1 - along^2 / M^2) > 0: |h| < c^2/M, V on the axis' open segment.
    arb_sqr(tmp.get(), along.get(), prec);
    arb_div(tmp.get(), tmp.get(), major2.get(), prec);
    arb_sub_si(tmp.get(), tmp.get(), 1, prec);
    arb_neg(tmp.get(), tmp.get());
    arb_mul(tmp.get(), tmp.get(), minor2.get(), prec);
    if (!arb_is_positive(tmp.get())) return false;
    arb_sqrt(across.get(), tmp.get(), prec);
    for (int sign : {1, -1}) {
        Ball off;
        arb_mul_si(off.get(), across.get(), sign, prec);
        // (xi, eta) in E's own frame; cos theta = xi / a, sin theta = eta / b.
        const Ball& xi = axis.along_a ? along : off;
        const Ball& eta = axis.along_a ? off : along;
        arb_div(c.get(), xi.get(), a.get(), prec);
        arb_div(s.get(), eta.get(), b.get(), prec);
        if (arb_contains(t, chart_parameter(chart.flipped(), c, s, prec).get())) return true;
    }
    return false;
}

}  // namespace

bool center_on_medial_axis(const std::array<const Ellipse*, 3>& sites,
                           const std::array<const BoundaryChart*, 3>& charts, const BallMatrix& K, int i, long prec,
                           CommonAxisTangency common_tangency) {
    if (!common_tangency || !arb_is_negative(K.at(3, 0))) return false;
    const std::optional<MedialAxis> axis = medial_axis(*sites[i]);
    if (!axis) return false;
    // The tangencies at about twice the box's bits: their boxes must fit in K.
    const long work = 2 * prec + kGuardBits;
    const AxisBalls balls(*axis, work);
    // V's coordinate along the axis (a start) and across it (must allow 0).
    Ball along, across, ox, oy, tmp;
    arb_sub(ox.get(), K.at(4, 0), balls.cx.get(), work);
    arb_sub(oy.get(), K.at(5, 0), balls.cy.get(), work);
    arb_mul(along.get(), ox.get(), balls.dx.get(), work);
    arb_addmul(along.get(), oy.get(), balls.dy.get(), work);
    arb_mul(across.get(), oy.get(), balls.dx.get(), work);
    arb_submul(across.get(), ox.get(), balls.dy.get(), work);
    if (!arb_contains_zero(across.get())) return false;

    std::array<BallMatrix, 2> tangency{BallMatrix(3, 1), BallMatrix(3, 1)};
    std::array<Rational, 4> bounds;
    for (int k = 0; k < 2; ++k) {
        const int j = (i + 1 + k) % 3;
        BallMatrix start(3, 1);
        arb_get_mid_arb(start.at(0, 0), K.at(j, 0));
        arb_get_mid_arb(start.at(1, 0), K.at(3, 0));
        arb_get_mid_arb(start.at(2, 0), along.get());
        std::optional<BallMatrix> root = certify_axis_tangency(*charts[j], balls, start, work);
        // The root's t_j and rho lie in K's: with the foot and V below, the
        // tuple is a root of the tritangent system in K.
        if (!root || !arb_contains(K.at(j, 0), root->at(0, 0)) || !arb_contains(K.at(3, 0), root->at(1, 0)))
            return false;
        open_hull(root->at(2, 0), work, bounds[2 * k], bounds[2 * k + 1]);
        tangency[k] = *root;
    }
    // h_j = h_k exactly (then rho_j = rho_k = -sqrt(s(h))).
    if (!common_tangency(*sites[i], *sites[(i + 1) % 3], *sites[(i + 2) % 3], bounds[0], bounds[1], bounds[2],
                         bounds[3]))
        return false;
    // V = C + h d in K's center, a foot of the circle in K's t_i.
    Ball h, vx, vy;
    arb_set(h.get(), tangency[0].at(2, 0));
    arb_mul(vx.get(), h.get(), balls.dx.get(), work);
    arb_add(vx.get(), vx.get(), balls.cx.get(), work);
    arb_mul(vy.get(), h.get(), balls.dy.get(), work);
    arb_add(vy.get(), vy.get(), balls.cy.get(), work);
    if (!arb_contains(K.at(4, 0), vx.get()) || !arb_contains(K.at(5, 0), vy.get())) return false;
    return foot_in(*sites[i], *axis, *charts[i], h, K.at(i, 0), work);
}

}  // namespace ellvor
