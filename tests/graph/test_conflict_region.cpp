// ConflictMarks, the memo of one conflict region: entries made for one region
// read as blank in the next, whatever indices the triangulation reuses. (The
// regions themselves are checked through whole graphs: test_graph_vs_cgal,
// test_insertion_order, test_delaunay_graph.)
#include "graph/conflict_region.hpp"

#include <catch2/catch.hpp>

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
