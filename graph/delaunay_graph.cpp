#include "graph/delaunay_graph.hpp"

#include "util/error.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <map>
#include <numeric>
#include <set>

namespace ellvor {
namespace {
std::string str(SiteId i) { return std::to_string(i); }
}  // namespace

DelaunayGraph::DelaunayGraph(std::vector<Ellipse> sites)
    : traits_(std::move(sites)), hidden_in_(traits_.size()), inserted_(traits_.size(), 0),
      vertex_of_site_(traits_.size(), -1) {}

void DelaunayGraph::insert_all(const std::function<void(std::size_t done, std::size_t total)>& progress) {
    std::vector<SiteId> order(traits_.size());
    std::iota(order.begin(), order.end(), 0);
    std::vector<Rational> area(order.size());
    for (SiteId i : order) area[i] = traits_.site(i).a() * traits_.site(i).b();
    std::stable_sort(order.begin(), order.end(), [&](SiteId x, SiteId y) { return area[y] < area[x]; });
    // Area order jumps across the plane; the grid keeps the walk short.
    grid_ = std::make_unique<SiteGrid>(traits_);
    std::size_t done = 0;
    for (SiteId i : order) {
        insert(i);
        if (progress) progress(++done, order.size());
    }
}

void DelaunayGraph::insert(SiteId p) {
    if (p >= traits_.size()) throw Error("DelaunayGraph::insert: no site " + str(p));
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
        if (traits_.is_hidden(v, p)) {
            hide(p, v);
            ++stats_.hidden_on_insert;
        } else if (traits_.is_hidden(p, v)) {
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
        if (traits_.is_hidden(s, p)) {
            hide(p, s);
            ++stats_.hidden_on_insert;
            return;
        }
    const bool t1 = traits_.is_hidden(p, s1), t2 = traits_.is_hidden(p, s2);
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
    // the graph of three sites (research digest 2.2 and 3).
    switch (finite_edge_conflict_type_degenerated(s1, s2, p)) {
        case ConflictType::left_vertex: tds_.make_tetrahedron(s1, s2, p); break;
        case ConflictType::right_vertex: tds_.make_tetrahedron(s2, s1, p); break;
        case ConflictType::interior: build_three(s1, p, s2, false); break;
        case ConflictType::entire_edge: build_three(s1, p, s2, true); break;
        case ConflictType::no_conflict: {
            // p does not reach the bisector: s1 or s2 lies between p and the other.
            const ConflictType ct1 = finite_edge_conflict_type_degenerated(s1, p, s2);
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
            const ConflictType ct1 = finite_edge_conflict_type_degenerated(s1, p, s2);
            if (ct1 == ConflictType::interior)
                build_three(s1, s2, p, false);
            else
                build_three(s2, s1, p, false);
            break;
        }
    }
    small_.clear();
    last_vertex_ = tds_.face(0).v[0] == Triangulation::kInfinite ? tds_.face(0).v[1] : tds_.face(0).v[0];
}

// Three sites without a Voronoi vertex (m between a and b, on the hull) or
// with two (m's cell bounded by a and b only).
void DelaunayGraph::build_three(SiteId a, SiteId m, SiteId b, bool middle_on_hull) {
    const auto v = tds_.make_tetrahedron(a, m, b);
    const Edge e = middle_on_hull ? find_edge(v[0], v[2]) : find_edge(v[1], Triangulation::kInfinite);
    tds_.flip(e.first, e.second);
}

DelaunayGraph::Edge DelaunayGraph::find_edge(int a, int b) const {
    for (std::size_t f = 0; f < tds_.face_capacity(); ++f) {
        if (!tds_.face(f).alive) continue;
        for (int i = 0; i < 3; ++i) {
            const int x = tds_.face(f).v[ccw(i)], y = tds_.face(f).v[cw(i)];
            if ((x == a && y == b) || (x == b && y == a)) return {static_cast<int>(f), i};
        }
    }
    throw Error("DelaunayGraph: edge not found (internal error)");
}

void DelaunayGraph::rebuild_small(std::vector<SiteId> visible) {
    tds_.clear();
    small_ = std::move(visible);
    last_vertex_ = -1;
    ++stats_.rebuilds;
}

// ---------------------------------------------------------------- general insertion

void DelaunayGraph::record_vertex(SiteId p, int v) {
    last_vertex_ = v;
    vertex_of_site_[p] = v;
    if (grid_) grid_->add(p);
}

int DelaunayGraph::walk_start(SiteId p) const {
    if (grid_)
        for (SiteId s : grid_->near(p)) {
            const int v = vertex_of_site_[s];
            if (v > 0 && v < static_cast<int>(tds_.vertex_capacity()) && tds_.vertex(v).alive && site_of(v) == s)
                return v;
        }
    return last_vertex_;
}

int DelaunayGraph::nearest_vertex(SiteId p) {
    int v = walk_start(p);
    if (v < 0 || v >= static_cast<int>(tds_.vertex_capacity()) || !tds_.vertex(v).alive || is_infinite(v)) {
        v = -1;
        for (std::size_t x = 1; x < tds_.vertex_capacity() && v < 0; ++x)
            if (tds_.vertex(x).alive) v = static_cast<int>(x);
    }
    for (bool moved = true; moved;) {
        moved = false;
        for (int f : tds_.incident_faces(v)) {
            const int w = tds_.face(f).v[ccw(tds_.index(f, v))];
            if (is_infinite(w) || w == v) continue;
            if (traits_.side_of_bisector(site_of(v), site_of(w), p) == Sign::negative) {
                v = w;
                moved = true;
                ++stats_.walk_steps;
                break;
            }
        }
    }
    return v;
}

void DelaunayGraph::insert_general(SiteId p) {
    const int nearest = nearest_vertex(p);
    if (traits_.is_hidden(site_of(nearest), p)) {
        hide(p, site_of(nearest));
        ++stats_.hidden_on_insert;
        return;
    }
    std::map<int, Sign> sign_of_face;
    auto in_conflict = [&](int f) {
        auto found = sign_of_face.find(f);
        if (found == sign_of_face.end()) found = sign_of_face.emplace(f, incircle(f, p)).first;
        return found->second == Sign::negative;
    };
    // First conflict: a Voronoi vertex around the nearest site, else the
    // interior of one of its Voronoi edges (p then gets a degree-2 vertex).
    int start = -1;
    const std::vector<int> around = tds_.incident_faces(nearest);
    for (int f : around)
        if (in_conflict(f)) {
            start = f;
            break;
        }
    if (start < 0) {
        for (int f : around) {
            const int i = cw(tds_.index(f, nearest));
            if (edge_interior(f, i, p, false)) {
                record_vertex(p, tds_.insert_degree_2(f, i, static_cast<long>(p)));
                ++stats_.degree_2_insertions;
                return;
            }
        }
        throw Error("site " + str(p) + " is in conflict with no Voronoi vertex or edge (covered by a union of sites?)");
    }

    // The conflict region: faces reached through edges whose whole Voronoi
    // edge is in conflict, or one of whose endpoints p hides.
    std::map<int, bool> hides;  // vertex -> p hides its site
    auto hidden_vertex = [&](int v) {
        if (is_infinite(v)) return false;
        auto found = hides.find(v);
        if (found == hides.end()) found = hides.emplace(v, traits_.is_hidden(p, site_of(v))).first;
        return found->second;
    };
    std::set<int> region{start};
    std::vector<int> region_list{start};
    std::map<Edge, bool> crossed;
    std::deque<int> queue{start};
    while (!queue.empty()) {
        const int f = queue.front();
        queue.pop_front();
        for (int i = 0; i < 3; ++i) {
            if (crossed.count({f, i})) continue;
            const int g = tds_.face(f).n[i], j = tds_.mirror_index(f, i);
            const bool h1 = hidden_vertex(tds_.face(f).v[ccw(i)]);
            const bool h2 = hidden_vertex(tds_.face(f).v[cw(i)]);
            const bool pass = h1 || h2 || (in_conflict(g) && edge_interior(f, i, p, true));
            crossed[{f, i}] = pass;
            crossed[{g, j}] = pass;
            if (pass && region.insert(g).second) {
                region_list.push_back(g);
                queue.push_back(g);
            }
        }
    }
    std::vector<int> hidden_vertices;
    for (const auto& [v, h] : hides)
        if (h) hidden_vertices.push_back(v);
    const std::size_t visible = tds_.number_of_vertices() - 1;
    if (visible - hidden_vertices.size() <= 1) {
        std::vector<SiteId> survivors;
        for (std::size_t v = 1; v < tds_.vertex_capacity(); ++v)
            if (tds_.vertex(v).alive && !hides[static_cast<int>(v)]) survivors.push_back(site_of(static_cast<int>(v)));
        for (int v : hidden_vertices) hide(site_of(v), p);
        survivors.push_back(p);
        rebuild_small(survivors);
        return;
    }
    stats_.conflict_faces += region_list.size();

    // Bogus vertices: an edge between two faces of the region that was not
    // crossed bounds the region on both sides; split it so that the hole is a disk.
    std::vector<int> bogus;
    {
        std::vector<Edge> touching;
        for (const auto& [e, pass] : crossed) {
            if (pass) continue;
            const int g = tds_.face(e.first).n[e.second];
            if (!region.count(e.first) || !region.count(g)) continue;
            const int j = tds_.mirror_index(e.first, e.second);
            if (e.first < g || (e.first == g && e.second < j)) touching.push_back(e);
        }
        for (const Edge& e : touching) bogus.push_back(tds_.insert_degree_2(e.first, e.second, -2));
        stats_.bogus_vertices += bogus.size();
    }

    // The boundary, counter-clockwise: from each boundary edge turn clockwise
    // around its end vertex through region faces to the next one.
    std::size_t boundary_size = 0;
    Edge first{-1, -1};
    for (int f : region_list)
        for (int i = 0; i < 3; ++i)
            if (!region.count(tds_.face(f).n[i])) {
                ++boundary_size;
                if (first.first < 0) first = {f, i};
            }
    std::vector<Edge> boundary{first};
    for (;;) {
        auto [f, i] = boundary.back();
        int k = ccw(i);
        std::size_t guard = 0;
        while (region.count(tds_.face(f).n[k])) {
            const int g = tds_.face(f).n[k], j = tds_.mirror_index(f, k);
            f = g;
            k = ccw(j);
            if (++guard > 4 * tds_.face_capacity()) throw Error("conflict region walk does not close (internal error)");
        }
        if (Edge{f, k} == first) break;
        boundary.push_back({f, k});
        if (boundary.size() > boundary_size) break;
    }
    if (boundary.size() != boundary_size)
        throw Error("the conflict region of site " + str(p) + " is not a disk (internal error)");
    // Vertices inside the hole must be exactly the hidden ones.
    std::set<int> on_boundary;
    for (const Edge& e : boundary) on_boundary.insert(tds_.face(e.first).v[ccw(e.second)]);
    for (int f : region_list)
        for (int v : tds_.face(f).v)
            if (!on_boundary.count(v) && !hidden_vertex(v))
                throw Error("site " + str(site_of(v)) + " would vanish inserting site " + str(p) + " (internal error)");
    for (int v : hidden_vertices)
        if (on_boundary.count(v))
            throw Error("hidden site " + str(site_of(v)) + " stays on the conflict boundary of site " + str(p) +
                        " (internal error)");

    for (int h : hidden_vertices) hide(site_of(h), p);
    const int v = tds_.star_hole(static_cast<long>(p), boundary, region_list);
    for (int b : bogus) tds_.remove_degree_2(b);
    record_vertex(p, v);
}

// ---------------------------------------------------------------- predicate wrappers

Sign DelaunayGraph::incircle(int f, SiteId q) {
    const auto& F = tds_.face(f);
    const int k = tds_.index(f, Triangulation::kInfinite);
    if (k < 0) return traits_.vertex_conflict(site_of(F.v[0]), site_of(F.v[1]), site_of(F.v[2]), q);
    return traits_.vertex_conflict(site_of(F.v[ccw(k)]), site_of(F.v[cw(k)]), q);
}

bool DelaunayGraph::edge_interior(int f, int i, SiteId q, bool b) {
    const int g = tds_.face(f).n[i];
    const bool inf_f = tds_.is_infinite_face(f), inf_g = tds_.is_infinite_face(g);
    if (!inf_f && !inf_g) {
        const auto& F = tds_.face(f);
        const SiteId p1 = site_of(F.v[ccw(i)]), p2 = site_of(F.v[cw(i)]);
        if (traits_.is_hidden(q, p1) || traits_.is_hidden(q, p2)) return true;
        return traits_.finite_edge_interior(p1, p2, site_of(F.v[i]), site_of(tds_.mirror_vertex(f, i)), q, b);
    }
    if (!inf_f || !inf_g || !tds_.is_infinite_edge(f, i)) return finite_edge_interior_degenerated(f, i, q, b);
    return infinite_edge_interior(f, i, q, b);
}

bool DelaunayGraph::finite_edge_interior_degenerated(int f, int i, SiteId q, bool b) {
    if (!is_infinite(tds_.mirror_vertex(f, i))) {
        const int g = tds_.face(f).n[i], j = tds_.mirror_index(f, i);
        if (!is_infinite(tds_.face(f).v[i])) throw Error("finite_edge_interior_degenerated: bad edge (internal error)");
        return finite_edge_interior_degenerated(g, j, q, b);
    }
    const auto& F = tds_.face(f);
    const SiteId p1 = site_of(F.v[ccw(i)]), p2 = site_of(F.v[cw(i)]);
    if (traits_.is_hidden(q, p1) || traits_.is_hidden(q, p2)) return true;
    if (is_infinite(F.v[i])) return traits_.finite_edge_interior(p1, p2, q, b);
    return traits_.finite_edge_interior(p1, p2, site_of(F.v[i]), q, b);
}

bool DelaunayGraph::infinite_edge_interior(int f, int i, SiteId q, bool b) {
    if (!is_infinite(tds_.face(f).v[ccw(i)])) {
        const int g = tds_.face(f).n[i], j = tds_.mirror_index(f, i);
        return infinite_edge_interior(g, j, q, b);
    }
    const auto& F = tds_.face(f);
    const SiteId p2 = site_of(F.v[cw(i)]);
    if (traits_.is_hidden(q, p2)) return true;
    return traits_.infinite_edge_interior(p2, site_of(F.v[i]), site_of(tds_.mirror_vertex(f, i)), q, b);
}

DelaunayGraph::ConflictType DelaunayGraph::finite_edge_conflict_type_degenerated(SiteId p1, SiteId p2, SiteId q) {
    const bool c1 = traits_.vertex_conflict(p1, p2, q) == Sign::negative;
    const bool c2 = traits_.vertex_conflict(p2, p1, q) == Sign::negative;
    if (c1 && !c2) return ConflictType::left_vertex;
    if (!c1 && c2) return ConflictType::right_vertex;
    const bool both = c1;  // (-, -) or (+, +)
    bool b = traits_.is_hidden(q, p1) || traits_.is_hidden(q, p2) || traits_.finite_edge_interior(p1, p2, q, both);
    if (both) return b ? ConflictType::entire_edge : ConflictType::both_vertices;
    return b ? ConflictType::interior : ConflictType::no_conflict;
}

// ---------------------------------------------------------------- output and checks

std::vector<SiteId> DelaunayGraph::visible_sites() const {
    std::vector<SiteId> out = small_;
    for (std::size_t v = 1; v < tds_.vertex_capacity(); ++v)
        if (tds_.vertex(v).alive) out.push_back(site_of(static_cast<int>(v)));
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
    for (std::size_t f = 0; f < tds_.face_capacity(); ++f) {
        if (!tds_.face(f).alive) continue;
        for (int i = 0; i < 3; ++i) {
            if (tds_.is_infinite_edge(static_cast<int>(f), i)) continue;
            const int g = tds_.face(f).n[i], j = tds_.mirror_index(static_cast<int>(f), i);
            if (!(static_cast<int>(f) < g || (static_cast<int>(f) == g && i < j))) continue;
            const SiteId a = site_of(tds_.face(f).v[ccw(i)]), b = site_of(tds_.face(f).v[cw(i)]);
            out.push_back({std::min(a, b), std::max(a, b)});
        }
    }
    std::sort(out.begin(), out.end());
    return out;
}

std::vector<std::array<SiteId, 3>> DelaunayGraph::faces() const {
    std::vector<std::array<SiteId, 3>> out;
    for (std::size_t f = 0; f < tds_.face_capacity(); ++f) {
        if (!tds_.face(f).alive || tds_.is_infinite_face(static_cast<int>(f))) continue;
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
    for (std::size_t f = 0; f < tds_.face_capacity(); ++f) {
        if (!tds_.face(f).alive) continue;
        const int k = tds_.index(static_cast<int>(f), Triangulation::kInfinite);
        if (k < 0) continue;
        out.push_back({site_of(tds_.face(f).v[ccw(k)]), site_of(tds_.face(f).v[cw(k)])});
    }
    std::sort(out.begin(), out.end());
    return out;
}

std::string DelaunayGraph::validate() {
    // Every inserted site is visible exactly once or hidden exactly once.
    std::vector<int> seen(traits_.size(), 0);
    const std::vector<SiteId> visible = visible_sites();
    for (SiteId s : visible) ++seen[s];
    for (const auto& [h, by] : hidden()) {
        ++seen[h];
        if (!std::binary_search(visible.begin(), visible.end(), by))
            return "site " + str(h) + " is hidden by site " + str(by) + ", which is not visible";
    }
    for (SiteId s = 0; s < traits_.size(); ++s)
        if (seen[s] != (inserted_[s] ? 1 : 0))
            return "site " + str(s) + " is " + (seen[s] ? "recorded " + std::to_string(seen[s]) + " times" : "lost");
    if (tds_.empty()) return small_.size() <= 2 ? "" : "more than two sites without a triangulation";
    if (!small_.empty()) return "sites outside the triangulation";
    const std::string tds = tds_.check();
    if (!tds.empty()) return "triangulation: " + tds;
    if (tds_.number_of_vertices() < 4) return "a triangulation with fewer than 3 sites";
    for (std::size_t f = 0; f < tds_.face_capacity(); ++f) {
        if (!tds_.face(f).alive) continue;
        for (int i = 0; i < 3; ++i) {
            const int w = tds_.mirror_vertex(static_cast<int>(f), i);
            if (is_infinite(w) || w == tds_.face(f).v[i]) continue;
            if (incircle(static_cast<int>(f), site_of(w)) == Sign::negative) {
                std::string face;
                for (int x : tds_.face(f).v) face += (face.empty() ? "" : " ") + (is_infinite(x) ? "inf" : str(site_of(x)));
                return "site " + str(site_of(w)) + " is in conflict with the Voronoi vertex of face (" + face + ")";
            }
        }
    }
    return "";
}

std::string DelaunayGraph::brute_force_check() {
    const std::string local = validate();
    if (!local.empty()) return local;
    for (const auto& [h, by] : hidden())
        if (!traits_.is_hidden(by, h)) return "site " + str(h) + " is recorded hidden but is not inside site " + str(by);
    for (std::size_t f = 0; f < tds_.face_capacity(); ++f) {
        if (!tds_.face(f).alive) continue;
        const auto& F = tds_.face(f);
        const int k = tds_.index(static_cast<int>(f), Triangulation::kInfinite);
        for (SiteId q = 0; q < traits_.size(); ++q) {
            if (!inserted_[q]) continue;
            bool own = false;
            for (int x : F.v) own = own || (!is_infinite(x) && site_of(x) == q);
            if (own) continue;
            if (k < 0) {
                const SiteId a = site_of(F.v[0]), b = site_of(F.v[1]), c = site_of(F.v[2]);
                if (traits_.vertex_conflict(a, b, c, q) == Sign::negative)
                    return "site " + str(q) + " is in conflict with the Voronoi circle of (" + str(a) + " " + str(b) +
                           " " + str(c) + ")";
            } else {
                const SiteId a = site_of(F.v[ccw(k)]), b = site_of(F.v[cw(k)]);
                if (traits_.vertex_conflict(a, b, q) == Sign::negative)
                    return "site " + str(q) + " is in conflict with the hull edge (" + str(a) + " " + str(b) + ")";
            }
        }
    }
    return "";
}

}  // namespace ellvor
