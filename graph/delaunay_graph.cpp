#include "graph/delaunay_graph.hpp"

#include "graph/insertion_order.hpp"

#include "graph/conflict_region.hpp"
#include "util/error.hpp"

#include "graph/subset_traits.hpp"

#include <algorithm>
#include <limits>
#include <numeric>
#include <unordered_map>

namespace ellvor {
namespace {
std::string str(SiteId i) { return std::to_string(i); }
// host_ of a site that no site hides.
constexpr std::uint32_t kNoHost = std::numeric_limits<std::uint32_t>::max();
}  // namespace

DelaunayGraph::DelaunayGraph(std::unique_ptr<DelaunayTraits> traits) : traits_(std::move(traits)) {
    if (!traits_) throw Error("DelaunayGraph: no traits");
    if (traits_->size() > Triangulation::kMaxSite + 1)
        throw Error("DelaunayGraph: " + str(traits_->size()) + " sites, more than a graph holds (2^32 - 2)");
    host_.assign(traits_->size(), kNoHost);
    inserted_.assign(traits_->size(), kOut);
    vertex_of_site_.resize(traits_->size());
}

void DelaunayGraph::insert_all(const std::function<void(std::size_t done, std::size_t total)>& progress) {
    const std::vector<SiteId> order = bulk_insertion_order(*traits_);
    // n sites make at most n + 1 vertices and 2n - 2 faces (bogus vertices
    // aside, which come and go): room for them at once, so that no doubling
    // leaves a freed copy behind in the peak memory.
    const std::size_t n = traits_->size();
    tds_.reserve(n + 1, 2 * n);
    conflict_marks_.reserve(n + 1, 2 * n);
    // Each round of the bulk order starts across the plane; the grid keeps the walk short.
    std::vector<LocationHint> hints;
    hints.reserve(order.size());
    for (SiteId i = 0; i < traits_->size(); ++i) hints.push_back(traits_->location_hint(i));
    grid_ = std::make_unique<SiteGrid>(std::move(hints));
    std::size_t done = 0;
    for (SiteId i : order) {
        insert(i);
        if (progress) progress(++done, order.size());
    }
}

void DelaunayGraph::insert(SiteId p) {
    if (p >= traits_->size()) throw Error("DelaunayGraph::insert: no site " + str(p));
    if (inserted_[p] == kIn) throw Error("DelaunayGraph::insert: site " + str(p) + " inserted twice");
    traits_->check_sites();  // bad pairs fail here, before any search (a model checks once)
    if (inserted_[p] == kRemoved) removed_.erase(std::find(removed_.begin(), removed_.end(), p));
    inserted_[p] = kIn;
    ++stats_.inserted;
    if (tds_.empty())
        insert_small(p);
    else
        insert_general(p);
}

std::vector<SiteId> DelaunayGraph::take_hidden(SiteId s) {
    const auto found = hidden_in_.find(s);
    if (found == hidden_in_.end()) return {};
    std::vector<SiteId> list = std::move(found->second);
    hidden_in_.erase(found);
    return list;
}

void DelaunayGraph::forget_hidden(SiteId hidden) {
    const auto found = hidden_in_.find(host_[hidden]);
    std::vector<SiteId>& list = found->second;
    list.erase(std::find(list.begin(), list.end(), hidden));
    if (list.empty()) hidden_in_.erase(found);
}

void DelaunayGraph::hide(SiteId hidden, SiteId by) {
    const std::vector<SiteId> inside = take_hidden(hidden);
    auto& list = hidden_in_[by];
    list.push_back(hidden);
    host_[hidden] = by;
    for (SiteId h : inside) {
        list.push_back(h);
        host_[h] = by;
    }
}

void DelaunayGraph::hide_in_union(SiteId hidden, SiteId host, std::vector<SiteId>& again) {
    // Only a site crossing `hidden` can cover its center without containing
    // it; anything else is a wrong nearest site or predicate.
    if (!traits_->crosses(host, hidden))
        throw Error("site " + str(hidden) + " has an empty cell but site " + str(host) +
                    ", nearest to its center, does not cross it (internal error)");
    // The sites `hidden` hid lie in it, not in `host`: they look for their
    // own host.
    for (SiteId h : take_hidden(hidden)) {
        forget_union_hidden(h);
        again.push_back(h);
    }
    hidden_in_[host].push_back(hidden);
    host_[hidden] = host;
    union_hidden_.push_back(hidden);
    ++stats_.union_hidden;
}

void DelaunayGraph::insert_again(std::vector<SiteId> sites) {
    // CGAL's order: largest first, so that fewer are hidden again.
    std::stable_sort(sites.begin(), sites.end(),
                     [&](SiteId x, SiteId y) { return traits_->compare_weight(x, y) == Sign::positive; });
    for (SiteId h : sites) {
        host_[h] = kNoHost;
        inserted_[h] = kOut;
        --stats_.inserted;  // counted again by insert
        insert(h);
    }
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
    // the graph of three sites (as CGAL's insert_third). Without Voronoi
    // vertices, the shadows of each site on the other two's bisector --
    // none or all of it -- tell a chain (the middle site's shadow is all, the
    // others' none) from a site covered by the union of the other two (its
    // shadow is none, the others' all).
    TriangulationPredicates pred = predicates();
    auto all = [&](SiteId a, SiteId b, SiteId q) {
        const ConflictType t = pred.finite_edge_conflict_type_degenerated(a, b, q);
        if (t != ConflictType::no_conflict && t != ConflictType::entire_edge)
            throw Error("inconsistent predicates for the three sites " + str(s1) + ", " + str(s2) + ", " + str(p));
        return t == ConflictType::entire_edge;
    };
    auto covered = [&](SiteId hidden, SiteId a, SiteId b) {
        std::vector<SiteId> again;
        hide_in_union(hidden, nearer_at_center(a, b, hidden), again);
        small_ = {a, b};
        insert_again(again);
    };
    switch (pred.finite_edge_conflict_type_degenerated(s1, s2, p)) {
        case ConflictType::left_vertex: tds_.make_tetrahedron(s1, s2, p); break;
        case ConflictType::right_vertex: tds_.make_tetrahedron(s2, s1, p); break;
        case ConflictType::interior: build_three(s1, p, s2, false); break;
        case ConflictType::entire_edge: {
            const bool s1_all = all(s2, p, s1), s2_all = all(s1, p, s2);
            if (!s1_all && !s2_all) {
                build_three(s1, p, s2, true);
            } else if (s1_all != s2_all) {
                return covered(s1_all ? s2 : s1, s1_all ? s1 : s2, p);
            } else {
                throw Error("inconsistent predicates for the three sites " + str(s1) + ", " + str(s2) + ", " + str(p));
            }
            break;
        }
        case ConflictType::no_conflict: {
            // p does not reach the bisector: s1 or s2 lies between p and the
            // other, or p is covered.
            if (!all(s1, p, s2))
                build_three(s2, s1, p, true);
            else if (!all(s2, p, s1))
                build_three(s1, s2, p, true);
            else
                return covered(p, s1, s2);
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
    for (VertexIndex v : tds_.finite_vertices()) vertex_of_site_[site_of(v)] = v;
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
    std::optional<FaceIndex> start = find_first_conflict(region, nearest);
    std::vector<SiteId> again;  // sites hidden by sites that p empties
    if (!start) {
        if (insert_in_voronoi_edge(p, nearest)) return;
        // A site crossing others need not own its center, so its cell may
        // lie away from the nearest site's. Whether it is empty is decided
        // among the sites that meet p (hiding_among_sites_meeting); only a
        // visible p needs the search over the whole graph.
        std::optional<Hiding> hiding;
        if (!whole_graph_search_) hiding = hiding_among_sites_meeting(p);
        if (!hiding) {
            start = find_any_conflict(region);
            if (!start && insert_in_any_voronoi_edge(p, nearest)) return;
            if (!start && !whole_graph_search_)
                throw Error("site " + str(p) + " has a cell among the sites it meets but conflicts with nothing (internal error)");
            if (!start) hiding = Hiding{site_of(nearest), true};
        }
        if (hiding) {
            if (hiding->by_union)
                hide_in_union(p, hiding->host, again);
            else
                hide(p, hiding->host);
            ++stats_.hidden_on_insert;
            insert_again(again);
            return;
        }
    }
    region.expand(*start);
    if (!rebuild_if_at_most_one_survives(region, again)) {
        stats_.conflict_faces += region.faces().size();
        const std::vector<VertexIndex> bogus = add_bogus_vertices(region);
        retriangulate_conflict_region(region, bogus, again);
    }
    insert_again(again);
}

// The nearest site (CGAL's nearest_neighbor): a greedy walk to the vertex
// whose site is nearest to p's center (kappa1); it ends because the distance
// decreases strictly.
VertexIndex DelaunayGraph::nearest_vertex(SiteId p) {
    VertexIndex v = walk_start(p);
    if (!tds_.is_vertex(v) || v == Triangulation::kInfiniteVertex) v = tds_.finite_vertices().front();
    for (bool moved = true; moved;) {
        tds_.any_incident_face(v, [&](FaceIndex f) {
            predicates().prefetch(tds_.face(f).v[ccw(tds_.index(f, v))]);
            return false;
        });
        VertexIndex next;
        moved = tds_.any_incident_face(v, [&](FaceIndex f) {
            const VertexIndex w = tds_.face(f).v[ccw(tds_.index(f, v))];
            if (w == Triangulation::kInfiniteVertex || w == v) return false;
            if (traits_->side_of_bisector(site_of(v), site_of(w), p) != Sign::negative) return false;
            next = w;
            return true;
        });
        if (moved) {
            v = next;
            ++stats_.walk_steps;
        }
    }
    return v;
}

VertexIndex DelaunayGraph::walk_start(SiteId p) const {
    auto has_vertex = [&](SiteId s) {
        const VertexIndex v = vertex_of_site_[s];
        return tds_.is_vertex(v) && v != Triangulation::kInfiniteVertex && site_of(v) == s;
    };
    if (grid_)
        if (const std::optional<SiteId> s = grid_->nearest(p, has_vertex)) return vertex_of_site_[*s];
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
    FaceIndex first;
    const bool found = tds_.any_incident_face(nearest, [&](FaceIndex f) {
        first = f;
        return region.in_conflict(f);
    });
    if (found) return first;
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

// Only sites that meet p can empty its cell: at a point of p a site apart
// from p is farther than p, and a non-empty cell holds points of p (inward
// along a normal the depth in p grows at rate 1, in any other site at rate
// <= 1). So p is hidden among all sites iff it is hidden among the visible
// sites that cross or contain it: a small graph of those (through
// SubsetTraits, searched exhaustively) decides, and names the host.
std::optional<DelaunayGraph::Hiding> DelaunayGraph::hiding_among_sites_meeting(SiteId p) {
    std::vector<SiteId> ids;
    for (VertexIndex v : tds_.finite_vertices()) {
        const SiteId s = site_of(v);
        if (traits_->crosses(s, p) || traits_->is_hidden(s, p)) ids.push_back(s);
    }
    if (ids.empty()) return std::nullopt;
    ++stats_.hiding_tests;
    const SiteId p_local = ids.size();
    ids.push_back(p);
    auto subset = std::make_unique<SubsetTraits>(*traits_, ids);
    const SubsetTraits& local = *subset;
    DelaunayGraph small(std::move(subset));
    small.whole_graph_search_ = true;
    for (SiteId i = 0; i <= p_local; ++i) small.insert(i);
    std::optional<Hiding> hiding;
    if (small.host_[p_local] != kNoHost) {
        const SiteId host = small.host_[p_local];
        const bool by_union = std::find(small.union_hidden_.begin(), small.union_hidden_.end(), p_local) != small.union_hidden_.end();
        hiding = Hiding{local.global(host), by_union};
    }
    // The small graph's faces were asked about in the big traits: drop them.
    TriangulationPredicates small_pred = small.predicates();
    for (FaceIndex f : small.tds_.faces()) small_pred.forget(f);
    return hiding;
}

std::optional<FaceIndex> DelaunayGraph::find_any_conflict(ConflictRegion& region) {
    ++stats_.global_searches;
    for (FaceIndex f : tds_.faces())
        if (region.in_conflict(f)) return f;
    return std::nullopt;
}

bool DelaunayGraph::insert_in_any_voronoi_edge(SiteId p, VertexIndex nearest) {
    TriangulationPredicates pred = predicates();
    for (FaceIndex f : tds_.faces())
        for (int i = 0; i < 3; ++i) {
            const Edge e{f, i};
            // Each edge once; the nearest site's were tested already.
            if (tds_.mirror_edge(e) < e || tds_.face(f).v[ccw(i)] == nearest || tds_.face(f).v[cw(i)] == nearest) continue;
            if (pred.edge_interior(e, p, false)) {
                record_vertex(p, tds_.insert_degree_2(e, p));
                ++stats_.degree_2_insertions;
                return true;
            }
        }
    return false;
}

// The site of a or b nearer to the center of site `of` (kappa1; a at a tie).
SiteId DelaunayGraph::nearer_at_center(SiteId a, SiteId b, SiteId of) {
    return traits_->side_of_bisector(a, b, of) == Sign::negative ? b : a;
}

// The sites of the vanishing vertices are hidden by p: inside p, or emptied
// by p with others.
void DelaunayGraph::hide_vanishing(const ConflictRegion& region, const std::vector<VertexIndex>& vanishing,
                                   std::vector<SiteId>& again) {
    const std::vector<VertexIndex>& swallowed = region.swallowed_vertices();
    for (VertexIndex v : vanishing) {
        if (std::binary_search(swallowed.begin(), swallowed.end(), v))
            hide_in_union(site_of(v), region.site(), again);
        else
            hide(site_of(v), region.site());
    }
}

// CGAL's fallbacks when p hides all the visible sites, or all but one: no
// triangulation is left, the survivors start again as the small cases.
bool DelaunayGraph::rebuild_if_at_most_one_survives(const ConflictRegion& region, std::vector<SiteId>& again) {
    const std::vector<VertexIndex> vanishing = region.vanishing_vertices();
    if (tds_.number_of_vertices() - 1 - vanishing.size() > 1) return false;
    std::vector<SiteId> survivors;
    for (VertexIndex v : tds_.finite_vertices())
        if (!std::binary_search(vanishing.begin(), vanishing.end(), v)) survivors.push_back(site_of(v));
    hide_vanishing(region, vanishing, again);
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
// vertex (star_hole); the vertices inside the region, exactly those p hides
// or empties, disappear.
void DelaunayGraph::retriangulate_conflict_region(ConflictRegion& region, const std::vector<VertexIndex>& bogus,
                                                  std::vector<SiteId>& again) {
    const std::vector<Edge> boundary = region.boundary();
    const std::vector<VertexIndex> vanishing = region.vanishing_vertices();
    region.check_inner_vertices(boundary, vanishing);
    hide_vanishing(region, vanishing, again);
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

// ---------------------------------------------------------------- deletion

void DelaunayGraph::remove(SiteId s) {
    if (s >= traits_->size()) throw Error("DelaunayGraph::remove: no site " + str(s));
    if (inserted_[s] != kIn) throw Error("DelaunayGraph::remove: site " + str(s) + " is not in the graph");
    inserted_[s] = kRemoved;
    ++stats_.removed;
    removed_.push_back(s);
    if (host_[s] != kNoHost) {
        forget_hidden(s);
        host_[s] = kNoHost;
        forget_union_hidden(s);
        return;
    }
    std::vector<SiteId> orphans = take_hidden(s);
    for (SiteId h : orphans) forget_union_hidden(h);
    // A site emptied by a union comes back if s was one of the sites
    // covering it: s crosses it (a site it does not meet has no say on its
    // points).
    for (std::size_t k = 0; k < union_hidden_.size();) {
        const SiteId h = union_hidden_[k];
        if (traits_->crosses(h, s) || traits_->is_hidden(s, h)) {
            forget_hidden(h);
            orphans.push_back(h);
            union_hidden_[k] = union_hidden_.back();
            union_hidden_.pop_back();
        } else {
            ++k;
        }
    }
    if (tds_.empty()) {
        small_.erase(std::find(small_.begin(), small_.end(), s));
    } else if (tds_.number_of_vertices() == 4) {
        // Three sites: the two others are the small case again.
        TriangulationPredicates pred = predicates();
        for (FaceIndex f : tds_.faces()) pred.forget(f);
        std::vector<SiteId> rest;
        for (VertexIndex v : tds_.finite_vertices())
            if (site_of(v) != s) rest.push_back(site_of(v));
        tds_.clear();
        small_ = rest;
        last_vertex_ = VertexIndex();
    } else {
        remove_vertex(vertex_of(s));
    }
    // The sites s hid come back (CGAL: largest first, so that fewer are hidden again).
    insert_again(orphans);
}

void DelaunayGraph::forget_union_hidden(SiteId h) {
    const auto found = std::find(union_hidden_.begin(), union_hidden_.end(), h);
    if (found == union_hidden_.end()) return;
    *found = union_hidden_.back();
    union_hidden_.pop_back();
}

VertexIndex DelaunayGraph::vertex_of(SiteId s) const {
    const VertexIndex v = vertex_of_site_[s];
    if (tds_.is_vertex(v) && v != Triangulation::kInfiniteVertex && site_of(v) == s) return v;
    for (VertexIndex w : tds_.finite_vertices())  // not recorded (sites of a rebuild): rare
        if (site_of(w) == s) return w;
    throw Error("DelaunayGraph: site " + str(s) + " has no vertex (internal error)");
}

// CGAL's remove with more than three vertices: degree 2 and 3 directly,
// larger degrees through the small graph of the neighbours.
void DelaunayGraph::remove_vertex(VertexIndex v) {
    minimize_degree(v);
    const std::vector<FaceIndex> star = tds_.incident_faces(v);
    for (FaceIndex f : star)
        for (VertexIndex w : tds_.face(f).v)
            if (w != v && w != Triangulation::kInfiniteVertex) last_vertex_ = w;
    if (star.size() > 3) {
        if (!replace_star_by_small_graph(v)) rebuild_without(v);
        return;
    }
    TriangulationPredicates pred = predicates();
    for (FaceIndex f : star) pred.forget(f);
    if (star.size() == 2) {
        tds_.remove_degree_2(v);
    } else {
        // Degree 3: the link is a triangle, one face fills it.
        const std::array<VertexIndex, 3> link = {tds_.face(star[0]).v[ccw(tds_.index(star[0], v))],
                                                 tds_.face(star[1]).v[ccw(tds_.index(star[1], v))],
                                                 tds_.face(star[2]).v[ccw(tds_.index(star[2], v))]};
        tds_.replace_star(v, {Triangulation::NewFace{link, {-1, -1, -1}, {1, 2, 0}}});
    }
}

// CGAL's minimize_degree: an edge at v whose two Voronoi vertices are one
// circle (four sites tangent to it) is flipped, so that the circle becomes a
// face of the neighbours; the small graph's conflict region then matches v's
// star (a circle merely tangent to v is not in conflict with it).
void DelaunayGraph::minimize_degree(VertexIndex v) {
    TriangulationPredicates pred = predicates();
    for (bool flipped = true; flipped;) {
        flipped = false;
        const std::vector<FaceIndex> star = tds_.incident_faces(v);
        if (star.size() <= 3) return;
        for (FaceIndex f : star) {
            const int k = tds_.index(f, v);
            const Edge e{f, ccw(k)};  // from w = f.v[cw(k)] to v
            const VertexIndex w = tds_.face(f).v[cw(k)], x = tds_.face(f).v[ccw(k)], y = tds_.mirror_vertex(e);
            if (w == Triangulation::kInfiniteVertex || x == Triangulation::kInfiniteVertex ||
                y == Triangulation::kInfiniteVertex || !tds_.is_flippable(e))
                continue;
            if (!traits_->is_degenerate_edge(site_of(w), site_of(v), site_of(x), site_of(y))) continue;
            pred.forget(f);
            pred.forget(tds_.neighbor(e));
            tds_.flip(e);
            ++stats_.degenerate_flips;
            flipped = true;
            break;
        }
    }
}

// CGAL's remove_degree_d_vertex, without replaying flips: the faces that
// fill v's star are those of the small graph of v's neighbours that v's site
// conflicts with. v's cell is the same in the small graph as in the whole one
// (cells are star-shaped about their sites), so that conflict region, bounded
// counter-clockwise, reads as v's link; it is copied in by matching the two
// cycles. False when they do not match (left to rebuild_without).
bool DelaunayGraph::replace_star_by_small_graph(VertexIndex v) {
    // A link edge with v on both sides gets a bogus vertex, as in insertion:
    // the star becomes a disk; the small graph's region gets them likewise.
    std::vector<VertexIndex> bogus;
    for (FaceIndex f : tds_.incident_faces(v)) {
        const int k = tds_.index(f, v);
        if (tds_.index(tds_.neighbor({f, k}), v) >= 0)
            bogus.push_back(tds_.insert_degree_2({f, k}, Triangulation::kBogusSite));
    }
    stats_.bogus_vertices += bogus.size();
    const std::vector<FaceIndex> star = tds_.incident_faces(v);
    const std::size_t m = star.size();
    std::vector<VertexIndex> link(m);  // start of link edge k
    // The neighbours in the order of the link: each inserted next to the
    // last, the small graph's walks stay short.
    std::vector<SiteId> neighbours;
    for (std::size_t k = 0; k < m; ++k) {
        link[k] = tds_.face(star[k]).v[ccw(tds_.index(star[k], v))];
        if (link[k] != Triangulation::kInfiniteVertex &&
            std::find(neighbours.begin(), neighbours.end(), site_of(link[k])) == neighbours.end())
            neighbours.push_back(site_of(link[k]));
    }
    const SiteId removed_local = neighbours.size();
    std::vector<SiteId> ids = neighbours;
    ids.push_back(site_of(v));
    auto subset = std::make_unique<SubsetTraits>(*traits_, ids);
    const SubsetTraits& local = *subset;
    DelaunayGraph small(std::move(subset));
    for (SiteId i = 0; i < removed_local; ++i) small.insert(i);
    const std::optional<Hole> hole = small.conflict_hole(removed_local);
    const Triangulation& st = small.tds_;
    auto label = [&](VertexIndex x) {
        return x == Triangulation::kInfiniteVertex ? Triangulation::kInfiniteSite : local.global(st.vertex(x).site());
    };
    auto big_label = [&](VertexIndex x) {
        return x == Triangulation::kInfiniteVertex ? Triangulation::kInfiniteSite : site_of(x);
    };
    // The rotation that lays the region's boundary onto the link.
    std::optional<std::size_t> rotation;
    if (hole && hole->boundary.size() == m)
        for (std::size_t r = 0; r < m && !rotation; ++r) {
            bool same = true;
            for (std::size_t k = 0; k < m && same; ++k) {
                const Edge& e = hole->boundary[(k + r) % m];
                same = label(st.face(e.face).v[ccw(e.index)]) == big_label(link[k]);
            }
            if (same) rotation = r;
        }
    bool filled = false;
    if (rotation) {
        std::unordered_map<int, VertexIndex> vertex_in_big;  // small vertex -> big vertex
        std::unordered_map<int, int> position;               // boundary edge (face * 3 + index) -> link position
        for (std::size_t k = 0; k < m; ++k) {
            const Edge& e = hole->boundary[(k + *rotation) % m];
            vertex_in_big[st.face(e.face).v[ccw(e.index)].value()] = link[k];
            position[3 * e.face.value() + e.index] = static_cast<int>(k);
        }
        std::unordered_map<int, int> new_face_of;  // small face -> index in fill
        for (std::size_t t = 0; t < hole->faces.size(); ++t) new_face_of[hole->faces[t].value()] = static_cast<int>(t);
        std::vector<Triangulation::NewFace> fill(hole->faces.size());
        for (std::size_t t = 0; t < fill.size(); ++t) {
            const FaceIndex f = hole->faces[t];
            for (int i = 0; i < 3; ++i) {
                fill[t].v[i] = vertex_in_big.at(st.face(f).v[i].value());
                const auto across = new_face_of.find(st.neighbor({f, i}).value());
                if (across != new_face_of.end()) {
                    fill[t].face[i] = across->second;
                    fill[t].index[i] = st.mirror_index({f, i});
                } else {
                    fill[t].face[i] = -1;
                    fill[t].index[i] = position.at(3 * f.value() + i);
                }
            }
        }
        TriangulationPredicates pred = predicates();
        for (FaceIndex f : star) pred.forget(f);
        tds_.replace_star(v, fill);
        filled = true;
        ++stats_.small_graph_removals;
    }
    for (VertexIndex b : bogus) tds_.remove_degree_2(b);
    // The small graph's other faces were asked about in the big traits: drop them.
    TriangulationPredicates small_pred = small.predicates();
    for (FaceIndex f : st.faces()) {
        const bool kept = filled && std::find(hole->faces.begin(), hole->faces.end(), f) != hole->faces.end();
        if (!kept) small_pred.forget(f);
    }
    return filled;
}

std::optional<DelaunayGraph::Hole> DelaunayGraph::conflict_hole(SiteId p) {
    if (tds_.empty()) return std::nullopt;
    const VertexIndex nearest = nearest_vertex(p);
    if (traits_->is_hidden(site_of(nearest), p)) return std::nullopt;
    ConflictRegion region(tds_, predicates(), p, conflict_marks_);
    const std::optional<FaceIndex> start = find_first_conflict(region, nearest);
    if (!start) return std::nullopt;
    region.expand(*start);
    if (!region.vanishing_vertices().empty()) return std::nullopt;
    add_bogus_vertices(region);
    return Hole{region.faces(), region.boundary()};
}

// The fallback of deletion: the triangulation of the other visible sites
// built again (their hidden lists stay); counted in stats().removal_rebuilds.
void DelaunayGraph::rebuild_without(VertexIndex v) {
    ++stats_.removal_rebuilds;
    std::vector<SiteId> rest;
    TriangulationPredicates pred = predicates();
    for (FaceIndex f : tds_.faces()) pred.forget(f);
    for (VertexIndex w : tds_.finite_vertices())
        if (w != v) rest.push_back(site_of(w));
    tds_.clear();
    small_.clear();
    last_vertex_ = VertexIndex();
    std::stable_sort(rest.begin(), rest.end(),
                     [&](SiteId x, SiteId y) { return traits_->compare_weight(x, y) == Sign::positive; });
    for (SiteId r : rest) {
        inserted_[r] = kOut;
        --stats_.inserted;
        insert(r);
    }
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
    for (const auto& [s, list] : hidden_in_)
        for (SiteId h : list) out.push_back({h, s});
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
        if (seen[s] != (inserted_[s] == kIn ? 1 : 0))
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
    // A hidden site lies in its host or, emptied by a union, crosses it; the
    // loop below checks that no Voronoi circle has a hidden site in conflict.
    for (const auto& [h, by] : hidden()) {
        const bool by_union = std::find(union_hidden_.begin(), union_hidden_.end(), h) != union_hidden_.end();
        if (by_union ? !traits_->crosses(by, h) : !traits_->is_hidden(by, h))
            return "site " + str(h) + " is recorded hidden but " + (by_union ? "does not cross" : "is not inside") +
                   " site " + str(by);
    }
    for (FaceIndex f : tds_.faces()) {
        const Triangulation::Face& F = tds_.face(f);
        const int k = tds_.index(f, Triangulation::kInfiniteVertex);
        for (SiteId q = 0; q < traits_->size(); ++q) {
            if (inserted_[q] != kIn) continue;
            bool own = false;
            for (VertexIndex x : F.v) own = own || (x != Triangulation::kInfiniteVertex && site_of(x) == q);
            if (own) continue;
            if (k < 0) {
                const SiteId a = site_of(F.v[0]), b = site_of(F.v[1]), c = site_of(F.v[2]);
                if (traits_->incircle(a, b, c, q) == Sign::negative)
                    return "site " + str(q) + " is in conflict with the Voronoi circle of (" + str(a) + " " + str(b) +
                           " " + str(c) + ")";
            } else {
                const SiteId a = site_of(F.v[ccw(k)]), b = site_of(F.v[cw(k)]);
                if (traits_->infinite_vertex_conflict(a, b, q) == Sign::negative)
                    return "site " + str(q) + " is in conflict with the hull edge (" + str(a) + " " + str(b) + ")";
            }
        }
    }
    return "";
}

}  // namespace ellvor
