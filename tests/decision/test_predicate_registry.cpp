// The registries of the decision core: every stage and predicate has one
// name (kStages, kPredicates), and the statistics the graph reports -- the
// JSON, `ellvor build --stats` -- list exactly those rows, in that order.
// A Stage or Predicate added to its enum without a row does not compile
// (the static_asserts of decision/stage.hpp and predicate_registry.hpp).
#include "decision/predicate_registry.hpp"
#include "graph/delaunay_graph.hpp"
#include "output/graph_json.hpp"
#include "sites/site_io.hpp"
#include "tests/support/command_runner.hpp"
#include "traits/ellipse_delaunay_traits.hpp"

#include <catch2/catch.hpp>

#include <set>
#include <sstream>
#include <string>

using namespace ellvor;

TEST_CASE("kStages and kPredicates: one distinct name each, rows in the enums' order", "[decision][registry]") {
    std::set<std::string> stages;
    for (std::size_t i = 0; i < kStages.size(); ++i) {
        CHECK(static_cast<std::size_t>(kStages[i]) == i);
        stages.insert(stage_name(kStages[i]));
    }
    CHECK(stages.size() == kStages.size());
    std::set<std::string> names;
    for (std::size_t i = 0; i < kPredicates.size(); ++i) {
        const PredicateInfo& p = kPredicates[i];
        CHECK(static_cast<std::size_t>(p.predicate) == i);
        CHECK(std::string(p.name).find(' ') == std::string::npos);
        CHECK(!std::string(p.question).empty());
        names.insert(p.name);
        CHECK(predicate_name(p.predicate) == std::string(p.name));
    }
    CHECK(names.size() == kPredicates.size());
}

TEST_CASE("The JSON's and --stats' predicate rows are kPredicates' with kStages' columns", "[decision][registry][cli]") {
    const std::string path = std::string(ELLVOR_SOURCE_DIR) + "/data/example.ell";
    DelaunayGraph graph(std::make_unique<EllipseDelaunayTraits>(read_site_file(path).sites));
    graph.insert_all();
    const nlohmann::json stats = build_stats_json(graph, 0.0);
    REQUIRE(stats["predicates"].size() == kPredicates.size());
    for (const PredicateInfo& p : kPredicates) {
        INFO(p.name);
        REQUIRE(stats["predicates"].contains(p.name));
        const nlohmann::json& row = stats["predicates"][p.name];
        CHECK(row.size() == kStages.size() + 1);
        std::uint64_t decided = 0;
        for (Stage s : kStages) decided += row[stage_name(s)].get<std::uint64_t>();
        CHECK(row["calls"].get<std::uint64_t>() == decided);
        CHECK(row["calls"].get<std::uint64_t>() == graph.predicate_stats()[p.predicate].calls);
    }
    CHECK(stats["predicates"]["incircle"]["calls"].get<std::uint64_t>() > 0);

    test::ScratchDirectory dir;
    const test::CommandResult r = dir.ellvor("build '" + path + "' --stats");
    REQUIRE(r.status == 0);
    std::size_t last = 0;
    for (const PredicateInfo& p : kPredicates) {
        const std::size_t at = r.out.find(std::string("\n  ") + p.name + ": ");
        INFO(p.name << " in\n" << r.out);
        REQUIRE(at != std::string::npos);
        CHECK(at > last);  // in the registry's order
        last = at;
    }
    for (Stage s : kStages) CHECK(test::contains(r.out, stage_name(s)));
}
