// Floating-point nearest boundary point of an ellipse (only a guess: every
// caller certifies what it uses).
#pragma once

namespace ellvor {

// The angle theta of the point (a cos theta, b sin theta) nearest to (x, y),
// all in the ellipse's own frame: Newton on the derivative of the squared
// distance, g(theta) = a x sin - b y cos - (a^2 - b^2) sin cos, from the
// angle of the scaled point.
double approximate_nearest_angle(double a, double b, double x, double y);

}  // namespace ellvor
