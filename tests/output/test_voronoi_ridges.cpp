// The Voronoi edges in scipy's terms (ridge_points, ridge_vertices): one
// ridge per Delaunay edge in the order of edges(), ends numbered as faces()
// lists the faces, -1 at infinity, and the faces the traced arcs name.
#include "output/bisector_trace.hpp"
#include "output/voronoi_ridges.hpp"
#include "sites/site_generators.hpp"
#include "tests/support/ellipse_graph.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <set>

using namespace ellvor;

TEST_CASE("voronoi_ridges: one per Delaunay edge, ends at the faces holding both sites", "[output]") {
    GeneratorOptions o;
    o.count = 120;
    o.seed = GENERATE(1, 2, 3);
    o.nested_fraction = Rational(1, 10);
    const std::vector<Ellipse> sites = generate_sites(o);
    DelaunayGraph graph = test::ellipse_graph(sites);
    graph.insert_all();
    const auto faces = graph.faces();
    const std::vector<long> numbers = face_numbers(graph);
    const std::vector<VoronoiRidge> ridges = voronoi_ridges(graph, numbers);

    const auto edges = graph.edges();
    REQUIRE(ridges.size() == edges.size());
    std::map<long, int> ends;
    long infinite = 0;
    for (std::size_t k = 0; k < ridges.size(); ++k) {
        const VoronoiRidge& r = ridges[k];
        CHECK(std::make_pair(std::min(r.p, r.q), std::max(r.p, r.q)) == edges[k]);
        for (long f : {r.from, r.to}) {
            if (f < 0) {
                ++infinite;
                continue;
            }
            REQUIRE(f < static_cast<long>(faces.size()));
            const auto& t = faces[static_cast<std::size_t>(f)];
            CHECK(std::count(t.begin(), t.end(), r.p) == 1);
            CHECK(std::count(t.begin(), t.end(), r.q) == 1);
            ++ends[f];
        }
        if (r.from >= 0) {  // p -> q runs counter-clockwise in the left face
            const auto& t = faces[static_cast<std::size_t>(r.from)];
            const auto i = std::find(t.begin(), t.end(), r.p) - t.begin();
            CHECK(t[static_cast<std::size_t>((i + 1) % 3)] == r.q);
        }
    }
    CHECK(infinite == static_cast<long>(graph.hull().size()));
    CHECK(ends.size() == faces.size());
    for (const auto& [f, count] : ends) CHECK(count == 3);

    // The traced arcs name the same ridges.
    const TracedDiagram traced = trace_voronoi_diagram(graph, sites, 0.02, 0.08);
    std::multiset<std::tuple<SiteId, SiteId, long, long>> from_arcs, from_ridges;
    for (const VoronoiEdgeArc& a : traced.arcs)
        from_arcs.insert({a.p, a.q, a.from_infinity ? -1 : face_number(numbers, a.left_face),
                          a.to_infinity ? -1 : face_number(numbers, a.right_face)});
    for (const VoronoiRidge& r : ridges) from_ridges.insert({r.p, r.q, r.from, r.to});
    CHECK(traced.failed_edges == 0);
    CHECK(from_arcs == from_ridges);
}

TEST_CASE("voronoi_ridges: two visible sites make one ridge without ends", "[output]") {
    DelaunayGraph graph = test::ellipse_graph({Ellipse::circle(0, 0, 1), Ellipse::circle(5, 0, 2),
                                               Ellipse::circle(5, 0, 1)});
    graph.insert_all();
    const std::vector<VoronoiRidge> ridges = voronoi_ridges(graph, face_numbers(graph));
    REQUIRE(ridges.size() == 1);
    CHECK(ridges[0].from == -1);
    CHECK(ridges[0].to == -1);
    CHECK(std::min(ridges[0].p, ridges[0].q) == 0);
    CHECK(face_number({}, FaceIndex{}) == -1);
}
