// The filter stage of InCircle when all four sites are circles, in two steps:
// the closed form of circle_predicates.hpp in plain doubles with a static
// error bound (circle_semi_static.hpp), then, when that cannot prove the sign
// or the sites are out of its range, the interval filter below: the
// Apollonius circles of three circles in closed form (the equations
// |V - C_i| = rho + r_i are linear in V after subtracting the first, then
// quadratic in rho), evaluated in outward-rounded double intervals. A root
// with rho > 0 is externally tangent to the three with an empty disk, i.e. a
// Voronoi circle; its orientation is that of its tangency points. Decides
// only what the intervals prove; anything else is left to the general
// cascade.
#pragma once

#include "decision/predicate_answers.hpp"
#include "sites/ellipse.hpp"

namespace ellvor {

// Decided by the filter stage (never tangent), or undecided: neither step
// proves the answer, or a site is not a circle.
Decision<InCircle> circle_incircle_filter(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3, const Ellipse& q);

// The interval step alone (tests reach it with inputs the first step leaves).
Decision<InCircle> circle_incircle_interval_filter(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3,
                                                   const Ellipse& q);

}  // namespace ellvor
