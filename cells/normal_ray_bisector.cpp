#include "cells/normal_ray_bisector.hpp"

#include "predicates/relative_position.hpp"

#include <algorithm>
#include <cmath>

namespace ellvor {

// A site's boundary at a complex angle: the point, the unnormalized outward
// normal n~, the derivatives of both in the angle, N^2 = |n~|^2.
struct NormalRayBisector::Boundary {
    ComplexBall x, y, nx, ny, dx, dy, dnx, dny, n2;
};

namespace {

using Boundary = NormalRayBisector::Boundary;

// (lx, ly) in the site's frame to the plane: (lx cos - ly sin, lx sin + ly cos).
void rotate(const SiteBalls& e, const ComplexBall& lx, const ComplexBall& ly, long prec, ComplexBall& x,
            ComplexBall& y) {
    ComplexBall t;
    acb_mul_arb(x.get(), lx.get(), e.cos.get(), prec);
    acb_mul_arb(t.get(), ly.get(), e.sin.get(), prec);
    acb_sub(x.get(), x.get(), t.get(), prec);
    acb_mul_arb(y.get(), lx.get(), e.sin.get(), prec);
    acb_mul_arb(t.get(), ly.get(), e.cos.get(), prec);
    acb_add(y.get(), y.get(), t.get(), prec);
}

void boundary_at(const SiteBalls& e, const ComplexBall& angle, long prec, Boundary& out) {
    ComplexBall c, s, lx, ly, t;
    acb_sin_cos(s.get(), c.get(), angle.get(), prec);
    // point (a c, b s)
    acb_mul_arb(lx.get(), c.get(), e.a.get(), prec);
    acb_mul_arb(ly.get(), s.get(), e.b.get(), prec);
    rotate(e, lx, ly, prec, out.x, out.y);
    acb_add_arb(out.x.get(), out.x.get(), e.xc.get(), prec);
    acb_add_arb(out.y.get(), out.y.get(), e.yc.get(), prec);
    // normal (b c, a s)
    acb_mul_arb(lx.get(), c.get(), e.b.get(), prec);
    acb_mul_arb(ly.get(), s.get(), e.a.get(), prec);
    rotate(e, lx, ly, prec, out.nx, out.ny);
    // N^2 = (a s)^2 + (b c)^2
    acb_mul(out.n2.get(), lx.get(), lx.get(), prec);
    acb_mul(t.get(), ly.get(), ly.get(), prec);
    acb_add(out.n2.get(), out.n2.get(), t.get(), prec);
    // d point = (-a s, b c)
    acb_mul_arb(lx.get(), s.get(), e.a.get(), prec);
    acb_neg(lx.get(), lx.get());
    acb_mul_arb(ly.get(), c.get(), e.b.get(), prec);
    rotate(e, lx, ly, prec, out.dx, out.dy);
    // d normal = (-b s, a c)
    acb_mul_arb(lx.get(), s.get(), e.b.get(), prec);
    acb_neg(lx.get(), lx.get());
    acb_mul_arb(ly.get(), c.get(), e.a.get(), prec);
    rotate(e, lx, ly, prec, out.dnx, out.dny);
}

double magnitude(const ComplexBall& z) {
    Mag m;
    acb_get_mag(m.get(), z.get());
    return mag_get_d(m.get());
}

// The complex square [z +/- r] + i [0 +/- r] around a real point z.
ComplexBall square(const ComplexBall& z, double r) {
    ComplexBall box(z);
    mag_set_d(arb_radref(box.real()), r);
    mag_set_d(arb_radref(box.imag()), r);
    return box;
}

// e = d . f for plane vectors given by coordinates.
void dot(const ComplexBall& dx, const ComplexBall& dy, const ComplexBall& fx, const ComplexBall& fy, long prec,
         ComplexBall& e) {
    ComplexBall t;
    acb_mul(e.get(), dx.get(), fx.get(), prec);
    acb_mul(t.get(), dy.get(), fy.get(), prec);
    acb_add(e.get(), e.get(), t.get(), prec);
}

// The foot-point equation of V on q at phi, f = (V - Q(phi)) . Q'(phi), and
// its derivative f' = -|Q'|^2 + (V - Q) . Q'' with Q'' = -(Q - C).
void foot_equation(const SiteBalls& q, const Boundary& bq, const ComplexBall& vx, const ComplexBall& vy, long prec,
                   ComplexBall& f, ComplexBall* df) {
    ComplexBall dx, dy;
    acb_sub(dx.get(), vx.get(), bq.x.get(), prec);
    acb_sub(dy.get(), vy.get(), bq.y.get(), prec);
    dot(dx, dy, bq.dx, bq.dy, prec, f);
    if (!df) return;
    ComplexBall t, cx, cy;
    dot(bq.dx, bq.dy, bq.dx, bq.dy, prec, *df);
    acb_neg(df->get(), df->get());
    acb_sub_arb(cx.get(), bq.x.get(), q.xc.get(), prec);
    acb_sub_arb(cy.get(), bq.y.get(), q.yc.get(), prec);
    dot(dx, dy, cx, cy, prec, t);
    acb_sub(df->get(), df->get(), t.get(), prec);
}

// Newton on the foot point of a point V (midpoints only).
void foot_newton(const SiteBalls& q, const ComplexBall& vx, const ComplexBall& vy, int steps, long prec, ComplexBall& phi) {
    Boundary b;
    ComplexBall f, df;
    for (int k = 0; k < steps; ++k) {
        boundary_at(q, phi, prec, b);
        foot_equation(q, b, vx, vy, prec, f, &df);
        acb_div(f.get(), f.get(), df.get(), prec);
        acb_sub(phi.get(), phi.get(), f.get(), prec);
        acb_get_mid(phi.get(), phi.get());
    }
}

// The tie function of V = P + s n~ and its foot point Q on q,
//     g = |V - Q|^2 - s^2 N^2 = |P - Q|^2 + 2 s (P - Q) . n~,
// and its total derivatives (the foot point's own derivative drops out,
// (V - Q) . Q' = 0; and P' . n~ = 0):
//     dg/ds = 2 (P - Q) . n~,   dg/dtheta = 2 (P - Q) . (P' + s n~').
// Written so, the s^2 terms cancel exactly: interval evaluation stays tight
// far along the edge, where |V - Q| is large.
void tie(const Boundary& bp, const Boundary& bq, const ComplexBall& s, long prec, ComplexBall* g, ComplexBall* dg_ds,
         ComplexBall* dg_dtheta) {
    ComplexBall dx, dy, t, u;
    acb_sub(dx.get(), bp.x.get(), bq.x.get(), prec);
    acb_sub(dy.get(), bp.y.get(), bq.y.get(), prec);
    dot(dx, dy, bp.nx, bp.ny, prec, u);  // (P - Q) . n~
    if (g) {
        dot(dx, dy, dx, dy, prec, *g);
        acb_mul(t.get(), s.get(), u.get(), prec);
        acb_mul_2exp_si(t.get(), t.get(), 1);
        acb_add(g->get(), g->get(), t.get(), prec);
    }
    if (dg_ds) acb_mul_2exp_si(dg_ds->get(), u.get(), 1);
    if (dg_dtheta) {
        ComplexBall wx, wy;
        acb_mul(wx.get(), s.get(), bp.dnx.get(), prec);
        acb_add(wx.get(), wx.get(), bp.dx.get(), prec);
        acb_mul(wy.get(), s.get(), bp.dny.get(), prec);
        acb_add(wy.get(), wy.get(), bp.dy.get(), prec);
        dot(dx, dy, wx, wy, prec, *dg_dtheta);
        acb_mul_2exp_si(dg_dtheta->get(), dg_dtheta->get(), 1);
    }
}

void ray_point(const Boundary& bp, const ComplexBall& s, long prec, ComplexBall& vx, ComplexBall& vy) {
    acb_mul(vx.get(), s.get(), bp.nx.get(), prec);
    acb_add(vx.get(), vx.get(), bp.x.get(), prec);
    acb_mul(vy.get(), s.get(), bp.ny.get(), prec);
    acb_add(vy.get(), vy.get(), bp.y.get(), prec);
}

// N and Nq, the normals' lengths (principal square roots: indeterminate if a
// ball reaches the cut, which the certificate then fails).
void normal_lengths(const Boundary& bp, const Boundary& bq, long prec, ComplexBall& np, ComplexBall& nq) {
    acb_sqrt_analytic(np.get(), bp.n2.get(), 1, prec);
    acb_sqrt_analytic(nq.get(), bq.n2.get(), 1, prec);
}

// The signed tie (see the header), g = (V - Q) . n~q - s N Nq, and dg/ds =
// n~ . n~q - N Nq (its derivative in the foot point, Nq' (t Nq - s N),
// vanishes on the bisector).
void signed_tie_value(const Boundary& bp, const Boundary& bq, const ComplexBall& s, long prec, ComplexBall& g,
                      ComplexBall& dg_ds) {
    ComplexBall vx, vy, np, nq, nn, t;
    ray_point(bp, s, prec, vx, vy);
    acb_sub(vx.get(), vx.get(), bq.x.get(), prec);
    acb_sub(vy.get(), vy.get(), bq.y.get(), prec);
    normal_lengths(bp, bq, prec, np, nq);
    acb_mul(nn.get(), np.get(), nq.get(), prec);
    dot(vx, vy, bq.nx, bq.ny, prec, g);
    acb_mul(t.get(), s.get(), nn.get(), prec);
    acb_sub(g.get(), g.get(), t.get(), prec);
    dot(bp.nx, bp.ny, bq.nx, bq.ny, prec, dg_ds);
    acb_sub(dg_ds.get(), dg_ds.get(), nn.get(), prec);
}



// A 2 x 2 complex matrix.
struct Matrix2 {
    ComplexBall m[2][2];
    // out = this x
    void apply(const ComplexBall x[2], long prec, ComplexBall out[2]) const {
        ComplexBall t;
        for (int i = 0; i < 2; ++i) {
            acb_mul(out[i].get(), m[i][0].get(), x[0].get(), prec);
            acb_mul(t.get(), m[i][1].get(), x[1].get(), prec);
            acb_add(out[i].get(), out[i].get(), t.get(), prec);
        }
    }
    // out = this b
    void times(const Matrix2& b, long prec, Matrix2& out) const {
        ComplexBall t;
        for (int i = 0; i < 2; ++i)
            for (int j = 0; j < 2; ++j) {
                acb_mul(out.m[i][j].get(), m[i][0].get(), b.m[0][j].get(), prec);
                acb_mul(t.get(), m[i][1].get(), b.m[1][j].get(), prec);
                acb_add(out.m[i][j].get(), out.m[i][j].get(), t.get(), prec);
            }
    }
};

// The bisector system in x = (s, phi) for a theta (p's boundary bp there)
// and q's boundary bq at phi:
//     F0 = (V - Q) . Q'                    (Q is a foot point of V on q)
//     F1 = |P - Q|^2 + 2 s (P - Q) . n~    (= |V - Q|^2 - s^2 N^2)
// with V = P + s n~; its Jacobian in (s, phi) and its derivative in theta:
//     J = [ n~ . Q'         -|Q'|^2 - (V - Q) . (Q - Cq) ]
//         [ 2 (P - Q) . n~  -2 F0                        ]
//     F_theta = ( (P' + s n~') . Q',  2 (P - Q) . (P' + s n~') ).
// With the signed tie, F1 = (V - Q) . n~q - s N Nq (the
// header) has the row (with Q' . n~q = 0 and N' = n~ . n~' / N)
//     [ n~ . n~q - N Nq,   (V - Q) . n~q' - s N (n~q . n~q') / Nq ],
//     F_theta = (P' + s n~') . n~q - s (n~ . n~' / N) Nq.
// Evaluated over boxes, each entry contains its values at every point.
struct BisectorSystem {
    ComplexBall F[2], F_theta[2];
    Matrix2 J;

