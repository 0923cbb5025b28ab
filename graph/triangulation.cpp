#include "graph/triangulation.hpp"

#include "util/error.hpp"

#include <algorithm>

namespace ellvor {

void Triangulation::clear() {
    vertices_.assign(1, Vertex{kStoredInfinite, FaceIndex()});
    vertex_alive_.assign(1, true);
    faces_.clear();
    face_alive_.clear();
    free_faces_.clear();
    free_vertices_.clear();
    number_of_faces_ = 0;
    number_of_vertices_ = 1;
}

void Triangulation::reserve(std::size_t vertices, std::size_t faces) {
    vertices_.reserve(vertices);
    vertex_alive_.reserve(vertices);
    faces_.reserve(faces);
    face_alive_.reserve(faces);
}

VertexIndex Triangulation::add_vertex(SiteId site) {
    if (site > kMaxSite && site != kInfiniteSite && site != kBogusSite)
        throw Error("Triangulation: site id " + std::to_string(site) + " above the largest a vertex holds");
    VertexIndex v;
    if (!free_vertices_.empty()) {
        v = free_vertices_.back();
        free_vertices_.pop_back();
    } else {
        v = VertexIndex(static_cast<int>(vertices_.size()));
        vertices_.emplace_back();
        vertex_alive_.push_back(false);
    }
    const std::uint32_t stored = site == kInfiniteSite ? kStoredInfinite
                                 : site == kBogusSite  ? kStoredBogus
                                                       : static_cast<std::uint32_t>(site);
    vertex_at(v) = Vertex{stored, FaceIndex()};
    vertex_alive_[static_cast<std::size_t>(v.value())] = true;
    ++number_of_vertices_;
    return v;
}

void Triangulation::delete_vertex(VertexIndex v) {
    if (v == kInfiniteVertex || !is_vertex(v)) throw Error("Triangulation: deleting an invalid vertex");
    vertex_alive_[static_cast<std::size_t>(v.value())] = false;
    vertex_at(v).face = FaceIndex();
    free_vertices_.push_back(v);
    --number_of_vertices_;
}

FaceIndex Triangulation::new_face(VertexIndex a, VertexIndex b, VertexIndex c) {
    FaceIndex f;
    if (!free_faces_.empty()) {
        f = free_faces_.back();
        free_faces_.pop_back();
    } else {
        f = FaceIndex(static_cast<int>(faces_.size()));
        faces_.emplace_back();
        face_alive_.push_back(false);
    }
    face_at(f) = Face{{{a, b, c}}, {}};
    face_alive_[static_cast<std::size_t>(f.value())] = true;
    ++number_of_faces_;
    return f;
}

void Triangulation::kill_face(FaceIndex f) {
    face_alive_[static_cast<std::size_t>(f.value())] = false;
    free_faces_.push_back(f);
    --number_of_faces_;
}

std::vector<FaceIndex> Triangulation::faces() const {
    std::vector<FaceIndex> out;
    out.reserve(number_of_faces_);
    for (std::size_t f = 0; f < faces_.size(); ++f)
        if (face_alive_[f]) out.push_back(FaceIndex(static_cast<int>(f)));
    return out;
}

std::vector<VertexIndex> Triangulation::finite_vertices() const {
    std::vector<VertexIndex> out;
    out.reserve(number_of_vertices_ - 1);
    for (std::size_t v = 1; v < vertices_.size(); ++v)
        if (vertex_alive_[v]) out.push_back(VertexIndex(static_cast<int>(v)));
    return out;
}

bool Triangulation::is_infinite_face(FaceIndex f) const { return index(f, kInfiniteVertex) >= 0; }

int Triangulation::index(FaceIndex f, VertexIndex v) const {
    for (int i = 0; i < 3; ++i)
        if (face(f).v[i] == v) return i;
    return -1;
}

int Triangulation::mirror_index(Edge e) const {
    const int k = index(neighbor(e), face(e.face).v[ccw(e.index)]);
    if (k < 0) throw Error("Triangulation: inconsistent neighbour");
    return ccw(k);
}

std::array<VertexIndex, 3> Triangulation::make_tetrahedron(SiteId a, SiteId b, SiteId c) {
    if (!empty()) throw Error("Triangulation::make_tetrahedron: not empty");
    const VertexIndex va = add_vertex(a), vb = add_vertex(b), vc = add_vertex(c);
    const VertexIndex I = kInfiniteVertex;
    const FaceIndex f0 = new_face(va, vb, vc);  // finite
    const FaceIndex f1 = new_face(vb, va, I);
    const FaceIndex f2 = new_face(vc, vb, I);
    const FaceIndex f3 = new_face(va, vc, I);
    // f0 edges: opp va = (vb,vc) ~ f2; opp vb = (vc,va) ~ f3; opp vc = (va,vb) ~ f1.
    link(f0, 0, f2, 2);
    link(f0, 1, f3, 2);
    link(f0, 2, f1, 2);
    // f1 = (vb, va, I): edge (va, I) ~ f3's (I, va); edge (I, vb) ~ f2's (vb, I);
    // f2 = (vc, vb, I): edge (I, vc) ~ f3's (vc, I).
    link(f1, 0, f3, 1);
    link(f1, 1, f2, 0);
    link(f2, 1, f3, 0);
    vertex_at(I).face = f1;
    vertex_at(va).face = f0;
    vertex_at(vb).face = f0;
    vertex_at(vc).face = f0;
    return {va, vb, vc};
}

bool Triangulation::is_flippable(Edge e) const {
    const FaceIndex f = e.face, g = neighbor(e);
    const int j = mirror_index(e);
    if (face(f).v[e.index] == face(g).v[j]) return false;
    for (const Edge& x : {Edge{f, ccw(e.index)}, Edge{f, cw(e.index)}, Edge{g, ccw(j)}, Edge{g, cw(j)}})
        if (neighbor(x) == f || neighbor(x) == g) return false;
    return true;
}

void Triangulation::flip(Edge e) {
    const FaceIndex f = e.face, g = neighbor(e);
    const int i = e.index, j = mirror_index(e);
    const VertexIndex vi = face(f).v[i], a = face(f).v[ccw(i)], b = face(f).v[cw(i)], w = face(g).v[j];
    if (vi == w) throw Error("Triangulation::flip: an edge between repeated vertices cannot be flipped");
    if (!is_flippable(e)) throw Error("Triangulation::flip: unsupported configuration");
    const Edge x1 = mirror_edge({f, ccw(i)});  // edge (b, vi)
    const Edge x2 = mirror_edge({f, cw(i)});   // edge (vi, a)
    const Edge x3 = mirror_edge({g, ccw(j)});  // edge (a, w)
    const Edge x4 = mirror_edge({g, cw(j)});   // edge (w, b)
    face_at(f).v = {vi, a, w};
    face_at(g).v = {w, b, vi};
    link(f, 0, x3.face, x3.index);
    link(f, 1, g, 1);
    link(f, 2, x2.face, x2.index);
    link(g, 0, x1.face, x1.index);
    link(g, 2, x4.face, x4.index);
    vertex_at(vi).face = f;
    vertex_at(a).face = f;
    vertex_at(w).face = f;
    vertex_at(b).face = g;
}

VertexIndex Triangulation::insert_degree_2(Edge e, SiteId site) {
    const Edge across = mirror_edge(e);
    const VertexIndex a = face(e.face).v[ccw(e.index)], b = face(e.face).v[cw(e.index)];
    const VertexIndex v = add_vertex(site);
    const FaceIndex f1 = new_face(b, a, v);
    const FaceIndex f2 = new_face(a, b, v);
    link(f1, 0, f2, 1);
    link(f1, 1, f2, 0);
    link(f1, 2, e.face, e.index);
    link(f2, 2, across.face, across.index);
    vertex_at(v).face = f1;
    return v;
}

void Triangulation::remove_degree_2(VertexIndex v) {
    const FaceIndex f1 = vertex(v).face;
    const int k1 = index(f1, v);
    const FaceIndex f2 = face(f1).n[ccw(k1)];
    if (face(f1).n[cw(k1)] != f2) throw Error("Triangulation::remove_degree_2: vertex degree is not 2");
    const int k2 = index(f2, v);
    const Edge x = mirror_edge({f1, k1}), y = mirror_edge({f2, k2});
    link(x.face, x.index, y.face, y.index);
    vertex_at(face(f1).v[ccw(k1)]).face = x.face;
    vertex_at(face(f1).v[cw(k1)]).face = x.face;
    kill_face(f1);
    kill_face(f2);
    delete_vertex(v);
}

VertexIndex Triangulation::star_hole(SiteId site, const std::vector<Edge>& boundary, const std::vector<FaceIndex>& hole) {
    const std::size_t m = boundary.size();
    if (m < 2) throw Error("Triangulation::star_hole: boundary too short");
    // Each boundary edge from a to b, and the face outside it.
    struct Outer {
        VertexIndex a, b;
        Edge across;
    };
    std::vector<Outer> outer(m);
    for (std::size_t k = 0; k < m; ++k) {
        const Edge& e = boundary[k];
        outer[k] = {face(e.face).v[ccw(e.index)], face(e.face).v[cw(e.index)], mirror_edge(e)};
    }
    for (std::size_t k = 0; k < m; ++k)
        if (outer[k].b != outer[(k + 1) % m].a) throw Error("Triangulation::star_hole: boundary is not a cycle");
    // Vertices of the hole that are not on its boundary disappear (sorted
    // vectors: a hole has a handful of vertices).
    std::vector<VertexIndex> on_boundary;
    for (const Outer& o : outer) on_boundary.push_back(o.a);
    std::sort(on_boundary.begin(), on_boundary.end());
    std::vector<VertexIndex> inner;
    for (FaceIndex f : hole)
        for (VertexIndex x : face(f).v)
            if (!std::binary_search(on_boundary.begin(), on_boundary.end(), x)) inner.push_back(x);
    std::sort(inner.begin(), inner.end());
    inner.erase(std::unique(inner.begin(), inner.end()), inner.end());
    for (FaceIndex f : hole) kill_face(f);
    const VertexIndex v = add_vertex(site);
    std::vector<FaceIndex> fan(m);
    for (std::size_t k = 0; k < m; ++k) {
        fan[k] = new_face(outer[k].a, outer[k].b, v);
        link(fan[k], 2, outer[k].across.face, outer[k].across.index);
        vertex_at(outer[k].a).face = fan[k];
    }
    for (std::size_t k = 0; k < m; ++k) link(fan[k], 0, fan[(k + 1) % m], 1);
    vertex_at(v).face = fan[0];
    for (VertexIndex x : inner) delete_vertex(x);
    return v;
}

void Triangulation::replace_star(VertexIndex v, const std::vector<NewFace>& fill) {
    const std::vector<FaceIndex> star = incident_faces(v);
    const std::size_t m = star.size();
    std::vector<Edge> outside(m);
    std::vector<std::array<VertexIndex, 2>> link_ends(m);
    for (std::size_t k = 0; k < m; ++k) {
        const int j = index(star[k], v);
        outside[k] = mirror_edge({star[k], j});
        link_ends[k] = {face(star[k]).v[ccw(j)], face(star[k]).v[cw(j)]};
        if (index(outside[k].face, v) >= 0) throw Error("Triangulation::replace_star: the star touches itself");
    }
    std::vector<int> used(m, 0);
    for (std::size_t t = 0; t < fill.size(); ++t)
        for (int i = 0; i < 3; ++i) {
            const NewFace& F = fill[t];
            const std::array<VertexIndex, 2> ends = {F.v[ccw(i)], F.v[cw(i)]};
            if (F.face[i] < 0) {
                const std::size_t k = static_cast<std::size_t>(F.index[i]);
                if (k >= m || link_ends[k] != ends) throw Error("Triangulation::replace_star: a new face misses the link");
                ++used[k];
            } else {
                const NewFace& G = fill.at(static_cast<std::size_t>(F.face[i]));
                const int j = F.index[i];
                if (G.face[j] != static_cast<int>(t) || G.index[j] != i || G.v[ccw(j)] != ends[1] || G.v[cw(j)] != ends[0])
                    throw Error("Triangulation::replace_star: new faces not mutual");
            }
        }
    if (std::any_of(used.begin(), used.end(), [](int u) { return u != 1; }))
        throw Error("Triangulation::replace_star: the new faces do not cover the link once");
    for (FaceIndex f : star) kill_face(f);
    std::vector<FaceIndex> made;
    made.reserve(fill.size());
    for (const NewFace& F : fill) made.push_back(new_face(F.v[0], F.v[1], F.v[2]));
    for (std::size_t t = 0; t < fill.size(); ++t)
        for (int i = 0; i < 3; ++i) {
            const NewFace& F = fill[t];
            if (F.face[i] < 0) {
                const Edge& out = outside[static_cast<std::size_t>(F.index[i])];
                link(made[t], i, out.face, out.index);
            } else {
                link(made[t], i, made[static_cast<std::size_t>(F.face[i])], F.index[i]);
            }
            vertex_at(F.v[i]).face = made[t];
        }
    delete_vertex(v);
}

std::vector<FaceIndex> Triangulation::incident_faces(VertexIndex v) const {
    std::vector<FaceIndex> out;
    any_incident_face(v, [&](FaceIndex f) {
        out.push_back(f);
        return false;
    });
    return out;
}

void Triangulation::circulator_error(const char* what) { throw Error(what); }

std::string Triangulation::check() const {
    if (empty()) return number_of_vertices_ == 1 ? "" : "vertices without faces";
    std::size_t faces = 0;
    for (std::size_t fi = 0; fi < faces_.size(); ++fi) {
        const FaceIndex f(static_cast<int>(fi));
        const Face& F = face(f);
        if (!face_alive_[fi]) continue;
        ++faces;
        const std::string name = "face " + std::to_string(fi);
        for (int i = 0; i < 3; ++i) {
            if (!is_vertex(F.v[i])) return name + ": dead vertex";
            if (F.v[i] == F.v[ccw(i)]) return name + ": repeated vertex";
            const FaceIndex g = F.n[i];
            if (!is_face(g)) return name + ": dead neighbour";
            const int k = index(g, F.v[ccw(i)]);
            if (k < 0) return name + ": neighbour does not share the edge";
            const int j = ccw(k);
            if (face(g).n[j] != f) return name + ": neighbour not mutual";
            if (face(g).v[ccw(j)] != F.v[cw(i)]) return name + ": neighbour edge mismatch";
        }
    }
    if (faces != number_of_faces_) return "face count mismatch";
    std::size_t vertices = 0, degree_sum = 0;
    for (std::size_t vi = 0; vi < vertices_.size(); ++vi) {
        const VertexIndex v(static_cast<int>(vi));
        if (!vertex_alive_[vi]) continue;
        ++vertices;
        const FaceIndex f = vertex(v).face;
        if (!is_face(f) || index(f, v) < 0) return "vertex " + std::to_string(vi) + ": bad face pointer";
        degree_sum += incident_faces(v).size();
    }
    if (vertices != number_of_vertices_) return "vertex count mismatch";
    if (degree_sum != 3 * faces) return "circulators do not visit every face corner";
    if (faces % 2 != 0) return "odd number of faces";
    const std::size_t edges = 3 * faces / 2;
    if (vertices + faces != edges + 2) return "Euler characteristic is not 2";
    return "";
}

}  // namespace ellvor
