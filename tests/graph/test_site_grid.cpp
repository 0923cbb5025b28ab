// SiteGrid proposes walk starts: its first answer must be a nearest added
// center (brute force over the added sites), whatever the spread of the sites.
#include "graph/site_grid.hpp"


#include <catch2/catch.hpp>

#include <cmath>
#include <random>

using namespace ellvor;

namespace {

double center_distance(const DelaunayTraits& traits, SiteId a, SiteId b) {
    const auto &p = traits.site(a).enclosure(), &q = traits.site(b).enclosure();
    return std::hypot(p.xc.mid() - q.xc.mid(), p.yc.mid() - q.yc.mid());
}

}  // namespace

TEST_CASE("SiteGrid: the first proposal is a nearest added center", "[graph][site-grid]") {
    std::mt19937_64 rng(2026);
    for (const long spread : {1L, 1000L, 1000000L}) {
        // Sites on a thin strip or a square, up to 400 of them.
        for (const bool strip : {false, true}) {
            std::vector<Ellipse> sites;
            for (int i = 0; i < 400; ++i) {
                const long x = static_cast<long>(rng() % 2000001) - 1000000;
                const long y = strip ? static_cast<long>(rng() % 3) : static_cast<long>(rng() % 2000001) - 1000000;
                sites.push_back(Ellipse::circle(Rational(x * spread, 1000000UL), Rational(y * spread, 1000000UL),
                                                Rational(1, 1000UL)));
            }
            DelaunayTraits traits(sites);
            SiteGrid grid(traits);
            CHECK(grid.near(0).empty());
            std::vector<SiteId> added;
            for (SiteId s = 0; s < sites.size(); ++s) {
                if (!added.empty()) {
                    const std::vector<SiteId> proposals = grid.near(s);
                    REQUIRE_FALSE(proposals.empty());
                    double nearest = HUGE_VAL;
                    for (SiteId t : added) nearest = std::min(nearest, center_distance(traits, s, t));
                    CHECK(center_distance(traits, s, proposals.front()) == nearest);
                    for (SiteId t : proposals) CHECK(t < s);  // only added sites
                }
                if (rng() % 2) grid.add(s), added.push_back(s);
            }
        }
    }
}
