#include "graph/delaunay_graph.hpp"

#include "graph/conflict_region.hpp"
#include "util/error.hpp"

#include <algorithm>
#include <numeric>

namespace ellvor {
namespace {
std::string str(SiteId i) { return std::to_string(i); }
}  // namespace

DelaunayGraph::DelaunayGraph(std::unique_ptr<DelaunayTraits> traits) : traits_(std::move(traits)) {
    if (!traits_) throw Error("DelaunayGraph: no traits");
    hidden_in_.resize(traits_->size());
    inserted_.assign(traits_->size(), 0);
    vertex_of_site_.resize(traits_->size());
}

void DelaunayGraph::insert_all(const std::function<void(std::size_t done, std::size_t total)>& progress) {
    std::vector<SiteId> order(traits_->size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](SiteId x, SiteId y) { return traits_->compare_weight(x, y) == Sign::positive; });
    // The bulk order jumps across the plane; the grid keeps the walk short.
    std::vector<LocationHint> hints;
    hints.reserve(order.size());
    for (SiteId i = 0; i < traits_->size(); ++i) hints.push_back(traits_->location_hint(i));
    grid_ = std::make_unique<SiteGrid>(hints);
    std::size_t done = 0;
    for (SiteId i : order) {
        insert(i);
        if (progress) progress(++done, order.size());
    }
}

void DelaunayGraph::insert(SiteId p) {
    if (p >= traits_->size()) throw Error("DelaunayGraph::insert: no site " + str(p));
    if (inserted_[p]) throw Error("DelaunayGraph::insert: site " + str(p) + " inserted twice");
    inserted_[p] = 1;
    ++stats_.inserted;
    if (tds_.empty())
        insert_small(p);
    else
        insert_general(p);
}

void DelaunayGraph::hide(SiteId hidden, SiteId by) {
    auto& list = hidden_in_[by];
    list.push_back(hidden);
    list.insert(list.end(), hidden_in_[hidden].begin(), hidden_in_[hidden].end());
    hidden_in_[hidden].clear();
}

// ---------------------------------------------------------------- small cases

void DelaunayGraph::insert_small(SiteId p) {
    if (small_.empty()) {
        small_.push_back(p);
    } else if (small_.size() == 1) {
        const SiteId v = small_[0];
        if (traits_->is_hidden(v, p)) {
            hide(p, v);
            ++stats_.hidden_on_insert;
        } else if (traits_->is_hidden(p, v)) {
            hide(v, p);
            small_[0] = p;
        } else {
            small_.push_back(p);
        }
    } else {
        insert_third(p);
    }
}

void DelaunayGraph::insert_third(SiteId p) {
    const SiteId s1 = small_[0], s2 = small_[1];
    for (SiteId s : {s1, s2})
        if (traits_->is_hidden(s, p)) {
            hide(p, s);
            ++stats_.hidden_on_insert;
            return;
        }
    const bool t1 = traits_->is_hidden(p, s1), t2 = traits_->is_hidden(p, s2);
    if (t1 || t2) {
        if (t1) hide(s1, p);
        if (t2) hide(s2, p);
        if (t1 && t2)
            small_ = {p};
        else
            small_[t1 ? 0 : 1] = p;
        return;
    }
    // The shadow of p on the single bisector of s1, s2 decides the shape of
    // the graph of three sites (as CGAL's insert_third).
    TriangulationPredicates pred = predicates();
    switch (pred.finite_edge_conflict_type_degenerated(s1, s2, p)) {
        case ConflictType::left_vertex: tds_.make_tetrahedron(s1, s2, p); break;
        case ConflictType::right_vertex: tds_.make_tetrahedron(s2, s1, p); break;
        case ConflictType::interior: build_three(s1, p, s2, false); break;
        case ConflictType::entire_edge: build_three(s1, p, s2, true); break;
        case ConflictType::no_conflict: {
            // p does not reach the bisector: s1 or s2 lies between p and the other.
            const ConflictType ct1 = pred.finite_edge_conflict_type_degenerated(s1, p, s2);
            if (ct1 == ConflictType::no_conflict)
                build_three(s2, s1, p, true);
            else if (ct1 == ConflictType::entire_edge)
                build_three(s1, s2, p, true);
            else
                throw Error("inconsistent predicates for the three sites " + str(s1) + ", " + str(s2) + ", " + str(p));
            break;
        }
        case ConflictType::both_vertices: {
            // A bounded piece of the bisector survives: one of s1, s2 has a bounded cell.
            const ConflictType ct1 = pred.finite_edge_conflict_type_degenerated(s1, p, s2);
            if (ct1 == ConflictType::interior)
                build_three(s1, s2, p, false);
            else
                build_three(s2, s1, p, false);
            break;
        }
    }
    small_.clear();
    const Triangulation::Face& first = tds_.face(FaceIndex(0));
    last_vertex_ = first.v[0] == Triangulation::kInfiniteVertex ? first.v[1] : first.v[0];
}

