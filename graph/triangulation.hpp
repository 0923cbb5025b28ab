// A compact triangulation data structure of the sphere (CGAL TDS style, our
// own): one infinite vertex; every face holds 3 vertex indices and 3
// neighbour indices, counter-clockwise, neighbour i opposite vertex i. Edge
// (f, i) is the edge of f opposite its vertex i, from f.v[ccw(i)] to
// f.v[cw(i)] (f on its left).
//
// Degenerate faces are legal: a vertex may have degree 2 (a site whose cell
// lies inside one Voronoi edge), and two faces may share all three vertices
// (or two edges). So the neighbour across an edge is found through vertex
// identities (mirror_index), never by searching for a face index.
//
// Only dimension 2 is stored (>= 3 finite vertices); the graph keeps the
// smaller cases (0, 1, 2 sites) itself. No geometry: a vertex carries a site
// id as a label, nothing is asked about it.
#pragma once

#include "graph/triangulation_index.hpp"
#include "decision/site_id.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace ellvor {

class Triangulation {
public:
    // The labels of the vertices that stand for no site: the infinite vertex,
    // and the temporary degree-2 vertices that split an edge along which a
    // conflict region touches itself (CGAL's bogus vertices).
    static constexpr SiteId kInfiniteSite = std::numeric_limits<SiteId>::max();
    static constexpr SiteId kBogusSite = kInfiniteSite - 1;
    static constexpr VertexIndex kInfiniteVertex{0};

    // 8 bytes a vertex and 24 a face (a build holds about n and 2n): the
    // site id in 32 bits, and whether each is alive in a bit vector apart.
    struct Vertex {
        SiteId site() const {
            return site_ == kStoredInfinite ? kInfiniteSite : site_ == kStoredBogus ? kBogusSite : site_;
        }
        std::uint32_t site_ = kStoredInfinite;
        FaceIndex face;  // one incident face
    };
    struct Face {
        std::array<VertexIndex, 3> v;
        std::array<FaceIndex, 3> n;
    };
    // The largest site id a vertex can carry (above it, the two labels).
    static constexpr SiteId kMaxSite = std::numeric_limits<std::uint32_t>::max() - 2;

    Triangulation() { clear(); }
    // Back to the infinite vertex alone, no faces.
    void clear();
    // Room for this many vertices and faces in all (insert_all knows them).
    void reserve(std::size_t vertices, std::size_t faces);

    bool empty() const { return number_of_faces_ == 0; }
    // A vertex without faces (the caller links it).
    VertexIndex add_vertex(SiteId site);
    // The tetrahedron on the infinite vertex and three new vertices, with the
    // finite face (a, b, c) counter-clockwise. Requires empty().
    std::array<VertexIndex, 3> make_tetrahedron(SiteId a, SiteId b, SiteId c);

    // Flips edge e = (f, i): the faces (v_i, a, b) and (w, b, a) become
    // (v_i, a, w) and (w, b, v_i). Throws when v_i is the mirror vertex w.
    void flip(Edge e);
    // Splits edge e with a new vertex of degree 2 (two new faces with the
    // edge's endpoints and the new vertex). Returns the new vertex.
    VertexIndex insert_degree_2(Edge e, SiteId site);
    // Inverse of insert_degree_2.
    void remove_degree_2(VertexIndex v);
    // Replaces the faces `hole` (a topological disk) by a fan around a new
    // vertex: `boundary` lists the hole's boundary edges (f, i), f in the hole,
    // counter-clockwise (each edge's end is the next edge's start). Vertices
    // strictly inside the hole are deleted. Returns the new vertex.
    VertexIndex star_hole(SiteId site, const std::vector<Edge>& boundary, const std::vector<FaceIndex>& hole);
    // Frees a vertex; the caller has removed it from every face.
    void delete_vertex(VertexIndex v);

    // A face of the triangulation that replaces a vertex's star: its vertices,
    // and across each edge i either another new face (`face[i]`, its edge
    // `index[i]`) or, with face[i] = -1, the star's link edge at position
    // index[i].
    struct NewFace {
        std::array<VertexIndex, 3> v;
        std::array<int, 3> face, index;
    };
    // Deletes v and the faces around it (its star) and puts `fill` in their
    // place. The link of v is the cycle of the edges opposite v in its faces,
    // counter-clockwise from incident_faces(v).front() (position 0); each
    // link edge must be used once, by a new edge with the same endpoints, and
    // no link edge may have the star on both sides (split it first with
    // insert_degree_2). Throws Error otherwise, before changing anything.
    void replace_star(VertexIndex v, const std::vector<NewFace>& fill);
    // Edge e can be flipped: its two faces have distinct opposite vertices
    // and the four edges around them lie in other faces.
    bool is_flippable(Edge e) const;

