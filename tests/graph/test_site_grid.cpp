// SiteGrid proposes walk starts: its answer must be a nearest added point
// (brute force over the added sites), whatever the spread of the points, and
// one that the caller accepts.
#include "graph/site_grid.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>

using namespace ellvor;

namespace {

double distance(const std::vector<LocationHint>& points, SiteId a, SiteId b) {
    return std::hypot(points[a].x - points[b].x, points[a].y - points[b].y);
}

}  // namespace

TEST_CASE("SiteGrid: the proposal is a nearest added point", "[graph][site-grid]") {
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
            SiteGrid grid{std::vector<LocationHint>(points)};
            auto any = [](SiteId) { return true; };
            auto odd = [](SiteId t) { return t % 2 == 1; };
            CHECK_FALSE(grid.nearest(0, any));
            std::vector<SiteId> added;
            for (SiteId s = 0; s < points.size(); ++s) {
                if (!added.empty()) {
                    const std::optional<SiteId> proposal = grid.nearest(s, any);
                    REQUIRE(proposal);
                    double nearest = HUGE_VAL;
                    for (SiteId t : added) nearest = std::min(nearest, distance(points, s, t));
                    CHECK(distance(points, s, *proposal) == nearest);
                    CHECK(std::find(added.begin(), added.end(), *proposal) != added.end());  // only added sites
                    // Restricted to odd ids: an added odd site, and none nearer
                    // among the odd ones (when the nearest added site is odd, it).
                    if (const std::optional<SiteId> o = grid.nearest(s, odd)) {
                        CHECK(*o % 2 == 1);
                        CHECK(std::find(added.begin(), added.end(), *o) != added.end());
                        if (*proposal % 2 == 1) CHECK(distance(points, s, *o) == nearest);
                    }
                }
                if (rng() % 2) grid.add(s), added.push_back(s);
            }
        }
    }
}
