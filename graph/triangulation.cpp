#include "graph/triangulation.hpp"

#include "util/error.hpp"

#include <set>

namespace ellvor {

void Triangulation::clear() {
    vertices_.assign(1, Vertex{kInfiniteSite, -1, true});
    faces_.clear();
    free_faces_.clear();
    free_vertices_.clear();
    number_of_faces_ = 0;
    number_of_vertices_ = 1;
}

int Triangulation::add_vertex(long site) {
    int v;
    if (!free_vertices_.empty()) {
        v = free_vertices_.back();
        free_vertices_.pop_back();
    } else {
        v = static_cast<int>(vertices_.size());
        vertices_.emplace_back();
    }
    vertices_[v] = Vertex{site, -1, true};
    ++number_of_vertices_;
    return v;
}

void Triangulation::delete_vertex(int v) {
    if (v == kInfinite || !vertices_[v].alive) throw Error("Triangulation: deleting an invalid vertex");
    vertices_[v].alive = false;
    vertices_[v].face = -1;
    free_vertices_.push_back(v);
    --number_of_vertices_;
}

int Triangulation::new_face(int a, int b, int c) {
    int f;
    if (!free_faces_.empty()) {
        f = free_faces_.back();
        free_faces_.pop_back();
    } else {
        f = static_cast<int>(faces_.size());
        faces_.emplace_back();
    }
    faces_[f] = Face{{{a, b, c}}, {{-1, -1, -1}}, true};
    ++number_of_faces_;
    return f;
}

void Triangulation::kill_face(int f) {
    faces_[f].alive = false;
    free_faces_.push_back(f);
    --number_of_faces_;
}

bool Triangulation::is_infinite_face(int f) const {
    const Face& F = faces_[f];
    return F.v[0] == kInfinite || F.v[1] == kInfinite || F.v[2] == kInfinite;
}

int Triangulation::index(int f, int v) const {
    for (int i = 0; i < 3; ++i)
        if (faces_[f].v[i] == v) return i;
    return -1;
}

int Triangulation::mirror_index(int f, int i) const {
    const int g = faces_[f].n[i];
    const int k = index(g, faces_[f].v[ccw(i)]);
    if (k < 0) throw Error("Triangulation: inconsistent neighbour");
    return ccw(k);
}

std::array<int, 3> Triangulation::make_tetrahedron(long a, long b, long c) {
    if (!empty()) throw Error("Triangulation::make_tetrahedron: not empty");
    const int va = add_vertex(a), vb = add_vertex(b), vc = add_vertex(c);
    const int I = kInfinite;
    const int f0 = new_face(va, vb, vc);  // finite
    const int f1 = new_face(vb, va, I);
    const int f2 = new_face(vc, vb, I);
    const int f3 = new_face(va, vc, I);
    // f0 edges: opp va = (vb,vc) ~ f2; opp vb = (vc,va) ~ f3; opp vc = (va,vb) ~ f1.
    link(f0, 0, f2, 2);
    link(f0, 1, f3, 2);
    link(f0, 2, f1, 2);
    // f1 = (vb, va, I): edge (va, I) ~ f3's (I, va); edge (I, vb) ~ f2's (vb, I);
    // f2 = (vc, vb, I): edge (I, vc) ~ f3's (vc, I).
    link(f1, 0, f3, 1);
    link(f1, 1, f2, 0);
    link(f2, 1, f3, 0);
    vertices_[I].face = f1;
    vertices_[va].face = f0;
    vertices_[vb].face = f0;
    vertices_[vc].face = f0;
    return {va, vb, vc};
}

void Triangulation::flip(int f, int i) {
    const int g = faces_[f].n[i], j = mirror_index(f, i);
    const int vi = faces_[f].v[i], a = faces_[f].v[ccw(i)], b = faces_[f].v[cw(i)], w = faces_[g].v[j];
    if (vi == w) throw Error("Triangulation::flip: an edge between repeated vertices cannot be flipped");
    const int x1 = faces_[f].n[ccw(i)], i1 = mirror_index(f, ccw(i));  // edge (b, vi)
    const int x2 = faces_[f].n[cw(i)], i2 = mirror_index(f, cw(i));    // edge (vi, a)
    const int x3 = faces_[g].n[ccw(j)], i3 = mirror_index(g, ccw(j));  // edge (a, w)
    const int x4 = faces_[g].n[cw(j)], i4 = mirror_index(g, cw(j));    // edge (w, b)
    if (x1 == f || x1 == g || x2 == f || x2 == g || x3 == f || x3 == g || x4 == f || x4 == g)
        throw Error("Triangulation::flip: unsupported configuration");
    faces_[f].v = {vi, a, w};
    faces_[g].v = {w, b, vi};
    link(f, 0, x3, i3);
    link(f, 1, g, 1);
    link(f, 2, x2, i2);
    link(g, 0, x1, i1);
    link(g, 2, x4, i4);
    vertices_[vi].face = f;
    vertices_[a].face = f;
    vertices_[w].face = f;
    vertices_[b].face = g;
}

int Triangulation::insert_degree_2(int f, int i, long site) {
    const int g = faces_[f].n[i], j = mirror_index(f, i);
    const int a = faces_[f].v[ccw(i)], b = faces_[f].v[cw(i)];
    const int v = add_vertex(site);
    const int f1 = new_face(b, a, v);
    const int f2 = new_face(a, b, v);
    link(f1, 0, f2, 1);
    link(f1, 1, f2, 0);
    link(f1, 2, f, i);
    link(f2, 2, g, j);
    vertices_[v].face = f1;
    return v;
}

void Triangulation::remove_degree_2(int v) {
    const int f1 = vertices_[v].face, k1 = index(f1, v);
    const int f2 = faces_[f1].n[ccw(k1)];
    if (faces_[f1].n[cw(k1)] != f2) throw Error("Triangulation::remove_degree_2: vertex degree is not 2");
    const int k2 = index(f2, v);
    const int x = faces_[f1].n[k1], xi = mirror_index(f1, k1);
    const int y = faces_[f2].n[k2], yi = mirror_index(f2, k2);
    link(x, xi, y, yi);
    vertices_[faces_[f1].v[ccw(k1)]].face = x;
    vertices_[faces_[f1].v[cw(k1)]].face = x;
    kill_face(f1);
    kill_face(f2);
    delete_vertex(v);
}

int Triangulation::star_hole(long site, const std::vector<Edge>& boundary, const std::vector<int>& hole) {
    const std::size_t m = boundary.size();
    if (m < 2) throw Error("Triangulation::star_hole: boundary too short");
    struct Outer {
        int a, b, g, j;
    };
    std::vector<Outer> outer(m);
    for (std::size_t k = 0; k < m; ++k) {
        const auto [f, i] = boundary[k];
        outer[k] = {faces_[f].v[ccw(i)], faces_[f].v[cw(i)], faces_[f].n[i], mirror_index(f, i)};
    }
    for (std::size_t k = 0; k < m; ++k)
        if (outer[k].b != outer[(k + 1) % m].a) throw Error("Triangulation::star_hole: boundary is not a cycle");
    // Vertices of the hole that are not on its boundary disappear.
    std::set<int> on_boundary;
    for (const Outer& o : outer) on_boundary.insert(o.a);
    std::set<int> inner;
    for (int f : hole)
        for (int x : faces_[f].v)
            if (!on_boundary.count(x)) inner.insert(x);
    for (int f : hole) kill_face(f);
    const int v = add_vertex(site);
    std::vector<int> fan(m);
    for (std::size_t k = 0; k < m; ++k) {
        fan[k] = new_face(outer[k].a, outer[k].b, v);
        link(fan[k], 2, outer[k].g, outer[k].j);
        vertices_[outer[k].a].face = fan[k];
    }
    for (std::size_t k = 0; k < m; ++k) link(fan[k], 0, fan[(k + 1) % m], 1);
    vertices_[v].face = fan[0];
    for (int x : inner) delete_vertex(x);
    return v;
}

std::vector<int> Triangulation::incident_faces(int v) const {
    std::vector<int> out;
    const int start = vertices_[v].face;
    int f = start;
    do {
        out.push_back(f);
        const int k = index(f, v);
        if (k < 0) throw Error("Triangulation: vertex not in its face");
        f = faces_[f].n[ccw(k)];
        if (out.size() > faces_.size()) throw Error("Triangulation: circulator does not close");
    } while (f != start);
    return out;
}

std::string Triangulation::check() const {
    std::size_t faces = 0;
    for (std::size_t f = 0; f < faces_.size(); ++f) {
        const Face& F = faces_[f];
        if (!F.alive) continue;
        ++faces;
        const std::string name = "face " + std::to_string(f);
        for (int i = 0; i < 3; ++i) {
            if (F.v[i] < 0 || F.v[i] >= static_cast<int>(vertices_.size()) || !vertices_[F.v[i]].alive)
                return name + ": dead vertex";
            if (F.v[i] == F.v[ccw(i)]) return name + ": repeated vertex";
            const int g = F.n[i];
            if (g < 0 || g >= static_cast<int>(faces_.size()) || !faces_[g].alive) return name + ": dead neighbour";
            const int k = index(g, F.v[ccw(i)]);
            if (k < 0) return name + ": neighbour does not share the edge";
            const int j = ccw(k);
            if (faces_[g].n[j] != static_cast<int>(f)) return name + ": neighbour not mutual";
            if (faces_[g].v[ccw(j)] != F.v[cw(i)]) return name + ": neighbour edge mismatch";
        }
    }
    if (faces != number_of_faces_) return "face count mismatch";
    std::size_t vertices = 0, degree_sum = 0;
    for (std::size_t v = 0; v < vertices_.size(); ++v) {
        if (!vertices_[v].alive) continue;
        ++vertices;
        const int f = vertices_[v].face;
        if (f < 0 || !faces_[f].alive || index(f, static_cast<int>(v)) < 0)
            return "vertex " + std::to_string(v) + ": bad face pointer";
        degree_sum += incident_faces(static_cast<int>(v)).size();
    }
    if (vertices != number_of_vertices_) return "vertex count mismatch";
    if (degree_sum != 3 * faces) return "circulators do not visit every face corner";
    if (faces % 2 != 0) return "odd number of faces";
    const std::size_t edges = 3 * faces / 2;
    if (vertices + faces != edges + 2) return "Euler characteristic is not 2";
    return "";
}

}  // namespace ellvor
