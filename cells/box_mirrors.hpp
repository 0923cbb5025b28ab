// A box with walls as a Voronoi diagram in the plane (docs/DESIGN.md §10):
// the sites with their mirror images across the walls. In the diagram of the
// sites and all their mirrors, a site's cell is exactly its cell among the
// sites clipped to the box, and its sides along a wall are its edges with its
// own mirror across that wall; so it is with fewer mirrors as long as every
// cell that meets a wall has its site's mirror across it.
#pragma once

#include "cells/cell_domain.hpp"
#include "decision/site_id.hpp"
#include "sites/ellipse.hpp"
#include "sites/mirror_symmetry.hpp"

#include <array>
#include <vector>

namespace ellvor {

// The line of a wall: x = x0 (left), y = y0 (bottom), x = x1, y = y1.
AxisLine wall_line(Wall wall, const CellDomain& box);

// Throws InputError naming the first site (its id) that is not strictly
// inside the box, decided exactly: its center inside, and strictly beside
// each wall's line (sites/mirror_symmetry.hpp).
void require_sites_inside_box(const std::vector<Ellipse>& sites, const CellDomain& box);

// Which walls a site is mirrored across, in the order of kWalls.
constexpr Wall kWalls[4] = {Wall::left, Wall::bottom, Wall::right, Wall::top};
using WallMirrors = std::array<bool, 4>;

// The sites followed by their mirrors across the walls `across` names for
// each (site by site, walls in kWalls' order).
struct MirroredSites {
    std::vector<Ellipse> sites;
    std::size_t originals = 0;
    std::vector<SiteId> original;  // every site's original (itself for an original)
    std::vector<Wall> wall;        // the wall a mirror is across; none for an original
};
MirroredSites with_box_mirrors(const std::vector<Ellipse>& sites, const CellDomain& box,
                               const std::vector<WallMirrors>& across);

// The walls whose lines are within `distance` plus its larger semi-axis of
// each site's center (in doubles: a guess of where a cell reaches, which the
// caller proves or corrects).
std::vector<WallMirrors> walls_near(const std::vector<Ellipse>& sites, const CellDomain& box, double distance);

// The distance from a site's center to a wall's line, rounded down.
double distance_to_wall(const Ellipse& site, Wall wall, const CellDomain& box);

}  // namespace ellvor
