// Indices into the triangulation's vertices and faces as distinct types, so
// that a face can never be passed where a vertex is expected; and an edge,
// CGAL's (face, i): the edge of the face opposite its vertex i. The index of
// a vertex or neighbour within a face (0, 1, 2) stays an int, turned by ccw/cw.
#pragma once

#include <tuple>

namespace ellvor {

inline int ccw(int i) { return (i + 1) % 3; }
inline int cw(int i) { return (i + 2) % 3; }

template <class Tag>
class TriangulationIndex {
public:
    constexpr TriangulationIndex() = default;  // none
    constexpr explicit TriangulationIndex(int value) : value_(value) {}

    constexpr int value() const { return value_; }
    constexpr bool is_none() const { return value_ < 0; }

    friend constexpr bool operator==(TriangulationIndex a, TriangulationIndex b) { return a.value_ == b.value_; }
    friend constexpr bool operator!=(TriangulationIndex a, TriangulationIndex b) { return a.value_ != b.value_; }
    friend constexpr bool operator<(TriangulationIndex a, TriangulationIndex b) { return a.value_ < b.value_; }

private:
    int value_ = -1;
};

using VertexIndex = TriangulationIndex<struct VertexIndexTag>;
using FaceIndex = TriangulationIndex<struct FaceIndexTag>;

struct Edge {
    FaceIndex face;
    int index = 0;  // the edge is opposite face's vertex `index`

    friend bool operator==(const Edge& a, const Edge& b) { return a.face == b.face && a.index == b.index; }
    friend bool operator!=(const Edge& a, const Edge& b) { return !(a == b); }
    friend bool operator<(const Edge& a, const Edge& b) {
        return std::tie(a.face, a.index) < std::tie(b.face, b.index);
    }
};

}  // namespace ellvor
