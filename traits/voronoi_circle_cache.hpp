// Cache of certified Voronoi circles, keyed by the ordered triple of site ids
// (a cyclic rotation of a triple is the same circle with the same
// orientation, so all three rotations share one entry). The cache belongs to
// whoever builds it -- a graph, a benchmark, a CLI call -- and holds pointers
// to sites that must outlive it; sites are never mutated.
#pragma once

#include "traits/triple_key.hpp"
#include "sites/ellipse.hpp"
#include "subdivision/voronoi_circle.hpp"

#include <array>
#include <cstddef>
#include <unordered_map>

namespace ellvor {

class VoronoiCircleCache {
public:
    struct Entry {
        std::array<SiteId, 3> ids;  // rotated so that the smallest id comes first
        VoronoiCircle circle;  // of the sites in the order of ids
        // Index in the circle's triple of the site with this id.
        int index_of(SiteId id) const;
    };

    // The entry of the Voronoi circle of the ordered triple (i, j, k) of
    // sites, created (not yet certified) on first use.
    Entry& at(SiteId i, const Ellipse& ei, SiteId j, const Ellipse& ej, SiteId k, const Ellipse& ek);

    // The entry of (i, j, k) or of a rotation of it, nullptr if there is none
    // (does not count as a hit or a miss).
    Entry* find(SiteId i, SiteId j, SiteId k);

    // Removes the entry of (i, j, k) or of a rotation of it, if any.
    void erase(SiteId i, SiteId j, SiteId k);

    std::size_t size() const { return entries_.size(); }
    std::size_t hits() const { return hits_; }
    std::size_t misses() const { return misses_; }
    void clear() { entries_.clear(); }

private:
    // Hashed: a build asks it about every face, and a tree's walk of ~log n
    // nodes scattered in memory cost more than the solvers at 10^5 sites.
    // Nodes keep their address on rehash, so an Entry& stays valid.
    struct KeyHash {
        std::size_t operator()(const std::array<SiteId, 3>& ids) const;
    };
    std::unordered_map<std::array<SiteId, 3>, Entry, KeyHash> entries_;
    std::size_t hits_ = 0, misses_ = 0;
};

}  // namespace ellvor
