// A box with walls as a Voronoi diagram in the plane (docs/DESIGN.md §10):
// every site with its mirror images across the four walls. In the diagram of
// the sites and their mirrors, a site's cell is exactly its cell among the
// sites clipped to the box, and its sides along a wall are its edges with its
// own mirror across that wall.
#pragma once

#include "cells/cell_domain.hpp"
#include "decision/site_id.hpp"
#include "sites/ellipse.hpp"
#include "sites/mirror_symmetry.hpp"

#include <vector>

namespace ellvor {

// The line of a wall: x = x0 (left), y = y0 (bottom), x = x1, y = y1.
AxisLine wall_line(Wall wall, const CellDomain& box);

// Throws InputError naming the first site (its id) that is not strictly
// inside the box, decided exactly: its center inside, and strictly beside
// each wall's line (sites/mirror_symmetry.hpp).
void require_sites_inside_box(const std::vector<Ellipse>& sites, const CellDomain& box);

// The sites followed by their mirrors: site i's mirror across the wall k
// (left, bottom, right, top: k = 0..3) is site n + 4 i + k.
struct MirroredSites {
    std::vector<Ellipse> sites;
    std::size_t originals = 0;
    // For a mirror, the wall it mirrors across and its original; none for an original.
    Wall wall_of(SiteId s) const { return s < originals ? Wall::none : static_cast<Wall>(1 + (s - originals) % 4); }
    SiteId original_of(SiteId s) const { return s < originals ? s : (s - originals) / 4; }
};
MirroredSites with_box_mirrors(const std::vector<Ellipse>& sites, const CellDomain& box);

}  // namespace ellvor