    void evaluate(const SiteBalls& q, const Boundary& bp, const Boundary& bq, const ComplexBall& s, bool is_signed,
                  long prec) {
        ComplexBall vx, vy, dx, dy, ex, ey, wx, wy, cx, cy, t;
        ray_point(bp, s, prec, vx, vy);
        acb_sub(dx.get(), vx.get(), bq.x.get(), prec);  // V - Q
        acb_sub(dy.get(), vy.get(), bq.y.get(), prec);
        acb_sub(ex.get(), bp.x.get(), bq.x.get(), prec);  // P - Q
        acb_sub(ey.get(), bp.y.get(), bq.y.get(), prec);
        dot(dx, dy, bq.dx, bq.dy, prec, F[0]);
        ComplexBall e_n;
        dot(ex, ey, bp.nx, bp.ny, prec, e_n);
        dot(ex, ey, ex, ey, prec, F[1]);
        acb_mul(t.get(), s.get(), e_n.get(), prec);
        acb_mul_2exp_si(t.get(), t.get(), 1);
        acb_add(F[1].get(), F[1].get(), t.get(), prec);

        dot(bp.nx, bp.ny, bq.dx, bq.dy, prec, J.m[0][0]);
        dot(bq.dx, bq.dy, bq.dx, bq.dy, prec, J.m[0][1]);
        acb_neg(J.m[0][1].get(), J.m[0][1].get());
        acb_sub_arb(cx.get(), bq.x.get(), q.xc.get(), prec);
        acb_sub_arb(cy.get(), bq.y.get(), q.yc.get(), prec);
        dot(dx, dy, cx, cy, prec, t);
        acb_sub(J.m[0][1].get(), J.m[0][1].get(), t.get(), prec);
        acb_mul_2exp_si(J.m[1][0].get(), e_n.get(), 1);
        acb_mul_2exp_si(J.m[1][1].get(), F[0].get(), 1);
        acb_neg(J.m[1][1].get(), J.m[1][1].get());

        // W = P' + s n~'
        acb_mul(wx.get(), s.get(), bp.dnx.get(), prec);
        acb_add(wx.get(), wx.get(), bp.dx.get(), prec);
        acb_mul(wy.get(), s.get(), bp.dny.get(), prec);
        acb_add(wy.get(), wy.get(), bp.dy.get(), prec);
        dot(wx, wy, bq.dx, bq.dy, prec, F_theta[0]);
        dot(ex, ey, wx, wy, prec, F_theta[1]);
        acb_mul_2exp_si(F_theta[1].get(), F_theta[1].get(), 1);
        if (is_signed) signed_row(bp, bq, s, dx, dy, wx, wy, prec);
    }

