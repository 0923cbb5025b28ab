// The graph's only window on geometry (DESIGN.md, layers): the sites, by id,
// and the predicates kappa1..kappa4 and is_hidden as signs and booleans.
// Everything above this class (triangulation, insertion, validity) sees site
// ids and signs only, never a number type.
//
// Every answer is certified by the predicate cascades; an undecided predicate
// is never guessed: the call throws Error naming the sites.
#pragma once

#include "predicates/stage.hpp"
#include "predicates/voronoi_circle_cache.hpp"
#include "sites/ellipse.hpp"

#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

namespace ellvor {

// Calls of one predicate and which stage decided them.
struct PredicateCount {
    std::uint64_t calls = 0;  // calls that reached the predicate (memoized answers excluded)
    StageCounters stages;
};

struct TraitsStats {
    PredicateCount is_hidden;          // relative_position
    PredicateCount side_of_bisector;   // kappa1
    PredicateCount vertex_conflict3;   // kappa2
    PredicateCount vertex_conflict4;   // kappa3
    PredicateCount finite_edge;        // kappa4, 6/5/4 sites
    PredicateCount infinite_edge;      // kappa4, infinite edge
};

class DelaunayTraits {
public:
    explicit DelaunayTraits(std::vector<Ellipse> sites);

    std::size_t size() const { return sites_.size(); }
    const Ellipse& site(SiteId i) const { return sites_.at(i); }
    const std::vector<Ellipse>& sites() const { return sites_; }

    // CGAL Is_hidden(p, q): site q lies inside site p (tangency and identical
    // included). Memoized. Throws Error when the two sites intersect (invalid input).
    bool is_hidden(SiteId p, SiteId q);
    // kappa1 at the center of site k: POSITIVE closer to i, NEGATIVE closer to j, ZERO tie.
    Sign side_of_bisector(SiteId i, SiteId j, SiteId k);
    // kappa2: infinite Voronoi vertex of (i, j) against q: NEGATIVE conflict, POSITIVE not.
    Sign vertex_conflict(SiteId i, SiteId j, SiteId q);
    // kappa3: Voronoi circle of the ccw triple (i, j, k) against q: NEGATIVE
    // conflict (or no such circle), ZERO tangent, POSITIVE no conflict.
    Sign vertex_conflict(SiteId i, SiteId j, SiteId k, SiteId q);
    // kappa4 (raw, without CGAL's "q hides an endpoint" shortcut).
    bool finite_edge_interior(SiteId p1, SiteId p2, SiteId p3, SiteId p4, SiteId q, bool b);
    bool finite_edge_interior(SiteId p1, SiteId p2, SiteId p3, SiteId q, bool b);
    bool finite_edge_interior(SiteId p1, SiteId p2, SiteId q, bool b);
    bool infinite_edge_interior(SiteId p2, SiteId p3, SiteId p4, SiteId q, bool b);

    const TraitsStats& stats() const { return stats_; }
    const VoronoiCircleCache& cache() const { return cache_; }

private:
    std::vector<Ellipse> sites_;
    VoronoiCircleCache cache_;
    std::unordered_map<std::uint64_t, bool> hidden_memo_;
    TraitsStats stats_;
};

}  // namespace ellvor
