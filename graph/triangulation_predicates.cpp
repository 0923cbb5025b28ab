#include "graph/triangulation_predicates.hpp"

#include "util/error.hpp"

namespace ellvor {

Sign TriangulationPredicates::incircle(FaceIndex f, SiteId q) {
    const Triangulation::Face& F = tds_.face(f);
    const int k = tds_.index(f, Triangulation::kInfiniteVertex);
    if (k < 0) return traits_.incircle(site(F.v[0]), site(F.v[1]), site(F.v[2]), q);
    return traits_.infinite_vertex_conflict(site(F.v[ccw(k)]), site(F.v[cw(k)]), q);
}

void TriangulationPredicates::forget(FaceIndex f) {
    const Triangulation::Face& F = tds_.face(f);
    for (VertexIndex v : F.v)
        if (is_infinite(v) || site(v) == Triangulation::kBogusSite) return;
    traits_.forget_face(site(F.v[0]), site(F.v[1]), site(F.v[2]));
}

bool TriangulationPredicates::edge_interior(Edge e, SiteId q, bool b) {
    const Triangulation::Face& F = tds_.face(e.face);
    for (VertexIndex v : {F.v[ccw(e.index)], F.v[cw(e.index)]})
        if (!is_infinite(v) && traits_.is_hidden(q, site(v))) return true;
    return edge_interior_of_visible(e, q, b);
}

bool TriangulationPredicates::edge_interior_of_visible(Edge e, SiteId q, bool b) {
    const FaceIndex g = tds_.neighbor(e);
    const bool inf_f = tds_.is_infinite_face(e.face), inf_g = tds_.is_infinite_face(g);
    if (!inf_f && !inf_g) {
        const Triangulation::Face& F = tds_.face(e.face);
        const SiteId p1 = site(F.v[ccw(e.index)]), p2 = site(F.v[cw(e.index)]);
        return traits_.finite_edge_interior_conflict(p1, p2, site(F.v[e.index]), site(tds_.mirror_vertex(e)), q, b);
    }
    if (!inf_f || !inf_g || !tds_.is_infinite_edge(e)) return finite_edge_interior_degenerated(e, q, b);
    return infinite_edge_interior(e, q, b);
}

bool TriangulationPredicates::finite_edge_interior_degenerated(Edge e, SiteId q, bool b) {
    // Seen from the side whose mirror vertex is the infinite one.
    if (!is_infinite(tds_.mirror_vertex(e))) {
        if (!is_infinite(tds_.face(e.face).v[e.index]))
            throw Error("finite_edge_interior_degenerated: bad edge (internal error)");
        return finite_edge_interior_degenerated(tds_.mirror_edge(e), q, b);
    }
    const Triangulation::Face& F = tds_.face(e.face);
    const SiteId p1 = site(F.v[ccw(e.index)]), p2 = site(F.v[cw(e.index)]);
    if (is_infinite(F.v[e.index])) return traits_.finite_edge_interior_conflict(p1, p2, q, b);
    return traits_.finite_edge_interior_conflict(p1, p2, site(F.v[e.index]), q, b);
}

bool TriangulationPredicates::infinite_edge_interior(Edge e, SiteId q, bool b) {
    // Seen from the side where the infinite vertex is the edge's start.
    if (!is_infinite(tds_.face(e.face).v[ccw(e.index)])) return infinite_edge_interior(tds_.mirror_edge(e), q, b);
    const Triangulation::Face& F = tds_.face(e.face);
    const SiteId p2 = site(F.v[cw(e.index)]);
    return traits_.infinite_edge_interior_conflict(p2, site(F.v[e.index]), site(tds_.mirror_vertex(e)), q, b);
}

TriangulationPredicates::ConflictType TriangulationPredicates::finite_edge_conflict_type_degenerated(SiteId p1, SiteId p2,
                                                                                                     SiteId q) {
    const bool c1 = traits_.infinite_vertex_conflict(p1, p2, q) == Sign::negative;
    const bool c2 = traits_.infinite_vertex_conflict(p2, p1, q) == Sign::negative;
    if (c1 && !c2) return ConflictType::left_vertex;
    if (!c1 && c2) return ConflictType::right_vertex;
    const bool both = c1;  // (-, -) or (+, +)
    const bool b = traits_.is_hidden(q, p1) || traits_.is_hidden(q, p2) || traits_.finite_edge_interior_conflict(p1, p2, q, both);
    if (both) return b ? ConflictType::entire_edge : ConflictType::both_vertices;
    return b ? ConflictType::interior : ConflictType::no_conflict;
}

}  // namespace ellvor
