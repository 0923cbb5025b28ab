#include "output/graph_json.hpp"

#include "subdivision/voronoi_circle_enclosure.hpp"
#include "exact/medial_axis_tangency.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace ellvor {

VoronoiVertexValue voronoi_vertex_value(const std::vector<Ellipse>& sites, const std::array<SiteId, 3>& f) {
    VoronoiCircleSolver solver(sites[f[0]], sites[f[1]], sites[f[2]], common_medial_axis_tangency);
    solver.refine_existing(53);  // a face of the graph has its counter-clockwise circle
    const VoronoiCircleEnclosure& c = solver.enclosure();
    VoronoiVertexValue v;
    v.x = c.center_x.mid_double();
    v.y = c.center_y.mid_double();
    v.radius = c.radius.mid_double();
    // `error` bounds the distance from each printed double to its exact value:
    // the ball's radius plus the rounding of its midpoint to that double (half
    // an ulp at most), rounded up.
    const std::pair<const Ball*, double> printed[] = {{&c.center_x, v.x}, {&c.center_y, v.y}, {&c.radius, v.radius}};
    for (const auto& [ball, value] : printed) {
        const double half_ulp = 0.5 * (std::nextafter(std::fabs(value), HUGE_VAL) - std::fabs(value));
        v.error = std::max(v.error, std::nextafter(ball->radius_double() + half_ulp, HUGE_VAL));
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
