// Starts for the Voronoi circles of three ellipses from a walk along the
// bisector of two of them, in doubles, for triples where the guesses lead
// Newton to the other circle or nowhere: sites close against their sizes, as
// in dense packings, and needles beside other thin sites (fuzz F11). The
// double certificate (voronoi_circle_in_doubles.hpp) tries them before its
// Arb tangent-line pass, the Arb solver (voronoi_circle_enclosure.hpp) before
// the needle chains (docs/DESIGN.md §4.1a, §4.2 item 4).
//
// Each point P(theta) of E_i's boundary, with outward unit normal n, has at
// most one circle tangent to E_i there and to E_j: the center V = P + rho n
// with d(V, E_j) = rho, rho > 0, where d(P + rho n, E_j) - rho is
// nonincreasing in rho (d is 1-Lipschitz). Along theta, the circle is also
// tangent to E_k where g(theta) = d(V, E_k) - rho changes sign: every
// Voronoi circle of the triple with a center outside the sites is such a
// sign change of g between two samples, whichever its orientation. Each is
// refined by regula falsi in theta and offered with its three foot points.
// A circle many times the sites' size touches p within a narrow range of
// theta next to the bitangent point, where the samples leave the domain (no
// circle on the other side): such circles may be missed, and the tangent-line
// starts of huge_circle_start.hpp are the ones for them. A candidate is only
// a start: the certificate judges it (and rejects the clockwise circle).
#pragma once

#include "sites/ellipse.hpp"
#include "subdivision/voronoi_circle_guess.hpp"

#include <array>
#include <functional>

namespace ellvor {

// Offers the circles tangent to the three sites found along the bisector of
// (E_i, E_j), k the third, for the pairs (1, 2), (2, 3), (3, 1) in turn,
// until `try_guess` accepts one (returns true), as VoronoiCircleGuesses
// (theta: the parametric angles of the three tangency points, in the order of
// the arguments). Returns whether one was accepted.
bool for_each_bisector_walk_circle(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3,
                                   const std::function<bool(const VoronoiCircleGuess&)>& try_guess);

}  // namespace ellvor
