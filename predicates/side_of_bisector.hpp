// kappa1 (seed section 5.1; CGAL Oriented_side_of_bisector_2): which of two
// ellipses is closer to a rational point p, under the signed distance
// (positive outside, negative inside, zero on the boundary).
#pragma once

#include "predicates/stage.hpp"
#include "sites/ellipse.hpp"

namespace ellvor {

struct SideOfBisectorOptions {
    bool use_filter = true;      // false: start at the Arb stage (for tests and experiments)
    long start_precision = 64;   // first Arb precision (bits)
    long max_precision = 512;    // beyond this the exact stage decides
};

// +1 when p is closer to E1 (CGAL's ON_POSITIVE_SIDE), -1 when closer to E2,
// 0 when equidistant (proven exactly). Cascade: double-interval filter ->
// Arb balls at doubling precision -> exact comparison of the two squared
// distances as real algebraic numbers of degree <= 4.
SignDecision side_of_bisector(const Ellipse& e1, const Ellipse& e2, const Point& p,
                              const SideOfBisectorOptions& options = {});

}  // namespace ellvor
