#include "cells/face_numbers.hpp"

#include <algorithm>
#include <array>
#include <utility>

namespace ellvor {

std::vector<long> face_numbers(const DelaunayGraph& graph) {
    const Triangulation& tds = graph.triangulation();
    // The rotated triple of every finite face, sorted as faces() sorts them.
    std::vector<std::pair<std::array<SiteId, 3>, FaceIndex>> keyed;
    for (FaceIndex f : tds.faces()) {
        if (tds.is_infinite_face(f)) continue;
        std::array<SiteId, 3> t;
        for (int i = 0; i < 3; ++i) t[i] = tds.vertex(tds.face(f).v[i]).site();
        std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
        keyed.push_back({t, f});
    }
    std::sort(keyed.begin(), keyed.end());
    std::vector<long> numbers;
    for (std::size_t k = 0; k < keyed.size(); ++k) {
        const auto f = static_cast<std::size_t>(keyed[k].second.value());
        if (f >= numbers.size()) numbers.resize(f + 1, -1);
        numbers[f] = static_cast<long>(k);
    }
    return numbers;
}

long face_number(const std::vector<long>& numbers, FaceIndex f) {
    const auto k = static_cast<std::size_t>(f.value());
    return f.is_none() || k >= numbers.size() ? -1 : numbers[k];
}

}  // namespace ellvor
