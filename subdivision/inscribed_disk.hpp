// Certified tests that a disk lies inside an ellipse. First, that the disk
// of an internal Voronoi circle lies in its site: for a center V at depth |rho| on the inward normal of E at P(t), is
// P(t) the boundary point nearest to V, so that rho is the signed distance
// delta(V, E) (docs/DESIGN.md §2)? The certificate of §4.1 proves it by
// Blaschke's rolling theorem while |rho| stays below E's smallest radius of
// curvature; this test reaches the deep internal circles beyond it, up to
// E's medial axis (§9).
#pragma once

#include "sites/ellipse.hpp"

namespace ellvor {

// True only if proven: for every (V, rho, t) in the given balls with
// P(t) + rho nu(t) = V and rho <= 0, the closed disk of radius -rho about V
// lies in E and meets its boundary only at P(t) (so P(t) is V's unique
// nearest boundary point and delta(V, E) = rho). False means not proven (the
// caller does not certify), never "disproven"; in particular false whenever
// rho is not certainly negative.
//
// t is the chart parameter of BoundaryChart(e, flipped) (t, or u = -1/t when
// flipped); the Krawczyk box of VoronoiCircleSolver provides the balls. All
// arithmetic is at prec. `pieces`, when given, receives the number of
// parameter intervals examined (at most a few thousand; past that cap the
// answer is false).
//
// Method: g(s) = |P(s) - V|^2 - rho^2 has the sign of a quartic Q(s) in every
// chart (P = (X, Y)/W with W > 0, Q = |(X, Y) - V W|^2 - rho^2 W^2), and
// Q(t) = Q'(t) = 0 at the true solution. Near t, Q'' > 0 on an interval N
// around the ball t gives Q > 0 on N minus t (Taylor at t); on the rest of the
// boundary (both charts, the i-point included) Q > 0 by bisection with a
// Taylor-form enclosure. Why this proves the disk inside: see the .cpp.
//
// With `mirror` other than none, the caller has proven that the true V lies
// on an axis of symmetry of E, across which the reflection maps a boundary
// point's chart parameter s to -s in the same chart (same_chart) or in the
// other one (other_chart). Then g is symmetric, so Q > 0 on N minus t gives
// Q > 0 on the mirror image of N minus t's mirror too, and the bisection
// skips that image: the disk may touch E at t and at its mirror image (a
// center exactly on the medial axis), and still lies in E (delta(V, E) = rho).
enum class AxisMirror { none, same_chart, other_chart };
bool disk_inside_ellipse(const Ellipse& e, bool flipped, const Ball& t, const Ball& rho, const Ball& vx,
                         const Ball& vy, long prec, long* pieces = nullptr, AxisMirror mirror = AxisMirror::none);

// For V = (vx, vy) inside E (the caller has proven it) and r > 0: the sign
// of dist(V, boundary of E) - r, proven. +1: the closed disk of radius r
// about V misses the boundary (Q > 0 on both charts, by the bisection
// above), so it lies in E; -1: a boundary point is certainly nearer than r;
// 0: undecided at prec (near equality, or the cap). InCircle asks it of an
// internal Voronoi circle (radius -r) and a site Q that holds its center.
int inside_distance_minus(const Ellipse& e, const Ball& r, const Ball& vx, const Ball& vy, long prec);

}  // namespace ellvor
