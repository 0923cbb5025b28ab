// Exhaustive certified search for the counter-clockwise Voronoi circle of an
// ordered triple (E1, E2, E3): the complete fallback of VoronoiCircleSolver
// when no floating-point guess certifies.
//
// Domain. Each tangency point ranges over its whole boundary: the chart t in
// [-1, 1] (flipped = false) and the chart u = -1/t in [-1, 1] (flipped =
// true), so 8 chart combinations of boxes [-1, 1]^3. Eliminating the center
// V = P1 + rho nu1 leaves a square system in (t1, t2, t3, radius), in three
// branches with bounded boxes that together cover rho in [-L_in, inf):
//   (A) rho = s L, s in [0, 1]:        P1 + rho nu1 - Pj - rho nuj = 0,
//   (B) rho = L / s, s in [0, 1]:      sigma (P1 - Pj) + nu1 - nuj = 0
//                                      (sigma = 1/rho), j = 2, 3,
//   (C) rho = -s L_in, s in [0, 1]:    the equations of (A), the slope in s
//                                      negated (internal circles, rho <= 0),
// with L a power of two near the diameter of the sites' bounding box (only a
// split point: its value does not affect correctness) and L_in the power of
// two above the smallest semi-axis of the three: a point at signed distance
// rho <= 0 from all three lies at depth -rho in each, and no point of an
// ellipse is deeper than its smaller semi-axis. Branch (C) is skipped when
// two sites certainly share no point (circumscribed circles apart): then no
// point is inside all three, the case of every disjoint triple but close ones.
//
// Exclusion of a box, in Arb balls over the box: some equation excludes 0
// (all three pairs, and the consequence (Pi - Pj).(nui + nuj) = 0 of each:
// it holds for every rho and, unlike the (B) equations, does not vanish on
// the whole of s = 0); or det(P2 - P1, P3 - P1) < 0 or det(nu2 - nu1, nu3 -
// nu1) < 0 (a CCW circle needs both >= 0: the first is rho^2 times the
// second at a solution, for either sign of rho); or the Krawczyk operator of
// the reduced system misses the box (roots just outside the box or the
// domain). In (C) also: V = P_i - s L_in nu_i beyond E_i's medial axis for
// some i over the whole box (an upper bound of the medial axis' depth along
// the inward normal over the arc: there the mirror point of P_i is nearer, so
// rho is not the signed distance -- without this rule boxes around such
// solutions of the algebraic system would be bisected until the cap), or V
// certainly outside a site. The ranges of P_i and nu_i over a chart interval
// are exact up to rounding (values at the ends plus the extremes inside),
// and s is narrowed by each equation, which is affine in s, and in (C) by
// the medial depth. Boxes are bisected along their widest coordinate,
// breadth-first; the midpoint of every box that survives the range tests is
// offered to the caller, which tries a Krawczyk certificate of the full
// 6-unknown system.
//
// Completeness. The t_i column of the Jacobian carries (1 + rho kappa_i)
// |P_i'| T_i (kappa_i the curvature of E_i at P_i), so at every solution
// with 1 + rho kappa_i > 0 for all i a singular direction would need (dV,
// drho) != 0 with nu_i.dV = drho for i = 1, 2, 3, i.e. three unit normals on
// a common line -- impossible for three distinct points of the unit circle.
// The normals are distinct: disjoint sites touch the circle at distinct
// points, and two crossing circles touching the circle at one point with one
// normal would be tangent there. For rho > 0, 1 + rho kappa_i > 0 always;
// for circles, every internal circle (-r_i < rho <= 0, the only ones of
// signed distances: |V - C_i| = rho + r_i > 0) has 1 + rho / r_i > 0, and the
// certificate accepts exactly these (voronoi_circle_enclosure.hpp). Any
// certified solution with counter-clockwise tangency points is THE
// counter-clockwise Voronoi circle. At every solution the orientation is
// nonzero (the normals' determinant: three distinct points of the unit
// circle; at rho = 0 the points' determinant vanishes), so clockwise
// solutions are excluded once boxes are small; the counter-clockwise one is
// certified from a small enough box around it. The Jacobian is nonsingular
// at every Voronoi circle: the t_i column carries (1 + rho kappa_i) with
// kappa_i the curvature at P_i, positive for rho >= 0 and for internal
// circles too, since V lies short of E_i's medial axis and the normal from
// P_i meets the medial axis before the center of curvature. The certificate
// proves every such circle (DESIGN.md §4.1: Blaschke's bound, then
// disk_inside_ellipse up to the medial axis). Hence the search either
// certifies the counter-clockwise circle or excludes every box, which proves
// that there is none -- except at degenerate circles where it would not
// terminate: an infinite one (s = 0 in (B) with nu1 = nu2 = nu3 and a line
// tangent to all three sites), or an internal one whose center lies on a
// site's medial axis (two nearest points); the number of boxes is capped,
// and the cap throws, never a wrong "none".
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
