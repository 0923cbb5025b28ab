// kappa2 (CGAL Vertex_conflict_2 with three sites): the infinite Voronoi
// vertex of the ordered pair (E1, E2) is the external bitangent line L whose
// tangency points appear in the order E1, E2, infinity along L; its "disk" H
// is the open half-plane beyond L (E1 and E2 lie on the other side, on the
// right of L directed from E1's to E2's tangency point).
#pragma once

#include "decision/stage.hpp"
#include "sites/ellipse.hpp"

namespace ellvor {

// NEGATIVE (-1): Q meets the open half-plane H (conflict); POSITIVE (+1):
// it does not. Never ZERO: when Q only touches L from the sites' side, the
// tie is broken as in CGAL: NEGATIVE iff Q's contact point lies strictly
// between the contact points of E1 and E2.
// Precondition: E1, E2 separated or externally tangent, as every pair of
// valid sites is. The exact stage checks it and throws Error; the filter does
// not spend time on it (for crossing E1, E2 the external bitangent still
// exists and its answer is the geometric one).
// Three circles: the closed form of circle_predicates.hpp in doubles with a
// static error bound (circle_semi_static.hpp; with use_filter), then exactly.
// Otherwise the cascade: double-interval filter on support
// functions -> exact signs at the bitangent's tangency parameter (a real
// algebraic number of degree <= 4), with Arb only to order contact points in
// the tie-break.
struct InfiniteVertexConflictOptions {
    bool use_filter = true;              // false: skip the filters (for tests and experiments)
    bool use_circle_closed_form = true;  // false: circles take the general path (tests compare the two)
};
// Always decided.
Decision<Sign> infinite_vertex_conflict(const Ellipse& e1, const Ellipse& e2, const Ellipse& q,
                                        const InfiniteVertexConflictOptions& options = {});

// The first step of the filter, exposed for its tests: the sign over the
// enclosure of L's normal of ArrivalNormalBox (support_function.hpp), contracted
// at most twice,
// -1 / +1 as above when proven, 0 when undecided (sites whose circumscribed
// disks are not proven apart, or Q near L).
int infinite_vertex_conflict_in_normal_box(const Ellipse& e1, const Ellipse& e2, const Ellipse& q);

}  // namespace ellvor
