// A chart of an ellipse's boundary for the numerical stages: the rational
// parametrization P(t) = (X, Y)/W in t, or in u = -1/t (the "symmetric"
// parametrization of the paper, section 2, which covers the i-point at u = 0).
// Both run counter-clockwise; a solver picks the chart in which its parameter
// stays within [-1, 1] so that no unknown runs off to infinity.
#pragma once

#include "sites/ellipse.hpp"

namespace ellvor {

class BoundaryChart {
public:
    BoundaryChart(const Ellipse& e, bool flipped);
    bool flipped() const { return flipped_; }
    // The parameter t of the ellipse for a chart parameter (t = -1/u when
    // flipped; u = 0 is the i-point, reported as t = infinity by callers).
    Ball ellipse_parameter(const Ball& chart_parameter, long prec) const;

    // Value of P, dP/dt and of the outward unit normal nu and d(nu)/dt at a
    // chart parameter, in balls (the derivatives only when asked for).
    struct Local {
        Ball px, py, dpx, dpy, nx, ny, dnx, dny;
    };
    Local evaluate(const Ball& t, long prec, bool with_derivatives = true) const;

private:
    bool flipped_;
    // X, Y, W and the tangent T = (X'W - XW', Y'W - YW') with its derivative.
    IntPolynomial X_, Y_, W_, Tx_, Ty_, dTx_, dTy_;
};

}  // namespace ellvor
