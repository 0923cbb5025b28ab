// The exact polynomials of one, two and three ellipses (seed sections 2-3),
// all with integer coefficients, primitive, in the boundary parameters
// t (of E1), r (of E2), s (of E3) -- variables 0, 1, 2 of DensePolynomial.
//
// Every polynomial here is defined by a geometric condition on boundary points
// P(t) = (X : Y : W)(t); the point t = infinity (the i-point) is a root "at
// infinity": when a polynomial of formal degree d has actual degree d - k, the
// i-point is a root of multiplicity k. Callers that isolate roots must add it.
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
// Normal line at P(t) (seed eq. 1, cleared of denominators); degree <= 4.
LinePolynomials normal_line(const Ellipse& e);
// Sign side of the tangent line at P(t) at a rational point q, degree 2 in t:
// tangent_line(e) evaluated at q. Negative when q is on the ellipse's side.
IntPolynomial tangent_side_quadratic(const Ellipse& e, const Point& q);
// Foot points: the normal at P(t) passes through q; degree <= 4 in t.
IntPolynomial foot_point_quartic(const Ellipse& e, const Point& q);
// Squared distance from q to the foot points: degree <= 4 in s (the variable
// of the returned polynomial). Its real roots include the squared distance
// from q to the ellipse (the smallest one attained at a real foot point).
IntPolynomial squared_distance_quartic(const Ellipse& e, const Point& q);

// --- two ellipses --------------------------------------------------------

// Intersection: conic of E2 at P1(t), times W1(t)^2; degree <= 4 in t.
// Identically zero iff the two ellipses are the same point set.
IntPolynomial intersection_quartic(const Ellipse& e1, const Ellipse& e2);
// Bitangent: the tangent line of E1 at t is tangent to E2; degree <= 4 in t.
IntPolynomial bitangent_quartic(const Ellipse& e1, const Ellipse& e2);
// Bisector B(t, r) (seed eqs. 1-2): the normals at P1(t) and P2(r) meet at a
// point equidistant from both; bidegree (6, 6) for two ellipses (lower when a
// circle is involved), factors (1 + t^2), (1 + r^2) removed.
DensePolynomial bisector_polynomial(const Ellipse& e1, const Ellipse& e2);
// Collinear normals: the normal of E1 at t is also normal to E2 at some r
// (seed Lemma 3.1's degree-12 factor); degree <= 12 in t.
IntPolynomial parallel_normals_polynomial(const Ellipse& e1, const Ellipse& e2);

// --- three ellipses ------------------------------------------------------

// Q(t, r, s): the normals of E1 at t, E2 at r, E3 at s are concurrent
// (seed system (4)); degree <= 4 in each variable.
DensePolynomial normals_concurrency_polynomial(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3);

}  // namespace ellvor
