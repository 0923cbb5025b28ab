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

// Positions along the bisector of (E1, E2): a Voronoi vertex (a solver of a
// triple with E1 first), or an end of the bisector (departure = -inf,
// arrival = +inf).
struct BisectorPoint {
    VoronoiCircleSolver* vertex = nullptr;
    int end = 0;  // -1, +1 for the ends; 0 for a vertex
};

class EdgeGeometry {
public:
    EdgeGeometry(const Ellipse& e1, const Ellipse& e2, const EdgeConflictOptions& options, long& precision)
        : frame_(e1, e2), options_(options), precision_(precision) {}
    // -1, 0, +1 (0: the same point, proven by the exact stage); nullopt when
    // the exact stage cannot isolate its resultant roots (order_on_bisector).
    std::optional<int> compare(const BisectorPoint& a, const BisectorPoint& b) {
        if (a.end || b.end) return a.end == b.end ? 0 : (a.end ? a.end : -b.end);
        return order_on_bisector(frame_, *a.vertex, 0, *b.vertex, 0, options_.max_precision, precision_);
    }

private:
    BisectorFrame frame_;
    const EdgeConflictOptions& options_;
    long& precision_;
};

// The edge [lo, hi] and Q's shadow boundaries c1 = VC(E1, E2, Q), c2 =
// VC(E1, Q, E2). Generic case: the shadow meets the open edge (interval
// shadow) or misses the closed edge (two-ray shadow) depending only on
// whether c1 lies strictly inside the edge. When c1 coincides with a vertex
// (a degenerate configuration proven by the exact stage) the general interval
// tests below decide, with c2 as well.
std::optional<bool> shadow_meets_edge(const Ellipse& e1, const Ellipse& e2, const Ellipse& q, const EdgeShape& edge,
                                      bool connected, const EdgeConflictOptions& options, long& precision) {
    EdgeGeometry geometry(e1, e2, options, precision);
    VoronoiCircleSolver c1_solver(e1, e2, q);
    std::vector<std::unique_ptr<VoronoiCircleSolver>> vertices;
    for (const auto& v : edge.vertices) vertices.push_back(std::make_unique<VoronoiCircleSolver>(*v[0], *v[1], *v[2]));
    BisectorPoint lo{nullptr, -1}, hi{nullptr, +1};  // the whole bisector by default
    if (vertices.size() == 1) hi = {vertices[0].get(), 0};  // the ray from the departure end
    if (vertices.size() == 2) {
        lo = {vertices[0].get(), 0}, hi = {vertices[1].get(), 0};
        const auto o = geometry.compare(lo, hi);
        if (!o) return std::nullopt;
        if (*o > 0) std::swap(lo, hi);
    }
    const BisectorPoint c1{&c1_solver, 0};
    const auto after_lo = geometry.compare(c1, lo), before_hi = geometry.compare(hi, c1);
    if (!after_lo || !before_hi) return std::nullopt;
    if (*after_lo != 0 && *before_hi != 0) {
        const bool inside = *after_lo > 0 && *before_hi > 0;
        return connected ? inside : !inside;
    }
    VoronoiCircleSolver c2_solver(e1, q, e2);
    BisectorPoint s_lo = c1, s_hi{&c2_solver, 0};
    const auto o = geometry.compare(s_lo, s_hi);
    if (!o) return std::nullopt;
    if (*o > 0) std::swap(s_lo, s_hi);
    auto less = [&](const BisectorPoint& a, const BisectorPoint& b) -> std::optional<bool> {
        const auto r = geometry.compare(a, b);
        if (!r) return std::nullopt;
        return *r < 0;
    };
    if (connected) {  // open (s_lo, s_hi) meets open (lo, hi)?
        const auto a = less(s_lo, hi), b = less(lo, s_hi);
        if (!a || !b) return std::nullopt;
        return *a && *b;
    }
    // closed [lo, hi] inside (-inf, s_lo) u (s_hi, +inf)?
    const auto a = less(hi, s_lo), b = less(s_hi, lo);
    if (!a || !b) return std::nullopt;
    return *a || *b;
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
    // Interval shadow, free ends: does it meet the open edge? Two-ray shadow,
    // ends in conflict: does it contain the whole closed edge?
    d.stage = Stage::subdivision;
    d.conflict = shadow_meets_edge(e1, e2, q, edge, shadow.connected, options, d.precision);
    if (d.precision > options.max_precision) d.stage = Stage::exact;
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
