// The numerical half of the proof that an internal Voronoi circle is centered
// exactly on a site's medial axis (docs/DESIGN.md §4.2, "On a medial axis").
// There the disk touches the site E_i at two mirror feet, so
// disk_inside_ellipse cannot prove delta(V, E_i) = rho alone; once the center
// is proven on E_i's axis, its mirror skip (AxisMirror) may.
//
// For each other site E_j, Krawczyk certifies a root (h_j, t_j, rho_j) of
//     P_j(t_j) + rho_j nu_j(t_j) = C_i + h_j d_i,   rho_j^2 = s_i(h_j)
// (the medial-axis circle of E_i about C_i + h_j d_i, radius^2 s_i(h_j), is
// tangent to E_j: sites/medial_axis.hpp); an exact test from above
// (CommonAxisTangency: exact/medial_axis_tangency.hpp, passed in by the
// predicates, since this layer does not know exact/) proves h_j = h_k. Then
// the tuple (a foot on E_i, t_j, t_k, rho_j, C_i + h_j d_i) solves the
// tritangent system, and lying in the solver's Krawczyk box K it is that
// box's unique root.
#pragma once

#include "sites/ellipse.hpp"
#include "subdivision/boundary_chart.hpp"

#include <array>

namespace ellvor {

// Proves, or returns false ("not proven"), that the axis coordinates h_f in
// (f_lo, f_hi) and h_g in (g_lo, g_hi) of two tangencies of e's medial-axis
// circles, to f and to g, are equal (exact/medial_axis_tangency.hpp).
using CommonAxisTangency = bool (*)(const Ellipse& e, const Ellipse& f, const Ellipse& g, const Rational& f_lo,
                                    const Rational& f_hi, const Rational& g_lo, const Rational& g_hi);

// True only if proven: the unique root of the tritangent system in the
// solver's Krawczyk image K (6 x 1: t_1, t_2, t_3 in the charts `charts`, rho,
// V; rho < 0) has its center exactly on the medial axis of sites[i]. Works at
// about twice prec. False whenever common_tangency is null.
bool center_on_medial_axis(const std::array<const Ellipse*, 3>& sites,
                           const std::array<const BoundaryChart*, 3>& charts, const BallMatrix& K, int i, long prec,
                           CommonAxisTangency common_tangency);

}  // namespace ellvor
