// A certified box of a face's Voronoi circle, tight enough for tests made of
// its coordinates (the tiled build's seam and hull tests, python/ellvor/
// distributed.py): the double-interval certificate when its box is tight
// (docs/DESIGN.md §4.1a: cheap), else the Arb solver at 53 bits. A huge
// circle (R ~ 10^7 times its sites, three sites nearly on a line) certifies
// in doubles with a box ~10^-6 of R wide, which no seam test can use.
#pragma once

#include "decision/site_id.hpp"
#include "sites/ellipse.hpp"
#include "subdivision/voronoi_circle_in_doubles.hpp"
#include "util/interval.hpp"

#include <array>
#include <vector>

namespace ellvor {

struct VoronoiCircleBox {
    Interval center_x, center_y, radius;
};

// The box of the counter-clockwise Voronoi circle of the face (i, j, k) of a
// graph of `sites` (which has one). Every component is within about 2^-40
// of the circle's magnitude |center| + |radius|, or is Arb's 53-bit ball.
VoronoiCircleBox voronoi_circle_box(const std::vector<Ellipse>& sites, const std::array<SiteId, 3>& face);
// The same from the face's double certificate made before (a build's circle
// cache, VoronoiCircle::in_doubles): `doubles` is nullptr when it failed.
VoronoiCircleBox voronoi_circle_box(const std::vector<Ellipse>& sites, const std::array<SiteId, 3>& face,
                                    const DoubleVoronoiCircle* doubles);

// The double certificate's box however wide (`doubles`, when not nullptr), else
// Arb's at 53 bits: for a test that asks voronoi_circle_box for the tight box
// only where a wide one leaves it undecided (Arb costs ~0.3 ms a huge circle).
VoronoiCircleBox voronoi_circle_box_any_width(const std::vector<Ellipse>& sites, const std::array<SiteId, 3>& face,
                                              const DoubleVoronoiCircle* doubles);

// Whether every component of the box is within 2^-40 of the circle's
// magnitude |center| + |radius|: a double box voronoi_circle_box keeps.
bool is_tight(const VoronoiCircleBox& box);

// Whether the boxes of two circles meet (all three components overlap).
bool circle_boxes_meet(const VoronoiCircleBox& a, const VoronoiCircleBox& b);

// Whether the Voronoi circle of `face`, certified in `box`, is proven to
// differ from that of `other` (a face of the same graph) by one circle box:
// a site of `other` that is not one of `face`'s is off face's circle
// (delta(V, Q) > rho for all of the box, incircle's double filter), while
// other's circle touches it. False: not proven (compare both boxes).
bool circle_differs_by_site(const std::vector<Ellipse>& sites, const VoronoiCircleBox& box,
                            const std::array<SiteId, 3>& face, const std::array<SiteId, 3>& other);

}  // namespace ellvor
