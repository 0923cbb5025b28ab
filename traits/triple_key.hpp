// The key of a counter-clockwise triple of sites up to cyclic rotation: the
// rotation that starts with the smallest id. (i, j, k), (j, k, i) and
// (k, i, j) are the same Voronoi circle; (i, k, j) is another.
#pragma once

#include "decision/site_id.hpp"

#include <algorithm>
#include <array>

namespace ellvor {

using TripleKey = std::array<SiteId, 3>;

// The position in (i, j, k) of the smallest id: rotating by it gives the key.
inline int first_of_rotation(const TripleKey& ids) {
    return static_cast<int>(std::min_element(ids.begin(), ids.end()) - ids.begin());
}

inline TripleKey triple_key(SiteId i, SiteId j, SiteId k) {
    TripleKey ids = {i, j, k};
    std::rotate(ids.begin(), ids.begin() + first_of_rotation(ids), ids.end());
    return ids;
}

}  // namespace ellvor
