// What the graph tests compare between two Delaunay graphs of the same sites
// (visible sites, [hidden, hiding] pairs, edges as a multiset, faces, hull),
// a replayable description of an input, and a seeded shuffle.
#pragma once

#include "graph/delaunay_graph.hpp"
#include "sites/ellipse.hpp"

#include <array>
#include <numeric>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace ellvor::test {

using Pairs = std::vector<std::pair<SiteId, SiteId>>;

struct GraphShape {
    std::vector<SiteId> visible;
    Pairs hidden, edges, hull;
    std::vector<std::array<SiteId, 3>> faces;
};

inline GraphShape shape_of(const DelaunayGraph& g) {
    return {g.visible_sites(), g.hidden(), g.edges(), g.hull(), g.faces()};
}

// The sites as .ell lines, then `what` and the ids (an insertion order, removals).
inline std::string replay(const std::vector<Ellipse>& sites, const std::string& what, const std::vector<SiteId>& ids) {
    std::ostringstream s;
    s << "sites (a b w xc yc):\n";
    for (const Ellipse& e : sites) s << e.str() << "\n";
    s << what << ":";
    for (SiteId i : ids) s << " " << i;
    return s.str();
}

// A random permutation of 0 .. n-1: our own shuffle (std::shuffle's algorithm
// is implementation-defined), so that a seed means the same order everywhere.
inline std::vector<SiteId> random_order(std::size_t n, std::mt19937_64& rng) {
    std::vector<SiteId> order(n);
    std::iota(order.begin(), order.end(), 0);
    for (std::size_t i = n; i > 1; --i) std::swap(order[i - 1], order[rng() % i]);
    return order;
}

}  // namespace ellvor::test