// Three sites without a Voronoi vertex (m between a and b, on the hull) or
// with two (m's cell bounded by a and b only).
void DelaunayGraph::build_three(SiteId a, SiteId m, SiteId b, bool middle_on_hull) {
    const auto v = tds_.make_tetrahedron(a, m, b);
    tds_.flip(middle_on_hull ? find_edge(v[0], v[2]) : find_edge(v[1], Triangulation::kInfiniteVertex));
}

Edge DelaunayGraph::find_edge(VertexIndex a, VertexIndex b) const {
    for (FaceIndex f : tds_.faces())
        for (int i = 0; i < 3; ++i) {
            const VertexIndex x = tds_.face(f).v[ccw(i)], y = tds_.face(f).v[cw(i)];
            if ((x == a && y == b) || (x == b && y == a)) return {f, i};
        }
    throw Error("DelaunayGraph: edge not found (internal error)");
}

void DelaunayGraph::rebuild_small(std::vector<SiteId> visible) {
    tds_.clear();
    small_ = std::move(visible);
    last_vertex_ = VertexIndex();
    ++stats_.rebuilds;
}

// ---------------------------------------------------------------- general insertion

void DelaunayGraph::insert_general(SiteId p) {
    const VertexIndex nearest = nearest_vertex(p);
    if (hide_in_nearest(p, nearest)) return;
    ConflictRegion region(tds_, predicates(), p, conflict_marks_);
    const std::optional<FaceIndex> start = find_first_conflict(region, nearest);
    if (!start) {
        if (insert_in_voronoi_edge(p, nearest)) return;
        throw Error("site " + str(p) + " is in conflict with no Voronoi vertex or edge (covered by a union of sites?)");
    }
    region.expand(*start);
    if (rebuild_if_at_most_one_survives(region)) return;
    stats_.conflict_faces += region.faces().size();
    const std::vector<VertexIndex> bogus = add_bogus_vertices(region);
    retriangulate_conflict_region(region, bogus);
}

// The nearest site (CGAL's nearest_neighbor): a greedy walk to the vertex
// whose site is nearest to p's center (kappa1); it ends because the distance
// decreases strictly.
VertexIndex DelaunayGraph::nearest_vertex(SiteId p) {
    VertexIndex v = walk_start(p);
    if (!tds_.is_vertex(v) || v == Triangulation::kInfiniteVertex) v = tds_.finite_vertices().front();
    for (bool moved = true; moved;) {
        moved = false;
        for (FaceIndex f : tds_.incident_faces(v)) {
            const VertexIndex w = tds_.face(f).v[ccw(tds_.index(f, v))];
            if (w == Triangulation::kInfiniteVertex || w == v) continue;
            if (traits_->side_of_bisector(site_of(v), site_of(w), p) == Sign::negative) {
                v = w;
                moved = true;
                ++stats_.walk_steps;
                break;
            }
        }
    }
    return v;
}

VertexIndex DelaunayGraph::walk_start(SiteId p) const {
    if (grid_)
        for (SiteId s : grid_->near(p)) {
            const VertexIndex v = vertex_of_site_[s];
            if (tds_.is_vertex(v) && v != Triangulation::kInfiniteVertex && site_of(v) == s) return v;
        }
    return last_vertex_;
}

// The hidden test: with disjoint or nested sites only a site containing p
// gives a negative distance at p's center, so the nearest site is the only
// one that can hide p.
bool DelaunayGraph::hide_in_nearest(SiteId p, VertexIndex nearest) {
    if (!traits_->is_hidden(site_of(nearest), p)) return false;
    hide(p, site_of(nearest));
    ++stats_.hidden_on_insert;
    return true;
}

// The first conflict: a Voronoi vertex around the nearest site in conflict with p.
std::optional<FaceIndex> DelaunayGraph::find_first_conflict(ConflictRegion& region, VertexIndex nearest) {
    for (FaceIndex f : tds_.incident_faces(nearest))
        if (region.in_conflict(f)) return f;
    return std::nullopt;
}

