// Starts for Voronoi circles far larger than their sites, of radius R up to
// 10^40 times the sites' size. A double-precision guess cannot resolve them,
// and the exhaustive search needs about log2(R / size) levels of boxes.
//
// As R grows, the circle near two of the sites tends to a line tangent to
// both: an external bitangent of sites i, j (tangent at S_i, S_j with outward
// normal n, d perpendicular to n; computed in Arb at high precision). Near
// the line the circle's boundary is, to first order in 1/R, the parabola
//     n.x = n.V - R + (d.x - c)^2 / (2 R),   c = (S_i.d + S_j.d) / 2,
// touching i and j at their support heights h_i = h_j:
//     n.V = h_i + R - (S_i.d - c)^2 / (2 R).
// The third site k touches it at the point S_k of outward normal u; with
// w = S_k - (c, h_i) in (d, n) coordinates, |V - S_k| = R gives
//     R = (w_d^2 - (S_i.d - c)^2 + w_n^2) / (2 w_n).
// u = n first; then u points from S_k to V, twice. This covers both ways a
// circle gets huge: the three sites nearly on a line (w_n = the gap
// h_k(n) - h_i(n) small; rows of grains, perturbed grids, rationals close to
// a line: R up to 10^40 times the sizes), and a third site far from a close
// pair (w_n ~ the distance; a far site seen past a needle's tip). Each
// tangency point is the site's boundary point whose outward normal points at
// V. The relative error is O(size / R), so Newton at a precision covering
// log2(R / size) converges from it; the caller certifies (or rejects) each
// start like any other.
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

// The same starts in doubles, for the double-precision certificate
// (subdivision/voronoi_circle_in_doubles.hpp) and circles from 2^min_ratio_bits
// up to 2^kMaxRatioBitsInDoubles times the sites: there the first-order
// circle's error O(size / R) is far above the doubles' rounding, so the Arb
// passes above add nothing but their cost. x: the three chart parameters,
// the radius and the center, as in a VoronoiCircleStart.
struct DoubleCircleStart {
    std::array<bool, 3> flipped{};
    std::array<double, 6> x{};
};
constexpr long kMaxRatioBitsInDoubles = 20;
bool for_each_huge_circle_start_in_doubles(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3,
                                           long min_ratio_bits,
                                           const std::function<bool(const DoubleCircleStart&)>& try_start);

}  // namespace ellvor
