// A compact triangulation data structure of the sphere (CGAL TDS style, our
// own): vertex 0 is the infinite vertex; every face holds 3 vertex indices
// and 3 neighbour indices, counter-clockwise, neighbour i opposite vertex i.
// Edge (f, i) is the edge of f opposite its vertex i, from f.v[ccw(i)] to
// f.v[cw(i)] (f on its left).
//
// Degenerate faces are legal (research digest section 4.1): a vertex may have
// degree 2, and two faces may share all three vertices (or two edges). So the
// neighbour across an edge is found through vertex identities (mirror_index),
// never by searching for a face pointer.
//
// Only dimension 2 is stored (>= 3 finite vertices); the graph keeps the
// smaller cases (0, 1, 2 sites) itself.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace ellvor {

inline int ccw(int i) { return (i + 1) % 3; }
inline int cw(int i) { return (i + 2) % 3; }

class Triangulation {
public:
    static constexpr long kInfiniteSite = -1;
    static constexpr int kInfinite = 0;  // index of the infinite vertex

    struct Vertex {
        long site = kInfiniteSite;  // site id; kInfiniteSite for the infinite vertex
        int face = -1;              // one incident face
        bool alive = false;
    };
    struct Face {
        std::array<int, 3> v{{-1, -1, -1}};
        std::array<int, 3> n{{-1, -1, -1}};
        bool alive = false;
    };
    using Edge = std::pair<int, int>;  // (face, index)

    Triangulation() { clear(); }
    // Back to the infinite vertex alone, no faces.
    void clear();

    bool empty() const { return number_of_faces_ == 0; }
    int add_vertex(long site);
    // The tetrahedron on the infinite vertex and three new vertices, with the
    // finite face (a, b, c) counter-clockwise. Requires empty().
    std::array<int, 3> make_tetrahedron(long a, long b, long c);

    // Flip the edge (f, i): the two faces (v_i, a, b), (w, b, a) become
    // (v_i, a, w), (w, b, v_i). The caller checks that f.v[i] != mirror vertex.
    void flip(int f, int i);
    // Split edge (f, i) with a new vertex of degree 2 (two new faces with the
    // edge's endpoints and the new vertex). Returns the new vertex.
    int insert_degree_2(int f, int i, long site);
    // Inverse of insert_degree_2.
    void remove_degree_2(int v);
    // Replace the faces `hole` (a topological disk) by a fan around a new
    // vertex: `boundary` lists the hole's boundary edges (f, i), f in the hole,
    // counter-clockwise (each edge's end is the next edge's start). Vertices
    // strictly inside the hole are deleted. Returns the new vertex.
    int star_hole(long site, const std::vector<Edge>& boundary, const std::vector<int>& hole);
    void delete_vertex(int v);

    const Vertex& vertex(int v) const { return vertices_[v]; }
    const Face& face(int f) const { return faces_[f]; }
    std::size_t vertex_capacity() const { return vertices_.size(); }
    std::size_t face_capacity() const { return faces_.size(); }
    std::size_t number_of_faces() const { return number_of_faces_; }
    std::size_t number_of_vertices() const { return number_of_vertices_; }  // the infinite one included

    bool is_infinite_face(int f) const;
    bool is_infinite_edge(int f, int i) const {
        return faces_[f].v[ccw(i)] == kInfinite || faces_[f].v[cw(i)] == kInfinite;
    }
    // Index of vertex v in face f, or -1.
    int index(int f, int v) const;
    int mirror_index(int f, int i) const;
    int mirror_vertex(int f, int i) const { return faces_[faces_[f].n[i]].v[mirror_index(f, i)]; }
    // Faces around v, counter-clockwise, starting at v's face.
    std::vector<int> incident_faces(int v) const;

    // Combinatorial consistency (neighbours mutual, vertex faces, Euler,
    // 2E = 3F, circulators close). Returns "" if valid, else a description.
    std::string check() const;

private:
    int new_face(int a, int b, int c);
    void kill_face(int f);
    void link(int f, int i, int g, int j) {
        faces_[f].n[i] = g;
        faces_[g].n[j] = f;
    }

    std::vector<Vertex> vertices_;
    std::vector<Face> faces_;
    std::vector<int> free_faces_, free_vertices_;
    std::size_t number_of_faces_ = 0, number_of_vertices_ = 0;
};

}  // namespace ellvor
