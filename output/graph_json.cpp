#include "output/graph_json.hpp"

#include "subdivision/voronoi_circle_enclosure.hpp"

#include <algorithm>
#include <array>
#include <utility>

namespace ellvor {
namespace {

nlohmann::json voronoi_vertex(const std::vector<Ellipse>& sites, const std::array<SiteId, 3>& f) {
    VoronoiCircleSolver solver(sites[f[0]], sites[f[1]], sites[f[2]]);
    nlohmann::json v = {{"face", f}};
    solver.refine_existing(53);  // a face of the graph has its counter-clockwise circle
    const VoronoiCircleEnclosure& c = solver.enclosure();
    double error = 0;
    for (const Ball* b : {&c.center_x, &c.center_y, &c.radius}) error = std::max(error, b->radius_double());
    v["center"] = {c.center_x.mid_double(), c.center_y.mid_double()};
    v["radius"] = c.radius.mid_double();
    v["error"] = error;
    return v;
}

}  // namespace

nlohmann::json build_stats_json(const DelaunayGraph& graph, double seconds) {
    nlohmann::json s = {{"seconds", seconds}, {"inserted", graph.stats().inserted}};
    const TraitsStats& t = graph.predicate_stats();
    const std::pair<const char*, const PredicateCount*> rows[] = {
        {"is_hidden", &t.is_hidden},         {"side_of_bisector", &t.side_of_bisector},
        {"vertex_conflict_3", &t.vertex_conflict3}, {"incircle", &t.vertex_conflict4},
        {"finite_edge", &t.finite_edge},     {"infinite_edge", &t.infinite_edge},
        {"degenerate_edge", &t.degenerate_edge}};
    for (const auto& [name, count] : rows) {
        nlohmann::json& row = s["predicates"][name];
        row["calls"] = count->calls;
        for (Stage stage : kStages) row[stage_name(stage)] = count->stages[stage];
    }
    return s;
}

nlohmann::json graph_json(const DelaunayGraph& graph, const std::vector<Ellipse>& sites, const nlohmann::json& stats) {
    const auto faces = graph.faces();
    nlohmann::json j;
    j["sites"] = nlohmann::json::array();
    for (const Ellipse& e : sites) j["sites"].push_back(e.str());
    // Removed sites keep their ids and appear nowhere else: null here.
    for (SiteId r : graph.removed()) j["sites"][r] = nullptr;
    j["removed"] = graph.removed();
    j["hidden"] = nlohmann::json::array();
    for (const auto& [h, by] : graph.hidden()) j["hidden"].push_back({h, by});
    j["edges"] = nlohmann::json::array();
    for (const auto& [a, b] : graph.edges()) j["edges"].push_back({a, b});
    j["faces"] = faces;
    j["voronoi_vertices"] = nlohmann::json::array();
    for (const auto& f : faces) j["voronoi_vertices"].push_back(voronoi_vertex(sites, f));
    j["stats"] = stats;
    return j;
}

}  // namespace ellvor
