#include "traits/voronoi_circle_cache.hpp"

#include "util/error.hpp"

#include <algorithm>

namespace ellvor {

int VoronoiCircleCache::Entry::index_of(SiteId id) const {
    for (int n = 0; n < 3; ++n)
        if (ids[n] == id) return n;
    throw Error("VoronoiCircleCache: site " + std::to_string(id) + " is not in this triple");
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

void VoronoiCircleCache::erase(SiteId i, SiteId j, SiteId k) { entries_.erase(triple_key(i, j, k)); }

}  // namespace ellvor
