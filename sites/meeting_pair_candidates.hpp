// The pairs of sites that may meet, without comparing every pair: the ones
// whose circumscribed disks (radius max(a, b)) are not proven apart. Checks
// of every pair of an input (its validity, docs/DESIGN.md §2) look at these
// only; on spread-out data there are O(n) of them.
#pragma once

#include "sites/ellipse.hpp"

#include <cstddef>
#include <utility>
#include <vector>

namespace ellvor {

// Every pair (i, j), i < j, of sites whose circumscribed disks may share a
// point, sorted by j, then i. A pair left out has disjoint disks, proven in
// outward-rounded doubles (their bounding boxes are apart); a pair listed may
// still be apart. Through a grid of several levels (site i in the level of
// its box's size, found from the smaller site of a pair): O(n log n) plus
// the pairs listed and their neighbours' in the grid.
std::vector<std::pair<std::size_t, std::size_t>> pairs_that_may_meet(const std::vector<Ellipse>& sites);

}  // namespace ellvor
