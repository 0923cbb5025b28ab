// kappa3, InCircle (CGAL Vertex_conflict_2 with four sites; docs/DESIGN.md §2): the
// position of a query site Q relative to the Voronoi circle of the ordered
// triple (E1, E2, E3) -- externally tangent to the three, tangency points
// counter-clockwise E1 -> E2 -> E3.
#pragma once

#include "decision/stage.hpp"
#include "decision/predicate_answers.hpp"
#include "decision/staged_refinement.hpp"
#include "sites/ellipse.hpp"
#include "subdivision/voronoi_circle.hpp"

namespace ellvor {

struct InCircleOptions {
    RefinementOptions refinement;  // the subdivision stage's cap; exact_stage = false stops there undecided
    bool use_filter = true;        // false: skip the double-interval filters
    bool use_circle_closed_form = true;  // false: four circles take the general path (tests compare the two)
    bool use_symmetry = true;  // false: skip the symmetry stage (tests that reach the exact stage on symmetric sites)
    // false: skip incircle_by_bounding_disks (a caller that asked it first).
    bool use_bounding_disks = true;
};

// delta(V, Q) - rho with double intervals (incircle's filter; also the tiled
// build's test that a site is off a face's circle), for every V and rho in the
// given intervals: -1, +1, or 0 (undecided). Most
// queries are far from tangent: Q's inscribed and circumscribed circles
// (radii min and max of a, b about its center C) decide them first, since
// |V - C| - max(a, b) <= delta(V, Q) <= |V - C| - min(a, b) (signed
// distances to nested sets), and delta(V, Q) >= -min(a, b). An internal
// circle (rho < 0) inside Q is left to the Arb stage, which measures the
// depth.
int filtered_distance_minus_radius(Interval center_x, Interval center_y, Interval radius, const Ellipse& q);

// The circle bounded by the sites' bounding disks
// (voronoi_circle_by_bounding_disks.hpp) against Q, with
// filtered_distance_minus_radius: conflict or no conflict at Stage::filter,
// else undecided. InCircle's first stage on ellipses; a cache of circles
// asks it before it looks a face's circle up (most questions of a random
// build end here, and their faces' circles are never made).
Decision<InCircle> incircle_by_bounding_disks(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3,
                                              const Ellipse& q);

// The cascade: for four circles, a closed-form filter in double intervals
// (circle_incircle_filter.hpp), then the closed form exactly in Q(sqrt D)
// (circle_predicates.hpp). Otherwise the filters are the circle bounded by
// the sites' inscribed and circumscribed disks
// (voronoi_circle_by_bounding_disks.hpp), then the circle certified in
// double intervals (voronoi_circle_in_doubles.hpp), each with the distance
// d(V, Q) in double intervals. When that does not decide: the existence of the
// counter-clockwise circle (certified by the doubles, or from three kappa2
// signs); then the Arb enclosure of the circle (center V, radius rho) and
// first the symmetry stage: two sites of the triple are mirror images
// across an axis-parallel line and Q is the third's mirror (box walls,
// docs/DESIGN.md §10): Q is tangent. Then
// the distance d(V, Q) compared with rho at doubling precision, past the cap
// the exact stage (staged_refinement.hpp): Q is tangent iff the circle is
// also a Voronoi circle of (E1, E2, Q) or (E1, Q, E2) touching E1 at the same
// point (voronoi_vertex_equality.hpp). Undecided only with exact_stage = false.
// `circle`, when given, is the cached circle of (E1, E2, E3) (see
// VoronoiCircleCache): its double certificate is made once, its solver
// refined in place.
Decision<InCircle> incircle(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3, const Ellipse& q,
                            const InCircleOptions& options = {}, VoronoiCircle* circle = nullptr);

}  // namespace ellvor
