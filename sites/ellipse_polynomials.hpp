// The exact polynomials of one, two and three ellipses (the paper, sections 2-3),
// all with integer coefficients, primitive, in the boundary parameters
// t (of E1), r (of E2), s (of E3) -- variables 0, 1, 2 of DensePolynomial.
//
// Every polynomial here is defined by a geometric condition on boundary points
// P(t) = (X : Y : W)(t); the point t = infinity (the i-point) is a root "at
// infinity": when a polynomial of formal degree d has actual degree d - k, the
// i-point is a root of multiplicity k. Callers that isolate roots must add it.
//
// The formal degrees are the same for circles (a == b) and ellipses, except
// for the bisector (whose (1 + t^2) factors are all removed) and the squared
// distance (a polynomial in a squared distance, not in a parameter). For a
// circle the normal line has the non-real common factor (1 + t^2); it is kept,
// so a circle's foot-point, parallel-normals and concurrency polynomials carry
// extra powers of (1 + t^2) (stated per function).
//
// Signs: "primitive" below means content-free with a positive leading
// coefficient (fmpz_poly_primitive_part / DensePolynomial::primitive_part),
// which fixes the representation but not a geometric sign. Functions whose
// sign carries meaning (tangent_side_quadratic, intersection_quartic,
// bitangent_quartic) are only divided by their positive content.
#pragma once

#include "sites/dense_polynomial.hpp"
#include "sites/ellipse.hpp"

#include <array>

namespace ellvor {

// A line l1 x + l2 y + l3 = 0 whose coefficients are polynomials in t.
struct LinePolynomials {
    IntPolynomial l1, l2, l3;
};

// --- one ellipse ---------------------------------------------------------

// Tangent line at P(t): the polar line conic * (X, Y, W)^T; degree 2 in t.
// Its value at a point is negative on the ellipse's side (the conic is
// negative inside and the polar line separates).
LinePolynomials tangent_line(const Ellipse& e);
// Normal line at P(t) (the paper's eq. 1, times W^3):
//   (Tx W, Ty W, -(Tx X + Ty Y)) divided by its positive integer content,
// T = (tangent_x, tangent_y). Formal degree 4; for a circle all three have the
// factor (1 + t^2) (the normal passes through the center).
// Orientation: (l1, l2) is a positive multiple of T(t), so l(q) > 0 iff q is
// ahead of P(t) in the direction of increasing t (|q - P(t)| decreasing).
LinePolynomials normal_line(const Ellipse& e);
// Sign side of the tangent line at P(t) at a rational point q, degree 2 in t:
// tangent_line(e) evaluated at q. Negative when q is on the ellipse's side.
IntPolynomial tangent_side_quadratic(const Ellipse& e, const Point& q);
// Foot points: the normal at P(t) passes through q, i.e. normal_line(e) at q;
// formal degree 4 (a circle: (1 + t^2) times a quadratic); primitive.
// Identically zero only when q is the center of a circle.
IntPolynomial foot_point_quartic(const Ellipse& e, const Point& q);
// Squared distance from q to the foot points: a polynomial in s (the variable
// of the returned IntPolynomial), degree 4 (ellipse) / 2 (circle, roots
// (|q - c| -+ r)^2), primitive. Its roots are |q - P(t_i)|^2 over all foot
// points t_i, INCLUDING the i-point when it is a foot point (q on the a-axis
// line); the smallest real root attained at a real foot point is the squared
// distance from q to the ellipse. For q the center of a circle: s - r^2.
// Computed as the Sylvester resultant in t (formal degrees) of the foot
// polynomial and s W^2 - |q W - (X, Y)|^2.
IntPolynomial squared_distance_quartic(const Ellipse& e, const Point& q);

// --- two ellipses --------------------------------------------------------

// Intersection: conic of E2 at P1(t), times W1(t)^2; degree <= 4 in t.
// Identically zero iff the two ellipses are the same point set.
IntPolynomial intersection_quartic(const Ellipse& e1, const Ellipse& e2);
// Bitangent: the tangent line of E1 at t is tangent to E2, L(t)^T adj(M2) L(t)
// with L = tangent_line(e1); formal degree 4 (also for circles). Divided by
// its positive content only: > 0 when the tangent line misses E2, 0 when it
// touches E2, < 0 when it crosses E2.
IntPolynomial bitangent_quartic(const Ellipse& e1, const Ellipse& e2);
// Bisector B(t, r) (the paper's eqs. 1-2): det [N1(t); N2(r); perpendicular bisector
// of P1(t) P2(r)], every factor (1 + t^2), (1 + r^2) removed, primitive.
// Bidegree (6, 6) for two ellipses (the paper, section 3); a circle E1 gives degree
// 2 in t (circle E2: 2 in r); two circles (2, 2).
DensePolynomial bisector_polynomial(const Ellipse& e1, const Ellipse& e2);
// Collinear normals: the normal of E1 at t passes through P2(r) and T1(t) is
// parallel to T2(r), i.e. it is also normal to E2 (the paper's Lemma 3.1's degree-12
// factor). res_r of the two conditions (formal degrees 2 and 2 in r).
// Degree 12 for every pair (formal degree 12); irreducible for two generic
// ellipses. Circle E1, ellipse E2: (1 + t^2)^2 times a degree-8 factor (the 4
// normals from the center of E1 to E2, each meeting E1 twice). Ellipse E1,
// circle E2: foot_point_quartic(E1, c2)^2 (Tx1^2 + Ty1^2), the last factor
// without real roots. Two circles: (the line c1c2 on E1)^2 (1 + t^2)^4.
// Primitive; the non-real factors are not removed.
IntPolynomial parallel_normals_polynomial(const Ellipse& e1, const Ellipse& e2);

// --- three ellipses ------------------------------------------------------

// Q(t, r, s) = det [N1(t); N2(r); N3(s)]: the normals of E1 at t, E2 at r,
// E3 at s are concurrent (or all parallel) (the paper's system (4)); degree 4 in each
// variable (a circle's variable, say t, through the factor (1 + t^2));
// primitive.
DensePolynomial normals_concurrency_polynomial(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3);

}  // namespace ellvor
