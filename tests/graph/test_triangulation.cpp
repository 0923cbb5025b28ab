// The triangulation data structure alone, without geometry: the sites are
// plain labels. Every operation the insertion uses, on small structures
// whose faces can be listed by hand, with check() after each; check() itself
// on structures corrupted through the public operations; and the
// degenerate faces a degree-2 vertex makes (an edge whose mirror vertex is
// the face's own opposite vertex).
#include "graph/triangulation.hpp"

#include "util/error.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <set>
#include <type_traits>
#include <vector>

using namespace ellvor;

namespace {

// The index types are not interchangeable, and no int becomes one silently.
static_assert(!std::is_convertible_v<FaceIndex, VertexIndex>);
static_assert(!std::is_convertible_v<VertexIndex, FaceIndex>);
static_assert(!std::is_convertible_v<int, VertexIndex>);
static_assert(!std::is_convertible_v<int, FaceIndex>);

constexpr SiteId kA = 10, kB = 11, kC = 12, kD = 13, kE = 14;

FaceIndex finite_face(const Triangulation& t) {
    for (FaceIndex f : t.faces())
        if (!t.is_infinite_face(f)) return f;
    FAIL("no finite face");
    return FaceIndex();
}

// The vertices around v, in the order of incident_faces: each face's vertex
// after v (counter-clockwise in that face).
std::vector<VertexIndex> neighbours(const Triangulation& t, VertexIndex v) {
    std::vector<VertexIndex> out;
    for (FaceIndex f : t.incident_faces(v)) out.push_back(t.face(f).v[ccw(t.index(f, v))]);
    return out;
}

// a, b, c as a cyclic sequence: some rotation of `want` equals `got`.
bool same_cycle(std::vector<VertexIndex> got, const std::vector<VertexIndex>& want) {
    for (std::size_t k = 0; k < got.size(); ++k) {
        if (got == want) return true;
        std::rotate(got.begin(), got.begin() + 1, got.end());
    }
    return false;
}

// Invariants that check() does not spell out: mirror_edge is an involution
// that keeps the edge's endpoints (reversed); consecutive faces around a
// vertex share the edge from the vertex to its next neighbour.
void check_local_structure(const Triangulation& t) {
    REQUIRE(t.check() == "");
    for (FaceIndex f : t.faces())
        for (int i = 0; i < 3; ++i) {
            const Edge e{f, i}, m = t.mirror_edge(e);
            CHECK(t.mirror_edge(m) == e);
            CHECK(t.face(m.face).v[ccw(m.index)] == t.face(f).v[cw(i)]);
            CHECK(t.face(m.face).v[cw(m.index)] == t.face(f).v[ccw(i)]);
            CHECK(t.mirror_vertex(e) == t.face(m.face).v[m.index]);
        }
    std::vector<VertexIndex> all = t.finite_vertices();
    all.push_back(Triangulation::kInfiniteVertex);
    for (VertexIndex v : all) {
        const std::vector<FaceIndex> around = t.incident_faces(v);
        for (std::size_t k = 0; k < around.size(); ++k) {
            const FaceIndex f = around[k], g = around[(k + 1) % around.size()];
            const VertexIndex shared = t.face(f).v[cw(t.index(f, v))];
            CHECK(t.face(g).v[ccw(t.index(g, v))] == shared);
        }
    }
}

}  // namespace

TEST_CASE("Triangulation: an empty structure holds the infinite vertex only", "[graph][triangulation]") {
    Triangulation t;
    CHECK(t.empty());
    CHECK(t.number_of_vertices() == 1);
    CHECK(t.number_of_faces() == 0);
    CHECK(t.finite_vertices().empty());
    CHECK(t.vertex(Triangulation::kInfiniteVertex).site() == Triangulation::kInfiniteSite);
    CHECK(t.check() == "");
}

TEST_CASE("Triangulation: make_tetrahedron", "[graph][triangulation]") {
    Triangulation t;
    const auto v = t.make_tetrahedron(kA, kB, kC);
    check_local_structure(t);
    CHECK(t.number_of_vertices() == 4);
    CHECK(t.number_of_faces() == 4);
    CHECK(t.vertex(v[0]).site() == kA);
    CHECK(t.vertex(v[1]).site() == kB);
    CHECK(t.vertex(v[2]).site() == kC);
    // One finite face, (a, b, c) counter-clockwise; three infinite ones.
    const FaceIndex f = finite_face(t);
    CHECK(same_cycle({t.face(f).v.begin(), t.face(f).v.end()}, {v[0], v[1], v[2]}));
    CHECK(t.faces().size() == 4);
    // Counter-clockwise around a: b, c, then the infinite vertex.
    CHECK(same_cycle(neighbours(t, v[0]), {v[1], v[2], Triangulation::kInfiniteVertex}));
    CHECK(same_cycle(neighbours(t, Triangulation::kInfiniteVertex), {v[1], v[0], v[2]}));
    CHECK_THROWS_AS(t.make_tetrahedron(kA, kB, kC), Error);
    t.clear();
    CHECK(t.empty());
    CHECK(t.number_of_vertices() == 1);
    CHECK(t.check() == "");
}

