// A uniform grid of the sites' location hints (a point per site, in doubles)
// that proposes a start for the nearest-neighbour walk: a site already in the
// graph whose hint is close to the new site's. Only the walk's length depends
// on it -- the walk itself is decided by kappa1 -- so rounding here is harmless.
#pragma once

#include "decision/delaunay_traits.hpp"

#include <vector>

namespace ellvor {

class SiteGrid {
public:
    // About one cell per site over the bounding box of all the points; site
    // i is at points[i].
    explicit SiteGrid(const std::vector<LocationHint>& points);
    void add(SiteId s);
    // Sites added so far around s's point, closest point first; the first is
    // a nearest added point (in doubles). Empty when nothing was added.
    std::vector<SiteId> near(SiteId s) const;

private:
    long cell_of(double x, double y) const;

    std::vector<double> x_, y_;  // the points
    double x0_ = 0, y0_ = 0, cell_ = 1;
    long columns_ = 1, rows_ = 1;
    std::vector<std::vector<SiteId>> cells_;
    std::size_t added_ = 0;
};

}  // namespace ellvor
