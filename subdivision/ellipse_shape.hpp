// An ellipse in doubles and what the floating-point code asks of it: its
// points and normals, nearest points, signed distances, and the point of the
// bisector of two sites on a normal ray. Only guesses and drawings come from
// here (the SVG tracer, the starts of the certified cell integrals); every
// certified answer is proved elsewhere.
#pragma once

#include "sites/ellipse.hpp"

#include <optional>

namespace ellvor {

// An ellipse in doubles (a, b, cos and sin of the rotation, center).
struct EllipseShape {
    double a = 1, b = 1, c = 1, s = 0, xc = 0, yc = 0;

    static EllipseShape of(const Ellipse& e);
    // Boundary point and outward unit normal at the angle theta:
    // P = C + a cos(theta) u + b sin(theta) v.
    void point(double theta, double& x, double& y) const;
    void normal(double theta, double& nx, double& ny) const;
    // Is (x, y) strictly inside?
    bool inside(double x, double y) const;
    // Angle of the boundary point nearest to (x, y), inside or outside (of
    // two equally near points, one of them).
    double nearest_angle(double x, double y) const;
    // Distance from (x, y) to the boundary, negative inside.
    double signed_distance(double x, double y) const;
    // How far the inward normal at theta runs before it meets the medial axis
    // (the segment of the major axis between the centers of curvature of its
    // vertices): the boundary point at theta is the nearest one of every point
    // of the normal up to that depth. min(a, b) / max(a, b) times the length of
    // (b cos theta, a sin theta); r for a circle.
    double medial_depth(double theta) const;
    // Support function max over the ellipse of (nx, ny) . point.
    double support(double nx, double ny) const;
    // Axis-aligned half extents.
    double half_width() const;
    double half_height() const;
};

// The signed distance rho at which the normal ray of p at the angle theta,
// V(rho) = P(theta) + rho n(theta), is as near to q as to p (docs/DESIGN.md
// §9: rho < 0 down to p's medial depth when P(theta) is inside q); empty when
// there is none or it is beyond `cap`. f(rho) = delta(V(rho), q) - rho is
// nonincreasing (delta is 1-Lipschitz): a safeguarded Newton / bisection.
std::optional<double> equal_distance_on_normal(const EllipseShape& p, const EllipseShape& q, double theta, double cap);

}  // namespace ellvor
