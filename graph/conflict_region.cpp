#include "graph/conflict_region.hpp"

#include "util/error.hpp"

#include <algorithm>
#include <string>

namespace ellvor {

void ConflictMarks::start() {
    // After 2^16 regions the generations wrap: blank everything once (16
    // bits: an entry of 8 bytes a face, not 12; 2n faces blanked every 65536
    // insertions cost nothing).
    if (++generation_ == 0) {
        faces_.assign(faces_.size(), Face{});
        vertices_.assign(vertices_.size(), Vertex{});
        generation_ = 1;
    }
}

template <class Entry>
Entry& ConflictMarks::entry(std::vector<Entry>& entries, int index) {
    const auto i = static_cast<std::size_t>(index);
    if (i >= entries.size()) entries.resize(i + 1);  // amortized: the capacity grows geometrically
    Entry& e = entries[i];
    if (e.generation != generation_) {
        e = Entry{};
        e.generation = generation_;
    }
    return e;
}

ConflictMarks::Face& ConflictMarks::face(FaceIndex f) { return entry(faces_, f.value()); }
ConflictMarks::Vertex& ConflictMarks::vertex(VertexIndex v) { return entry(vertices_, v.value()); }

const ConflictMarks::Face* ConflictMarks::find(FaceIndex f) const {
    const auto i = static_cast<std::size_t>(f.value());
    return i < faces_.size() && faces_[i].generation == generation_ ? &faces_[i] : nullptr;
}

ConflictRegion::ConflictRegion(const Triangulation& tds, TriangulationPredicates predicates, SiteId p,
                               ConflictMarks& marks)
    : tds_(tds), predicates_(predicates), p_(p), marks_(marks) {
    marks_.start();
}

bool ConflictRegion::in_conflict(FaceIndex f) {
    ConflictMarks::Face& m = marks_.face(f);
    if (m.incircle == ConflictMarks::kUnknown) m.incircle = static_cast<signed char>(to_int(predicates_.incircle(f, p_)));
    return m.incircle < 0;
}

bool ConflictRegion::hides(VertexIndex v) {
    if (v == Triangulation::kInfiniteVertex) return false;
    ConflictMarks::Vertex& m = marks_.vertex(v);
    if (m.hidden == ConflictMarks::kUnknown) {
        m.hidden = predicates_.is_hidden(p_, predicates_.site(v));
        if (m.hidden) hidden_.push_back(v);
    }
    return m.hidden;
}

void ConflictRegion::expand(FaceIndex start) {
    faces_ = {start};
    marks_.face(start).in_region = true;
    // faces_ is the breadth-first queue: faces [next, end) are still to visit.
    for (std::size_t next = 0; next < faces_.size(); ++next) {
        const FaceIndex f = faces_[next];
        for (int i = 0; i < 3; ++i) {
            if (marks_.face(f).crossed[i] != ConflictMarks::kUntested) continue;
            const Edge e{f, i};
            const Edge across = tds_.mirror_edge(e);
            // Every face around a hidden vertex is in conflict.
            const bool h1 = hides(tds_.face(f).v[ccw(i)]);
            const bool h2 = hides(tds_.face(f).v[cw(i)]);
            const bool pass = h1 || h2 || (in_conflict(across.face) && predicates_.edge_interior_of_visible(e, p_, true));
            marks_.face(f).crossed[i] = pass;
            ConflictMarks::Face& other = marks_.face(across.face);
            other.crossed[across.index] = pass;
            if (pass && !other.in_region) {
                other.in_region = true;
                faces_.push_back(across.face);
            }
        }
    }
    find_swallowed_vertices();
}

// A vertex is examined only when both of its edges in some region face were
// crossed (cheap, from the marks: most vertices of the region are on its
// boundary and fail it), and its site must cross p: a site whose cell p
// empties does not contain p (that would hide p) and shares points with it
// (p has no say where it is absent).
void ConflictRegion::find_swallowed_vertices() {
    swallowed_.clear();
    for (FaceIndex f : faces_)
        for (int k = 0; k < 3; ++k) {
            const VertexIndex v = tds_.face(f).v[k];
            const ConflictMarks::Face& mf = *marks_.find(f);
            if (v == Triangulation::kInfiniteVertex || mf.crossed[ccw(k)] != 1 || mf.crossed[cw(k)] != 1) continue;
            ConflictMarks::Vertex& m = marks_.vertex(v);
            if (m.swallowed != ConflictMarks::kUnknown) continue;
            m.swallowed = !hides(v) && every_edge_around_crossed(v) && predicates_.crosses(p_, predicates_.site(v));
            if (m.swallowed) swallowed_.push_back(v);
        }
    std::sort(swallowed_.begin(), swallowed_.end());
}

bool ConflictRegion::every_edge_around_crossed(VertexIndex v) const {
    // Around v as Triangulation::incident_faces turns, without its vector:
    // this runs in every insertion.
    const FaceIndex start = tds_.vertex(v).face;
    FaceIndex f = start;
    std::size_t guard = 0;
    do {
        const ConflictMarks::Face* m = marks_.find(f);
        if (!m || !m->in_region) return false;
        const int k = tds_.index(f, v);
        if (m->crossed[ccw(k)] != 1 || m->crossed[cw(k)] != 1) return false;
        f = tds_.face(f).n[ccw(k)];
        if (++guard > tds_.number_of_faces()) throw Error("conflict region: the faces around a vertex do not close (internal error)");
    } while (f != start);
    return true;
}

std::vector<VertexIndex> ConflictRegion::hidden_vertices() const {
    std::vector<VertexIndex> out = hidden_;
    std::sort(out.begin(), out.end());
    return out;
}

std::vector<VertexIndex> ConflictRegion::vanishing_vertices() const {
    std::vector<VertexIndex> out = hidden_vertices();
    out.insert(out.end(), swallowed_.begin(), swallowed_.end());
    std::sort(out.begin(), out.end());
    return out;
}

std::vector<Edge> ConflictRegion::self_touching_edges() const {
    std::vector<Edge> out;
    for (FaceIndex f : faces_)
        for (int i = 0; i < 3; ++i) {
            if (marks_.find(f)->crossed[i] != 0) continue;  // the growth crossed it
            const Edge e{f, i};
            const Edge across = tds_.mirror_edge(e);
            if (contains(across.face) && e < across) out.push_back(e);
        }
    std::sort(out.begin(), out.end());
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

void ConflictRegion::check_inner_vertices(const std::vector<Edge>& boundary, const std::vector<VertexIndex>& vanishing) {
    for (const Edge& e : boundary) marks_.vertex(tds_.face(e.face).v[ccw(e.index)]).on_boundary = true;
    for (FaceIndex f : faces_)
        for (VertexIndex v : tds_.face(f).v)
            if (!marks_.vertex(v).on_boundary && !hides(v) && marks_.vertex(v).swallowed != 1)
                throw Error("site " + std::to_string(predicates_.site(v)) + " would vanish inserting site " +
                            std::to_string(p_) + " (internal error)");
    for (VertexIndex v : vanishing)
        if (marks_.vertex(v).on_boundary)
            throw Error("hidden site " + std::to_string(predicates_.site(v)) + " stays on the conflict boundary of site " +
                        std::to_string(p_) + " (internal error)");
}

}  // namespace ellvor
