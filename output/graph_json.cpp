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

std::vector<VoronoiVertexValue> voronoi_vertex_values(const DelaunayGraph& graph, const std::vector<Ellipse>& sites) {
    std::vector<VoronoiVertexValue> vertices;
    for (const auto& f : graph.faces()) vertices.push_back(voronoi_vertex_value(sites, f));
    return vertices;
}

void write_graph_json(std::ostream& out, const DelaunayGraph& graph, const std::vector<Ellipse>& sites,
                      const nlohmann::json& stats, const std::vector<VoronoiVertexValue>& vertices) {
    const auto faces = graph.faces();
    if (vertices.size() != faces.size()) throw Error("write_graph_json: one Voronoi vertex per face expected");
    // Each member an array written an element at a time, the members in
    // nlohmann's (sorted) order.
    const auto array = [&out](const char* name, std::size_t size, const auto& element) {
        out << '"' << name << "\":[";
        for (std::size_t k = 0; k < size; ++k) out << (k ? "," : "") << nlohmann::json(element(k)).dump();
        out << ']';
    };
    const auto edges = graph.edges();
    const auto hidden = graph.hidden();
    out << '{';
    array("edges", edges.size(), [&](std::size_t k) { return nlohmann::json{edges[k].first, edges[k].second}; });
    out << ',';
    array("faces", faces.size(), [&](std::size_t k) { return nlohmann::json(faces[k]); });
    out << ',';
    array("hidden", hidden.size(), [&](std::size_t k) { return nlohmann::json{hidden[k].first, hidden[k].second}; });
    out << ",\"removed\":" << nlohmann::json(graph.removed()).dump() << ',';
    // Removed sites keep their ids and appear nowhere else: null here.
    std::vector<char> removed(sites.size(), 0);
    for (SiteId r : graph.removed()) removed.at(r) = 1;
    array("sites", sites.size(),
          [&](std::size_t k) { return removed[k] ? nlohmann::json(nullptr) : nlohmann::json(sites[k].str()); });
    out << ",\"stats\":" << stats.dump() << ',';
    array("voronoi_vertices", faces.size(), [&](std::size_t k) {
        const VoronoiVertexValue& v = vertices[k];
        return nlohmann::json{{"face", faces[k]}, {"center", {v.x, v.y}}, {"radius", v.radius}, {"error", v.error}};
    });
    out << '}';
}

}  // namespace ellvor
