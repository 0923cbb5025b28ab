#include "output/cells_geojson.hpp"

#include "output/cells_json.hpp"
#include "output/outward_decimal.hpp"
#include "output/packing_fraction.hpp"

#include <algorithm>
#include <ostream>

namespace ellvor {
namespace {

// Twice the signed area of a polygon (the shoelace sum in doubles: only its
// sign is used, for a ring that is a cell's boundary, far from degenerate).
double twice_signed_area(const std::vector<std::array<double, 2>>& ring) {
    double sum = 0;
    for (std::size_t k = 0; k < ring.size(); ++k) {
        const auto& p = ring[k];
        const auto& q = ring[(k + 1) % ring.size()];
        sum += p[0] * q[1] - q[0] * p[1];
    }
    return sum;
}

}  // namespace

void write_cells_geojson(std::ostream& out, const CellTessellation& t) {
    // The members in nlohmann's (sorted) order; each feature dumped alone.
    const std::size_t without_ring =
        std::count_if(t.cells.begin(), t.cells.end(), [](const Cell& c) { return c.ring.empty(); });
    out << "{\"cells_without_ring\":" << without_ring << ",\"features\":[";
    bool first = true;
    for (const Cell& c : t.cells) {
        if (c.ring.empty()) continue;
        std::vector<std::array<double, 2>> points = c.ring;
        // RFC 7946: an exterior ring runs counter-clockwise, and is closed.
        if (twice_signed_area(points) < 0) std::reverse(points.begin(), points.end());
        points.push_back(points.front());
        const nlohmann::json ring = points;
        const auto [area_lo, area_hi] = double_bounds(c.area);
        const std::optional<Ball> fraction = packing_fraction(c);
        const auto [pf_lo, pf_hi] = fraction ? double_bounds(*fraction) : std::pair<double, double>{NAN, NAN};
        const nlohmann::json feature = {{"type", "Feature"},
                                        {"geometry", {{"type", "Polygon"}, {"coordinates", {ring}}}},
                                        {"properties",
                                         {{"site", c.site},
                                          {"area_lo", json_bound(area_lo)},
                                          {"area_hi", json_bound(area_hi)},
                                          {"packing_fraction_lo", json_bound(pf_lo)},
                                          {"packing_fraction_hi", json_bound(pf_hi)}}}};
        out << (first ? "" : ",") << feature.dump();
        first = false;
    }
    out << "],\"type\":\"FeatureCollection\"}";
}

}  // namespace ellvor
