// A uniform grid of the sites' centers (in doubles) that proposes a start for
// the nearest-neighbour walk: a site already in the graph whose center is
// close to the new site's. Only the walk's length depends on it -- the walk
// itself is decided by kappa1 -- so rounding here is harmless.
#pragma once

#include "graph/delaunay_traits.hpp"

#include <vector>

namespace ellvor {

class SiteGrid {
public:
    // About one cell per site over the bounding box of all the centers.
    explicit SiteGrid(const DelaunayTraits& traits);
    void add(SiteId s);
    // Sites added so far around s's center, closest center first; the first
    // is a nearest added center (in doubles). Empty when nothing was added.
    std::vector<SiteId> near(SiteId s) const;

private:
    long cell_of(double x, double y) const;

    std::vector<double> x_, y_;  // centers
    double x0_ = 0, y0_ = 0, cell_ = 1;
    long columns_ = 1, rows_ = 1;
    std::vector<std::vector<SiteId>> cells_;
    std::size_t added_ = 0;
};

}  // namespace ellvor
