// A certified cover of a Voronoi edge by small boxes (docs/DESIGN.md §10), for
// the rings of the cells and for the periodic certificate.
//
// The edge of p and q, seen from p, is V(theta) = P(theta) + s(theta) n~(theta)
// for theta between its two vertex angles (cells/normal_ray_bisector.hpp).
// The angle range, from the lower end of the first vertex's ball to the upper
// end of the second's, is split into consecutive pieces J, bisecting until on
// each NormalRayBisector::solve certifies s over J and the box V(J) (ball
// arithmetic over all of J) has a center within `radius` of each of its points.
// Then every point of the edge lies in a box; the first box holds the first
// vertex and the last box the second (the end pieces hold the whole vertex
// balls); two consecutive boxes share the point V at their common angle.
#pragma once

#include "cells/normal_ray_bisector.hpp"
#include "util/flint_types.hpp"

#include <array>
#include <vector>

namespace ellvor {

struct EdgeCoverBox {
    Ball x, y;                      // encloses V(J)
    std::array<double, 2> center;   // every point of V(J) lies within `radius` of it
    double radius = 0;              // an upper bound, rounded up
};

struct EdgeCoverOptions {
    double radius = 1e-3;  // the largest radius of a box
    long prec = 64;        // Arb precision of the certificates
    long max_boxes = 1L << 20;
};

// The boxes in increasing theta, from `from` to `to` (lifted angles on p, from
// <= to within the balls). Throws Error when a piece cannot be certified
// before it is 2^-40 of the range wide or the box count exceeds its limit:
// never a guess.
std::vector<EdgeCoverBox> voronoi_edge_cover(NormalRayBisector& bisector, const Ball& from, const Ball& to,
                                             const EdgeCoverOptions& options);

// An upper bound (rounded up) of |x - (cx, cy)| over the points x of a box.
double distance_bound(const EdgeCoverBox& box, const Rational& cx, const Rational& cy, long prec);

}  // namespace ellvor