    // Row 1 of the signed tie (above), V - Q = (dx, dy), P' + s n~' = (wx, wy).
    void signed_row(const Boundary& bp, const Boundary& bq, const ComplexBall& s, const ComplexBall& dx,
                    const ComplexBall& dy, const ComplexBall& wx, const ComplexBall& wy, long prec) {
        ComplexBall np, nq, nn, t;
        normal_lengths(bp, bq, prec, np, nq);
        acb_mul(nn.get(), np.get(), nq.get(), prec);
        dot(dx, dy, bq.nx, bq.ny, prec, F[1]);
        acb_mul(t.get(), s.get(), nn.get(), prec);
        acb_sub(F[1].get(), F[1].get(), t.get(), prec);
        dot(bp.nx, bp.ny, bq.nx, bq.ny, prec, J.m[1][0]);
        acb_sub(J.m[1][0].get(), J.m[1][0].get(), nn.get(), prec);
        dot(dx, dy, bq.dnx, bq.dny, prec, J.m[1][1]);
        dot(bq.nx, bq.ny, bq.dnx, bq.dny, prec, t);
        acb_mul(t.get(), t.get(), s.get(), prec);
        acb_mul(t.get(), t.get(), np.get(), prec);
        acb_div(t.get(), t.get(), nq.get(), prec);
        acb_sub(J.m[1][1].get(), J.m[1][1].get(), t.get(), prec);
        dot(wx, wy, bq.nx, bq.ny, prec, F_theta[1]);
        dot(bp.nx, bp.ny, bp.dnx, bp.dny, prec, t);
        acb_mul(t.get(), t.get(), s.get(), prec);
        acb_mul(t.get(), t.get(), nq.get(), prec);
        acb_div(t.get(), t.get(), np.get(), prec);
        acb_sub(F_theta[1].get(), F_theta[1].get(), t.get(), prec);
    }

