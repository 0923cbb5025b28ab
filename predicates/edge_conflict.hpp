// kappa4 (CGAL Finite_edge_interior_conflict_2): does a query site Q conflict
// with the Voronoi edge of (E1, E2)? The edge runs between two Voronoi
// vertices, or to the ends of the bisector (infinite vertices):
//   6 sites: from VC(E1, E2, E3) to VC(E1, E4, E2);
//   5 sites: from the end at the infinite vertex (E2, E1, inf) to VC(E1, E2, E3);
//   4 sites: the whole bisector.
// `endpoints_in_conflict` (CGAL's b) is Q's conflict status at the edge's
// vertices. With b = true the answer is "the whole edge is in conflict", with
// b = false "some interior point of the edge is in conflict".
//
// Q's shadow region on the bisector (the points whose Voronoi disk Q meets) is
// bounded by the Voronoi circles of (E1, E2, Q) and (E1, Q, E2) when both
// exist; it is one interval, or two rays when it reaches both ends (kappa2).
// The answer then only needs the position of one of them along the bisector
// relative to the edge's vertices (bisector_order.hpp; for circles the closed
// form of circle_predicates.hpp); with fewer than two
// circles the shadow region cannot separate the edge's ends and the answer
// is b.
#pragma once

#include "decision/stage.hpp"
#include "decision/staged_refinement.hpp"
#include "sites/ellipse.hpp"

namespace ellvor {

// Decided, with the latest stage and the highest precision any vertex order
// needed; undecided only with options.exact_stage = false.
Decision<bool> finite_edge_interior_conflict(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3,
                                             const Ellipse& e4, const Ellipse& q, bool endpoints_in_conflict,
                                             const RefinementOptions& options = {});
Decision<bool> finite_edge_interior_conflict(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3,
                                             const Ellipse& q, bool endpoints_in_conflict,
                                             const RefinementOptions& options = {});
Decision<bool> finite_edge_interior_conflict(const Ellipse& e1, const Ellipse& e2, const Ellipse& q,
                                             bool endpoints_in_conflict, const RefinementOptions& options = {});

// CGAL's Is_degenerate_edge_2: the Voronoi edge of (E1, E2) between
// VC(E1, E2, E3) and VC(E1, E4, E2) has length 0, i.e. the two Voronoi
// vertices are one circle tangent to the four sites (both must exist).
// Deletion flips such edges first. Equality is proven exactly (the closed
// form for circles, voronoi_vertex_equality.hpp otherwise); undecided only
// with options.exact_stage = false.
Decision<bool> is_degenerate_edge(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3, const Ellipse& e4,
                                          const RefinementOptions& options = {});

// kappa4 for the Voronoi edge dual to the Delaunay edge (infinity, E2), whose
// neighbours on the convex hull are E3 (before) and E4 (after) (CGAL
// Infinite_edge_interior_conflict_2). The edge is made of the tangent lines of
// E2 turning counter-clockwise from the infinite vertex of the hull face
// (E2, E3, inf) to that of (E4, E2, inf); Q's conflict region on it is bounded
// by the tangent lines of the infinite vertices (Q, E2, inf) and (E2, Q, inf).
// Everything is a comparison of tangency points on E2, in the order of their
// normals: first proven in double intervals (support_function.hpp; unless
// use_filter is false), else exactly (tangency parameters of degree 4; for
// four circles the closed form of circle_predicates.hpp, unless
// use_circle_closed_form is false), so the answer is always decided.
Decision<bool> infinite_edge_interior_conflict(const Ellipse& e2, const Ellipse& e3, const Ellipse& e4,
                                               const Ellipse& q, bool endpoints_in_conflict,
                                               bool use_circle_closed_form = true, bool use_filter = true);

}  // namespace ellvor
