// ellvor build: summary, validation, JSON output, bad input.
#include "tests/support/command_runner.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

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

TEST_CASE("build: ellipses crossing in four points are an input error naming them", "[cli][build]") {
    ScratchDirectory dir;
    const std::string f = dir.write("bad.ell", "3 1 0 0 0\n1 1 0 10 0\n1 3 0 0 0\n");
    const std::string json = dir.path() + "/g.json";
    const auto r = dir.ellvor("build '" + f + "' --json '" + json + "'");
    INFO(r.out << r.err);
    CHECK(r.status == 2);
    CHECK(contains(r.err, f + ":3:1: site 2 crosses site 0 (line 1): their boundaries meet in 4 points"));
    CHECK(r.out.find("Delaunay edges") == std::string::npos);
    CHECK(!std::ifstream(json));  // nothing written
}

TEST_CASE("build: an invalid pair among valid ones is an input error before any search (issue 21, input B)",
          "[cli][build][early-validity]") {
    // Sites 2 and 3 meet in four points; the triple (0, 1, 2) would need a long search.
    ScratchDirectory dir;
    const std::string f = dir.write("b.ell", "10 10 0 0 0\n10 10 0 12 0\n11/30 10 0 6 10\n3 3 0 6 4\n");
    const std::string json = dir.path() + "/g.json";
    for (const char* validate : {"", " --validate"}) {
        const auto r = dir.ellvor("build '" + f + "'" + validate + " --json '" + json + "'");
        INFO(r.out << r.err);
        CHECK(r.status == 2);
        CHECK(contains(r.err, f + ":4:1: site 3 crosses site 2 (line 3): their boundaries meet in 4 points"));
        CHECK(r.out.find("Delaunay edges") == std::string::npos);
        CHECK(!std::ifstream(json));  // nothing written
    }
}

TEST_CASE("build: crossing circles, an internal Voronoi circle of negative radius in the JSON", "[cli][build]") {
    // Three pairwise crossing circles of radius 10 whose common part holds the
    // point (6, 16/5), at distance 34/5 from each center: the Voronoi vertex
    // of the face (0, 1, 2) is the internal circle of radius -16/5 there.
    ScratchDirectory dir;
    const std::string f = dir.write("o.ell", "10 10 0 0 0\n10 10 0 12 0\n10 10 0 6 10\n3 3 0 6 4\n2 2 0 30 30\n");
    const std::string json = dir.path() + "/g.json";
    const auto r = dir.ellvor("build '" + f + "' --validate --json '" + json + "'");
    INFO(r.out << r.err);
    REQUIRE(r.status == 0);
    CHECK(contains(r.out, "5 sites (1 hidden)"));
    const nlohmann::json g = nlohmann::json::parse(std::ifstream(json));
    CHECK(g["hidden"] == nlohmann::json::array({nlohmann::json::array({3, 2})}));
    bool internal = false;
    for (const auto& v : g["voronoi_vertices"])
        if (v["face"] == nlohmann::json::array({0, 1, 2})) {
            internal = true;
            const double error = v["error"].get<double>();
            CHECK(std::fabs(v["radius"].get<double>() + 3.2) <= error + 1e-15);
            CHECK(std::fabs(v["center"][0].get<double>() - 6.0) <= error + 1e-15);
            CHECK(std::fabs(v["center"][1].get<double>() - 3.2) <= error + 1e-15);
        }
    CHECK(internal);
}

TEST_CASE("build: crossing ellipses, a needle hidden by a union, its overlaps drawn", "[cli][build][svg]") {
    // The needle (a = 10, b = 1/10) between two disks of radius 6 that cross
    // it and each other: hidden, listed under a disk; `check` lists the
    // three crossing pairs; a thin ellipse crossing a disk elsewhere stays
    // visible. The SVG shades the lenses of visible sites.
    ScratchDirectory dir;
    const std::string f = dir.write("needle.ell", "10 1/10 0 0 0\n6 6 0 -5 0\n6 6 0 5 0\n8 1 1/2 30 10\n4 4 0 35 14\n");
    const auto c = dir.ellvor("check '" + f + "'");
    INFO(c.out << c.err);
    REQUIRE(c.status == 0);
    for (const char* pair : {"crossing: 0 1", "crossing: 0 2", "crossing: 1 2", "crossing: 3 4"}) CHECK(contains(c.out, pair));
    CHECK(contains(c.out, "5 sites (3 circles), 0 hidden, 4 crossing pairs, OK"));
    const std::string json = dir.path() + "/g.json";
    const auto r = dir.ellvor("build '" + f + "' --validate --json '" + json + "' --svg '" + dir.path() + "/d.svg'");
    INFO(r.out << r.err);
    REQUIRE(r.status == 0);
    CHECK(contains(r.out, "5 sites (1 hidden)"));
    CHECK(contains(r.out, "valid"));
    CHECK(!contains(r.err, "not drawn"));
    const nlohmann::json g = nlohmann::json::parse(std::ifstream(json));
    REQUIRE(g["hidden"].size() == 1);
    CHECK(g["hidden"][0][0] == 0);
    CHECK((g["hidden"][0][1] == 1 || g["hidden"][0][1] == 2));
    const std::string svg = ellvor::test::read_file(dir.path() + "/d.svg");
    CHECK(contains(svg, ">overlapping pairs: 2<"));  // the lenses of visible sites: (1, 2) and (3, 4)
}

