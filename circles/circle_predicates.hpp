// The predicates for circle sites (ellipses with a == b) in closed form,
// exactly: the Voronoi circle of three circles has its center and radius in
// one quadratic field Q(sqrt D), so kappa2, kappa3, the count of Voronoi
// circles and the order of Voronoi vertices along a bisector are signs of
// elements of Q(sqrt D), or of a difference of two such fields, decided by
// exact/quadratic_number.hpp. Nothing is approximated and nothing is left
// undecided: no stage, no precision.
//
// Distances are signed (|x - C| - r, negative inside), so sites may cross:
// the Voronoi circle (V, R) of crossing circles may be internal, R < 0
// (docs/DESIGN.md §2, §4.6).
//
// Why it is linear (the lifting). Move C1 to the origin and subtract r1 from
// every radius: site i becomes a_i = (D_i, rho_i) = (C_i - C1, r_i - r1) (a_1 =
// 0, a point) and a circle (V, R) at signed distance R from site i becomes
// the point w = (x, y, s) = (V - C1, R + r1) of the cone x^2 + y^2 = s^2 with
//     |(x, y) - D_i| = s + rho_i   <=>   a_i . w = h_i,   h_i = (|D_i|^2 - rho_i^2) / 2
// (square, subtract the cone equation; every h_i > 0 when no site contains
// another) and s + rho_i = R + r_i > 0 (squaring loses that sign). So:
//   * the circles tangent to C1, C2, C3 are the points of the line
//     {a_2 . w = h_2, a_3 . w = h_3} = {p + t k}, k = a_2 x a_3, on the cone:
//     a quadratic in t; the Voronoi circles are its roots with R + r_i > 0
//     for the three sites (R > 0 for sites that do not overlap);
//   * their tangency points are counter-clockwise iff <w, k> < 0, where
//     <u, v> = u_x v_x + u_y v_y - u_s v_s (the orientation determinant of the
//     tangency points, rows scaled by R + r_i > 0, is -<w, k>); at a root <w,
//     k> is half the quadratic's slope, so the counter-clockwise circle is the
//     root where the quadratic decreases: at most one per orientation;
//   * Q's signed distance at V is below R iff |V - C_Q| < R + r_Q iff
//     h_Q - a_Q . w < 0 (the same subtraction), when R + r_Q >= 0; kappa3 is
//     one linear form, and POSITIVE when R + r_Q < 0.
// Closed form (circle_predicates.cpp): with p_i = |D_i|^2 - rho_i^2 (= 2 h_i),
// g = D_2 . D_3 - rho_2 rho_3 and p_23 = p_2 + p_3 - 2 g (the same quantity
// for the pair C2, C3), the two roots are
//     w = -(p_3 (p_2 - g) b_2 + p_2 (p_3 - g) b_3 +- sqrt(p_2 p_3 p_23) k) / (2 <k, k>),
// b_i = (D_i, -rho_i), <k, k> = g^2 - p_2 p_3: one square root, of the product
// of the three squared external tangent lengths, positive for every valid
// triple; collinear centers and equal radii need nothing special.
// Special cases, each exact: k = 0 (rank 1: collinear centers with radii
// affine along the line, equal radii included; the two planes are then
// parallel: no circle); <k, k> = 0 with k != 0 (the three circles have a
// common tangent line: one root went to infinity, the other is rational and
// comes from the linear system with the exact pivot s).
#pragma once

#include "exact/quadratic_number.hpp"
#include "decision/predicate_answers.hpp"
#include "sites/ellipse.hpp"

#include <array>

namespace ellvor {

// The counter-clockwise Voronoi circle of an ordered triple of circle sites
// (the Voronoi vertex of the Delaunay face (C1, C2, C3)), built once and then
// asked many questions. The clockwise circle of (C1, C2, C3) is the vertex of
// (C1, C3, C2). Keeps pointers to the sites, which must outlive it.
class CircleVoronoiVertex {
public:
    // Sites: circles (Error otherwise), none inside another: separated,
    // tangent or crossing. A site inside another (or internally tangent) is
    // detected for free and throws Error.
    CircleVoronoiVertex(const Ellipse& c1, const Ellipse& c2, const Ellipse& c3);