TEST_CASE("Triangulation: flip, and back", "[graph][triangulation]") {
    Triangulation t;
    const auto v = t.make_tetrahedron(kA, kB, kC);
    const VertexIndex a = v[0], b = v[1], c = v[2], inf = Triangulation::kInfiniteVertex;
    // The edge a -> b of the finite face: flipping it joins c and infinity.
    const FaceIndex f = finite_face(t);
    const Edge ab{f, t.index(f, c)};
    REQUIRE(t.face(f).v[ccw(ab.index)] == a);
    REQUIRE(t.mirror_vertex(ab) == inf);
    t.flip(ab);
    check_local_structure(t);
    CHECK(t.number_of_faces() == 4);
    CHECK(t.incident_faces(a).size() == 2);
    CHECK(t.incident_faces(b).size() == 2);
    CHECK(t.incident_faces(c).size() == 4);
    CHECK(t.incident_faces(inf).size() == 4);
    for (FaceIndex g : t.faces()) CHECK(t.is_infinite_face(g));  // no finite face is left
    // a now has degree 2: both its faces are (a, c, infinity). Across an
    // edge at a, the mirror vertex is the face's own opposite vertex: such an
    // edge joins two faces on the same three vertices and cannot be flipped.
    const FaceIndex fa = t.vertex(a).face;
    const Edge at_a{fa, ccw(t.index(fa, a))};
    CHECK(t.mirror_vertex(at_a) == t.face(fa).v[at_a.index]);
    CHECK_THROWS_AS(t.flip(at_a), Error);
    check_local_structure(t);
    // Flipping c -- infinity on b's side restores a -- b.
    const FaceIndex fb = t.vertex(b).face;
    const Edge c_inf{fb, t.index(fb, b)};
    REQUIRE(t.mirror_vertex(c_inf) != b);
    t.flip(c_inf);
    check_local_structure(t);
    for (VertexIndex x : {a, b, c, inf}) CHECK(t.incident_faces(x).size() == 3);
    const FaceIndex back = finite_face(t);
    CHECK(same_cycle({t.face(back).v.begin(), t.face(back).v.end()}, {a, b, c}));
}

TEST_CASE("Triangulation: insert_degree_2, remove_degree_2, mirror_index on degenerate faces",
          "[graph][triangulation]") {
    Triangulation t;
    const auto v = t.make_tetrahedron(kA, kB, kC);
    const VertexIndex a = v[0], b = v[1];
    const FaceIndex f = finite_face(t);
    const Edge ab{f, t.index(f, v[2])};
    const Edge across = t.mirror_edge(ab);
    const VertexIndex d = t.insert_degree_2(ab, kD);
    check_local_structure(t);
    CHECK(t.vertex(d).site() == kD);
    CHECK(t.number_of_vertices() == 5);
    CHECK(t.number_of_faces() == 6);
    // d sits between f and its former neighbour, in two faces on {a, b, d}.
    const std::vector<FaceIndex> around = t.incident_faces(d);
    REQUIRE(around.size() == 2);
    for (FaceIndex g : around) {
        const std::set<VertexIndex> corners(t.face(g).v.begin(), t.face(g).v.end());
        CHECK(corners == std::set<VertexIndex>{a, b, d});
    }
    CHECK(same_cycle(neighbours(t, d), {a, b}));
    CHECK(t.face(t.neighbor(ab)).v[t.mirror_index(ab)] == d);
    // Degenerate faces: across the edges at d, the mirror vertex is the
    // face's own opposite vertex; mirror_index still finds the right side.
    for (FaceIndex g : around)
        for (int i = 0; i < 3; ++i) {
            if (t.face(g).v[i] == d) continue;  // the edge a -- b
            const Edge e{g, i};
            CHECK(t.mirror_vertex(e) == t.face(g).v[i]);
            CHECK(t.neighbor(e) != g);
            CHECK(t.mirror_edge(t.mirror_edge(e)) == e);
        }
    CHECK_THROWS_AS(t.remove_degree_2(a), Error);  // degree 3
    t.remove_degree_2(d);
    check_local_structure(t);
    CHECK_FALSE(t.is_vertex(d));
    CHECK(t.number_of_vertices() == 4);
    CHECK(t.number_of_faces() == 4);
    CHECK(t.mirror_edge(ab) == across);  // f and its old neighbour are linked again
    // Two degree-2 vertices on the same edge, then removed in either order.
    const VertexIndex d1 = t.insert_degree_2(ab, kD);
    const VertexIndex d2 = t.insert_degree_2(ab, kE);
    check_local_structure(t);
    CHECK(t.number_of_faces() == 8);
    t.remove_degree_2(d1);
    check_local_structure(t);
    t.remove_degree_2(d2);
    check_local_structure(t);
    CHECK(t.mirror_edge(ab) == across);
}

