// The traits of a subset of another traits' sites, renumbered 0 .. k-1.
// Deletion builds the small Delaunay graph of a removed vertex's neighbours
// (CGAL's remove_degree_d_vertex) through it: every question goes to the big
// graph's traits, so their caches, memos and stage counters serve and count
// both graphs.
#pragma once

#include "decision/delaunay_traits.hpp"

#include <utility>
#include <vector>

namespace ellvor {

class SubsetTraits final : public DelaunayTraits {
public:
    // Local site i is `parent`'s site ids[i]; the parent must outlive this.
    SubsetTraits(DelaunayTraits& parent, std::vector<SiteId> ids) : parent_(parent), ids_(std::move(ids)) {}

    SiteId global(SiteId local) const { return ids_[local]; }

    std::size_t size() const override { return ids_.size(); }
    Sign compare_weight(SiteId a, SiteId b) const override { return parent_.compare_weight(g(a), g(b)); }
    std::optional<WeightBounds> weight_bounds(SiteId i) const override { return parent_.weight_bounds(g(i)); }
    LocationHint location_hint(SiteId i) const override { return parent_.location_hint(g(i)); }
    // The parent's sites are this one's: their check is the parent's (done once).
    void check_sites() override { parent_.check_sites(); }
    bool is_hidden(SiteId p, SiteId q) override { return parent_.is_hidden(g(p), g(q)); }
    bool crosses(SiteId p, SiteId q) override { return parent_.crosses(g(p), g(q)); }
    Sign side_of_bisector(SiteId i, SiteId j, SiteId k) override { return parent_.side_of_bisector(g(i), g(j), g(k)); }
    Sign infinite_vertex_conflict(SiteId i, SiteId j, SiteId q) override { return parent_.infinite_vertex_conflict(g(i), g(j), g(q)); }
    Sign incircle(SiteId i, SiteId j, SiteId k, SiteId q) override {
        return parent_.incircle(g(i), g(j), g(k), g(q));
    }
    bool finite_edge_interior_conflict(SiteId p1, SiteId p2, SiteId p3, SiteId p4, SiteId q, bool b) override {
        return parent_.finite_edge_interior_conflict(g(p1), g(p2), g(p3), g(p4), g(q), b);
    }
    bool finite_edge_interior_conflict(SiteId p1, SiteId p2, SiteId p3, SiteId q, bool b) override {
        return parent_.finite_edge_interior_conflict(g(p1), g(p2), g(p3), g(q), b);
    }
    bool finite_edge_interior_conflict(SiteId p1, SiteId p2, SiteId q, bool b) override {
        return parent_.finite_edge_interior_conflict(g(p1), g(p2), g(q), b);
    }
    bool infinite_edge_interior_conflict(SiteId p2, SiteId p3, SiteId p4, SiteId q, bool b) override {
        return parent_.infinite_edge_interior_conflict(g(p2), g(p3), g(p4), g(q), b);
    }
    bool is_degenerate_edge(SiteId p1, SiteId p2, SiteId p3, SiteId p4) override {
        return parent_.is_degenerate_edge(g(p1), g(p2), g(p3), g(p4));
    }
    // Forgetting only costs the parent a recomputation should it ask again.
    void forget_face(SiteId i, SiteId j, SiteId k) override { parent_.forget_face(g(i), g(j), g(k)); }
    const TraitsStats& stats() const override { return parent_.stats(); }

private:
    SiteId g(SiteId local) const { return ids_[local]; }

    DelaunayTraits& parent_;
    std::vector<SiteId> ids_;
};

}  // namespace ellvor
