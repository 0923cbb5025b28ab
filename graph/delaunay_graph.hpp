// The Delaunay graph of ellipses (the dual of their Voronoi diagram), built
// incrementally as CGAL's Apollonius_graph_2 does (research digest section 2):
// nearest-neighbour walk (kappa1), hidden test, first conflict (kappa2/kappa3
// around the nearest vertex, else an edge-interior conflict and a degree-2
// insertion), conflict region grown through edges whose whole Voronoi edge is
// in conflict (kappa4) or whose endpoint the new site hides, retriangulation
// by starring the hole. 0, 1, 2 and 3 sites are handled as in CGAL.
//
// Sites are disjoint or nested ellipses (DESIGN.md). A site inside another one
// is hidden: it has no vertex, and `hidden()` names the visible site that
// contains it. Sees only signs through DelaunayTraits.
#pragma once

#include "graph/delaunay_traits.hpp"
#include "graph/site_grid.hpp"
#include "graph/triangulation.hpp"

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace ellvor {

struct GraphStats {
    std::size_t inserted = 0, hidden_on_insert = 0, degree_2_insertions = 0, bogus_vertices = 0;
    std::size_t conflict_faces = 0;      // faces removed by conflict regions, in all
    std::size_t walk_steps = 0;          // nearest-neighbour walk moves
    std::size_t rebuilds = 0;            // "all / all but one hidden" fallbacks
};

class DelaunayGraph {
public:
    explicit DelaunayGraph(std::vector<Ellipse> sites);

    // Inserts every site, largest area first (CGAL's bulk order; the graph
    // does not depend on the order except in degenerate configurations).
    void insert_all(const std::function<void(std::size_t done, std::size_t total)>& progress = {});
    // Inserts one site (each id at most once).
    void insert(SiteId id);

    std::size_t number_of_sites() const { return traits_.size(); }
    // Visible sites (those with a vertex), increasing ids.
    std::vector<SiteId> visible_sites() const;
    // [hidden, hiding] pairs, hiding visible, sorted by hidden id.
    std::vector<std::pair<SiteId, SiteId>> hidden() const;
    // Finite Delaunay edges as (i, j) with i < j, sorted; an edge that the
    // graph holds twice (two Voronoi edges between the same sites, e.g. the
    // two sides of a degree-2 vertex's neighbour) is listed twice.
    std::vector<std::pair<SiteId, SiteId>> edges() const;
    // Finite faces (Voronoi vertices) as counter-clockwise triples rotated so
    // that the smallest id comes first, sorted.
    std::vector<std::array<SiteId, 3>> faces() const;
    // Infinite faces as the ordered pair (i, j) of the face (i, j, infinity):
    // the hull edges, counter-clockwise pairs, sorted.
    std::vector<std::pair<SiteId, SiteId>> hull() const;

    // Combinatorial consistency plus CGAL's local test: for every edge, the
    // mirror vertex (when finite and distinct from the face's own opposite
    // vertex) is not in conflict with the face's Voronoi vertex. "" if valid.
    std::string validate();
    bool is_valid() { return validate().empty(); }
    // Brute force for small inputs: every finite face's Voronoi circle has no
    // other site in conflict (kappa3 != conflict), every hull face's
    // half-plane likewise (kappa2 == +1); every hidden site is inside its
    // hiding site; every site is visible or hidden. "" if valid. O(n * faces).
    std::string brute_force_check();

    const TraitsStats& predicate_stats() const { return traits_.stats(); }
    const GraphStats& stats() const { return stats_; }
    const DelaunayTraits& traits() const { return traits_; }
    const Triangulation& triangulation() const { return tds_; }

private:
    using Edge = Triangulation::Edge;
    enum class ConflictType { no_conflict, interior, left_vertex, right_vertex, both_vertices, entire_edge };

    SiteId site_of(int v) const { return static_cast<SiteId>(tds_.vertex(v).site); }
    bool is_infinite(int v) const { return v == Triangulation::kInfinite; }
    void hide(SiteId hidden, SiteId by);  // moves `hidden`'s own hidden list to `by` too

    void insert_small(SiteId p);  // fewer than 3 visible sites
    void insert_third(SiteId p);
    void build_three(SiteId a, SiteId m, SiteId b, bool middle_on_hull);
    void insert_general(SiteId p);
    void rebuild_small(std::vector<SiteId> visible);

    int nearest_vertex(SiteId p);
    // A start for the walk: the vertex of a nearby site (grid_), else the last vertex.
    int walk_start(SiteId p) const;
    void record_vertex(SiteId p, int v);
    // CGAL's graph-level wrappers.
    Sign incircle(int f, SiteId q);
    bool edge_interior(int f, int i, SiteId q, bool b);
    bool finite_edge_interior_degenerated(int f, int i, SiteId q, bool b);
    bool infinite_edge_interior(int f, int i, SiteId q, bool b);
    ConflictType finite_edge_conflict_type_degenerated(SiteId p1, SiteId p2, SiteId q);
    Edge find_edge(int a, int b) const;

    DelaunayTraits traits_;
    Triangulation tds_;
    std::vector<SiteId> small_;                  // the visible sites while tds_ is empty (< 3)
    std::vector<std::vector<SiteId>> hidden_in_; // per visible site: the sites it hides
    std::vector<char> inserted_;
    int last_vertex_ = -1;
    std::unique_ptr<SiteGrid> grid_;   // insert_all only: sites with a vertex, by center
    std::vector<int> vertex_of_site_;  // the vertex a site got (checked before use: vertices die)
    GraphStats stats_;
};

}  // namespace ellvor