TEST_CASE("Triangulation: star_hole", "[graph][triangulation]") {
    Triangulation t;
    const auto v = t.make_tetrahedron(kA, kB, kC);
    // The finite face as a hole: its three edges, counter-clockwise.
    const FaceIndex f = finite_face(t);
    const std::vector<Edge> triangle = {{f, 2}, {f, 0}, {f, 1}};
    const VertexIndex d = t.star_hole(kD, triangle, {f});
    check_local_structure(t);
    CHECK(t.number_of_vertices() == 5);
    CHECK(t.number_of_faces() == 6);
    CHECK(same_cycle(neighbours(t, d), {v[0], v[1], v[2]}));
    // The three faces around d as a hole: d is strictly inside and disappears.
    std::vector<Edge> boundary;
    const std::vector<FaceIndex> hole = t.incident_faces(d);
    for (FaceIndex g : hole) boundary.push_back({g, t.index(g, d)});
    const VertexIndex e = t.star_hole(kE, boundary, hole);
    check_local_structure(t);
    CHECK(t.number_of_vertices() == 5);
    CHECK(t.number_of_faces() == 6);
    CHECK(t.vertex(e).site() == kE);
    CHECK_FALSE(t.is_vertex(d));
    CHECK(same_cycle(neighbours(t, e), {v[0], v[1], v[2]}));
    // A boundary that is not a cycle is refused before anything changes.
    const FaceIndex g = t.vertex(e).face;
    const std::vector<Edge> broken = {{g, t.index(g, e)}, {g, t.index(g, e)}, {g, t.index(g, e)}};
    CHECK_THROWS_AS(t.star_hole(kD, broken, {g}), Error);
    CHECK_THROWS_AS(t.star_hole(kD, {{g, 0}}, {g}), Error);
    check_local_structure(t);
}

TEST_CASE("Triangulation: add_vertex and delete_vertex", "[graph][triangulation]") {
    Triangulation t;
    t.make_tetrahedron(kA, kB, kC);
    const VertexIndex x = t.add_vertex(kD);
    CHECK(t.number_of_vertices() == 5);
    CHECK(t.check() == "vertex " + std::to_string(x.value()) + ": bad face pointer");  // no face yet
    t.delete_vertex(x);
    CHECK(t.number_of_vertices() == 4);
    CHECK(t.check() == "");
    CHECK_THROWS_AS(t.delete_vertex(x), Error);                          // twice
    CHECK_THROWS_AS(t.delete_vertex(Triangulation::kInfiniteVertex), Error);
    CHECK_THROWS_AS(t.delete_vertex(VertexIndex(1000)), Error);          // never existed
    CHECK(t.add_vertex(kE) == x);                                        // the slot is reused
}

TEST_CASE("Triangulation: check() catches corrupted structures", "[graph][triangulation]") {
    {  // a vertex deleted while faces still use it
        Triangulation t;
        const auto v = t.make_tetrahedron(kA, kB, kC);
        t.delete_vertex(v[1]);
        CHECK_THAT(t.check(), Catch::Matchers::EndsWith(": dead vertex"));
    }
    {  // a hole given without its face: the face stays, its neighbours point to the fan
        Triangulation t;
        t.make_tetrahedron(kA, kB, kC);
        const FaceIndex f = finite_face(t);
        t.star_hole(kD, {{f, 2}, {f, 0}, {f, 1}}, {});
        CHECK_THAT(t.check(), Catch::Matchers::EndsWith(": neighbour not mutual"));
    }
    {  // a degree-2 vertex deleted without removing its two faces
        Triangulation t;
        const auto v = t.make_tetrahedron(kA, kB, kC);
        const FaceIndex f = finite_face(t);
        const VertexIndex d = t.insert_degree_2({f, t.index(f, v[2])}, kD);
        REQUIRE(t.check() == "");
        t.delete_vertex(d);
        CHECK(t.check() != "");
    }
}

TEST_CASE("Triangulation: a vertex keeps its site id in 32 bits, the two labels apart", "[graph][triangulation]") {
    Triangulation t;
    const VertexIndex big = t.add_vertex(Triangulation::kMaxSite), zero = t.add_vertex(0);
    const VertexIndex bogus = t.add_vertex(Triangulation::kBogusSite), inf = t.add_vertex(Triangulation::kInfiniteSite);
    CHECK(t.vertex(big).site() == Triangulation::kMaxSite);
    CHECK(t.vertex(zero).site() == 0);
    CHECK(t.vertex(bogus).site() == Triangulation::kBogusSite);
    CHECK(t.vertex(inf).site() == Triangulation::kInfiniteSite);
    CHECK(t.vertex(Triangulation::kInfiniteVertex).site() == Triangulation::kInfiniteSite);
    CHECK_THROWS_AS(t.add_vertex(Triangulation::kMaxSite + 1), Error);
    CHECK_THROWS_AS(t.add_vertex(SiteId{1} << 40), Error);
    for (VertexIndex v : {big, zero, bogus, inf}) CHECK(t.is_vertex(v));
    t.delete_vertex(zero);
    CHECK(!t.is_vertex(zero));
    CHECK(t.is_vertex(big));
}
