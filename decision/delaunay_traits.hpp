// Everything the Delaunay graph may ask about its sites: the predicates'
// contract with the layer above (graph/). Sites are ids 0 .. size() - 1; the
// answers are signs and booleans, never numbers -- except location_hint, which
// only chooses where a search starts.
//
// The operations are those of CGAL's Apollonius_graph_2 traits (Compare_weight_2,
// Is_hidden_2, Oriented_side_of_bisector_2, Vertex_conflict_2,
// Finite_edge_interior_conflict_2, Infinite_edge_interior_conflict_2) on site
// ids; docs/DESIGN.md §2 fixes their signs. A model certifies every
// answer; one it cannot certify is never guessed: the call throws Error naming
// the sites. The predicates are not const: a model may memoize and counts
// every call.
//
// Nothing here knows what a site is (this header includes nothing from sites/
// or subdivision/); traits/ellipse_delaunay_traits.hpp is the model for
// ellipses.
#pragma once

#include "decision/predicate_registry.hpp"
#include "decision/site_id.hpp"
#include "decision/stage.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>

namespace ellvor {

// A point in doubles near a site (its center). Only the length of the
// nearest-neighbour walk depends on it, never where the walk ends, so rounding
// here is harmless.
struct LocationHint {
    double x = 0, y = 0;
};

class DelaunayTraits {
public:
    DelaunayTraits(const DelaunayTraits&) = delete;
    DelaunayTraits& operator=(const DelaunayTraits&) = delete;
    virtual ~DelaunayTraits() = default;

    virtual std::size_t size() const = 0;
    // Compare_weight_2, exact: POSITIVE when site a is larger than site b,
    // ZERO when they are as large. Bulk insertion takes larger sites first, so
    // that fewer vertices have to be removed by sites hiding them later.
    virtual Sign compare_weight(SiteId a, SiteId b) const = 0;
    // Certified bounds lo <= w <= hi on a number w that orders the sites as
    // compare_weight does (a larger site has a larger w), or nullopt. Only
    // for speed, like location_hint: the bulk insertion's sort reads them
    // once a site and calls compare_weight where two overlap, so that most
    // of its n log n comparisons read two numbers, not two sites.
    struct WeightBounds {
        double lo, hi;
    };
    virtual std::optional<WeightBounds> weight_bounds(SiteId i) const { return std::nullopt; }
    virtual LocationHint location_hint(SiteId i) const = 0;
    // Only for speed, like location_hint: the graph is about to ask about
    // site i (a walk step's neighbours, asked for all of them before the
    // first question, so that their cache misses overlap). No answer
    // depends on it.
    virtual void prefetch(SiteId i) const {}

    // Called by a graph before its first insertion: a model may check here, at
    // once, every pair of sites it would reject later (throwing
    // IntersectingSites), so that bad input fails before any costly predicate.
    virtual void check_sites() {}

    // Is_hidden(p, q): site q lies inside site p (internal tangency and
    // identical sites included). Throws IntersectingSites when they cross.
    virtual bool is_hidden(SiteId p, SiteId q) = 0;
    // The boundaries of p and q cross: the sites share interior points and
    // neither contains the other. Only such sites can hide a site together
    // without one containing it (a union-hidden site, docs/DESIGN.md §9).
    virtual bool crosses(SiteId p, SiteId q) = 0;
    // kappa1 at the center of site k: POSITIVE closer to site i, NEGATIVE
    // closer to site j, ZERO equidistant (signed distances, negative inside).
    virtual Sign side_of_bisector(SiteId i, SiteId j, SiteId k) = 0;
    // kappa2: the infinite Voronoi vertex of (i, j) -- the half-plane beyond
    // the external bitangent -- against q: NEGATIVE conflict, POSITIVE not; never ZERO.
    virtual Sign infinite_vertex_conflict(SiteId i, SiteId j, SiteId q) = 0;
    // kappa3: the Voronoi circle of the counter-clockwise triple (i, j, k)
    // against q: NEGATIVE conflict (or no such circle), ZERO tangent, POSITIVE no conflict.
    virtual Sign incircle(SiteId i, SiteId j, SiteId k, SiteId q) = 0;
    // kappa4: does q conflict with the interior of the Voronoi edge of (p1, p2)
    // -- with b, the whole edge -- between the Voronoi vertices of (p1, p2, p3)
    // and (p1, p4, p2); without p4 the edge is a ray, without p3 too the whole
    // bisector. Raw: without CGAL's "q hides an endpoint" shortcut, which the
    // graph applies.
    virtual bool finite_edge_interior_conflict(SiteId p1, SiteId p2, SiteId p3, SiteId p4, SiteId q, bool b) = 0;
    virtual bool finite_edge_interior_conflict(SiteId p1, SiteId p2, SiteId p3, SiteId q, bool b) = 0;
    virtual bool finite_edge_interior_conflict(SiteId p1, SiteId p2, SiteId q, bool b) = 0;
    // kappa4 on the Voronoi edge of (infinity, p2), between the hull neighbours p3 and p4.
    virtual bool infinite_edge_interior_conflict(SiteId p2, SiteId p3, SiteId p4, SiteId q, bool b) = 0;

    // CGAL's Is_degenerate_edge_2: the faces (p1, p2, p3) and (p1, p4, p2)
    // beside the Delaunay edge (p1, p2) have one Voronoi circle (the Voronoi
    // edge has length 0). Deletion flips such edges first.
    virtual bool is_degenerate_edge(SiteId p1, SiteId p2, SiteId p3, SiteId p4) = 0;

    // The graph no longer has the face of the counter-clockwise triple
    // (i, j, k): what the traits keep for its Voronoi circle may go (it is
    // computed again should the triple be asked about later).
    virtual void forget_face(SiteId i, SiteId j, SiteId k) = 0;

    // Which stage decided the calls so far, per predicate.
    virtual const TraitsStats& stats() const = 0;

protected:
    DelaunayTraits() = default;
};

}  // namespace ellvor
