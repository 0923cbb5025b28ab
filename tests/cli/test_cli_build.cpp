// ellvor build: summary, validation, JSON output, bad input.
#include "tests/support/command_runner.hpp"

#include <nlohmann/json.hpp>

#include <set>
#include <utility>

using ellvor::test::contains;
using ellvor::test::ScratchDirectory;

TEST_CASE("build: the bundled example is valid and its JSON is complete", "[cli][build]") {
    ScratchDirectory dir;
    const std::string example = std::string(ELLVOR_SOURCE_DIR) + "/data/example.ell";
    const auto r = dir.ellvor("build '" + example + "' --validate --stats --json '" + dir.path() + "/g.json'");
    INFO(r.out << r.err);
    REQUIRE(r.status == 0);
    CHECK(contains(r.out, "20 sites (4 hidden)"));
    CHECK(contains(r.out, "\nvalid\n"));
    CHECK(contains(r.out, "predicate calls"));
    const auto j = nlohmann::json::parse(ellvor::test::read_file(dir.path() + "/g.json"));
    REQUIRE(j["sites"].size() == 20);
    // The example's nested pairs (see data/example.ell): hidden, by their hosts.
    std::set<std::pair<int, int>> hidden;
    for (const auto& h : j["hidden"]) hidden.insert({h[0].get<int>(), h[1].get<int>()});
    CHECK(hidden == std::set<std::pair<int, int>>{{7, 6}, {9, 8}, {13, 12}, {19, 18}});
    // Edges and faces join visible sites only; each face's Voronoi vertex is there.
    const std::set<int> hidden_ids = {7, 9, 13, 19};
    for (const auto& e : j["edges"]) {
        CHECK(hidden_ids.count(e[0].get<int>()) == 0);
        CHECK(hidden_ids.count(e[1].get<int>()) == 0);
        CHECK(e[0].get<int>() != e[1].get<int>());
    }
    REQUIRE(j["voronoi_vertices"].size() == j["faces"].size());
    for (const auto& v : j["voronoi_vertices"]) {
        CHECK(v["radius"].get<double>() > 0);
        CHECK(v["error"].get<double>() < 1e-10);
    }
    CHECK(j["stats"]["predicates"]["incircle"]["calls"].get<long>() > 0);
}

TEST_CASE("build: three collinear circles give the CGAL structure", "[cli][build]") {
    // graph_and_vorell.md section 3: centers (100,100), (150,150), (200,200);
    // radii 20, 15, 20: the middle site is not on the hull, so the graph is the
    // path 0 - 1 - 2 plus the edge 0 - 2 around it (two faces sharing all three).
    ScratchDirectory dir;
    const std::string f = dir.write("c.cin", "100 100 20\n150 150 15\n200 200 20\n");
    const auto r = dir.ellvor("build --cin '" + f + "' --validate --json -");
    INFO(r.out << r.err);
    REQUIRE(r.status == 0);
    const std::string json_line = r.out.substr(r.out.find("\n{") + 1);
    const auto j = nlohmann::json::parse(json_line);
    std::multiset<std::pair<int, int>> edges;
    for (const auto& e : j["edges"]) edges.insert({e[0].get<int>(), e[1].get<int>()});
    CHECK(edges.count({0, 1}) + edges.count({1, 0}) >= 1);
    CHECK(edges.count({1, 2}) + edges.count({2, 1}) >= 1);
    CHECK(contains(r.out, "valid"));
}

TEST_CASE("build: intersecting sites are an input error naming them", "[cli][build]") {
    ScratchDirectory dir;
    const std::string f = dir.write("bad.ell", "1 1 0 0 0\n1 1 0 10 0\n1 1 0 1 0\n");
    const auto r = dir.ellvor("build '" + f + "'");
    INFO(r.out << r.err);
    CHECK(r.status == 2);
    CHECK(contains(r.err, f + ":3:1: site 2 intersects site 0 (line 1)"));
    CHECK(r.out.find("Delaunay edges") == std::string::npos);
}

TEST_CASE("build --help", "[cli][build]") {
    ScratchDirectory dir;
    const auto r = dir.ellvor("build --help");
    CHECK(r.status == 0);
    CHECK(r.out.rfind("usage: ellvor build", 0) == 0);
}