    // The triple has a counter-clockwise Voronoi circle.
    bool exists() const { return exists_; }
    // Its center and radius, exactly (Error if it does not exist). All three
    // lie in one field Q(sqrt D) (rational when the sites have a common
    // tangent line).
    QuadraticNumber center_x() const;
    QuadraticNumber center_y() const;
    QuadraticNumber radius() const;

    const std::array<const Ellipse*, 3>& sites() const { return sites_; }

private:
    friend int circle_vertex_conflict(const CircleVoronoiVertex& vertex, const Ellipse& q);
    friend int circle_order_on_bisector(const Ellipse& c1, const Ellipse& c2, const CircleVoronoiVertex& a,
                                        const CircleVoronoiVertex& b);
    void require_exists(const char* who) const;

    std::array<const Ellipse*, 3> sites_;
    bool exists_ = false;
    // Integers throughout: the sites scaled by `scale` (the least common
    // multiple of their denominators), C1 scaled is `origin`, and the lifted
    // circle scale (V - C1, R + r1) = (m + sqrt(radicand) n) / denominator.
    Integer scale_;
    std::array<Integer, 3> origin_, m_, n_;
    Integer denominator_, radicand_;
};

// kappa3 (InCircle): -1 when Q's signed distance at the center of the
// counter-clockwise Voronoi circle of (C1, C2, C3) is below its radius (for
// R > 0: Q meets its open disk), or when the triple has none (CGAL's rule); 0
// when equal; +1 otherwise. Q: a circle site.
int circle_vertex_conflict(const Ellipse& c1, const Ellipse& c2, const Ellipse& c3, const Ellipse& q);
// The same against a vertex built once.
int circle_vertex_conflict(const CircleVoronoiVertex& vertex, const Ellipse& q);

// kappa2 with the semantics of infinite_vertex_conflict.hpp: -1 iff Q meets
// the open half-plane beyond the external bitangent of (C1, C2) whose
// tangency points come in the order C1, C2, infinity; never 0: when Q touches
// the line from the sites' side, -1 iff its contact point lies strictly
// between those of C1 and C2. Throws Error when one of C1, C2 lies inside the
// other (no external bitangent).
int circle_infinite_vertex_conflict(const Ellipse& c1, const Ellipse& c2, const Ellipse& q);

// Which Voronoi circles (C1, C2, C3) has: counter-clockwise, clockwise, both,
// none (voronoi_circle_count.hpp). The same preconditions and Error as
// CircleVoronoiVertex.
VoronoiCircles circle_voronoi_circle_count(const Ellipse& c1, const Ellipse& c2, const Ellipse& c3);

// Order along the bisector of (C1, C2) of two Voronoi vertices whose triples
// both contain C1 and C2 (in any places; the vertices must exist): -1 if `a`
// comes first from the departure end (the infinite vertex (C2, C1, inf)), 0
// if they are the same circle, +1 if after (bisector_order.hpp). The bisector
// branch is a graph over J = (C2 - C1) turned by +90 degrees, traversed with
// J . V increasing, so this is the sign of J . (V_a - V_b). Throws Error if a
// vertex does not exist or its triple lacks C1 or C2.
int circle_order_on_bisector(const Ellipse& c1, const Ellipse& c2, const CircleVoronoiVertex& a,
                             const CircleVoronoiVertex& b);

// kappa4 for the Voronoi edge dual to the Delaunay edge (infinity, C2) with
// hull neighbours C3 (before) and C4 (after), with the semantics of
// infinite_edge_interior_conflict (edge_conflict.hpp): the contact directions
// on C2 of the external bitangents with C3, C4 and Q (unit normals n =
// ((r2 - rX) D +- sqrt(|D|^2 - (r2 - rX)^2) J) / |D|^2, D = C_X - C2, J = D
// turned by +90 degrees; + where the hull arrives on C2, - where it departs)
// are ordered counter-clockwise by signs of cross and dot products, elements
// of a biquadratic field (exact/quadratic_number.hpp). Throws Error when a
// site lies inside C2 (no external bitangent).
bool circle_infinite_edge_interior_conflict(const Ellipse& c2, const Ellipse& c3, const Ellipse& c4, const Ellipse& q,
                                            bool endpoints_in_conflict);

}  // namespace ellvor
