// Double-interval bounds on the distance from a point to an ellipse: the
// filter stage shared by kappa1 and InCircle. Everything is outward rounded,
// so a decided comparison is proven; an unhelpful bound only sends the
// question to the Arb stage.
#pragma once

#include "sites/ellipse.hpp"
#include "util/interval.hpp"

namespace ellvor {

// A point in the ellipse's own frame (x along the a-axis), with the axes.
struct LocalPoint {
    Interval x, y, a, b;
};

LocalPoint to_local(const Ellipse& e, Interval x, Interval y);

// Sign of (x/a)^2 + (y/b)^2 - 1: -1 inside, +1 outside, 0 undecided.
int filtered_side(const LocalPoint& q);

// Bounds on the signed distance (DESIGN.md §2) from any point p to an
// ellipse with center C, from its inscribed and circumscribed disks of radii
// r = min(a, b) and R = max(a, b): |p - C| - R <= delta(p, E) <= |p - C| - r
// (outside: E lies in the big disk and holds the small one; inside: the
// boundary is at most R - |p - C| away along the ray from C through p, and
// the disk of radius r - |p - C| about p lies in the small one). A dozen
// interval operations against the nearest-point search below.
Interval signed_distance_disk_bounds(const Ellipse::Enclosure& k, Interval x, Interval y);

// Bounds on the distance from an outside point to the ellipse: the distance
// to a boundary point is an upper bound, the distance to the tangent line
// there (the ellipse lies on one side of it) a lower bound; both meet at the
// nearest point, so a good floating-point guess gives a tight interval.
Interval outside_distance_bounds(const LocalPoint& q);

}  // namespace ellvor
