// write_graph_json (output/graph_json.hpp): written an element at a time, the
// bytes of nlohmann's dump of the parsed document, and the graph's contents.
#include "output/graph_json.hpp"
#include "sites/site_generators.hpp"
#include "tests/support/ellipse_graph.hpp"

#include <catch2/catch.hpp>

#include <sstream>

using namespace ellvor;

TEST_CASE("write_graph_json: the dump's bytes; edges, faces, hidden and removed sites, vertices", "[output]") {
    GeneratorOptions g;
    g.kind = SiteKind::ellipses;
    g.count = 40;
    g.seed = 3;
    std::vector<Ellipse> sites = generate_sites(g);
    sites.push_back(Ellipse::circle(sites[0].xc(), sites[0].yc(), Rational(1, 1000000)));  // hidden in site 0
    DelaunayGraph graph = test::ellipse_graph(sites);
    graph.insert_all();
    graph.remove(5);
    std::ostringstream out;
    const std::vector<VoronoiVertexValue> vertices = voronoi_vertex_values(graph, sites);
    write_graph_json(out, graph, sites, build_stats_json(graph, 0.5), vertices);
    const nlohmann::json j = nlohmann::json::parse(out.str());
    CHECK(j.dump() == out.str());

    CHECK(j["edges"].size() == graph.edges().size());
    CHECK(j["edges"][0] == nlohmann::json{graph.edges()[0].first, graph.edges()[0].second});
    CHECK(j["faces"] == nlohmann::json(graph.faces()));
    CHECK(j["hidden"] == nlohmann::json::array({{sites.size() - 1, 0}}));
    CHECK(j["removed"] == nlohmann::json::array({5}));
    REQUIRE(j["sites"].size() == sites.size());
    CHECK(j["sites"][5].is_null());
    CHECK(j["sites"][4] == sites[4].str());
    CHECK(j["stats"]["seconds"] == 0.5);
    REQUIRE(j["voronoi_vertices"].size() == vertices.size());
    const nlohmann::json& v = j["voronoi_vertices"].back();
    CHECK(v["face"] == nlohmann::json(graph.faces().back()));
    CHECK(v["center"] == nlohmann::json{vertices.back().x, vertices.back().y});
    CHECK(v["radius"] == vertices.back().radius);
    CHECK(v["error"] == vertices.back().error);

    std::ostringstream unmatched;
    CHECK_THROWS_AS(write_graph_json(unmatched, graph, sites, nlohmann::json::object(), {}), Error);
}
