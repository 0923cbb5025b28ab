// CGAL's graph-level wrappers of the traits' predicates (Apollonius_graph_2's
// incircle(f, q), edge_interior(f, i, q, b) and the conflict type of a single
// bisector): they read a face or an edge of the triangulation as the sites the
// traits expect, in CGAL's argument order (ccw(i), cw(i), i, mirror), with an
// infinite face rotated so that the infinite vertex drops out and its two
// finite sites stay counter-clockwise. A wrong order inverts a predicate
// silently, so the order is written once, here.
//
// A view: it holds references to the graph's triangulation and traits and
// lives no longer than one call of the graph.
#pragma once

#include "graph/triangulation.hpp"
#include "decision/delaunay_traits.hpp"

namespace ellvor {

class TriangulationPredicates {
public:
    // How a site q meets the whole bisector of two sites p1, p2, whose ends
    // are the infinite Voronoi vertices of (p1, p2) ("left") and (p2, p1) ("right").
    enum class ConflictType { no_conflict, interior, left_vertex, right_vertex, both_vertices, entire_edge };

    TriangulationPredicates(const Triangulation& tds, DelaunayTraits& traits) : tds_(tds), traits_(traits) {}

    SiteId site(VertexIndex v) const { return tds_.vertex(v).site(); }
    // DelaunayTraits::prefetch of v's site (nothing for the infinite vertex).
    void prefetch(VertexIndex v) const {
        if (v != Triangulation::kInfiniteVertex) traits_.prefetch(site(v));
    }
    // Site p hides site q (the traits' is_hidden).
    bool is_hidden(SiteId p, SiteId q) { return traits_.is_hidden(p, q); }
    bool crosses(SiteId p, SiteId q) { return traits_.crosses(p, q); }
    // kappa3 of face f's Voronoi circle against q, kappa2 for an infinite face:
    // NEGATIVE conflict, ZERO tangent, POSITIVE no conflict.
    Sign incircle(FaceIndex f, SiteId q);
    // kappa4 of edge e's Voronoi edge against q (with b: the whole edge); true
    // at once when q hides one of the edge's sites.
    bool edge_interior(Edge e, SiteId q, bool b);
    // The same for a q known to hide neither of the edge's sites (a conflict
    // region has asked already).
    bool edge_interior_of_visible(Edge e, SiteId q, bool b);
    ConflictType finite_edge_conflict_type_degenerated(SiteId p1, SiteId p2, SiteId q);
    // Face f is about to leave the triangulation: the traits may drop its
    // Voronoi circle (finite faces of real sites only).
    void forget(FaceIndex f);

private:
    // Edge e with one infinite face beside it: a ray or the whole bisector.
    bool finite_edge_interior_degenerated(Edge e, SiteId q, bool b);
    // Edge e from or to the infinite vertex.
    bool infinite_edge_interior(Edge e, SiteId q, bool b);
    bool is_infinite(VertexIndex v) const { return v == Triangulation::kInfiniteVertex; }

    const Triangulation& tds_;
    DelaunayTraits& traits_;
};

}  // namespace ellvor