    const Vertex& vertex(VertexIndex v) const { return vertices_[static_cast<std::size_t>(v.value())]; }
    const Face& face(FaceIndex f) const { return faces_[static_cast<std::size_t>(f.value())]; }
    bool is_vertex(VertexIndex v) const {
        return v.value() >= 0 && static_cast<std::size_t>(v.value()) < vertices_.size() &&
               vertex_alive_[static_cast<std::size_t>(v.value())];
    }
    // Every live face, by increasing index.
    std::vector<FaceIndex> faces() const;
    // Every live vertex but the infinite one, by increasing index.
    std::vector<VertexIndex> finite_vertices() const;
    std::size_t number_of_faces() const { return number_of_faces_; }
    std::size_t number_of_vertices() const { return number_of_vertices_; }  // the infinite one included

    bool is_infinite_face(FaceIndex f) const;
    bool is_infinite_edge(Edge e) const {
        const Face& F = face(e.face);
        return F.v[ccw(e.index)] == kInfiniteVertex || F.v[cw(e.index)] == kInfiniteVertex;
    }
    // Index of vertex v in face f, or -1.
    int index(FaceIndex f, VertexIndex v) const;
    FaceIndex neighbor(Edge e) const { return face(e.face).n[e.index]; }
    int mirror_index(Edge e) const;
    // The same edge seen from the neighbouring face.
    Edge mirror_edge(Edge e) const { return {neighbor(e), mirror_index(e)}; }
    VertexIndex mirror_vertex(Edge e) const { return face(neighbor(e)).v[mirror_index(e)]; }
    // Faces around v, counter-clockwise, starting at v's face.
    std::vector<FaceIndex> incident_faces(VertexIndex v) const;
    // The same faces in the same order, without a vector (the walk and the
    // first conflict ask this in every insertion): visit(f) until it returns
    // true; whether it did.
    template <class Visit>
    bool any_incident_face(VertexIndex v, Visit&& visit) const;

    // Combinatorial consistency (neighbours mutual, vertex faces, Euler,
    // 2E = 3F, circulators close); the infinite vertex alone is valid.
    // Returns "" if valid, else a description.
    std::string check() const;

private:
    Vertex& vertex_at(VertexIndex v) { return vertices_[static_cast<std::size_t>(v.value())]; }
    Face& face_at(FaceIndex f) { return faces_[static_cast<std::size_t>(f.value())]; }
    FaceIndex new_face(VertexIndex a, VertexIndex b, VertexIndex c);
    void kill_face(FaceIndex f);
    void link(FaceIndex f, int i, FaceIndex g, int j) {
        face_at(f).n[i] = g;
        face_at(g).n[j] = f;
    }

    [[noreturn]] static void circulator_error(const char* what);
    bool is_face(FaceIndex f) const {
        return f.value() >= 0 && static_cast<std::size_t>(f.value()) < faces_.size() &&
               face_alive_[static_cast<std::size_t>(f.value())];
    }

    static constexpr std::uint32_t kStoredInfinite = std::numeric_limits<std::uint32_t>::max();
    static constexpr std::uint32_t kStoredBogus = kStoredInfinite - 1;

    std::vector<Vertex> vertices_;
    std::vector<Face> faces_;
    std::vector<bool> vertex_alive_, face_alive_;
    std::vector<FaceIndex> free_faces_;
    std::vector<VertexIndex> free_vertices_;
    std::size_t number_of_faces_ = 0, number_of_vertices_ = 0;
};

template <class Visit>
bool Triangulation::any_incident_face(VertexIndex v, Visit&& visit) const {
    const FaceIndex start = vertex(v).face;
    FaceIndex f = start;
    std::size_t count = 0;
    do {
        if (visit(f)) return true;
        const int k = index(f, v);
        if (k < 0) circulator_error("Triangulation: vertex not in its face");
        f = face(f).n[ccw(k)];
        if (++count > faces_.size()) circulator_error("Triangulation: circulator does not close");
    } while (f != start);
    return false;
}

}  // namespace ellvor
