// Cells assume that no two sites touch or cross (docs/DESIGN.md §10): this
// checks it up front, in the plane, a box, or on the torus (every periodic
// copy), naming the input ids, so that no later stage meets such a pair.
#pragma once

#include "cells/cell_domain.hpp"
#include "sites/ellipse.hpp"

#include <vector>

namespace ellvor {

// Throws InputError naming the pair (and the shift in periods on the torus)
// when two sites touch or cross, or a site meets one of its own periodic
// images (the periodic box is too small for it). Exact
// (predicates/relative_position.hpp) after a bounding-circle filter: in the
// plane and a box on the pairs of sites/meeting_pair_candidates.hpp (O(n) on
// spread-out data), on the torus on every pair. There the sites must have
// their centers in the box (wrap_into_box).
void require_sites_apart(const std::vector<Ellipse>& sites, const CellDomain& domain);

}  // namespace ellvor
