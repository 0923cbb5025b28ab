#include "subdivision/boundary_chart.hpp"

#include <arb_fmpz_poly.h>

namespace ellvor {

namespace {

// u^2 p(-1/u) for p of degree <= 2: (p0, p1, p2) -> (p2, -p1, p0).
IntPolynomial flip(const IntPolynomial& p) {
    IntPolynomial r;
    r.set_coeff(0, p.coeff(2));
    r.set_coeff(1, -p.coeff(1));
    r.set_coeff(2, p.coeff(0));
    return r;
}

IntPolynomial derivative(const IntPolynomial& p) {
    IntPolynomial r;
    fmpz_poly_derivative(r.get(), p.get());
    return r;
}

}  // namespace

BoundaryChart::BoundaryChart(const Ellipse& e, bool flipped) : flipped_(flipped) {
    X_ = flipped ? flip(e.X()) : e.X();
    Y_ = flipped ? flip(e.Y()) : e.Y();
    W_ = flipped ? flip(e.W()) : e.W();
    Tx_ = homogeneous_tangent(X_, W_);
    Ty_ = homogeneous_tangent(Y_, W_);
    dTx_ = derivative(Tx_);
    dTy_ = derivative(Ty_);
}

Ball BoundaryChart::ellipse_parameter(const Ball& u, long prec) const {
    if (!flipped_) return u;
    Ball t;
    arb_inv(t.get(), u.get(), prec);
    arb_neg(t.get(), t.get());
    return t;
}

// P = (X, Y)/W, P' = T/W^2; the outward normal of a counter-clockwise
// boundary is the tangent turned clockwise, g = (Ty, -Tx), nu = g/|g|, and
// nu' = (g' - g (g.g')/|g|^2)/|g|. One division and one reciprocal square
// root per call: they dominate the cost at high precision.
BoundaryChart::Local BoundaryChart::evaluate(const Ball& t, long prec, bool with_derivatives) const {
    Local r;
    Ball w, inv_w, tx, ty, norm2, inv_norm, tmp;
    auto eval = [&](const IntPolynomial& p, Ball& out) { arb_fmpz_poly_evaluate_arb(out.get(), p.get(), t.get(), prec); };
    eval(X_, r.px);
    eval(Y_, r.py);
    eval(W_, w);
    eval(Tx_, tx);
    eval(Ty_, ty);
    arb_inv(inv_w.get(), w.get(), prec);
    arb_mul(r.px.get(), r.px.get(), inv_w.get(), prec);
    arb_mul(r.py.get(), r.py.get(), inv_w.get(), prec);
    arb_sqr(norm2.get(), tx.get(), prec);
    arb_addmul(norm2.get(), ty.get(), ty.get(), prec);
    arb_rsqrt(inv_norm.get(), norm2.get(), prec);
    arb_mul(r.nx.get(), ty.get(), inv_norm.get(), prec);
    arb_mul(r.ny.get(), tx.get(), inv_norm.get(), prec);
    arb_neg(r.ny.get(), r.ny.get());
    if (!with_derivatives) return r;

    Ball dtx, dty, dot;
    eval(dTx_, dtx);
    eval(dTy_, dty);
    arb_sqr(tmp.get(), inv_w.get(), prec);
    arb_mul(r.dpx.get(), tx.get(), tmp.get(), prec);
    arb_mul(r.dpy.get(), ty.get(), tmp.get(), prec);
    arb_mul(dot.get(), ty.get(), dty.get(), prec);  // g.g' = ty dty + tx dtx
    arb_addmul(dot.get(), tx.get(), dtx.get(), prec);
    arb_sqr(tmp.get(), inv_norm.get(), prec);
    arb_mul(dot.get(), dot.get(), tmp.get(), prec);  // (g.g')/|g|^2
    arb_mul(tmp.get(), ty.get(), dot.get(), prec);
    arb_sub(r.dnx.get(), dty.get(), tmp.get(), prec);
    arb_mul(r.dnx.get(), r.dnx.get(), inv_norm.get(), prec);
    arb_mul(tmp.get(), tx.get(), dot.get(), prec);
    arb_sub(r.dny.get(), tmp.get(), dtx.get(), prec);
    arb_mul(r.dny.get(), r.dny.get(), inv_norm.get(), prec);
    return r;
}

}  // namespace ellvor
