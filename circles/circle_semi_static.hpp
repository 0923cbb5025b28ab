// The circle predicates of circle_predicates.hpp in plain doubles, with the
// static error bounds of semi_static.hpp: the same closed forms (the lifting
// to the cone, circle_predicates.hpp), evaluated in round-to-nearest and
// compared against an error bound fixed by the operations. Each decides
// (Stage::filter) when every parameter of its sites is a double (a dyadic
// rational with a numerator below 2^53) -- InCircle also on other rationals,
// through their nearest doubles (semi_static.hpp, rounded_input) -- and the
// bound proves the sign, and is undecided otherwise: a common tangent line, a
// tangency, nested sites, sites out of range -- the caller goes on to the
// next stage. None answers tangent or zero.
#pragma once

#include "decision/predicate_answers.hpp"
#include "sites/ellipse.hpp"

namespace ellvor {

// kappa3 of four circle sites (incircle.hpp): conflict, no-conflict or
// no-circle.
Decision<InCircle> circle_incircle_semi_static(const Ellipse& c1, const Ellipse& c2, const Ellipse& c3,
                                               const Ellipse& q);

// The Voronoi circles of three circle sites (voronoi_circle_count.hpp).
// Decided only for sites that are not nested (it proves every pair's power
// positive).
Decision<VoronoiCircles> circle_voronoi_circle_count_semi_static(const Ellipse& c1, const Ellipse& c2,
                                                                 const Ellipse& c3);

// kappa2 of three circle sites (infinite_vertex_conflict.hpp), when Q does
// not touch the bitangent line (the tie-break is left to the exact stage).
Decision<Sign> circle_infinite_vertex_conflict_semi_static(const Ellipse& c1, const Ellipse& c2, const Ellipse& q);

// kappa1 of two circle sites at the center of a third (side_of_bisector.hpp:
// POSITIVE when that center is nearer to C1), when all three are exact
// doubles; an exact tie and its near misses are left to the exact stage.
Decision<Sign> circle_side_of_bisector_at_center_semi_static(const Ellipse& c1, const Ellipse& c2,
                                                             const Ellipse& site);

}  // namespace ellvor
