// The Delaunay traits of ellipse sites: the model of DelaunayTraits that the
// graph is built with. It owns the sites, the certified Voronoi circles of the
// faces asked about (one solver per triple, reused by every kappa3 call on
// it), the memo of relative positions and the stage counters.
#pragma once

#include "decision/delaunay_traits.hpp"
#include "predicates/incircle.hpp"
#include "traits/voronoi_circle_cache.hpp"
#include "sites/ellipse.hpp"

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace ellvor {

class EllipseDelaunayTraits final : public DelaunayTraits {
public:
    explicit EllipseDelaunayTraits(std::vector<Ellipse> sites);

    const Ellipse& site(SiteId i) const { return sites_.at(i); }
    const std::vector<Ellipse>& sites() const { return sites_; }

    std::size_t size() const override { return sites_.size(); }
    // The weight is the area (up to the factor pi): a b.
    Sign compare_weight(SiteId a, SiteId b) const override;
    // An enclosure of the area a b from the double enclosures.
    std::optional<WeightBounds> weight_bounds(SiteId i) const override;
    // The center.
    LocationHint location_hint(SiteId i) const override;
    // The site's exact parameters and enclosures, one pointer away from
    // the site array.
    void prefetch(SiteId i) const override { sites_[i].prefetch(); }

    // Every pair whose circumscribed disks may meet (sites/meeting_pair_candidates.hpp),
    // two circles aside (always acceptable): its relative position, memoized, and
    // IntersectingSites for the first pair, by the larger id then the smaller,
    // whose boundaries meet in three or four points. Once; later calls return.
    void check_sites() override;
    // Memoized, both ways at once (one relative position answers both).
    bool is_hidden(SiteId p, SiteId q) override;
    // From the same relative position, memoized with it.
    bool crosses(SiteId p, SiteId q) override;
    Sign side_of_bisector(SiteId i, SiteId j, SiteId k) override;
    Sign infinite_vertex_conflict(SiteId i, SiteId j, SiteId q) override;
    Sign incircle(SiteId i, SiteId j, SiteId k, SiteId q) override;
    bool finite_edge_interior_conflict(SiteId p1, SiteId p2, SiteId p3, SiteId p4, SiteId q, bool b) override;
    bool finite_edge_interior_conflict(SiteId p1, SiteId p2, SiteId p3, SiteId q, bool b) override;
    bool finite_edge_interior_conflict(SiteId p1, SiteId p2, SiteId q, bool b) override;
    bool infinite_edge_interior_conflict(SiteId p2, SiteId p3, SiteId p4, SiteId q, bool b) override;
    // kappa3 of (p1, p2, p3) against p4 not tangent: no; else
    // is_degenerate_edge.
    bool is_degenerate_edge(SiteId p1, SiteId p2, SiteId p3, SiteId p4) override;

    // Drops the face's cached solver: the cache holds live faces only.
    void forget_face(SiteId i, SiteId j, SiteId k) override {
        if (cache_.size() != 0) cache_.erase(i, j, k);  // a circle build caches nothing
    }

    // The cached Voronoi circle of the face (i, j, k) (the same circle for
    // every rotation), nullptr if no predicate has asked about it: after a
    // build, the faces whose questions the bounding disks left open
    // (incircle_by_bounding_disks), certified; readers need not certify
    // those again.
    VoronoiCircle* cached_circle(SiteId i, SiteId j, SiteId k) {
        VoronoiCircleCache::Entry* e = cache_.find(i, j, k);
        return e ? &e->circle : nullptr;
    }

    const TraitsStats& stats() const override { return stats_; }
    std::size_t cached_circles() const { return cache_.size(); }

private:
    // kappa3 on the face's cached Voronoi circle (the closed form for circles).
    Decision<InCircle> incircle_of_face(SiteId i, SiteId j, SiteId k, SiteId q);

    std::vector<Ellipse> sites_;
    VoronoiCircleCache cache_;
    std::unordered_map<std::uint64_t, bool> hidden_memo_;    // (p, q): q inside p
    std::unordered_map<std::uint64_t, bool> crossing_memo_;  // (min, max): the two cross
    TraitsStats stats_;
    bool sites_checked_ = false;
};

}  // namespace ellvor
