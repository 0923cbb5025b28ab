// A certified separation of two sites by a slab: a direction n with
//   n.(c2 - c1) - h1(n) - h2(n) >= gap |n|,
// h the support functions of the centered ellipses, sqrt(a^2 (n.u)^2 +
// b^2 (n.v)^2), proves that the sites are at least `gap` apart (every point of
// E1 lies in n.x <= n.c1 + h1, every point of E2 in n.x >= n.c2 - h2). Two
// disjoint sites always have such a direction with gap > 0, and the best one
// gives their distance; it is searched for in doubles (a scan and a
// golden-section search: the separating directions of two disjoint convex
// sets form an arc) and the slab is then proven in outward-rounded double
// intervals (util/interval.hpp). So it decides pairs that are close but not
// tangent, where the line of the centers or the bounding circles do not.
//
// The same search gives the largest scale of one site about its center that
// keeps it `gap` from the other (the packing generator grows sites with it).
// Only IEEE 754 basic operations are used (+ - * / sqrt), so a result is the
// same on every IEEE machine.
#pragma once

#include "sites/ellipse.hpp"
#include "util/interval.hpp"

namespace ellvor {

// What the slab test needs of a site: axes, rotation and center as intervals
// (exact doubles are point intervals), and their midpoints for the search.
struct SlabSite {
    Interval a, b, cos, sin, xc, yc;
    double ad, bd, cd, sd, xd, yd;

    static SlabSite of(const Interval& a, const Interval& b, const Interval& cos, const Interval& sin,
                       const Interval& xc, const Interval& yc);
    static SlabSite of(const Ellipse& e);  // from its enclosure
};

// A certified lower bound of the largest scale of p (about its center, q
// fixed) that keeps a slab of width >= gap between them; 0 when none is
// proven. gap_upper >= the gap (an upper enclosure), gap its approximation for
// the search. The search stops as soon as `enough` is proven.
double certified_separating_scale(const SlabSite& p, const SlabSite& q, double gap, double gap_upper,
                                  double enough);

// A certified lower bound of the width of a slab between p and q (the
// distance of the sites is at least that), along the line of the centers
// first and then along the searched direction; <= 0 when none is proven.
// Stops as soon as `enough` is proven.
double certified_separation(const SlabSite& p, const SlabSite& q, double enough);

// The support function of the centered site in the direction (nx, ny) (exact
// doubles), certified.
Interval support_enclosure(const SlabSite& s, double nx, double ny);

}  // namespace ellvor
