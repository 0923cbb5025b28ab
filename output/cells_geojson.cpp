#include "output/cells_geojson.hpp"

#include "output/cells_json.hpp"
#include "output/outward_decimal.hpp"
#include "output/packing_fraction.hpp"

namespace ellvor {

nlohmann::json cells_geojson(const CellTessellation& t) {
    nlohmann::json features = nlohmann::json::array();
    std::size_t without_ring = 0;
    for (const Cell& c : t.cells) {
        if (c.ring.empty()) {
            ++without_ring;
            continue;
        }
        nlohmann::json ring = c.ring;
        ring.push_back(c.ring.front());  // GeoJSON closes its rings
        const auto [area_lo, area_hi] = double_bounds(c.area);
        const std::optional<Ball> fraction = packing_fraction(c);
        const auto [pf_lo, pf_hi] = fraction ? double_bounds(*fraction) : std::pair<double, double>{NAN, NAN};
        features.push_back({{"type", "Feature"},
                            {"geometry", {{"type", "Polygon"}, {"coordinates", {ring}}}},
                            {"properties",
                             {{"site", c.site},
                              {"area_lo", json_bound(area_lo)},
                              {"area_hi", json_bound(area_hi)},
                              {"packing_fraction_lo", json_bound(pf_lo)},
                              {"packing_fraction_hi", json_bound(pf_hi)}}}});
    }
    return {{"type", "FeatureCollection"}, {"features", features}, {"cells_without_ring", without_ring}};
}

}  // namespace ellvor
