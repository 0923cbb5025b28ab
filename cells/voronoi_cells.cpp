#include "cells/voronoi_cells.hpp"

#include "cells/face_numbers.hpp"

namespace ellvor {

bool VoronoiCell::bounded() const {
    if (!visible || edges.empty()) return false;
    for (const CellEdge& e : edges)
        if (e.from < 0 || e.to < 0) return false;
    return true;
}

std::vector<VoronoiCell> voronoi_cells(const DelaunayGraph& graph, const std::vector<long>& numbers) {
    std::vector<VoronoiCell> cells(graph.number_of_sites());
    for (SiteId s = 0; s < cells.size(); ++s) cells[s].site = s;
    const std::vector<SiteId> visible = graph.visible_sites();
    for (SiteId s : visible) cells[s].visible = true;
    const Triangulation& tds = graph.triangulation();
    if (tds.empty()) {
        // Fewer than three visible sites: two share one edge, infinite at both ends.
        if (visible.size() == 2) {
            cells[visible[0]].edges.push_back({visible[1], -1, -1});
            cells[visible[1]].edges.push_back({visible[0], -1, -1});
        }
        return cells;
    }
    for (VertexIndex v : tds.finite_vertices()) {
        const SiteId p = tds.vertex(v).site();
        // Around v counter-clockwise: between the face f = (v, A, B) and the
        // next face lies the Delaunay edge v -> B, f on its right; its Voronoi
        // edge runs from the next face's vertex to f's with p's tangency angle
        // decreasing, so counter-clockwise around p it runs from f to the next.
        const std::vector<FaceIndex> star = tds.incident_faces(v);
        for (std::size_t k = 0; k < star.size(); ++k) {
            const FaceIndex f = star[k], next = star[(k + 1) % star.size()];
            const Triangulation::Face& F = tds.face(f);
            const VertexIndex b = F.v[cw(tds.index(f, v))];
            if (b == Triangulation::kInfiniteVertex) continue;
            cells[p].edges.push_back({tds.vertex(b).site(), face_number(numbers, f), face_number(numbers, next)});
        }
    }
    return cells;
}

}  // namespace ellvor
