#include "output/cells_json.hpp"

#include "output/outward_decimal.hpp"
#include "output/packing_fraction.hpp"

#include <cmath>

namespace ellvor {
namespace {

const char* domain_kind(CellDomain::Kind k) {
    switch (k) {
        case CellDomain::Kind::box: return "box";
        case CellDomain::Kind::periodic: return "periodic";
        case CellDomain::Kind::plane: break;
    }
    return "plane";
}

nlohmann::json side_json(const CellSide& s) {
    nlohmann::json j;
    j["neighbor"] = s.neighbor >= 0 ? nlohmann::json(s.neighbor) : nlohmann::json(nullptr);
    j["wall"] = s.neighbor < 0 ? nlohmann::json(wall_name(s.wall)) : nlohmann::json(nullptr);
    j["shift"] = s.shift;
    j["from"] = s.from;
    j["to"] = s.to;
    return j;
}

nlohmann::json cell_json(const Cell& c) {
    nlohmann::json j;
    j["site"] = c.site;
    j["visible"] = c.visible;
    j["bounded"] = c.bounded;
    j["area"] = ball_json(c.area);
    j["site_area"] = ball_json(c.site_area);
    const std::optional<Ball> fraction = packing_fraction(c);
    j["packing_fraction"] = fraction ? ball_json(*fraction) : nlohmann::json(nullptr);
    j["perimeter"] = ball_json(c.perimeter);
    j["centroid"] = {ball_json(c.centroid[0]), ball_json(c.centroid[1])};
    j["second_moments"] = {ball_json(c.second_moments[0]), ball_json(c.second_moments[1]),
                           ball_json(c.second_moments[2])};
    j["neighbors"] = nlohmann::json::array();
    j["sides"] = nlohmann::json::array();
    for (const CellSide& s : c.sides) {
        j["neighbors"].push_back(s.neighbor >= 0 ? nlohmann::json(s.neighbor)
                                                 : nlohmann::json(std::string("wall:") + wall_name(s.wall)));
        j["sides"].push_back(side_json(s));
    }
    j["ring"] = c.ring;
    j["precision"] = c.precision;
    return j;
}

}  // namespace

nlohmann::json json_bound(double x) {
    if (std::isnan(x)) return nullptr;
    if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
    return x;
}

nlohmann::json ball_json(const Ball& b) {
    const auto [lo, hi] = double_bounds(b);
    if (std::isnan(lo) || std::isnan(hi)) return nullptr;
    return {{"lo", json_bound(lo)}, {"hi", json_bound(hi)}};
}

void write_cells_json(std::ostream& out, const CellTessellation& t) {
    // The members in nlohmann's (sorted) order; each cell and vertex dumped alone.
    nlohmann::json domain = {{"kind", domain_kind(t.domain.kind)}};
    if (t.domain.kind != CellDomain::Kind::plane)
        domain["box"] = {t.domain.x0.str(), t.domain.y0.str(), t.domain.x1.str(), t.domain.y1.str()};
    out << "{\"boundary_tolerance\":" << nlohmann::json(t.boundary_tolerance).dump() << ",\"cells\":[";
    for (std::size_t k = 0; k < t.cells.size(); ++k) out << (k ? "," : "") << cell_json(t.cells[k]).dump();
    out << "],\"domain\":" << domain.dump() << ",\"vertices\":[";
    for (std::size_t k = 0; k < t.vertices.size(); ++k) {
        const CellVertex& v = t.vertices[k];
        out << (k ? "," : "") << nlohmann::json{{"x", ball_json(v.x)}, {"y", ball_json(v.y)}}.dump();
    }
    out << "]}";
}

}  // namespace ellvor