// No vertex in conflict: p may still conflict with the interior of a Voronoi
// edge of the nearest site; its cell then lies inside that edge and its
// vertex has degree 2.
bool DelaunayGraph::insert_in_voronoi_edge(SiteId p, VertexIndex nearest) {
    TriangulationPredicates pred = predicates();
    for (FaceIndex f : tds_.incident_faces(nearest)) {
        const Edge e{f, cw(tds_.index(f, nearest))};
        if (pred.edge_interior(e, p, false)) {
            record_vertex(p, tds_.insert_degree_2(e, p));
            ++stats_.degree_2_insertions;
            return true;
        }
    }
    return false;
}

// CGAL's fallbacks when p hides all the visible sites, or all but one: no
// triangulation is left, the survivors start again as the small cases.
bool DelaunayGraph::rebuild_if_at_most_one_survives(const ConflictRegion& region) {
    const std::vector<VertexIndex> hidden = region.hidden_vertices();
    if (tds_.number_of_vertices() - 1 - hidden.size() > 1) return false;
    std::vector<SiteId> survivors;
    for (VertexIndex v : tds_.finite_vertices())
        if (!std::binary_search(hidden.begin(), hidden.end(), v)) survivors.push_back(site_of(v));
    for (VertexIndex v : hidden) hide(site_of(v), region.site());
    survivors.push_back(region.site());
    rebuild_small(survivors);
    return true;
}

// Bogus vertices: an edge along which the region touches itself gets a
// temporary degree-2 vertex, so that the hole to star is a disk.
std::vector<VertexIndex> DelaunayGraph::add_bogus_vertices(const ConflictRegion& region) {
    std::vector<VertexIndex> bogus;
    for (const Edge& e : region.self_touching_edges()) bogus.push_back(tds_.insert_degree_2(e, Triangulation::kBogusSite));
    stats_.bogus_vertices += bogus.size();
    return bogus;
}

// Retriangulation: the region's faces are replaced by a fan around p's new
// vertex (star_hole); the vertices inside the region, exactly those p hides,
// disappear.
void DelaunayGraph::retriangulate_conflict_region(ConflictRegion& region, const std::vector<VertexIndex>& bogus) {
    const std::vector<Edge> boundary = region.boundary();
    const std::vector<VertexIndex> hidden = region.hidden_vertices();
    region.check_inner_vertices(boundary, hidden);
    for (VertexIndex h : hidden) hide(site_of(h), region.site());
    TriangulationPredicates pred = predicates();
    for (FaceIndex f : region.faces()) pred.forget(f);
    const VertexIndex v = tds_.star_hole(region.site(), boundary, region.faces());
    for (VertexIndex b : bogus) tds_.remove_degree_2(b);
    record_vertex(region.site(), v);
}

void DelaunayGraph::record_vertex(SiteId p, VertexIndex v) {
    last_vertex_ = v;
    vertex_of_site_[p] = v;
    if (grid_) grid_->add(p);
}

// ---------------------------------------------------------------- output and checks

std::vector<SiteId> DelaunayGraph::visible_sites() const {
    std::vector<SiteId> out = small_;
    for (VertexIndex v : tds_.finite_vertices()) out.push_back(site_of(v));
    std::sort(out.begin(), out.end());
    return out;
}

std::vector<std::pair<SiteId, SiteId>> DelaunayGraph::hidden() const {
    std::vector<std::pair<SiteId, SiteId>> out;
    for (SiteId s = 0; s < hidden_in_.size(); ++s)
        for (SiteId h : hidden_in_[s]) out.push_back({h, s});
    std::sort(out.begin(), out.end());
    return out;
}

std::vector<std::pair<SiteId, SiteId>> DelaunayGraph::edges() const {
    std::vector<std::pair<SiteId, SiteId>> out;
    if (small_.size() == 2) out.push_back({std::min(small_[0], small_[1]), std::max(small_[0], small_[1])});
    for (FaceIndex f : tds_.faces())
        for (int i = 0; i < 3; ++i) {
            const Edge e{f, i};
            if (tds_.is_infinite_edge(e) || tds_.mirror_edge(e) < e) continue;  // each edge once
            const SiteId a = site_of(tds_.face(f).v[ccw(i)]), b = site_of(tds_.face(f).v[cw(i)]);
            out.push_back({std::min(a, b), std::max(a, b)});
        }
    std::sort(out.begin(), out.end());
    return out;
}

