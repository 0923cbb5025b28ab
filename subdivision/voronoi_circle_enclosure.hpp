// Certified enclosure of the Voronoi circle of an ordered triple (E1, E2, E3)
// (DESIGN.md: externally tangent to the three, tangency points
// counter-clockwise in that order), by the Krawczyk form of interval Newton
// on the tritangent system
//     P_i(t_i) + rho nu_i(t_i) - V = 0,   i = 1, 2, 3
// (unknowns: the three tangency parameters, the radius rho and the center V;
// nu_i the outward unit normal) in Arb balls at adaptive precision.
//
// Why a certificate identifies THE Voronoi circle: when the Krawczyk image of
// a box lies inside it, the box holds exactly one solution; if moreover rho > 0
// on the box, each P_i is the nearest point of the convex E_i to V (V lies on
// the outward normal ray of P_i), so the circle touches every E_i from outside
// and its open disk misses all three; with the tangency points
// counter-clockwise this is the unique counter-clockwise Voronoi circle.
#pragma once

#include "sites/ellipse.hpp"
#include "subdivision/boundary_chart.hpp"
#include "subdivision/voronoi_circle_guess.hpp"

#include <array>
#include <vector>

namespace ellvor {

struct VoronoiCircleEnclosure {
    // Chart parameter of each tangency point: t_i, or u_i = -1/t_i when
    // flipped (u_i = 0 is the i-point).
    std::array<Ball, 3> parameter;
    std::array<bool, 3> flipped{};
    Ball radius, center_x, center_y;
    long precision = 0;     // working precision of the last certificate
    long newton_steps = 0;  // Arb Newton steps so far (all precisions)

    // Tangency parameter t_i on E_i (an unbounded ball when the box holds the i-point).
    Ball tangency_parameter(int i, long prec) const;
    // Correct bits of the least accurate component: relative to the value for
    // |value| >= 1, absolute below.
    long correct_bits() const;
};

class VoronoiCircleSolver {
public:
    VoronoiCircleSolver(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3);

    // Finds and certifies the counter-clockwise Voronoi circle at about 64
    // bits. False when no certificate could be made (no floating-point
    // solution, or Krawczyk failed): the caller must treat that as undecided.
    bool certify();
    // Refines a certified enclosure until every component has at least `bits`
    // correct bits, doubling the working precision; reuses the current
    // enclosure. False if a certificate fails on the way (undecided).
    bool refine(long bits);

    bool certified() const { return certified_; }
    const std::array<const Ellipse*, 3>& sites() const { return sites_; }
    const VoronoiCircleEnclosure& enclosure() const { return enclosure_; }

private:
    bool certify_from(const VoronoiCircleGuess& guess);
    bool krawczyk(long prec);
    // One Newton step on the midpoint; returns the step's size in bits below
    // the values (larger = smaller step), or -1 if the Jacobian is singular.
    long newton_step(long prec);

    std::array<const Ellipse*, 3> sites_;
    std::vector<BoundaryChart> charts_;  // chosen from the floating-point guess
    BallMatrix midpoint_{6, 1};  // exact midpoint of the current box
    VoronoiCircleEnclosure enclosure_;
    bool certified_ = false;
};

}  // namespace ellvor
