// The cells' writers on tessellations made by hand, for what the library
// does not produce yet: walls and periodic shifts in the CSV's neighbours
// (quoted when they hold a comma), rings in the GeoJSON (closed and turned
// counter-clockwise), values not computed (nan / null, never a number).
#include "output/cells_csv.hpp"
#include "output/cells_geojson.hpp"
#include "output/cells_json.hpp"

#include <catch2/catch.hpp>

#include <sstream>

using namespace ellvor;

namespace {

// Two cells of a periodic box: site 0 with a wall-free periodic neighbour,
// site 1 with a clockwise square ring; areas 4 +- 2^-20 and 2 +- 2^-20.
CellTessellation two_cells() {
    CellTessellation t;
    t.domain.kind = CellDomain::Kind::periodic;
    t.domain.x0 = 0, t.domain.y0 = 0, t.domain.x1 = 4, t.domain.y1 = 2;
    t.cells.resize(2);
    for (SiteId k = 0; k < 2; ++k) {
        Cell& c = t.cells[k];
        c.site = k;
        c.visible = c.bounded = true;
        arb_set_si(c.area.get(), k == 0 ? 4 : 2);
        mag_set_ui_2exp_si(arb_radref(c.area.get()), 1, -20);
        arb_set_si(c.site_area.get(), 1);
        arb_indeterminate(c.perimeter.get());
        for (Ball* b : {&c.centroid[0], &c.centroid[1], &c.second_moments[0], &c.second_moments[1], &c.second_moments[2]})
            arb_indeterminate(b->get());
    }
    t.cells[0].sides = {{1, Wall::none, {0, 0}, 0, 1}, {1, Wall::none, {1, -1}, 1, 0}};
    t.cells[1].sides = {{0, Wall::none, {0, 0}, 1, 0}, {-1, Wall::top, {0, 0}, 0, 1}};
    t.cells[1].ring = {{0, 0}, {0, 1}, {1, 1}, {1, 0}};  // clockwise
    return t;
}

}  // namespace

TEST_CASE("cells CSV: walls and periodic shifts in the neighbours; nan for what is not computed", "[output][cells]") {
    CHECK(neighbor_label({7, Wall::none, {0, 0}, 0, 1}) == "7");
    CHECK(neighbor_label({7, Wall::none, {-1, 2}, 0, 1}) == "7@-1,2");
    CHECK(neighbor_label({-1, Wall::left, {0, 0}, 0, 1}) == "wall:left");
    std::ostringstream out;
    write_cells_csv(out, two_cells());
    std::istringstream in(out.str());
    std::string header, row0, row1;
    std::getline(in, header);
    std::getline(in, row0);
    std::getline(in, row1);
    CHECK(header == kCellsCsvHeader);
    // The shifted neighbour holds a comma: the field is quoted.
    CHECK(row0.substr(row0.rfind(",nan,nan,")) == ",nan,nan,\"1 1@1,-1\"");
    CHECK(row1.substr(row1.rfind(",nan,nan,")) == ",nan,nan,0 wall:top");
    CHECK(row0.rfind("0,1,3.99999904632568", 0) == 0);  // 4 - 2^-20, rounded down
}

TEST_CASE("cells GeoJSON: rings closed and counter-clockwise; JSON nulls for what is not computed", "[output][cells]") {
    const CellTessellation t = two_cells();
    std::ostringstream geojson, json;
    write_cells_geojson(geojson, t);
    write_cells_json(json, t);
    const nlohmann::json g = nlohmann::json::parse(geojson.str());
    // Written a feature at a time, the bytes of nlohmann's dump of the whole.
    CHECK(g.dump() == geojson.str());
    CHECK(g["type"] == "FeatureCollection");
    CHECK(g["cells_without_ring"] == 1);
    REQUIRE(g["features"].size() == 1);
    const auto& f = g["features"][0];
    CHECK(f["properties"]["site"] == 1);
    const auto& ring = f["geometry"]["coordinates"][0];
    REQUIRE(ring.size() == 5);
    CHECK(ring.front() == ring.back());
    double twice_area = 0;
    for (std::size_t k = 0; k + 1 < ring.size(); ++k)
        twice_area += ring[k][0].get<double>() * ring[k + 1][1].get<double>() -
                      ring[k + 1][0].get<double>() * ring[k][1].get<double>();
    CHECK(twice_area == 2);  // counter-clockwise now
    CHECK(f["properties"]["area_lo"].get<double>() < 2);
    CHECK(f["properties"]["area_hi"].get<double>() > 2);
    CHECK(f["properties"]["packing_fraction_lo"].get<double>() < 0.5);
    CHECK(f["properties"]["packing_fraction_hi"].get<double>() > 0.5);

    const nlohmann::json j = nlohmann::json::parse(json.str());
    CHECK(j.dump() == json.str());
    CHECK(j["domain"]["kind"] == "periodic");
    CHECK(j["domain"]["box"] == nlohmann::json({"0", "0", "4", "2"}));
    CHECK(j["cells"][0]["perimeter"].is_null());
    CHECK(j["cells"][0]["centroid"][1].is_null());
    CHECK(j["cells"][0]["sides"][1]["shift"] == nlohmann::json({1, -1}));
    CHECK(j["cells"][1]["sides"][1]["wall"] == "top");
    CHECK(j["cells"][1]["sides"][1]["neighbor"].is_null());
    CHECK(j["cells"][1]["neighbors"] == nlohmann::json({0, "wall:top"}));
}
