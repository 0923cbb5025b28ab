// Starts for Voronoi circles far larger than their sites: nearly collinear
// sites (rows of grains, perturbed grids, rationals close to a line) have
// Voronoi circles of radius R up to 10^40 times the sites' size. A
// double-precision guess cannot resolve them, and the exhaustive search needs
// about log2(R / size) levels of boxes.
//
// As R grows the circle tends to a line tangent to the three sites. From an
// external bitangent of two of the sites (tangent at S_i, S_j with outward
// normal n; computed in Arb at high precision), the gap g = h_k(n) - h_i(n)
// of the third site's support value beyond it, and the positions x_m = S_m.d
// of the support points along the line (d perpendicular to n), the circle
// follows to first order in 1/R: near the line its boundary is the parabola
//     n.x = n.V - R + (d.x - c)^2 / (2 R),
// and asking that it touch the three sites at their support heights gives
//     c = (x_i + x_j) / 2,   1/R = 2 g / ((x_k - x_i)(x_k - x_j)),
// n.V = h_i + R - (x_i - c)^2 / (2 R), each tangency point the site's boundary
// point whose outward normal points at V. The relative error is O(size / R),
// so Newton at a precision covering log2(R / size) converges from it; the
// caller certifies (or rejects) each start like any other.
#pragma once

#include "sites/ellipse.hpp"
#include "subdivision/voronoi_circle_search.hpp"

#include <functional>

namespace ellvor {

// Offers one start per external bitangent of each pair of the triple that
// has a circle of positive radius on its far side, until `try_start`
// accepts one (returns true). `min_ratio_bits`: only circles at least
// 2^min_ratio_bits times larger than the sites are offered (smaller ones are
// the double-precision guesses' business). Returns whether one was accepted.
bool for_each_huge_circle_start(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3, long min_ratio_bits,
                                const std::function<bool(const VoronoiCircleStart&)>& try_start);

}  // namespace ellvor
