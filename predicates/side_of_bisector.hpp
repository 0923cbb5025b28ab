// kappa1 (the paper, section 5.1; CGAL Oriented_side_of_bisector_2): which of two
// ellipses is closer to a rational point p, under the signed distance
// (positive outside, negative inside, zero on the boundary).
#pragma once

#include "decision/stage.hpp"
#include "sites/ellipse.hpp"
#include "util/precision.hpp"

namespace ellvor {

struct SideOfBisectorOptions {
    bool use_filter = true;                          // false: start at the Arb stage (tests, experiments)
    long max_precision = precision::kSideOfBisectorCap;  // beyond this the exact stage decides
};

// POSITIVE when p is closer to E1 (CGAL's ON_POSITIVE_SIDE), NEGATIVE when
// closer to E2, ZERO when equidistant (proven exactly). Always decided.
// Cascade: double-interval filter -> Arb balls at doubling precision -> exact
// comparison of the two squared distances as real algebraic numbers of
// degree <= 4.
Decision<Sign> side_of_bisector(const Ellipse& e1, const Ellipse& e2, const Point& p,
                                const SideOfBisectorOptions& options = {});
// The same at the center of `site`, whose cached enclosure saves converting
// the center (the graph's nearest-site walk asks this).
Decision<Sign> side_of_bisector_at_center(const Ellipse& e1, const Ellipse& e2, const Ellipse& site,
                                          const SideOfBisectorOptions& options = {});

}  // namespace ellvor
