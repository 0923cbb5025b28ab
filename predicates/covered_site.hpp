// A site covered by two others, proven to leave the triple without any
// Voronoi circle (docs/DESIGN.md §9): the count's alternative to the
// complete search, which cannot exclude the near-solutions at a needle's tip
// (fuzz F6, experiments/results/fuzz.md).
#pragma once

#include "sites/ellipse.hpp"

namespace ellvor {

// True only if proven that the triple (x, y, z), in either orientation, has
// no Voronoi circle: false means not proven. Two conditions, for x crossing
// y and z:
//  (A) every boundary point of x lies strictly inside y or z (exactly: the
//      signs of the intersection quartics of x against y and z between and
//      at their real roots). Then no circle has rho >= 0: x's contact P would
//      lie in the open y (say), so delta(V, y) < |V - P| = rho.
//  (B) no point q of x's major-axis segment S has both delta(q, y) and
//      delta(q, z) in [-2 r, r], r = min(a, b) of x (interval bounds and the
//      inscribed-disk test on pieces of S, at most a few thousand). An
//      internal circle has -rho <= r (its disk lies in x), its center V
//      within r of S, and delta(V, y) = delta(V, z) = rho; delta is
//      1-Lipschitz, so the point of S nearest V would have both in [-2 r, r].
bool covered_without_circle(const Ellipse& x, const Ellipse& y, const Ellipse& z);

}  // namespace ellvor