    // C = (mid J)^-1, a midpoint matrix; false if mid J is singular.
    bool inverse_of_mid_jacobian(long prec, Matrix2& C) const {
        ComplexBall a, b, c, d, det, t;
        acb_get_mid(a.get(), J.m[0][0].get());
        acb_get_mid(b.get(), J.m[0][1].get());
        acb_get_mid(c.get(), J.m[1][0].get());
        acb_get_mid(d.get(), J.m[1][1].get());
        acb_mul(det.get(), a.get(), d.get(), prec);
        acb_mul(t.get(), b.get(), c.get(), prec);
        acb_sub(det.get(), det.get(), t.get(), prec);
        if (acb_contains_zero(det.get())) return false;
        acb_inv(det.get(), det.get(), prec);
        acb_mul(C.m[0][0].get(), d.get(), det.get(), prec);
        acb_mul(C.m[0][1].get(), b.get(), det.get(), prec);
        acb_neg(C.m[0][1].get(), C.m[0][1].get());
        acb_mul(C.m[1][0].get(), c.get(), det.get(), prec);
        acb_neg(C.m[1][0].get(), C.m[1][0].get());
        acb_mul(C.m[1][1].get(), a.get(), det.get(), prec);
        for (auto& row : C.m)
            for (ComplexBall& e : row) acb_get_mid(e.get(), e.get());
        return true;
    }
};

}  // namespace

SiteBalls::SiteBalls(const Ellipse& e, long prec)
    : a(e.a(), prec), b(e.b(), prec), cos(e.cos_rotation(), prec), sin(e.sin_rotation(), prec), xc(e.xc(), prec),
      yc(e.yc(), prec) {}

NormalRayBisector::NormalRayBisector(const Ellipse& p, const Ellipse& q)
    : NormalRayBisector(p, q, uses_signed_tie(p, q)) {}

NormalRayBisector::NormalRayBisector(const Ellipse& p, const Ellipse& q, bool signed_tie)
    : p_(&p), q_(&q), p_shape_(EllipseShape::of(p)), q_shape_(EllipseShape::of(q)), signed_(signed_tie) {
    origin_[0] = p_shape_.xc, origin_[1] = p_shape_.yc;
    size_ = std::max({p_shape_.a, p_shape_.b, q_shape_.a, q_shape_.b,
                      std::hypot(p_shape_.xc - q_shape_.xc, p_shape_.yc - q_shape_.yc)});
}

bool NormalRayBisector::meet(const Ellipse& p, const Ellipse& q) {
    if (bounding_circles_apart_in_doubles(p, q)) return false;
    const RelativePosition position = *relative_position(p, q);
    return position == RelativePosition::intersecting || position == RelativePosition::externally_tangent;
}

bool NormalRayBisector::uses_signed_tie(const Ellipse& p, const Ellipse& q) {
    // Every pair that meets (its bounding circles overlap, certified), and, a
    // choice either way, pairs whose centers are within 5/4 of the sum of
    // their larger semi-axes: close pairs.
    if (!bounding_circles_apart_in_doubles(p, q)) return true;
    const EllipseShape ps = EllipseShape::of(p), qs = EllipseShape::of(q);
    return std::hypot(ps.xc - qs.xc, ps.yc - qs.yc) < 1.25 * (std::max(ps.a, ps.b) + std::max(qs.a, qs.b));
}

void NormalRayBisector::set_precision(long prec) {
    if (prec == prec_) return;
    pb_ = SiteBalls(*p_, prec);
    qb_ = SiteBalls(*q_, prec);
    // r = min(a, b) / max(a, b), the depth of the medial axis in units of n~.
    for (auto [r, e] : {std::pair<Ball*, const SiteBalls*>{&medial_p_, &pb_}, {&medial_q_, &qb_}}) {
        const bool a_major = arb_ge(e->a.get(), e->b.get());
        arb_div(r->get(), (a_major ? e->b : e->a).get(), (a_major ? e->a : e->b).get(), prec);
    }
    prec_ = prec;
}

bool NormalRayBisector::solve(const ComplexBall& theta, long prec, ComplexBall& s_out) {
    return solve(theta, prec, s_out, nullptr, nullptr, nullptr);
}

bool NormalRayBisector::solve(const ComplexBall& theta, long prec, LinearModel& model) {
    ComplexBall s;
    return solve(theta, prec, s, nullptr, nullptr, nullptr, &model);
}

bool NormalRayBisector::solve(const ComplexBall& theta, long prec, ComplexBall& s_out, ComplexBall* tie_ds,
                              ComplexBall* tie_dtheta, Boundary* p_boundary, LinearModel* model) {
    set_precision(prec);
    // The start: the bisector point on the real normal ray at the middle of
    // the ball, in doubles.
    const double theta0 = arf_get_d(arb_midref(theta.real()), ARF_RND_NEAR);
    if (!std::isfinite(theta0)) return false;
    const std::optional<double> rho = equal_distance_on_normal(p_shape_, q_shape_, theta0, 1e12 * size_);
    if (!rho || !(signed_ || *rho > 0)) return false;
    double px, py, nx, ny;
    p_shape_.point(theta0, px, py);
    p_shape_.normal(theta0, nx, ny);
    const double np = std::hypot(p_shape_.b * std::cos(theta0), p_shape_.a * std::sin(theta0));
    ComplexBall s0, phi0;
    arb_set_d(s0.real(), *rho / np);
    arb_set_d(phi0.real(), q_shape_.nearest_angle(px + *rho * nx, py + *rho * ny));

    // Newton at the real middle of the ball, on midpoints: s, and the foot point of V(s) with it.
    ComplexBall mid, vx, vy, g, dg, step;
    arb_get_mid_arb(mid.real(), theta.real());
    Boundary bp, bq;
    boundary_at(pb_, mid, prec, bp);
    // Until the step is at the working precision (quadratic convergence from
    // the double start; the limit only guards a start that does not converge,
    // which the certificate below then rejects).
    const double small = std::ldexp(1.0, static_cast<int>(std::max(-1000L, 4 - prec)));
    // Rounding noise can keep the step above `small`: stop as soon as it no
    // longer shrinks quadratically (the certificate judges the point).
    // At one limb the double start is already as close as Arb would get it.
    double previous = INFINITY;
    for (int k = 0; k < (prec > 64 ? 60 : 0); ++k) {
        ray_point(bp, s0, prec, vx, vy);
        foot_newton(qb_, vx, vy, 1, prec, phi0);
        boundary_at(qb_, phi0, prec, bq);
        if (signed_)
            signed_tie_value(bp, bq, s0, prec, g, dg);
        else
            tie(bp, bq, s0, prec, &g, &dg, nullptr);
        acb_div(step.get(), g.get(), dg.get(), prec);
        acb_sub(s0.get(), s0.get(), step.get(), prec);
        acb_get_mid(s0.get(), s0.get());
        const double size = magnitude(step);
        if (size <= small * (1 + magnitude(s0)) || size > 0.25 * previous) break;
        previous = size;
    }
    ray_point(bp, s0, prec, vx, vy);
    foot_newton(qb_, vx, vy, 1, prec, phi0);
    boundary_at(qb_, phi0, prec, bq);

    // The system in x = (s, phi) with theta as a parameter, at the middle.
    BisectorSystem at_mid;
    at_mid.evaluate(qb_, bp, bq, s0, signed_, prec);
    Matrix2 C;  // the midpoint inverse of the Jacobian
    if (!at_mid.inverse_of_mid_jacobian(prec, C)) return false;
    // The root moves with theta at about x' = -J^-1 F_theta: the unknown is
    // the remainder y in x = x0 + x' (theta - mid) + y, so that the box of y
    // stays small over a ball on which x itself varies a lot (any slope is
    // correct; a good one makes the certificate hold on wider balls).
    ComplexBall slope[2];
    C.apply(at_mid.F_theta, prec, slope);
    for (ComplexBall& d : slope) {
        acb_neg(d.get(), d.get());
        acb_get_mid(d.get(), d.get());
    }
    ComplexBall dtheta, x_lin[2], t;
    acb_sub(dtheta.get(), theta.get(), mid.get(), prec);
    const ComplexBall* x0[2] = {&s0, &phi0};
    for (int i = 0; i < 2; ++i) {
        acb_mul(x_lin[i].get(), slope[i].get(), dtheta.get(), prec);
        acb_add(x_lin[i].get(), x_lin[i].get(), x0[i]->get(), prec);
    }
    // H(0, theta) = F(x_lin(theta), theta) over the theta-ball in the
    // mean-value form around the middle: F(x0, mid) + H'(S) (Theta - mid),
    // H' = J x' + F_theta over (x_lin(S), S), S a ball holding the segment
    // from mid to every theta of the ball: the ball itself when it holds mid
    // (balls about the reals, as the integrator's and the covers'), else its
    // union with mid (a ball off the reals: H' on it alone proves nothing).
    Boundary bpT;
    boundary_at(pb_, theta, prec, bpT);
    Boundary bp_segment;
    ComplexBall x_segment[2];
    const bool holds_mid = acb_contains(theta.get(), mid.get());
    if (!holds_mid) {
        ComplexBall segment, offset;
        acb_union(segment.get(), theta.get(), mid.get(), prec);
        boundary_at(pb_, segment, prec, bp_segment);
        acb_sub(offset.get(), segment.get(), mid.get(), prec);
        for (int i = 0; i < 2; ++i) {
            acb_mul(x_segment[i].get(), slope[i].get(), offset.get(), prec);
            acb_add(x_segment[i].get(), x_segment[i].get(), x0[i]->get(), prec);
        }
    }
    const Boundary& bp_line = holds_mid ? bpT : bp_segment;
    const ComplexBall* x_line = holds_mid ? x_lin : x_segment;
    boundary_at(qb_, x_line[1], prec, bq);
    BisectorSystem on_line;
    on_line.evaluate(qb_, bp_line, bq, x_line[0], signed_, prec);
    ComplexBall H[2];
    for (int i = 0; i < 2; ++i) {
        ComplexBall& h = H[i];
        acb_mul(h.get(), on_line.J.m[i][0].get(), slope[0].get(), prec);
        acb_mul(t.get(), on_line.J.m[i][1].get(), slope[1].get(), prec);
        acb_add(h.get(), h.get(), t.get(), prec);
        acb_add(h.get(), h.get(), on_line.F_theta[i].get(), prec);
        acb_mul(h.get(), h.get(), dtheta.get(), prec);
        acb_add(h.get(), h.get(), at_mid.F[i].get(), prec);
    }
    ComplexBall CH[2];
    C.apply(H, prec, CH);
    const double floor_s = std::ldexp(1.0 + magnitude(s0), static_cast<int>(std::max(-1000L, 8 - prec)));
    const double floor_phi = std::ldexp(1.0 + magnitude(phi0), static_cast<int>(std::max(-1000L, 8 - prec)));
    double r[2] = {2 * magnitude(CH[0]) + floor_s, 2 * magnitude(CH[1]) + floor_phi};
    const ComplexBall zero;
    for (int attempt = 0; attempt < 3; ++attempt) {
        if (!std::isfinite(r[0]) || !std::isfinite(r[1]) || r[1] > 1) return false;
        ComplexBall Y[2] = {square(zero, r[0]), square(zero, r[1])}, X[2];
        for (int i = 0; i < 2; ++i) acb_add(X[i].get(), x_lin[i].get(), Y[i].get(), prec);
        // Re s > 0, or Re s > -r_p with the signed tie (see the header).
        if (signed_) {
            Ball depth;
            arb_add(depth.get(), X[0].real(), medial_p_.get(), prec);
            if (!arb_is_positive(depth.get())) return false;
        } else if (!arb_is_positive(X[0].real())) {
            return false;
        }
        boundary_at(qb_, X[1], prec, bq);
        BisectorSystem on_box;
        on_box.evaluate(qb_, bpT, bq, X[0], signed_, prec);
        // K = -C H + (I - C J(X)) Y inside the interior of Y?
        Matrix2 CJ;
        C.times(on_box.J, prec, CJ);
        ComplexBall K[2], u;
        bool inside = true;
        for (int i = 0; i < 2; ++i) {
            acb_neg(K[i].get(), CH[i].get());
            for (int j = 0; j < 2; ++j) {
                acb_neg(u.get(), CJ.m[i][j].get());
                if (i == j) acb_add_ui(u.get(), u.get(), 1, prec);
                acb_mul(u.get(), u.get(), Y[j].get(), prec);
                acb_add(K[i].get(), K[i].get(), u.get(), prec);
            }
            inside = inside && acb_contains_interior(Y[i].get(), K[i].get());
        }
        if (inside) {
            // One root in X, holomorphic in theta; Q is q's nearest point to V
            // when V - Q points out of q (Re (V - Q) . n~q > 0), or with the
            // signed tie when V is above q's medial axis (Re ((V - Q) . n~q +
            // r_q Nq^2) > 0; see the header).
            ComplexBall side;
            ray_point(bpT, X[0], prec, vx, vy);
            acb_sub(vx.get(), vx.get(), bq.x.get(), prec);
            acb_sub(vy.get(), vy.get(), bq.y.get(), prec);
            dot(vx, vy, bq.nx, bq.ny, prec, side);
            if (signed_) {
                ComplexBall depth;
                acb_mul_arb(depth.get(), bq.n2.get(), medial_q_.get(), prec);
                acb_add(side.get(), side.get(), depth.get(), prec);
            }
            if (!arb_is_positive(side.real())) return false;
            acb_add(s_out.get(), x_lin[0].get(), K[0].get(), prec);
            // The derivatives over the box X contain their values at the root.
            if (tie_ds) *tie_ds = on_box.J.m[1][0];
            if (tie_dtheta) *tie_dtheta = on_box.F_theta[1];
            if (p_boundary) *p_boundary = std::move(bpT);
            if (model) {
                model->mid = mid;
                model->s0 = s0;
                model->s1 = slope[0];
                acb_get_mag(model->remainder.get(), K[0].get());
            }
            return true;
        }
        for (int i = 0; i < 2; ++i) r[i] = std::max(2 * r[i], 2 * magnitude(K[i]));
    }
    return false;
}

bool NormalRayBisector::point(const ComplexBall& theta, long prec, ComplexBall& vx, ComplexBall& vy) {
    ComplexBall s;
    Boundary bp;
    if (!solve(theta, prec, s, nullptr, nullptr, &bp)) return false;
    ray_point(bp, s, prec, vx, vy);
    return true;
}

bool NormalRayBisector::densities(const ComplexBall& theta, long prec, Densities& out) {
    ComplexBall s, g_s, g_theta;
    Boundary bp;
    if (!solve(theta, prec, s, &g_s, &g_theta, &bp)) return false;
    // s' = -g_theta / g_s (g_theta and g_s carry the factor 2 alike).
    ComplexBall ds, t, X, Y, dX, dY;
    acb_div(ds.get(), g_theta.get(), g_s.get(), prec);
    acb_neg(ds.get(), ds.get());
    // V - O and V' = P' + s' n~ + s n~'.
    ray_point(bp, s, prec, X, Y);
    Ball origin[2];
    for (int i = 0; i < 2; ++i) arb_set_d(origin[i].get(), origin_[i]);
    acb_sub_arb(X.get(), X.get(), origin[0].get(), prec);
    acb_sub_arb(Y.get(), Y.get(), origin[1].get(), prec);
    for (int i = 0; i < 2; ++i) {
        ComplexBall& v = i == 0 ? dX : dY;
        acb_mul(v.get(), ds.get(), (i == 0 ? bp.nx : bp.ny).get(), prec);
        acb_add(v.get(), v.get(), (i == 0 ? bp.dx : bp.dy).get(), prec);
        acb_mul(t.get(), s.get(), (i == 0 ? bp.dnx : bp.dny).get(), prec);
        acb_add(v.get(), v.get(), t.get(), prec);
    }
    ComplexBall X2, Y2;
    acb_sqr(X2.get(), X.get(), prec);
    acb_sqr(Y2.get(), Y.get(), prec);
    using M = EdgeMeasure;
    acb_mul(out.m[M::x_dy].get(), X.get(), dY.get(), prec);
    acb_mul(out.m[M::y_dx].get(), Y.get(), dX.get(), prec);
    acb_mul(out.m[M::x2_dy].get(), X2.get(), dY.get(), prec);
    acb_mul(out.m[M::y2_dx].get(), Y2.get(), dX.get(), prec);
    acb_mul(out.m[M::xy_dy].get(), out.m[M::x_dy].get(), Y.get(), prec);
    acb_mul(out.m[M::x3_dy].get(), out.m[M::x2_dy].get(), X.get(), prec);
    acb_mul(out.m[M::y3_dx].get(), out.m[M::y2_dx].get(), Y.get(), prec);
    acb_mul(out.m[M::x2y_dy].get(), out.m[M::x2_dy].get(), Y.get(), prec);
    dot(dX, dY, dX, dY, prec, t);
    // Holomorphic only away from the cut (|V'|^2 > 0 on the reals).
    acb_sqrt_analytic(out.m[M::length].get(), t.get(), 1, prec);
    return acb_is_finite(out.m[M::length].get());
}

}  // namespace ellvor
