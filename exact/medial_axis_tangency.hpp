// The exact half of the proof that an internal Voronoi circle is centered
// exactly on a site's medial axis (docs/DESIGN.md §4.2): which circles of the
// medial-axis family of E (sites/medial_axis.hpp) are tangent to another
// site F, as the roots of one polynomial in the axis coordinate h, and the
// test that two such tangencies (to F and to G) are one circle.
#pragma once

#include "sites/ellipse.hpp"
#include "util/flint_types.hpp"

namespace ellvor {

// P_F(h), integer: the discriminant in lambda of det(lambda C(h) + M_F), with
// C(h) the conic of the circle about C + h d of radius^2 s(h) (E's medial-axis
// family) and M_F F's conic. Two non-degenerate conics that share a point of
// multiplicity >= 2 (over C) have a pencil with a repeated singular member, so
// P_F(h) = 0 wherever that circle (s(h) > 0) is tangent to F. The zero
// polynomial when E is a circle or the discriminant vanishes identically (then
// it proves nothing).
IntPolynomial medial_circle_tangency_polynomial(const Ellipse& e, const Ellipse& f);

// True only if proven, for h_F in the open interval (f_lo, f_hi) a root of
// P_F and h_G in (g_lo, g_hi) a root of P_G (the caller proves that much):
// h_F = h_G. P_F has exactly one distinct real root in (f_lo, f_hi), P_G
// exactly one in (g_lo, g_hi), and gcd(P_F, P_G) a real root in both; that
// root is then h_F and h_G. False means "not proven", never "distinct".
// The signature is the solver's CommonAxisTangency (subdivision/medial_axis_circle.hpp).
bool common_medial_axis_tangency(const Ellipse& e, const Ellipse& f, const Ellipse& g, const Rational& f_lo,
                                 const Rational& f_hi, const Rational& g_lo, const Rational& g_hi);

}  // namespace ellvor
