// A floating-point approximation of the Voronoi circle of an ordered triple
// (E1, E2, E3): the circle externally tangent to the three with tangency
// points counter-clockwise in that order. Only a starting point: the Arb
// stage certifies (or refuses) it.
#pragma once

#include "sites/ellipse.hpp"

#include <array>
#include <functional>
#include <vector>

namespace ellvor {

// Unknowns of the tritangent system (docs/DESIGN.md §4.1; the paper's system (3) in
// another form): the angles theta_i of the tangency points
// P_i = C_i + R_i (a_i cos theta_i, b_i sin theta_i), the radius rho and the
// center V, with P_i + rho nu_i(theta_i) = V (nu_i the outward unit normal).
// The center (x, y) is relative to E1's center: V = C_1 + (x, y). The guesses
// are computed in that frame (each site's center minus C_1, exactly, then
// rounded), so they do not depend on where the triple lies in the plane.
struct VoronoiCircleGuess {
    std::array<double, 3> theta;
    double radius, x, y;
};

// Floating-point solutions with positive radius and counter-clockwise
// tangency points, offered to `try_guess` until it accepts one (returns
// true): first Newton from the Apollonius circles of three circle models of
// the sites (inscribed, mean, circumscribed radius; collinear centers
// included), then continuation from those circles to the ellipses, then
// Newton in the plane for equal distances from a grid of start points. A
// floating-point solution can be spurious (e.g. a huge circle of nearly
// collinear sites); the caller's certificate is what decides. Returns false
// when no offered guess was accepted.
bool for_each_voronoi_circle_guess(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3,
                                   const std::function<bool(const VoronoiCircleGuess&)>& try_guess);

// The three sites as circles of the same centers: radius min(a, b)
// (inscribed, so still disjoint), the mean, or max(a, b).
enum class CircleModel { inscribed, mean, circumscribed };
constexpr CircleModel kCircleModels[] = {CircleModel::inscribed, CircleModel::mean, CircleModel::circumscribed};

// The circles externally tangent to the three circles of a model
// (Apollonius, collinear centers included), as {radius, x, y} with the
// center (x, y) relative to E1's center, like VoronoiCircleGuess.
std::vector<std::array<double, 3>> model_apollonius_circles(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3,
                                                            CircleModel model);

}  // namespace ellvor
