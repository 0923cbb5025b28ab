// Certified distance from a point known as balls to an ellipse, for the Arb
// stage of InCircle (is the Voronoi circle's center V farther from Q than the
// radius?).
#pragma once

#include "sites/ellipse.hpp"

namespace ellvor {

// Sign of Q's conic at (x, y): -1 certainly inside, +1 certainly outside, 0
// undecided at this precision.
int certified_side(const Ellipse& q, const Ball& x, const Ball& y, long prec);

// For (x, y) certainly outside the ellipse: an enclosure of its distance to
// the ellipse. The nearest point is isolated by interval Newton on "(x, y)
// lies on the normal at P(t)", uniquely for every point of the balls; since
// the ellipse is convex, a boundary point whose outward normal ray holds
// (x, y) is the nearest one, and the distance is the (positive) length along
// that ray. Returns false when the foot point could not be isolated at this
// precision (undecided).
bool certified_outside_distance(const Ellipse& q, const Ball& x, const Ball& y, long prec, Ball& distance);

}  // namespace ellvor
