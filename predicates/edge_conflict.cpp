#include "predicates/edge_conflict.hpp"

#include "predicates/bisector_order.hpp"
#include "circles/circle_predicates.hpp"
#include "predicates/infinite_vertex_conflict.hpp"
#include "predicates/support_function.hpp"
#include "predicates/voronoi_circle_count.hpp"
#include "subdivision/voronoi_circle.hpp"
#include "subdivision/voronoi_circle_enclosure.hpp"
#include "exact/medial_axis_tangency.hpp"

#include <memory>
#include <optional>
#include <vector>

namespace ellvor {

namespace {

// Q's shadow region on the bisector of (E1, E2): `bounded` is false when it
// has fewer than two boundary circles.
struct ShadowRegion {
    bool bounded = false;
    bool connected = false;  // one interval (else two rays through both ends)
};

Decision<ShadowRegion> shadow_region(const Ellipse& e1, const Ellipse& e2, const Ellipse& q) {
    const Decision<bool> both = has_both_voronoi_circles(e1, e2, q);
    if (!*both) return both.with(ShadowRegion{});
    // Both circles exist: the region holds both ends of the bisector or
    // neither; it holds the end at (E2, E1, inf) iff Q conflicts with it.
    const Decision<Sign> end = infinite_vertex_conflict(e2, e1, q);
    Decision<ShadowRegion> shadow = both.with(ShadowRegion{true, *end == Sign::positive});
    shadow.depends_on(end);
    return shadow;
}

// An edge of the bisector of (E1, E2): its finite vertices (triples starting
// with E1); with one vertex it is the ray from the departure end (the
// infinite vertex (E2, E1, inf)), with none the whole bisector.
struct EdgeShape {
    std::vector<std::array<const Ellipse*, 3>> vertices;
};

// A position along the bisector of (E1, E2): a Voronoi vertex of a triple
// starting with E1 (an index into EdgeGeometry's vertices), or an end of the
// bisector (departure = -inf, arrival = +inf).
struct BisectorPoint {
    int vertex = -1;
    int end = 0;  // -1, +1 for the ends; 0 for a vertex
};

// The Voronoi vertices of one edge question, and their order along the
// bisector: by the closed form when both triples are circles
// (circle_predicates.hpp), else by certified enclosures (bisector_order.hpp).
// Keeps the provenance of every comparison it made (the latest stage, the
// highest precision).
class EdgeGeometry {
public:
    EdgeGeometry(const Ellipse& e1, const Ellipse& e2, const RefinementOptions& options, Decision<bool>& provenance)
        : e1_(e1), e2_(e2), options_(options), provenance_(provenance) {}

    BisectorPoint vertex(const Ellipse& a, const Ellipse& b, const Ellipse& c) {
        Vertex v{{&a, &b, &c}, nullptr, nullptr};
        if (a.is_circle() && b.is_circle() && c.is_circle())
            v.circle = std::make_unique<CircleVoronoiVertex>(a, b, c);
        vertices_.push_back(std::move(v));
        return {static_cast<int>(vertices_.size()) - 1, 0};
    }

    // NEGATIVE, ZERO (the same point, proven exactly), POSITIVE; nullopt only
    // when undecided (options.exact_stage = false).
    std::optional<Sign> compare(const BisectorPoint& a, const BisectorPoint& b) {
        if (a.end || b.end) return sign_of(a.end == b.end ? 0 : (a.end ? a.end : -b.end));
        Vertex &va = vertices_[a.vertex], &vb = vertices_[b.vertex];
        if (va.circle && vb.circle) {
            provenance_.depends_on(Decision<bool>::decided(true, Stage::exact));
            return sign_of(circle_order_on_bisector(e1_, e2_, *va.circle, *vb.circle));
        }
        // The double certificates first (most calls on dense packings, where
        // the vertices are close), then Arb and the exact stage.
        const DoubleVoronoiCircle *da = circle(va).in_doubles(), *db = circle(vb).in_doubles();
        if (da && db) {
            if (!frame_in_doubles_) frame_in_doubles_.emplace(e1_, e2_);
            if (const std::optional<Sign> order = order_on_bisector_in_doubles(*frame_in_doubles_, *da, 0, *db, 0)) {
                provenance_.depends_on(Decision<bool>::decided(true, Stage::filter));
                return *order;
            }
        }
        if (!frame_) frame_.emplace(e1_, e2_);
        const Decision<Sign> order =
            order_on_bisector(*frame_, circle(va).solver(), 0, circle(vb).solver(), 0, options_);
        provenance_.depends_on(order);
        if (!order.is_decided()) return std::nullopt;
        return *order;
    }
    std::optional<bool> less(const BisectorPoint& a, const BisectorPoint& b) {
        const auto order = compare(a, b);
        if (!order) return std::nullopt;
        return *order == Sign::negative;
    }

private:
    struct Vertex {
        std::array<const Ellipse*, 3> triple;
        std::unique_ptr<CircleVoronoiVertex> circle;  // three circles
        std::unique_ptr<VoronoiCircle> enclosure;     // compared by enclosures (made on first use)
    };