TEST_CASE("build --svg: crossing circles are drawn, their overlaps shaded", "[cli][build][svg]") {
    // Circles 0 and 1 cross, and 2 crosses both: three lenses; every Voronoi
    // edge is drawn, the internal Voronoi vertex in the common part included.
    ScratchDirectory dir;
    const std::string f = dir.write("cross.ell", "2 2 0 0 0\n2 2 0 3 0\n1.5 1.5 0 1.5 2.5\n1 1 0 7 1\n1 1 0 -4 3\n");
    const auto r = dir.ellvor("build '" + f + "' --svg '" + dir.path() + "/d.svg'");
    INFO(r.out << r.err);
    REQUIRE(r.status == 0);
    CHECK(contains(r.out, "5 sites (0 hidden), 7 Delaunay edges, 3 faces"));
    CHECK(!contains(r.err, "not drawn"));
    const std::string svg = ellvor::test::read_file(dir.path() + "/d.svg");
    CHECK(contains(svg, "<g id=\"overlaps\""));
    CHECK(contains(svg, "data-overlaps=\"3\""));
    CHECK(contains(svg, "data-voronoi-edges=\"7\""));
    CHECK(contains(svg, ">overlapping pairs: 3<"));
}

TEST_CASE("build --help", "[cli][build]") {
    ScratchDirectory dir;
    const auto r = dir.ellvor("build --help");
    CHECK(r.status == 0);
    CHECK(r.out.rfind("usage: ellvor build", 0) == 0);
}

TEST_CASE("build --remove: the graph of the other sites, removed ids nowhere in the JSON", "[cli][build][removal]") {
    // data/example.ell: 20 sites, 6 hosts 7 (hidden by 6): removing 6 brings 7 back.
    ScratchDirectory dir;
    const std::string example = std::string(ELLVOR_SOURCE_DIR) + "/data/example.ell";
    const std::string ids = dir.write("ids.txt", "# removal order\n6\n  3\n\n11  # a comment\n");
    const auto r = dir.ellvor("build '" + example + "' --remove @'" + ids + "' --validate --stats --json '" + dir.path() +
                              "/g.json'");
    INFO(r.out << r.err);
    REQUIRE(r.status == 0);
    CHECK(contains(r.out, "3 sites removed in"));
    CHECK(contains(r.out, "\nvalid\n"));
    CHECK(contains(r.out, "time per removal:"));
    const auto j = nlohmann::json::parse(ellvor::test::read_file(dir.path() + "/g.json"));
    CHECK(j["removed"] == nlohmann::json({6, 3, 11}));
    CHECK(j["stats"]["removed"].get<int>() == 3);
    const std::set<int> gone = {6, 3, 11};
    for (int s : gone) CHECK(j["sites"][s].is_null());
    for (const auto& e : j["edges"])
        for (const auto& id : e) CHECK(gone.count(id.get<int>()) == 0);
    for (const auto& f : j["faces"])
        for (const auto& id : f) CHECK(gone.count(id.get<int>()) == 0);
    std::set<std::pair<int, int>> hidden;
    for (const auto& h : j["hidden"]) hidden.insert({h[0].get<int>(), h[1].get<int>()});
    CHECK(hidden == std::set<std::pair<int, int>>{{9, 8}, {13, 12}, {19, 18}});  // 7 is visible again

    // The same graph as the file without those lines (ids shift: compare by site text).
    std::istringstream lines(ellvor::test::read_file(example));
    std::string line, kept;
    for (int id = 0; std::getline(lines, line);) {
        const auto first = line.find_first_not_of(" \t");
        if (first == std::string::npos || line[first] == '#') continue;
        if (!gone.count(id++)) kept += line + "\n";
    }
    const std::string smaller = dir.write("smaller.ell", kept);
    REQUIRE(dir.ellvor("build '" + smaller + "' --json '" + dir.path() + "/h.json'").status == 0);
    const auto k = nlohmann::json::parse(ellvor::test::read_file(dir.path() + "/h.json"));
    auto edges_by_text = [](const nlohmann::json& doc) {
        std::multiset<std::pair<std::string, std::string>> out;
        for (const auto& e : doc["edges"]) {
            std::string a = doc["sites"][e[0].get<int>()], b = doc["sites"][e[1].get<int>()];
            out.insert({std::min(a, b), std::max(a, b)});
        }
        return out;
    };
    CHECK(edges_by_text(j) == edges_by_text(k));
    CHECK(j["faces"].size() == k["faces"].size());
}

TEST_CASE("build --remove: bad id lists exit 2 with a clear message", "[cli][build][removal]") {
    ScratchDirectory dir;
    const std::string example = std::string(ELLVOR_SOURCE_DIR) + "/data/example.ell";
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"--remove 3,3", "item 2: site id 3 is listed twice (first at item 1)"},
        {"--remove 20", "site id 20 is out of range (the file has 20 sites, ids 0 to 19)"},
        {"--remove 1,x", "item 2: expected a site id (a 0-based integer), found 'x'"},
        {"--remove 1,", "expected site ids separated by commas"},
        {"--remove -1", "found '-1'"},
        {"--remove @" + dir.write("bad.txt", "4\n\n  17x\n"), "bad.txt:3:3: expected a site id"},
        {"--remove @" + dir.write("twice.txt", "4\n5\n4\n"), "twice.txt:3:1: site id 4 is listed twice (first at"},
        {"--remove @" + dir.write("empty.txt", "# nothing\n"), "empty.txt: no site ids to remove"},
        {"--remove @" + dir.path() + "/missing.txt", "missing.txt: cannot read"},
    };
    for (const auto& [option, message] : cases) {
        const auto r = dir.ellvor("build '" + example + "' " + option + " --json '" + dir.path() + "/never.json'");
        INFO(option << "\n" << r.out << r.err);
        CHECK(r.status == 2);
        CHECK(contains(r.err, message));
        CHECK_FALSE(std::ifstream(dir.path() + "/never.json").good());  // nothing half-written
    }
}
