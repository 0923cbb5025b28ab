// A periodic box (the torus) as a Voronoi diagram in the plane
// (docs/DESIGN.md §10): the sites with their centers taken into the box, and
// their copies shifted by whole periods in k rings around it. A cell of an
// original is the torus's cell once no copy outside the rings can cut it
// (periodic_cell_is_proven).
#pragma once

#include "cells/cell_domain.hpp"
#include "decision/site_id.hpp"
#include "sites/ellipse.hpp"

#include <array>
#include <vector>

namespace ellvor {

// e translated by whole periods so that its center lies in [x0, x1) x [y0, y1),
// exactly: xc - floor((xc - x0) / Lx) Lx.
Ellipse wrap_into_box(const Ellipse& e, const CellDomain& box);

// How far beyond the box copies are made: (Dx, Dy).
using CopyMargin = std::array<Rational, 2>;

// The wrapped sites (ids 0..n-1) followed by their copies shifted by (i Lx,
// j Ly), (i, j) != (0, 0), whose centers lie in [x0 - Dx, x1 + Dx) x
// [y0 - Dy, y1 + Dy): a copy left out has its center at least
// distance_to_missing_copies from the center of any site in the box.
struct PeriodicCopies {
    std::vector<Ellipse> sites;
    std::vector<SiteId> original;            // per site: the site it copies
    std::vector<std::array<long, 2>> shift;  // per site
    std::size_t originals = 0;
};
PeriodicCopies periodic_copies(const std::vector<Ellipse>& wrapped, const CellDomain& box, const CopyMargin& margin);

// The margin of whole rings of copies at level k: k rings along the longer
// period and k times the ratio of the periods (rounded up) along the
// shorter, so that the copies reach about as far both ways.
CopyMargin ring_margin(const CellDomain& box, long rings);

// Throws InputError naming the site and the shift (in periods) when a site
// meets one of its own periodic images: the periodic box is too small for
// it. Different sites may cross or touch, on the torus as in the plane
// (docs/DESIGN.md §9). Exact (predicates/relative_position.hpp) after a
// bounding-circle filter; the sites must have their centers in the box
// (wrap_into_box).
void require_sites_fit_periodic_box(const std::vector<Ellipse>& wrapped, const CellDomain& box);

// The lowest ring level with kx Lx and ky Ly > 2 max semi-axis: then every
// copy outside the rings is apart from every site in the box.
long starting_rings(const std::vector<Ellipse>& wrapped, const CellDomain& box);

// A lower bound of the distance from the center of wrapped site p to the
// center of any copy left out at `margin`:
// min(Dx + min(x1 - xc, xc - x0), Dy + min(y1 - yc, yc - y0)).
Rational distance_to_missing_copies(const Ellipse& p, const CellDomain& box, const CopyMargin& margin);

// The certificate (docs/DESIGN.md §10): when every point x of p's cell among
// the copies has |x - c_p| <= reach, and 2 reach < d_out + min(a_p, b_p) -
// e_max (d_out from distance_to_missing_copies, e_max the largest semi-axis
// of all sites), no missing copy cuts the cell: it is the torus's cell.
bool periodic_cell_is_proven(double reach, const Ellipse& p, const Rational& d_out, const Rational& e_max);

}  // namespace ellvor
