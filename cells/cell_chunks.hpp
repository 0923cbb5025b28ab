// Cells in chunks along a Hilbert curve, each chunk by itself, on threads
// (docs/DESIGN.md §10). A chunk's work depends on its cells alone (a solver
// of its own, its caches and the edges it shares between its cells), so the
// result does not depend on the threads or on the order they take chunks in.
#pragma once

#include "decision/site_id.hpp"
#include "sites/ellipse.hpp"

#include <cstddef>
#include <functional>
#include <vector>

namespace ellvor {

// The cells of a chunk by default. An edge between chunks is integrated or
// covered once for each of its cells: 2000 random cells in a box cost 4.3%
// more instructions in chunks of 256 than of 1024, and 500 cells make two
// chunks for two threads.
constexpr std::size_t kCellChunk = 256;

// `which` ordered along a Hilbert curve through the sites' centers.
std::vector<SiteId> hilbert_order(const std::vector<Ellipse>& sites, std::vector<SiteId> which);

// work(begin, end) for every chunk of `chunk` consecutive entries of `order`
// (the last one shorter), on `threads` threads (0: one per core; the calling
// thread is one of them). After an exception the chunks after the failed one
// are skipped, and the first failed chunk's exception is rethrown, whatever
// the threads. Throws Error when chunk is 0.
void for_each_chunk(const std::vector<SiteId>& order, std::size_t chunk, unsigned threads,
                    const std::function<void(const SiteId* begin, const SiteId* end)>& work);

}  // namespace ellvor
