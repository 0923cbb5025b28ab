#include "predicates/edge_conflict.hpp"

#include "predicates/bisector_order.hpp"
#include "predicates/infinite_vertex_conflict.hpp"
#include "predicates/voronoi_circle_count.hpp"
#include "subdivision/voronoi_circle_enclosure.hpp"

#include <algorithm>
#include <memory>
#include <vector>

namespace ellvor {

namespace {

// Where Q's shadow region on the bisector of (E1, E2) begins: the Voronoi
// circle of (E1, E2, Q). `present` is false when the region has fewer than two
// boundary circles.
struct ShadowRegion {
    bool present = false;
    bool connected = false;  // one interval (else two rays through both ends)
    Stage stage = Stage::filter;
};

ShadowRegion shadow_region(const Ellipse& e1, const Ellipse& e2, const Ellipse& q) {
    ShadowRegion s;
    const VoronoiCircleCount count = voronoi_circle_count_decided(e1, e2, q);
    s.stage = count.stage;
    if (count.circles != VoronoiCircles::both) return s;
    s.present = true;
    // Both circles exist: the region holds both ends of the bisector or
    // neither; it holds the end at (E2, E1, inf) iff Q conflicts with it.
    const SignDecision end = infinite_vertex_conflict(e2, e1, q);
    s.stage = std::max(s.stage, end.stage);
    s.connected = end.sign > 0;
    return s;
}

// An edge of the bisector of (E1, E2): its finite vertices (triples starting
// with E1); with one vertex it is the ray from the departure end (the
// infinite vertex (E2, E1, inf)), with none the whole bisector.
struct EdgeShape {
    std::vector<std::array<const Ellipse*, 3>> vertices;
};

// Whether the shadow boundary VC(E1, E2, Q) lies strictly inside the edge:
// true/false when decided; nullopt when some circle cannot be certified or
// the positions cannot be separated below the precision cap.
std::optional<bool> boundary_inside_edge(const Ellipse& e1, const Ellipse& e2, const Ellipse& q, const EdgeShape& edge,
                                         const EdgeConflictOptions& options, long& precision) {
    BisectorFrame frame(e1, e2);
    VoronoiCircleSolver boundary(e1, e2, q);
    std::vector<std::unique_ptr<VoronoiCircleSolver>> ends;  // the edge's finite vertices
    for (const auto& v : edge.vertices) ends.push_back(std::make_unique<VoronoiCircleSolver>(*v[0], *v[1], *v[2]));
    if (ends.empty()) return true;  // the whole bisector
    if (ends.size() == 1) {
        // The ray from the departure end to the vertex.
        const auto order = order_on_bisector(frame, boundary, 0, *ends[0], 0, options.max_precision, precision);
        if (!order) return std::nullopt;
        return *order < 0;
    }
    const auto first = order_on_bisector(frame, boundary, 0, *ends[0], 0, options.max_precision, precision);
    if (!first) return std::nullopt;
    const auto second = order_on_bisector(frame, boundary, 0, *ends[1], 0, options.max_precision, precision);
    if (!second) return std::nullopt;
    return *first != *second;  // after one end and before the other
}

EdgeConflictDecision decide(const Ellipse& e1, const Ellipse& e2, const Ellipse& q, bool b, const EdgeShape& edge,
                            const EdgeConflictOptions& options) {
    EdgeConflictDecision d;
    const ShadowRegion shadow = shadow_region(e1, e2, q);
    d.stage = shadow.stage;
    if (!shadow.present) {
        d.conflict = b;
        return d;
    }
    // An interval shadow contains no vertex of a b = false edge, and a
    // two-ray shadow contains every vertex of a b = true edge.
    if (shadow.connected && b) {
        d.conflict = true;
        return d;
    }
    if (!shadow.connected && !b) {
        d.conflict = false;
        return d;
    }
    d.stage = Stage::subdivision;
    const auto inside = boundary_inside_edge(e1, e2, q, edge, options, d.precision);
    if (!inside) return d;
    // Interval shadow, free ends: it meets the edge iff it lies inside it.
    // Two-ray shadow, ends in conflict: the whole edge is in conflict iff the
    // gap between the rays is not inside the edge.
    d.conflict = shadow.connected ? *inside : !*inside;
    return d;
}

}  // namespace

EdgeConflictDecision finite_edge_interior_conflict(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3,
                                                   const Ellipse& e4, const Ellipse& q, bool b,
                                                   const EdgeConflictOptions& options) {
    EdgeShape edge;
    edge.vertices = {{&e1, &e2, &e3}, {&e1, &e4, &e2}};
    return decide(e1, e2, q, b, edge, options);
}

EdgeConflictDecision finite_edge_interior_conflict(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3,
                                                   const Ellipse& q, bool b, const EdgeConflictOptions& options) {
    EdgeShape edge;
    edge.vertices = {{&e1, &e2, &e3}};
    return decide(e1, e2, q, b, edge, options);
}

EdgeConflictDecision finite_edge_interior_conflict(const Ellipse& e1, const Ellipse& e2, const Ellipse& q, bool b,
                                                   const EdgeConflictOptions& options) {
    return decide(e1, e2, q, b, EdgeShape{}, options);
}

EdgeConflictDecision infinite_edge_interior_conflict(const Ellipse& e2, const Ellipse& e3, const Ellipse& e4,
                                                     const Ellipse& q, bool b) {
    // Contact points on E2 of the edge's ends and of Q's boundary lines.
    BoundaryParameter from = external_bitangent_on(e2, e3, HullSide::arrival);   // vertex (E2, E3, inf)
    BoundaryParameter to = external_bitangent_on(e2, e4, HullSide::departure);   // vertex (E4, E2, inf)
    BoundaryParameter start = external_bitangent_on(e2, q, HullSide::departure);  // vertex (Q, E2, inf)
    EdgeConflictDecision d;
    d.stage = Stage::exact;
    int inside = position_in_arc(from, to, start);
    if (inside == 0) {  // Q's line coincides with an end: use its other line (Q, E2)
        BoundaryParameter other = external_bitangent_on(e2, q, HullSide::arrival);  // vertex (E2, Q, inf)
        inside = position_in_arc(from, to, other);
        if (inside == 0) {
            d.conflict = !b;
            return d;
        }
    }
    // b: the whole edge is in conflict unless Q's conflict region begins inside
    // it; !b: some interior point is in conflict iff it begins inside it.
    d.conflict = b ? inside < 0 : inside > 0;
    return d;
}

}  // namespace ellvor
