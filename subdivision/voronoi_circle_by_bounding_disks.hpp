// The Voronoi circle of an ordered triple (E1, E2, E3) bounded from the
// sites' inscribed and circumscribed disks alone, in doubles with proven
// bounds: the cheapest enclosure of its center and radius (docs/DESIGN.md
// §3), which decides most of InCircle's questions on sites small against
// their distances before any circle is certified
// (predicates/incircle.hpp, incircle_by_bounding_disks).
#pragma once

#include "sites/ellipse.hpp"
#include "util/interval.hpp"

#include <optional>

namespace ellvor {

// Whether every triple of points x_i of the sites' bounding disks (center,
// the larger semi-axis) has one orientation, in doubles with a bound of their
// rounding (a bound symmetric in the three: the answer does not depend on
// their order). Then the
// line through a point of one site and a point of the next has the third
// strictly on one side, the same side for the three cyclic rotations: the
// three kappa2 signs agree (their lines touch two of the sites), 0 or 3
// conflicts, never `both` (has_both_voronoi_circles' first filter). The
// disks are then pairwise apart. `bounding_disks_orientation` says which:
// +1 counter-clockwise, -1 clockwise (the sign of the centers' orientation),
// 0 when not proven uniform.
int bounding_disks_orientation(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3);
inline bool bounding_disks_uniformly_oriented(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3) {
    return bounding_disks_orientation(e1, e2, e3) != 0;
}

// Center and radius of a Voronoi circle, enclosed.
struct CircleBounds {
    Interval center_x, center_y, radius;
};

// The counter-clockwise Voronoi circle of (E1, E2, E3) enclosed, or nullopt
// when not proven. Why it is a proof: a site E with center c and semi-axes
// a, b contains the disk D(c, min(a, b)) and lies in D(c, max(a, b)), so its
// signed distance at any point V is |V - c| - w for some w in [min(a, b),
// max(a, b)] (outside E by the two disks' distances; inside, the ray from c
// through V leaves E within max(a, b) of c, and D(V, min(a, b) - |V - c|)
// lies in E). The circle (V, rho) therefore solves the Apollonius system
// |V - c_i| = rho + w_i for some weights in those ranges, with rho + w_i >=
// 0. Differences of the squared equations leave V = V0 + rho V1 and a
// quadratic in rho, both enclosed over the box of weights; a root whose rho +
// w_i is negative for some site is not the circle's, and when one root is
// left and the bounding disks are uniformly oriented counter-clockwise (then
// the triple has exactly one Voronoi circle, the counter-clockwise one:
// bounding_disks_orientation), the circle lies in that root's enclosure.
// About as wide as the semi-axes' spread times the system's conditioning.
std::optional<CircleBounds> voronoi_circle_by_bounding_disks(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3);

}  // namespace ellvor
