// ConflictMarks, the memo of one conflict region: entries made for one region
// read as blank in the next, whatever indices the triangulation reuses. (The
// regions themselves are checked through whole graphs: test_graph_vs_cgal,
// test_insertion_order, test_delaunay_graph.)
#include "graph/conflict_region.hpp"

#include <catch2/catch.hpp>

#include <random>
#include <vector>

using namespace ellvor;

TEST_CASE("ConflictMarks: entries belong to the region that made them", "[graph][conflict-region]") {
    ConflictMarks marks;
    marks.start();
    CHECK(marks.find(FaceIndex(5)) == nullptr);
    ConflictMarks::Face& f = marks.face(FaceIndex(5));
    CHECK(f.incircle == ConflictMarks::kUnknown);
    CHECK(!f.in_region);
    for (signed char c : f.crossed) CHECK(c == ConflictMarks::kUntested);
    f.in_region = true;
    f.incircle = -1;
    f.crossed[1] = 1;
    marks.vertex(VertexIndex(3)).hidden = 1;
    marks.vertex(VertexIndex(3)).on_boundary = true;
    REQUIRE(marks.find(FaceIndex(5)) != nullptr);
    CHECK(marks.find(FaceIndex(5))->in_region);
    CHECK(marks.find(FaceIndex(5))->crossed[1] == 1);
    CHECK(marks.find(FaceIndex(4)) == nullptr);  // stored below 5, never made
    CHECK(marks.find(FaceIndex(1000)) == nullptr);
    CHECK(marks.vertex(VertexIndex(3)).hidden == 1);

    marks.start();
    CHECK(marks.find(FaceIndex(5)) == nullptr);
    CHECK(marks.face(FaceIndex(5)).incircle == ConflictMarks::kUnknown);
    CHECK(!marks.face(FaceIndex(5)).in_region);
    CHECK(marks.face(FaceIndex(5)).crossed[1] == ConflictMarks::kUntested);
    CHECK(marks.vertex(VertexIndex(3)).hidden == ConflictMarks::kUnknown);
    CHECK(!marks.vertex(VertexIndex(3)).on_boundary);
}

TEST_CASE("ConflictMarks: an entry made 2^16 regions ago reads blank (the generations wrap)", "[graph][conflict-region]") {
    // Random entries, then exactly one full turn of the 16-bit generation:
    // the generation comes back to the value the entries carry, and only
    // the wrap's blanking keeps them from reading as the current region's.
    std::mt19937_64 rng(16);
    for (const int before : {0, 1, 700, 65534}) {
        ConflictMarks marks;
        for (int k = 0; k < before; ++k) marks.start();
        marks.start();
        std::vector<int> faces, vertices;  // with repeats: checked (read) before any entry is made again
        for (int k = 0; k < 20; ++k) {
            const int f = static_cast<int>(rng() % 500), v = static_cast<int>(rng() % 300);
            marks.face(FaceIndex(f)).in_region = true;
            marks.face(FaceIndex(f)).crossed[k % 3] = 1;
            marks.vertex(VertexIndex(v)).on_boundary = true;
            faces.push_back(f), vertices.push_back(v);
        }
        for (int k = 0; k < 65536; ++k) marks.start();
        for (int f : faces) CHECK(marks.find(FaceIndex(f)) == nullptr);
        for (int f : faces) {
            CHECK(!marks.face(FaceIndex(f)).in_region);
            CHECK(marks.face(FaceIndex(f)).crossed[0] == ConflictMarks::kUntested);
        }
        for (int v : vertices) CHECK(!marks.vertex(VertexIndex(v)).on_boundary);
    }
}
