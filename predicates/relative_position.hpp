// Relative position of two ellipses (docs/DESIGN.md §3),
// decided exactly from the real roots of the intersection quartic and their
// multiplicities, after a filter: the bounding circles, or the extents along
// the line of the centers, apart.
#pragma once

#include "decision/stage.hpp"
#include "sites/ellipse.hpp"

#include <string>
#include <vector>

namespace ellvor {

enum class RelativePosition {
    separated,              // disjoint closed sets, neither inside the other
    externally_tangent,     // touching from outside (one or two contact points), no crossing
    intersecting,           // the boundaries cross (crossing_pair_problem says whether that is allowed)
    first_inside,           // E1 strictly inside E2 (E1 is hidden by E2)
    first_inside_tangent,   // E1 inside E2, boundaries touching
    second_inside,          // E2 strictly inside E1 (E2 is hidden by E1)
    second_inside_tangent,  // E2 inside E1, boundaries touching
    identical,              // the same point set
};

const char* relative_position_name(RelativePosition p);

// Always decided: by the filter (bounding circles or extents along the line
// of the centers apart, or a slab between two ellipses along a searched
// direction) or exactly (the intersection quartic).
Decision<RelativePosition> relative_position(const Ellipse& e1, const Ellipse& e2);

// The filter's first step alone: the circumscribed circles (radius max(a, b))
// are apart, proved in outward-rounded doubles. False when the doubles cannot
// tell; then relative_position decides. Cheaper than any memo lookup.
bool bounding_circles_apart_in_doubles(const Ellipse& e1, const Ellipse& e2);

// Two circles: q is not inside p (tangency and identity included), proved in
// outward-rounded doubles from one coordinate: q in p needs |C_p - C_q| <=
// r_p - r_q, so a larger q, or an equal one elsewhere, is not. False when
// the doubles cannot tell, or for an ellipse. A build asks whether its new,
// smaller site hides a neighbour: this settles it in a few operations.
bool circle_not_inside_in_doubles(const Ellipse& p, const Ellipse& q);

// Neither site inside the other, nor the same point set: each center lies
// certainly outside the other site (the sign of its conic at the center, in
// outward-rounded doubles; a convex site inside another has its center
// there). False when the doubles cannot tell. It does not tell separated from
// crossing: none_inside_another (voronoi_circle_count.hpp) needs no more, and
// decides close sites side by side (dense packings) with it instead of
// relative_position's separating slab.
bool centers_outside_each_other_in_doubles(const Ellipse& p, const Ellipse& q);

// How many distinct points the boundaries of two different sites share (0
// to 4), exactly: the real roots of the intersection quartic, t = infinity
// included.
int boundary_meeting_points(const Ellipse& e1, const Ellipse& e2);

// For two sites whose boundaries cross: why they cannot be sites of one
// diagram, or "" when they can (docs/DESIGN.md §2): sites may cross in two
// points (pseudo-circles, signed distances), never in three or four.
std::string crossing_pair_problem(const Ellipse& e1, const Ellipse& e2);

// Throws IntersectingSites (util/error.hpp) naming the first pair (i < j, in
// the order of j, then i) that crosses in a way crossing_pair_problem rejects.
// Only pairs whose circumscribed disks may meet are compared
// (pairs_that_may_meet); the graph's traits check the same before inserting
// (EllipseDelaunayTraits::check_sites).
void require_acceptable_crossings(const std::vector<Ellipse>& sites);

// CGAL's Is_hidden(p, q): q lies inside p, internal tangency and identical
// sites included.
bool is_hidden(const Ellipse& p, const Ellipse& q);

}  // namespace ellvor
