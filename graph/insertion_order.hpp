// The order in which insert_all inserts the sites (bulk insertion): largest
// first, as CGAL's Apollonius graph, in rounds of doubling size (the 1024
// largest sites, the next 1024, 2048, 4096, ...), each round but the first
// along a Hilbert curve through the sites' location hints (the first keeps
// the weight order: up to 1024 sites it is the order). Every site of a round weighs at
// least as much as every site of the later rounds, so a site contained in
// another comes after it unless both fall in one round (then inserting the
// container hides it: the graph does not depend on the order,
// test_insertion_order.cpp). Consecutive insertions are close: the walk is
// short and the sites, faces and cached circles they touch are in cache
// (at 10^5 sites the weight order alone jumps across the plane each time).
#pragma once

#include "decision/delaunay_traits.hpp"

#include <cstdint>
#include <vector>

namespace ellvor {

// A permutation of 0 .. traits.size() - 1.
std::vector<SiteId> bulk_insertion_order(const DelaunayTraits& traits);

// The sizes of the rounds of a bulk order of n sites, in order (1024, 1024,
// 2048, 4096, ..., the last one what remains).
std::vector<std::size_t> bulk_insertion_rounds(std::size_t n);

// The position of (x, y) along the Hilbert curve of order 16 through the
// square [x0, x0 + side] x [y0, y0 + side] (points outside are clamped).
std::uint32_t hilbert_index(double x, double y, double x0, double y0, double side);

}  // namespace ellvor
