// SiteGrid proposes walk starts: its first answer must be a nearest added
// point (brute force over the added sites), whatever the spread of the points.
#include "graph/site_grid.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

using namespace ellvor;

namespace {

double distance(const std::vector<LocationHint>& points, SiteId a, SiteId b) {
    return std::hypot(points[a].x - points[b].x, points[a].y - points[b].y);
}

}  // namespace

TEST_CASE("SiteGrid: the first proposal is a nearest added point", "[graph][site-grid]") {
    std::mt19937_64 rng(2026);
    for (const long spread : {1L, 1000L, 1000000L}) {
        // Points on a thin strip or a square, up to 400 of them.
        for (const bool strip : {false, true}) {
            std::vector<LocationHint> points;
            for (int i = 0; i < 400; ++i) {
                const long x = static_cast<long>(rng() % 2000001) - 1000000;
                const long y = strip ? static_cast<long>(rng() % 3) : static_cast<long>(rng() % 2000001) - 1000000;
                points.push_back({static_cast<double>(x * spread) / 1e6, static_cast<double>(y * spread) / 1e6});
            }
            SiteGrid grid(points);
            CHECK(grid.near(0).empty());
            std::vector<SiteId> added;
            for (SiteId s = 0; s < points.size(); ++s) {
                if (!added.empty()) {
                    const std::vector<SiteId> proposals = grid.near(s);
                    REQUIRE_FALSE(proposals.empty());
                    double nearest = HUGE_VAL;
                    for (SiteId t : added) nearest = std::min(nearest, distance(points, s, t));
                    CHECK(distance(points, s, proposals.front()) == nearest);
                    for (SiteId t : proposals) CHECK(t < s);  // only added sites
                }
                if (rng() % 2) grid.add(s), added.push_back(s);
            }
        }
    }
}