    // The vertex's circle, made on first use. Its double certificate is
    // tried first, so that its Arb solver starts at that box: the guesses of
    // a fresh solver cost milliseconds (a dense packing's build spent 60% of
    // its time there).
    VoronoiCircle& circle(Vertex& v) {
        if (!v.enclosure) {
            v.enclosure =
                std::make_unique<VoronoiCircle>(*v.triple[0], *v.triple[1], *v.triple[2], common_medial_axis_tangency);
            v.enclosure->in_doubles();
        }
        return *v.enclosure;
    }

    const Ellipse &e1_, &e2_;
    const RefinementOptions& options_;
    Decision<bool>& provenance_;
    std::optional<BisectorFrameInDoubles> frame_in_doubles_;  // built when double certificates are compared
    std::optional<BisectorFrame> frame_;                      // built when Arb enclosures are compared
    std::vector<Vertex> vertices_;
};

// The edge [lo, hi] and Q's shadow boundaries c1 = VC(E1, E2, Q), c2 =
// VC(E1, Q, E2). Generic case: the shadow meets the open edge (interval
// shadow) or misses the closed edge (two-ray shadow) depending only on
// whether c1 lies strictly inside the edge. When c1 coincides with a vertex
// (a degenerate configuration proven by the exact stage) the general interval
// tests below decide, with c2 as well. nullopt: undecided.
std::optional<bool> shadow_meets_edge(const Ellipse& e1, const Ellipse& e2, const Ellipse& q, const EdgeShape& edge,
                                      bool connected, EdgeGeometry& geometry) {
    BisectorPoint lo{-1, -1}, hi{-1, +1};  // the whole bisector by default
    if (edge.vertices.size() >= 1) hi = geometry.vertex(*edge.vertices[0][0], *edge.vertices[0][1], *edge.vertices[0][2]);
    if (edge.vertices.size() == 2) {
        lo = hi;
        hi = geometry.vertex(*edge.vertices[1][0], *edge.vertices[1][1], *edge.vertices[1][2]);
        const auto o = geometry.compare(lo, hi);
        if (!o) return std::nullopt;
        if (*o == Sign::positive) std::swap(lo, hi);
    }
    const BisectorPoint c1 = geometry.vertex(e1, e2, q);
    const auto after_lo = geometry.compare(c1, lo), before_hi = geometry.compare(hi, c1);
    if (!after_lo || !before_hi) return std::nullopt;
    if (*after_lo != Sign::zero && *before_hi != Sign::zero) {
        const bool inside = *after_lo == Sign::positive && *before_hi == Sign::positive;
        return connected ? inside : !inside;
    }
    BisectorPoint s_lo = c1, s_hi = geometry.vertex(e1, q, e2);
    const auto o = geometry.compare(s_lo, s_hi);
    if (!o) return std::nullopt;
    if (*o == Sign::positive) std::swap(s_lo, s_hi);
    if (connected) {  // open (s_lo, s_hi) meets open (lo, hi)?
        const auto a = geometry.less(s_lo, hi), b = geometry.less(lo, s_hi);
        if (!a || !b) return std::nullopt;
        return *a && *b;
    }
    // closed [lo, hi] inside (-inf, s_lo) u (s_hi, +inf)?
    const auto a = geometry.less(hi, s_lo), b = geometry.less(s_hi, lo);
    if (!a || !b) return std::nullopt;
    return *a || *b;
}

Decision<bool> decide(const Ellipse& e1, const Ellipse& e2, const Ellipse& q, bool b, const EdgeShape& edge,
                      const RefinementOptions& options) {
    const Decision<ShadowRegion> shadow = shadow_region(e1, e2, q);
    // Fewer than two shadow boundaries cannot separate the edge's ends; an
    // interval shadow contains no vertex of a b = false edge, and a two-ray
    // shadow contains every vertex of a b = true edge.
    if (!shadow->bounded || shadow->connected == b) return shadow.with(b);
    // Interval shadow, free ends: does it meet the open edge? Two-ray shadow,
    // ends in conflict: does it contain the whole closed edge?
    Decision<bool> provenance = shadow.with(b);
    EdgeGeometry geometry(e1, e2, options, provenance);
    const std::optional<bool> meets = shadow_meets_edge(e1, e2, q, edge, shadow->connected, geometry);
    if (!meets) return Decision<bool>::undecided(provenance.stage, provenance.precision);
    return provenance.with(*meets);
}

}  // namespace

Decision<bool> finite_edge_interior_conflict(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3,
                                             const Ellipse& e4, const Ellipse& q, bool b,
                                             const RefinementOptions& options) {
    EdgeShape edge;
    edge.vertices = {{&e1, &e2, &e3}, {&e1, &e4, &e2}};
    return decide(e1, e2, q, b, edge, options);
}

Decision<bool> finite_edge_interior_conflict(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3,
                                             const Ellipse& q, bool b, const RefinementOptions& options) {
    EdgeShape edge;
    edge.vertices = {{&e1, &e2, &e3}};
    return decide(e1, e2, q, b, edge, options);
}

Decision<bool> finite_edge_interior_conflict(const Ellipse& e1, const Ellipse& e2, const Ellipse& q, bool b,
                                             const RefinementOptions& options) {
    return decide(e1, e2, q, b, EdgeShape{}, options);
}

Decision<bool> is_degenerate_edge(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3, const Ellipse& e4,
                                          const RefinementOptions& options) {
    Decision<bool> provenance = Decision<bool>::decided(false, Stage::filter);
    EdgeGeometry geometry(e1, e2, options, provenance);
    const BisectorPoint a = geometry.vertex(e1, e2, e3), b = geometry.vertex(e1, e4, e2);
    const std::optional<Sign> order = geometry.compare(a, b);
    if (!order) return Decision<bool>::undecided(provenance.stage, provenance.precision);
    return provenance.with(*order == Sign::zero);
}

Decision<bool> infinite_edge_interior_conflict(const Ellipse& e2, const Ellipse& e3, const Ellipse& e4,
                                               const Ellipse& q, bool b, bool use_circle_closed_form, bool use_filter) {
    if (use_circle_closed_form && e2.is_circle() && e3.is_circle() && e4.is_circle() && q.is_circle())
        return Decision<bool>::decided(circle_infinite_edge_interior_conflict(e2, e3, e4, q, b), Stage::exact);
    if (use_filter) {
        // The same order, on the tangents' normals proven in intervals; a
        // coincidence (Q's line through an end) is left to the exact stage.
        const auto from = certified_bitangent_normal(e2, e3, true), to = certified_bitangent_normal(e2, e4, false),
                   start = certified_bitangent_normal(e2, q, false);
        if (from && to && start)
            if (const std::optional<int> inside = normal_in_arc(*from, *to, *start))
                return Decision<bool>::decided(b ? *inside < 0 : *inside > 0, Stage::filter);
    }
    // Contact points on E2 of the edge's ends and of Q's boundary lines.
    BoundaryParameter from = external_bitangent_on(e2, e3, HullSide::arrival);   // vertex (E2, E3, inf)
    BoundaryParameter to = external_bitangent_on(e2, e4, HullSide::departure);   // vertex (E4, E2, inf)
    BoundaryParameter start = external_bitangent_on(e2, q, HullSide::departure);  // vertex (Q, E2, inf)
    int inside = position_in_arc(from, to, start);
    if (inside == 0) {  // Q's line coincides with an end: use its other line (Q, E2)
        BoundaryParameter other = external_bitangent_on(e2, q, HullSide::arrival);  // vertex (E2, Q, inf)
        inside = position_in_arc(from, to, other);
        if (inside == 0) return Decision<bool>::decided(!b, Stage::exact);
    }
    // b: the whole edge is in conflict unless Q's conflict region begins inside
    // it; !b: some interior point is in conflict iff it begins inside it.
    return Decision<bool>::decided(b ? inside < 0 : inside > 0, Stage::exact);
}

}  // namespace ellvor
