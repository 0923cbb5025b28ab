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

constexpr long kStartPrecision = 64;

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

// Is the shadow boundary VC(E1, E2, Q) strictly inside the edge interval?
// The edge is given by its vertices (triples starting with E1) and by whether
// it reaches the departure end (position 0) or the arrival end (2 pi).
struct EdgeShape {
    std::vector<std::array<const Ellipse*, 3>> vertices;  // 0, 1 or 2 finite vertices
    bool from_departure_end = false;
    bool to_arrival_end = false;
};

// true/false when decided; nullopt when some circle cannot be certified or the
// positions cannot be separated below the precision cap.
std::optional<bool> boundary_inside_edge(const Ellipse& e1, const Ellipse& e2, const Ellipse& q, const EdgeShape& edge,
                                         const EdgeConflictOptions& options, long& precision) {
    BisectorFrame frame(e1, e2);
    std::vector<std::unique_ptr<VoronoiCircleSolver>> solvers;
    for (const auto& v : edge.vertices) solvers.push_back(std::make_unique<VoronoiCircleSolver>(*v[0], *v[1], *v[2]));
    VoronoiCircleSolver boundary(e1, e2, q);
    for (long prec = kStartPrecision; prec <= options.max_precision; prec *= 2) {
        precision = prec;
        if (!boundary.refine(prec - 16)) return std::nullopt;
        const auto& b = boundary.enclosure();
        const Ball s = frame.position(b.parameter[0], b.flipped[0], prec);
        // Positions of the edge's ends: a finite vertex, or an end of the bisector.
        std::vector<Ball> ends;
        for (auto& solver : solvers) {
            if (!solver->refine(prec - 16)) return std::nullopt;
            const auto& c = solver->enclosure();
            ends.push_back(frame.position(c.parameter[0], c.flipped[0], prec));
        }
        // s strictly after the lower end and strictly before the upper end?
        int above_low = 1, below_high = 1;  // an end of the bisector is passed by every finite circle
        Ball d;
        if (edge.from_departure_end) {
            if (!ends.empty()) {
                arb_sub(d.get(), ends[0].get(), s.get(), prec);
                below_high = d.certain_sign();
            }
        } else if (edge.to_arrival_end) {
            arb_sub(d.get(), s.get(), ends[0].get(), prec);
            above_low = d.certain_sign();
        } else if (ends.size() == 2) {
            Ball lo = ends[0], hi = ends[1], diff;
            arb_sub(diff.get(), hi.get(), lo.get(), prec);
            if (diff.certain_sign() == 0) continue;
            if (diff.certain_sign() < 0) std::swap(lo, hi);
            arb_sub(d.get(), s.get(), lo.get(), prec);
            above_low = d.certain_sign();
            arb_sub(d.get(), hi.get(), s.get(), prec);
            below_high = d.certain_sign();
        }
        if (above_low < 0 || below_high < 0) return false;
        if (above_low > 0 && below_high > 0) return true;
    }
    return std::nullopt;
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
    edge.from_departure_end = true;
    return decide(e1, e2, q, b, edge, options);
}

EdgeConflictDecision finite_edge_interior_conflict(const Ellipse& e1, const Ellipse& e2, const Ellipse& q, bool b,
                                                   const EdgeConflictOptions& options) {
    EdgeShape edge;
    edge.from_departure_end = edge.to_arrival_end = true;
    return decide(e1, e2, q, b, edge, options);
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
