// Exhaustive certified search for the counter-clockwise Voronoi circle of an
// ordered triple (E1, E2, E3): the complete fallback of VoronoiCircleSolver
// when no floating-point guess certifies.
//
// Domain. Each tangency point ranges over its whole boundary: the chart t in
// [-1, 1] (flipped = false) and the chart u = -1/t in [-1, 1] (flipped =
// true), so 8 chart combinations of boxes [-1, 1]^3. Eliminating the center
// V = P1 + rho nu1 leaves a square system in (t1, t2, t3, radius), in two
// branches with bounded boxes that together cover rho in (0, inf):
//   (A) rho = s L, s in [0, 1]:        P1 + rho nu1 - Pj - rho nuj = 0,
//   (B) rho = L / s, s in [0, 1]:      sigma (P1 - Pj) + nu1 - nuj = 0
//                                      (sigma = 1/rho), j = 2, 3,
// with L a power of two near the diameter of the sites' bounding box (only a
// split point: its value does not affect correctness).
//
// Exclusion of a box, in Arb balls over the box: some equation excludes 0
// (all three pairs, and the consequence (Pi - Pj).(nui + nuj) = 0 of each:
// it holds for every rho and, unlike the (B) equations, does not vanish on
// the whole of s = 0); or det(P2 - P1, P3 - P1) < 0 (a CCW circle needs
// > 0); or the Krawczyk operator of the reduced system misses the box (roots
// just outside the box or the domain). The ranges of P_i and nu_i over a
// chart interval are exact up to rounding (values at the ends plus the
// extremes inside), and s is narrowed by each equation, which is affine in
// s. Boxes are bisected along their widest coordinate, breadth-first; the
// midpoint of every box that survives the range tests is offered to the
// caller, which tries a Krawczyk certificate of the full 6-unknown system.
//
// Completeness. At every solution with rho > 0 the Jacobian is nonsingular:
// the t_i column carries (1 + rho kappa_i)|P_i'| T_i with kappa_i > 0, so a
// singular direction would need (dV, drho) != 0 with nu_i.dV = drho for i =
// 1, 2, 3, i.e. three unit normals on a common line -- impossible for three
// distinct points of the unit circle, and the normals are distinct because
// disjoint sites touch the circle at distinct points. Any certified solution
// with rho > 0 and counter-clockwise tangency points is THE counter-clockwise
// Voronoi circle (voronoi_circle_enclosure.hpp). At every solution the
// orientation is nonzero (three distinct points of a circle are not
// collinear), so clockwise solutions are excluded once boxes are small; the
// counter-clockwise one is certified from a small enough box around it.
// Hence the search either certifies the circle or excludes every box, which
// proves that there is none -- except at a degenerate infinite circle (s = 0
// in (B) with nu1 = nu2 = nu3 and a line tangent to all three sites), where it
// would not terminate: the number of boxes is capped, and the cap throws.
#pragma once

#include "sites/ellipse.hpp"

#include <array>
#include <functional>

namespace ellvor {

// Bits by which the sites' magnitude (largest center coordinate plus axis)
// exceeds their size (smallest semi-axis), at least 0: the bits that rounding
// loses before the geometry of the triple is resolved.
long site_magnitude_bits(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3);

// A start point for a certificate: the midpoint of a surviving box.
struct VoronoiCircleStart {
    std::array<bool, 3> flipped{};   // chart of each tangency parameter
    std::array<Ball, 3> parameter;   // chart parameters, exact
    Ball radius, center_x, center_y;  // exact; V = P1 + rho nu1
    long precision = 0;              // the Arb precision the search used on the box
};

struct VoronoiCircleSearchOptions {
    // Generous: random triples needed at most a few thousand boxes, and
    // near-degenerate ones grow slowly (collinear equal circles with the
    // middle one moved by 10^-12: 14000). The degenerate collinear triple
    // reaches this cap after about 25 s (boxes cost more with depth).
    long max_boxes = 500'000;
};

struct VoronoiCircleSearchResult {
    bool found = false;  // a start was accepted; false: every box excluded (no CCW circle)
    long boxes = 0;      // boxes examined
};

// Examines boxes breadth-first and offers the midpoint of each surviving box
// to `try_start` until it accepts one (returns true). Throws Error when
// `options.max_boxes` boxes did not decide (a degenerate triple).
VoronoiCircleSearchResult search_voronoi_circle(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3,
                                                const std::function<bool(const VoronoiCircleStart&)>& try_start,
                                                const VoronoiCircleSearchOptions& options = {});

}  // namespace ellvor
