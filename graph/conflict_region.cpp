#include "graph/conflict_region.hpp"

#include "util/error.hpp"

#include <deque>
#include <string>

namespace ellvor {

bool ConflictRegion::in_conflict(FaceIndex f) {
    auto found = incircle_.find(f);
    if (found == incircle_.end()) found = incircle_.emplace(f, predicates_.incircle(f, p_)).first;
    return found->second == Sign::negative;
}

bool ConflictRegion::hides(VertexIndex v) {
    if (v == Triangulation::kInfiniteVertex) return false;
    auto found = hides_.find(v);
    if (found == hides_.end()) found = hides_.emplace(v, predicates_.is_hidden(p_, predicates_.site(v))).first;
    return found->second;
}

void ConflictRegion::expand(FaceIndex start) {
    faces_ = {start};
    face_set_ = {start};
    std::deque<FaceIndex> queue{start};
    while (!queue.empty()) {
        const FaceIndex f = queue.front();
        queue.pop_front();
        for (int i = 0; i < 3; ++i) {
            const Edge e{f, i};
            if (crossed_.count(e)) continue;
            const Edge across = tds_.mirror_edge(e);
            // Every face around a hidden vertex is in conflict.
            const bool h1 = hides(tds_.face(f).v[ccw(i)]);
            const bool h2 = hides(tds_.face(f).v[cw(i)]);
            const bool pass = h1 || h2 || (in_conflict(across.face) && predicates_.edge_interior(e, p_, true));
            crossed_[e] = pass;
            crossed_[across] = pass;
            if (pass && face_set_.insert(across.face).second) {
                faces_.push_back(across.face);
                queue.push_back(across.face);
            }
        }
    }
}

std::vector<VertexIndex> ConflictRegion::hidden_vertices() const {
    std::vector<VertexIndex> out;
    for (const auto& [v, hidden] : hides_)
        if (hidden) out.push_back(v);
    return out;
}

std::vector<Edge> ConflictRegion::self_touching_edges() const {
    std::vector<Edge> out;
    for (const auto& [e, pass] : crossed_) {
        if (pass) continue;
        const Edge across = tds_.mirror_edge(e);
        if (!contains(e.face) || !contains(across.face)) continue;
        if (e < across) out.push_back(e);
    }
    return out;
}

std::vector<Edge> ConflictRegion::boundary() const {
    std::size_t boundary_size = 0;
    Edge first;
    for (FaceIndex f : faces_)
        for (int i = 0; i < 3; ++i)
            if (!contains(tds_.face(f).n[i])) {
                ++boundary_size;
                if (first.face.is_none()) first = {f, i};
            }
    // From each boundary edge, turn clockwise around its end vertex through
    // region faces to the next boundary edge.
    std::vector<Edge> boundary{first};
    for (;;) {
        Edge e{boundary.back().face, ccw(boundary.back().index)};
        std::size_t guard = 0;
        while (contains(tds_.neighbor(e))) {
            const Edge across = tds_.mirror_edge(e);
            e = {across.face, ccw(across.index)};
            if (++guard > 4 * tds_.number_of_faces()) throw Error("conflict region walk does not close (internal error)");
        }
        if (e == first) break;
        boundary.push_back(e);
        if (boundary.size() > boundary_size) break;
    }
    if (boundary.size() != boundary_size)
        throw Error("the conflict region of site " + std::to_string(p_) + " is not a disk (internal error)");
    return boundary;
}

void ConflictRegion::check_inner_vertices(const std::vector<Edge>& boundary, const std::vector<VertexIndex>& hidden) {
    std::set<VertexIndex> on_boundary;
    for (const Edge& e : boundary) on_boundary.insert(tds_.face(e.face).v[ccw(e.index)]);
    for (FaceIndex f : faces_)
        for (VertexIndex v : tds_.face(f).v)
            if (!on_boundary.count(v) && !hides(v))
                throw Error("site " + std::to_string(predicates_.site(v)) + " would vanish inserting site " +
                            std::to_string(p_) + " (internal error)");
    for (VertexIndex v : hidden)
        if (on_boundary.count(v))
            throw Error("hidden site " + std::to_string(predicates_.site(v)) + " stays on the conflict boundary of site " +
                        std::to_string(p_) + " (internal error)");
}

}  // namespace ellvor