std::vector<std::array<SiteId, 3>> DelaunayGraph::faces() const {
    std::vector<std::array<SiteId, 3>> out;
    for (FaceIndex f : tds_.faces()) {
        if (tds_.is_infinite_face(f)) continue;
        std::array<SiteId, 3> t;
        for (int i = 0; i < 3; ++i) t[i] = site_of(tds_.face(f).v[i]);
        std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
        out.push_back(t);
    }
    std::sort(out.begin(), out.end());
    return out;
}

std::vector<std::pair<SiteId, SiteId>> DelaunayGraph::hull() const {
    std::vector<std::pair<SiteId, SiteId>> out;
    if (small_.size() == 2) {
        out.push_back({small_[0], small_[1]});
        out.push_back({small_[1], small_[0]});
    }
    for (FaceIndex f : tds_.faces()) {
        const int k = tds_.index(f, Triangulation::kInfiniteVertex);
        if (k < 0) continue;
        out.push_back({site_of(tds_.face(f).v[ccw(k)]), site_of(tds_.face(f).v[cw(k)])});
    }
    std::sort(out.begin(), out.end());
    return out;
}

std::string DelaunayGraph::validate() {
    // Every inserted site is visible exactly once or hidden exactly once.
    std::vector<int> seen(traits_->size(), 0);
    const std::vector<SiteId> visible = visible_sites();
    for (SiteId s : visible) ++seen[s];
    for (const auto& [h, by] : hidden()) {
        ++seen[h];
        if (!std::binary_search(visible.begin(), visible.end(), by))
            return "site " + str(h) + " is hidden by site " + str(by) + ", which is not visible";
    }
    for (SiteId s = 0; s < traits_->size(); ++s)
        if (seen[s] != (inserted_[s] ? 1 : 0))
            return "site " + str(s) + " is " + (seen[s] ? "recorded " + std::to_string(seen[s]) + " times" : "lost");
    if (tds_.empty()) return small_.size() <= 2 ? "" : "more than two sites without a triangulation";
    if (!small_.empty()) return "sites outside the triangulation";
    const std::string tds = tds_.check();
    if (!tds.empty()) return "triangulation: " + tds;
    if (tds_.number_of_vertices() < 4) return "a triangulation with fewer than 3 sites";
    TriangulationPredicates pred = predicates();
    for (FaceIndex f : tds_.faces())
        for (int i = 0; i < 3; ++i) {
            const VertexIndex w = tds_.mirror_vertex({f, i});
            if (w == Triangulation::kInfiniteVertex || w == tds_.face(f).v[i]) continue;
            if (pred.incircle(f, site_of(w)) == Sign::negative) {
                std::string face;
                for (VertexIndex x : tds_.face(f).v)
                    face += (face.empty() ? "" : " ") + (x == Triangulation::kInfiniteVertex ? "inf" : str(site_of(x)));
                return "site " + str(site_of(w)) + " is in conflict with the Voronoi vertex of face (" + face + ")";
            }
        }
    return "";
}

std::string DelaunayGraph::brute_force_check() {
    const std::string local = validate();
    if (!local.empty()) return local;
    for (const auto& [h, by] : hidden())
        if (!traits_->is_hidden(by, h)) return "site " + str(h) + " is recorded hidden but is not inside site " + str(by);
    for (FaceIndex f : tds_.faces()) {
        const Triangulation::Face& F = tds_.face(f);
        const int k = tds_.index(f, Triangulation::kInfiniteVertex);
        for (SiteId q = 0; q < traits_->size(); ++q) {
            if (!inserted_[q]) continue;
            bool own = false;
            for (VertexIndex x : F.v) own = own || (x != Triangulation::kInfiniteVertex && site_of(x) == q);
            if (own) continue;
            if (k < 0) {
                const SiteId a = site_of(F.v[0]), b = site_of(F.v[1]), c = site_of(F.v[2]);
                if (traits_->vertex_conflict(a, b, c, q) == Sign::negative)
                    return "site " + str(q) + " is in conflict with the Voronoi circle of (" + str(a) + " " + str(b) +
                           " " + str(c) + ")";
            } else {
                const SiteId a = site_of(F.v[ccw(k)]), b = site_of(F.v[cw(k)]);
                if (traits_->vertex_conflict(a, b, q) == Sign::negative)
                    return "site " + str(q) + " is in conflict with the hull edge (" + str(a) + " " + str(b) + ")";
            }
        }
    }
    return "";
}

}  // namespace ellvor
