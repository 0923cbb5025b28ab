#include "output/graph_json.hpp"

#include "output/voronoi_circle_box.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace ellvor {

VoronoiVertexValue voronoi_vertex_value(const std::vector<Ellipse>& sites, const std::array<SiteId, 3>& f) {
    // The box is the double certificate's when tight (about 2^-50 of the
    // circle's magnitude, ~5 us), else Arb's at 53 bits (~100 us).
    const VoronoiCircleBox box = voronoi_circle_box(sites, f);
    VoronoiVertexValue v;
    // `error` bounds the distance from each printed double (a point of its
    // interval) to the exact value, which the interval holds: the larger
    // distance to an end, rounded up.
    const std::pair<const Interval*, double*> printed[] = {
        {&box.center_x, &v.x}, {&box.center_y, &v.y}, {&box.radius, &v.radius}};
    for (const auto& [x, value] : printed) {
        *value = Interval::min(Interval::max(0.5 * x->lo + 0.5 * x->hi, x->lo), x->hi);
        v.error = Interval::max(v.error, Interval::max(Interval::up(x->hi - *value), Interval::up(*value - x->lo)));
    }
    return v;
}

nlohmann::json build_stats_json(const DelaunayGraph& graph, double seconds) {
    nlohmann::json s = {{"seconds", seconds}, {"inserted", graph.stats().inserted}};
    const TraitsStats& t = graph.predicate_stats();
    for (const PredicateInfo& p : kPredicates) {
        nlohmann::json& row = s["predicates"][p.name];
        row["calls"] = t[p.predicate].calls;
        for (Stage stage : kStages) row[stage_name(stage)] = t[p.predicate].stages[stage];
    }
    return s;
}

nlohmann::json graph_json(const DelaunayGraph& graph, const std::vector<Ellipse>& sites, const nlohmann::json& stats) {
    std::vector<VoronoiVertexValue> vertices;
    for (const auto& f : graph.faces()) vertices.push_back(voronoi_vertex_value(sites, f));
    return graph_json(graph, sites, stats, vertices);
}

nlohmann::json graph_json(const DelaunayGraph& graph, const std::vector<Ellipse>& sites, const nlohmann::json& stats,
                          const std::vector<VoronoiVertexValue>& vertices) {
    const auto faces = graph.faces();
    if (vertices.size() != faces.size()) throw Error("graph_json: one Voronoi vertex per face expected");
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
    for (std::size_t k = 0; k < faces.size(); ++k) {
        const VoronoiVertexValue& v = vertices[k];
        j["voronoi_vertices"].push_back(
            {{"face", faces[k]}, {"center", {v.x, v.y}}, {"radius", v.radius}, {"error", v.error}});
    }
    j["stats"] = stats;
    return j;
}

}  // namespace ellvor
