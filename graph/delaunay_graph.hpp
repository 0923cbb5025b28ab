// The Delaunay graph of a set of sites (the dual of their Voronoi diagram),
// built incrementally as CGAL's Apollonius_graph_2 does (Karavelas and
// Yvinec's algorithm): 0, 1, 2 and 3 sites are handled apart;
// from then on a new site p is inserted in named steps -- the nearest site
// (a walk decided by kappa1), the hidden test, a first conflict (kappa2/kappa3
// around the nearest vertex, else an edge-interior conflict and a degree-2
// vertex), the conflict region grown through edges whose whole Voronoi edge
// is in conflict (kappa4) or whose site p hides, bogus vertices where the
// region touches itself, and the hole starred around p.
//
// A site is hidden when its cell is empty (docs/DESIGN.md §2): it has no
// vertex, and `hidden()` names a visible site that contains it or -- for a
// site inside the union of crossing sites and in none of them -- a visible
// site that crosses it and covers its center. The graph finds a hidden site
// at insertion, marks the sites a new site empties, and gives every hidden
// site another chance when a site that may uncover it is removed.
//
// The graph knows sites by id only and sees them through its DelaunayTraits,
// which it owns: signs and booleans, never a number, never a site's shape.
#pragma once

#include "graph/conflict_region.hpp"
#include "graph/site_grid.hpp"
#include "graph/triangulation.hpp"
#include "graph/triangulation_predicates.hpp"
#include "decision/delaunay_traits.hpp"

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace ellvor {

struct GraphStats {
    std::size_t inserted = 0, hidden_on_insert = 0, degree_2_insertions = 0, bogus_vertices = 0;
    std::size_t union_hidden = 0;        // sites found hidden by a union of crossing sites (at insertion or later)
    std::size_t global_searches = 0;     // insertions whose first conflict was sought over the whole graph
    std::size_t hiding_tests = 0;        // small graphs of the sites meeting a new site, built to decide its hiding
    std::size_t conflict_faces = 0;      // faces removed by conflict regions, in all
    std::size_t walk_steps = 0;          // nearest-neighbour walk moves
    std::size_t rebuilds = 0;            // "all / all but one hidden" fallbacks
    std::size_t removed = 0;             // remove() calls
    std::size_t degenerate_flips = 0;    // deletion: edges of length 0 flipped away first
    std::size_t small_graph_removals = 0;  // deletion through the neighbours' small graph (degree > 3)
    std::size_t removal_rebuilds = 0;    // deletion that fell back to rebuilding the triangulation
};

class DelaunayGraph {
public:
    // The graph of traits->size() sites, none inserted yet. The graph owns its
    // traits: their memos, caches and counters belong to this one graph.
    explicit DelaunayGraph(std::unique_ptr<DelaunayTraits> traits);

    // Inserts every site, largest first by rounds, each round along a
    // Hilbert curve (bulk_insertion_order, graph/insertion_order.hpp; the
    // graph does not depend on the order except in degenerate
    // configurations), each walk started at a site with a near location hint.
    void insert_all(const std::function<void(std::size_t done, std::size_t total)>& progress = {});
    // Inserts one site (each id at most once, unless removed in between). The
    // first insertion asks the traits to check the sites (check_sites).
    void insert(SiteId id);
    // Removes an inserted site (CGAL's remove): a hidden one leaves its host's
    // list; a visible one loses its vertex -- edges of length 0 around it are
    // flipped away, a vertex of degree 2 or 3 is removed directly, else its
    // star is replaced by the faces of its neighbours' small graph that the
    // site conflicts with -- and then the sites it hid are inserted again,
    // largest first.
    void remove(SiteId id);
    bool contains(SiteId id) const { return id < inserted_.size() && inserted_[id] == kIn; }
    // The sites removed and not inserted again, in the order of removal.
    const std::vector<SiteId>& removed() const { return removed_; }

    std::size_t number_of_sites() const { return traits_->size(); }
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
    // half-plane likewise (kappa2 == +1), hidden sites included; every hidden
    // site is inside its hiding site or, hidden by a union, crosses it; every
    // site is visible or hidden. "" if valid. O(n * faces).
    std::string brute_force_check();

    const TraitsStats& predicate_stats() const { return traits_->stats(); }
    const GraphStats& stats() const { return stats_; }
    const Triangulation& triangulation() const { return tds_; }

private:
    using ConflictType = TriangulationPredicates::ConflictType;

    SiteId site_of(VertexIndex v) const { return tds_.vertex(v).site(); }
    TriangulationPredicates predicates() { return {tds_, *traits_}; }
    void hide(SiteId hidden, SiteId by);  // moves `hidden`'s own hidden list to `by` too
    std::vector<SiteId> take_hidden(SiteId s);  // s's hidden list, emptied
    void forget_hidden(SiteId hidden);           // `hidden` leaves its host's list
    // `hidden`'s cell is empty though `host` does not contain it; the sites
    // `hidden` itself hid are appended to `again` (to be inserted again).
    void hide_in_union(SiteId hidden, SiteId host, std::vector<SiteId>& again);
    // Inserts the sites again, largest first.
    void insert_again(std::vector<SiteId> sites);
    void forget_union_hidden(SiteId h);  // h leaves union_hidden_ (if there)

    // Fewer than 3 visible sites.
    void insert_small(SiteId p);
    void insert_third(SiteId p);
    void build_three(SiteId a, SiteId m, SiteId b, bool middle_on_hull);
    Edge find_edge(VertexIndex a, VertexIndex b) const;
    void rebuild_small(std::vector<SiteId> visible);

    // 3 visible sites or more, in CGAL's steps.
    void insert_general(SiteId p);
    VertexIndex nearest_vertex(SiteId p);
    VertexIndex walk_start(SiteId p) const;  // the vertex of a nearby site (grid_), else the last vertex
    bool hide_in_nearest(SiteId p, VertexIndex nearest);
    std::optional<FaceIndex> find_first_conflict(ConflictRegion& region, VertexIndex nearest);
    bool insert_in_voronoi_edge(SiteId p, VertexIndex nearest);
    struct Hiding {
        SiteId host;
        bool by_union;  // else the host contains the site
    };
    std::optional<Hiding> hiding_among_sites_meeting(SiteId p);
    std::optional<FaceIndex> find_any_conflict(ConflictRegion& region);
    bool insert_in_any_voronoi_edge(SiteId p, VertexIndex nearest);
    SiteId nearer_at_center(SiteId a, SiteId b, SiteId of);
    bool rebuild_if_at_most_one_survives(const ConflictRegion& region, std::vector<SiteId>& again);
    std::vector<VertexIndex> add_bogus_vertices(const ConflictRegion& region);
    void retriangulate_conflict_region(ConflictRegion& region, const std::vector<VertexIndex>& bogus,
                                       std::vector<SiteId>& again);
    void hide_vanishing(const ConflictRegion& region, const std::vector<VertexIndex>& vanishing, std::vector<SiteId>& again);
    void record_vertex(SiteId p, VertexIndex v);

    // Deletion.
    VertexIndex vertex_of(SiteId s) const;
    void remove_vertex(VertexIndex v);
    void minimize_degree(VertexIndex v);
    bool replace_star_by_small_graph(VertexIndex v);
    // The faces p's insertion would remove, as a disk (bogus vertices added),
    // with its boundary counter-clockwise; nullopt when p would not get a
    // vertex of degree 3 or more by starring (deletion asks this of the small graph).
    struct Hole {
        std::vector<FaceIndex> faces;
        std::vector<Edge> boundary;
    };
    std::optional<Hole> conflict_hole(SiteId p);
    void rebuild_without(VertexIndex v);

    std::unique_ptr<DelaunayTraits> traits_;
    Triangulation tds_;
    std::vector<SiteId> small_;                  // the visible sites while tds_ is empty (< 3)
    // The sites each visible site hides, for the hosts only: a vector per
    // site cost 24 bytes a site, and most sites hide nothing.
    std::unordered_map<SiteId, std::vector<SiteId>> hidden_in_;
    std::vector<std::uint32_t> host_;            // per hidden site: the visible site that hides it
    std::vector<SiteId> union_hidden_;           // hidden sites whose host does not contain them
    // A small graph that decides hiding (hiding_among_sites_meeting): a site
    // without a conflict near its nearest site is searched for over the
    // whole graph, and hidden if nothing conflicts.
    bool whole_graph_search_ = false;
    enum : char { kOut, kIn, kRemoved };  // per site: not inserted, in the graph, removed
    std::vector<char> inserted_;
    std::vector<SiteId> removed_;
    VertexIndex last_vertex_;
    std::unique_ptr<SiteGrid> grid_;   // insert_all only: sites with a vertex, by location hint
    std::vector<VertexIndex> vertex_of_site_;  // the vertex a site got (checked before use: vertices die)
    ConflictMarks conflict_marks_;             // the memo of the current insertion's conflict region
    GraphStats stats_;
};

}  // namespace ellvor
