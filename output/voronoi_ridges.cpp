#include "output/voronoi_ridges.hpp"

#include <algorithm>
#include <array>
#include <utility>

namespace ellvor {

std::vector<VoronoiRidge> voronoi_ridges(const DelaunayGraph& graph, const std::vector<long>& numbers) {
    std::vector<VoronoiRidge> ridges;
    const Triangulation& tds = graph.triangulation();
    if (tds.empty()) {
        const std::vector<SiteId> visible = graph.visible_sites();
        if (visible.size() == 2) ridges.push_back({visible[0], visible[1], -1, -1});
        return ridges;
    }
    auto number = [&](FaceIndex f) { return face_number(numbers, f); };
    for (FaceIndex f : tds.faces())
        for (int i = 0; i < 3; ++i) {
            const Edge e{f, i};
            if (tds.is_infinite_edge(e) || tds.mirror_edge(e) < e) continue;  // each edge once, as edges() does
            const Triangulation::Face& F = tds.face(f);
            ridges.push_back({tds.vertex(F.v[ccw(i)]).site(), tds.vertex(F.v[cw(i)]).site(), number(f), number(F.n[i])});
        }
    auto key = [](const VoronoiRidge& r) { return std::make_pair(std::min(r.p, r.q), std::max(r.p, r.q)); };
    std::stable_sort(ridges.begin(), ridges.end(),
                     [&](const VoronoiRidge& a, const VoronoiRidge& b) { return key(a) < key(b); });
    return ridges;
}

}  // namespace ellvor
