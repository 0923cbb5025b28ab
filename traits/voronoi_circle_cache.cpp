#include "traits/voronoi_circle_cache.hpp"

#include "util/error.hpp"

#include <algorithm>
#include <cstdint>

namespace ellvor {

int VoronoiCircleCache::Entry::index_of(SiteId id) const {
    for (int n = 0; n < 3; ++n)
        if (ids[n] == id) return n;
    throw Error("VoronoiCircleCache: site " + std::to_string(id) + " is not in this triple");
}

std::size_t VoronoiCircleCache::KeyHash::operator()(const std::array<SiteId, 3>& ids) const {
    // Mixing of the three ids (multipliers from splitmix64): faces of nearby
    // sites differ in few bits.
    std::uint64_t h = 0x9e3779b97f4a7c15ull;
    for (SiteId id : ids) {
        h ^= static_cast<std::uint64_t>(id) + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
        h *= 0xbf58476d1ce4e5b9ull;
        h ^= h >> 31;
    }
    return static_cast<std::size_t>(h);
}

VoronoiCircleCache::Entry& VoronoiCircleCache::at(SiteId i, const Ellipse& ei, SiteId j, const Ellipse& ej,
                                                   SiteId k, const Ellipse& ek) {
    std::array<SiteId, 3> ids = {i, j, k};
    std::array<const Ellipse*, 3> sites = {&ei, &ej, &ek};
    const int first = first_of_rotation(ids);
    std::rotate(ids.begin(), ids.begin() + first, ids.end());
    std::rotate(sites.begin(), sites.begin() + first, sites.end());
    auto found = entries_.find(ids);
    if (found != entries_.end()) {
        ++hits_;
        return found->second;
    }
    ++misses_;
    return entries_.emplace(ids, Entry{ids, VoronoiCircle(*sites[0], *sites[1], *sites[2])}).first->second;
}

VoronoiCircleCache::Entry* VoronoiCircleCache::find(SiteId i, SiteId j, SiteId k) {
    const auto found = entries_.find(triple_key(i, j, k));
    return found == entries_.end() ? nullptr : &found->second;
}

void VoronoiCircleCache::erase(SiteId i, SiteId j, SiteId k) { entries_.erase(triple_key(i, j, k)); }

}  // namespace ellvor
