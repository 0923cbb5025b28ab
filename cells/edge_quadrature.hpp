// The measures of EdgeMeasure (cells/normal_ray_bisector.hpp) over a piece
// [a, b] of an edge, seen from its site p (docs/DESIGN.md §10), by Gauss-Legendre quadrature in double
// intervals: the fast stage of the cell integrals, for goals up to about
// 44 bits (the default tolerance 1e-9 needs 34).
//
// On each piece [a, b] (half-length h) one complex disk about its middle
// holds the Bernstein ellipse with foci a, b and parameter rho (semi-axes
// h (rho +- 1/rho) / 2): its radius is the major semi-axis. The certificate
// of NormalRayInDoubles::bounds_on_disk proves the densities holomorphic
// there and bounds each, f, by M (from their Taylor models); then n-point Gauss-Legendre
// quadrature errs by at most h (64/15) M rho^(2 - 2n) / (rho^2 - 1)
// (Trefethen, Approximation Theory and Approximation Practice, Thm. 19.3,
// stated for n + 1 points with rho^(-2n): we use the weaker exponent of n - 1),
// and n is the least that meets the piece's share of the tolerance. As the
// rule integrates polynomials of degree 2n - 1 exactly, M may bound f - p
// instead, p the model's polynomial (degree 2, so n >= 2): its remainder,
// about a tenth of |f|'s bound (1.5 nodes fewer a piece). The nodes
// are certified in double intervals too. An edge's first piece is as wide as
// the edge or as its pole angles allow (NormalRayInDoubles::pole_angles); a
// piece whose disk or nodes cannot be certified is halved; nothing is claimed when that goes too deep, and the
// caller integrates the edge with Arb's integrator instead.
#pragma once

#include "cells/gauss_legendre_rule.hpp"
#include "cells/normal_ray_bisector.hpp"
#include "cells/normal_ray_in_doubles.hpp"
#include "cells/quadrature_counts.hpp"

#include <array>
#include <optional>

namespace ellvor {

// tolerance[j]: the absolute tolerance of measure j over the whole [a, b].
// `counts`, when given, is added to. `reach`, when given, is raised to upper
// bounds of |V(theta) - p's center| and |V(theta) - q's center| over [a, b],
// from the pieces' certificates: how far the edge gets from either site (the
// cells' reach).
std::optional<MeasureIntervals> integrate_edge(NormalRayInDoubles& bisector, GaussLegendreRules& rules, double a,
                                               double b, const double (&tolerance)[MeasureIntervals::count],
                                               QuadratureCounts* counts = nullptr, std::array<double, 2>* reach = nullptr);

// The same measures at precision prec, between the exact angles `ends`
// (balls of radius zero): the certificate of `bounds`, each node from its
// piece's disk proof (NormalRayInDoubles::densities_in_balls) or else by
// `bisector` (the same pair of sites); `counts` and `reach` as above.
std::optional<NormalRayBisector::Densities> integrate_edge_in_arb(NormalRayInDoubles& bounds,
                                                                  NormalRayBisector& bisector,
                                                                  GaussLegendreRules& rules, const Ball (&ends)[2],
                                                                  const double (&tolerance)[MeasureIntervals::count],
                                                                  long prec, QuadratureCounts* counts = nullptr,
                                                                  std::array<double, 2>* reach = nullptr);

}  // namespace ellvor
