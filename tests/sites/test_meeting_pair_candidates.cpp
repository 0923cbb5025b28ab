// pairs_that_may_meet: every pair whose circumscribed disks meet (exactly,
// by the independent rational test) is listed, once, in the documented
// order, and spread-out sites give O(n) pairs, not all of them.
#include "sites/meeting_pair_candidates.hpp"
#include "tests/support/random_sites.hpp"

#include <catch2/catch.hpp>

#include <random>
#include <set>
#include <utility>
#include <vector>

using namespace ellvor;

namespace {

using Pairs = std::vector<std::pair<std::size_t, std::size_t>>;

// The listed pairs hold every pair with meeting disks, each once, i < j, by j then i.
void check_against_every_pair(const std::vector<Ellipse>& sites) {
    const Pairs listed = pairs_that_may_meet(sites);
    for (std::size_t k = 0; k < listed.size(); ++k) {
        INFO("pair " << listed[k].first << ", " << listed[k].second);
        REQUIRE(listed[k].first < listed[k].second);
        REQUIRE(listed[k].second < sites.size());
        if (k > 0) {
            const auto &x = listed[k - 1], &y = listed[k];
            REQUIRE((x.second < y.second || (x.second == y.second && x.first < y.first)));
        }
    }
    const std::set<std::pair<std::size_t, std::size_t>> found(listed.begin(), listed.end());
    for (std::size_t j = 0; j < sites.size(); ++j)
        for (std::size_t i = 0; i < j; ++i)
            if (!test::bounding_circles_apart(sites[i], sites[j])) {
                INFO("sites " << i << " and " << j << " have meeting disks");
                CHECK(found.count({i, j}) == 1);
            }
}

}  // namespace

TEST_CASE("pairs_that_may_meet: every pair with meeting disks, sizes from 10^-6 to 10^3 and far from the origin",
          "[sites][meeting-pairs]") {
    std::mt19937_64 rng(20261127);
    for (const long offset : {0L, 1000000000L}) {
        for (int set = 0; set < 4; ++set) {
            std::vector<Ellipse> sites;
            for (int k = 0; k < 300; ++k) {
                // Semi-axes of several scales, so that the grid has several levels.
                const long scale = 1L << (rng() % 5 * 5);  // 1 .. 2^20
                const Rational a = test::random_fraction(rng, 1, 1000, scale), b = test::random_fraction(rng, 1, 1000, scale);
                sites.emplace_back(a, b, test::random_fraction(rng, -9, 9, 10),
                                   Rational(offset) + test::random_fraction(rng, -2000, 2000, 100),
                                   test::random_fraction(rng, -2000, 2000, 100));
            }
            // A column and a row of equal circles touching their neighbours, and concentric sites.
            for (long k = 0; k < 20; ++k) {
                sites.push_back(Ellipse::circle(Rational(offset), Rational(2 * k), Rational(1)));
                sites.push_back(Ellipse::circle(Rational(offset + 2 * k), Rational(-50), Rational(1)));
                sites.emplace_back(Rational(k + 1), Rational(k + 2, 2UL), Rational(0), Rational(offset + 100), Rational(100));
            }
            INFO("offset " << offset << ", set " << set);
            check_against_every_pair(sites);
        }
    }
}

TEST_CASE("pairs_that_may_meet: spread-out sites give a few pairs a site, not every pair", "[sites][meeting-pairs]") {
    // 3000 unit-sized ellipses on a 60 x 50 lattice of spacing 3 (each disk meets at most its
    // eight neighbours') and a few large ones over them.
    std::mt19937_64 rng(7);
    std::vector<Ellipse> sites;
    for (long x = 0; x < 60; ++x)
        for (long y = 0; y < 50; ++y)
            sites.emplace_back(test::random_fraction(rng, 50, 150, 100), test::random_fraction(rng, 50, 150, 100),
                               test::random_fraction(rng, -9, 9, 10), Rational(3 * x), Rational(3 * y));
    for (long k = 0; k < 5; ++k) sites.push_back(Ellipse::circle(Rational(30 * k), Rational(70), Rational(10)));
    const Pairs listed = pairs_that_may_meet(sites);
    CHECK(listed.size() < 4 * sites.size());
    check_against_every_pair(sites);
}
