// A floating-point approximation of the Voronoi circle of an ordered triple
// (E1, E2, E3): the circle externally tangent to the three with tangency
// points counter-clockwise in that order. Only a starting point: the Arb
// stage certifies (or refuses) it.
#pragma once

#include "sites/ellipse.hpp"

#include <array>
#include <optional>

namespace ellvor {

// Unknowns of the tritangent system (research digest 3; seed system (3) in
// another form): the angles theta_i of the tangency points
// P_i = C_i + R_i (a_i cos theta_i, b_i sin theta_i), the radius rho and the
// center V, with P_i + rho nu_i(theta_i) = V (nu_i the outward unit normal).
struct VoronoiCircleGuess {
    std::array<double, 3> theta;
    double radius, x, y;
};

// Newton from the Apollonius circles of the inscribed circles (radius
// min(a, b)), then, if that fails, continuation from those circles to the
// ellipses. nullopt when no counter-clockwise solution with positive radius
// was found (the caller reports "undecided").
std::optional<VoronoiCircleGuess> guess_voronoi_circle(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3);

}  // namespace ellvor
