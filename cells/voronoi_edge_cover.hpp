// A certified cover of a Voronoi edge by small boxes (docs/DESIGN.md §10), for
// the rings of the cells and for the periodic certificate.
//
// The edge of p and q, seen from p, is V(theta) = P(theta) + s(theta) n~(theta)
// for theta between its two vertex angles (cells/normal_ray_bisector.hpp).
// The angle range, from the lower end of the first vertex's ball to the upper
// end of the second's, is split into consecutive pieces J, bisecting until
// one of two certificates holds on J (never a guess: a piece that fails both
// is bisected, down to 2^-40 of the range, then an Error):
//  - second order: the root's model on a region about J (the quadratic
//    NormalRayInDoubles::RootModel on the disk of radius |J| about J's
//    middle, else the linear NormalRayBisector::LinearModel on the box of
//    real radius |J| and imaginary radius |J|/2) bounds |V'| and |V''| on J
//    (voronoi_edge_cover.cpp: closed forms for the model's part, Cauchy's
//    estimates for its remainder, holomorphic there); J is cut into k equal steps with step^2/8 |V''| <= 7/10 of
//    the radius less the overshoot |V'| w (at the range's ends V runs past
//    the true vertex by at most that, w the vertex ball's width), and V at
//    the k + 1 angles, certified in double intervals (NormalRayInDoubles, else
//    Arb) within a tenth of it, are the piece's points: the chord of each
//    step is within step^2/8 |V''| of V there, both ways.
//  - first order: solve certifies s over J and the box V(J) in real balls
//    lies within the radius of its center. The piece's point: the center.
// Each piece's points then form a polyline within `radius` of V(J) and V(J)
// within `radius` of it, its first point within `radius` of V at J's start
// and its last of V at J's end; consecutive pieces share V at their common
// angle. So the polyline through all points is within `radius` of the edge
// (Hausdorff), and the end points within `radius` of its vertices.
#pragma once

#include "cells/normal_ray_bisector.hpp"
#include "util/flint_types.hpp"

#include <array>
#include <vector>

namespace ellvor {

struct EdgeCoverBox {
    Ball x, y;                                  // encloses V(J)
    std::vector<std::array<double, 2>> points;  // the piece's polyline (above)
    double error = 0;                           // it and V(J) within this of each other (<= radius)
};

struct EdgeCoverOptions {
    double radius = 1e-3;  // each piece's polyline and V(J) within this of each other
    long prec = 64;        // Arb precision of the certificates
    long max_boxes = 1L << 20;
};

// The boxes in increasing theta, from `from` to `to` (lifted angles on p, from
// <= to within the balls). Throws Error when a piece cannot be certified
// before it is 2^-40 of the range wide or the box count exceeds its limit:
// never a guess.
std::vector<EdgeCoverBox> voronoi_edge_cover(NormalRayBisector& bisector, const Ball& from, const Ball& to,
                                             const EdgeCoverOptions& options);

// The boxes' points as one polyline from the edge's start to its end, fewer
// of them: Douglas-Peucker within `radius` less the boxes' largest error.
// Each dropped point lies within that of the segment that replaces it, so
// the segment lies within it of the dropped part (the part's points project
// onto all of the segment, and the segment's neighbourhood is convex), and
// the polyline is within `radius` of the edge as the boxes' points are (the
// boxes' points, certified for the chords' sagitta under a bound of |V''|
// that is mostly the speed's change along the edge, are five to seven times
// as many as a polyline of that tolerance needs).
std::vector<std::array<double, 2>> simplified_polyline(const std::vector<EdgeCoverBox>& boxes, double radius);

// An upper bound (rounded up) of |x - (cx, cy)| over the points x of a box.
double distance_bound(const EdgeCoverBox& box, const Rational& cx, const Rational& cy, long prec);

}  // namespace ellvor
