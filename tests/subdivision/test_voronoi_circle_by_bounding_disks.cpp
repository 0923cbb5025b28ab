// The Voronoi circle bounded by the sites' inscribed and circumscribed disks
// (subdivision/voronoi_circle_by_bounding_disks.hpp) against Arb's certified
// circle, and InCircle's stage on it (predicates/incircle.hpp) against the
// Arb stage alone.
#include "predicates/incircle.hpp"
#include "predicates/voronoi_circle_count.hpp"
#include "subdivision/voronoi_circle.hpp"
#include "subdivision/voronoi_circle_by_bounding_disks.hpp"
#include "subdivision/voronoi_circle_enclosure.hpp"
#include "traits/ellipse_delaunay_traits.hpp"
#include "tests/support/apollonius_oracle.hpp"
#include "tests/support/diagnostics.hpp"
#include "tests/support/random_sites.hpp"

#include <catch2/catch.hpp>

#include <cstdio>
#include <random>
#include <vector>

using namespace ellvor;
using ellvor::test::verbose;

namespace {

using Rng = std::mt19937_64;
using ellvor::test::bounding_circles_apart;
using ellvor::test::random_fraction;

// A site of aspect 1 to 10 (a fifth of them circles), semi-axes 1/10 to
// max_tenths / 10, center in [-half_box, half_box]^2.
Ellipse random_site(Rng& rng, long half_box, long max_tenths) {
    const Rational major = random_fraction(rng, 1, max_tenths, 10);
    const Rational x = random_fraction(rng, -1000 * half_box, 1000 * half_box, 1000);
    const Rational y = random_fraction(rng, -1000 * half_box, 1000 * half_box, 1000);
    if (std::uniform_int_distribution<int>(0, 4)(rng) == 0) return Ellipse::circle(x, y, major);
    const Rational minor = major / random_fraction(rng, 10, 100, 10);
    return Ellipse(major, minor, random_fraction(rng, -300, 300, 97), x, y);
}

// Three sites with their bounding circles apart; large sites against their
// distances in one triple out of three.
std::vector<Ellipse> random_triple(Rng& rng) {
    const long max_tenths = std::uniform_int_distribution<int>(0, 2)(rng) == 0 ? 60 : 15;
    std::vector<Ellipse> e;
    while (e.size() < 3) {
        Ellipse s = random_site(rng, 10, max_tenths);
        bool apart = true;
        for (const Ellipse& o : e) apart = apart && bounding_circles_apart(o, s);
        if (apart) e.push_back(s);
    }
    return e;
}

bool holds(const Interval& box, const Ball& b) {
    const Interval e = enclose(b);
    return box.lo <= e.lo && e.hi <= box.hi;
}

}  // namespace

TEST_CASE("bounding disks: the counter-clockwise circle lies in the Apollonius circle's bounds",
          "[subdivision][voronoi_circle_by_bounding_disks]") {
    // Arb's circle refined to 80 bits lies in every bound; no bound where the
    // disks are not uniformly counter-clockwise (there the triple's circle
    // may be the other one, or both may exist).
    Rng rng(20261130);
    int bounded = 0, elongated = 0, large = 0, clockwise = 0;
    for (int trial = 0; trial < 6000; ++trial) {
        const std::vector<Ellipse> e = random_triple(rng);
        const std::optional<CircleBounds> bounds = voronoi_circle_by_bounding_disks(e[0], e[1], e[2]);
        const int orientation = bounding_disks_orientation(e[0], e[1], e[2]);
        if (orientation < 0) {
            ++clockwise;
            CHECK(!bounds);
            CHECK(bounding_disks_orientation(e[0], e[2], e[1]) > 0);
        }
        if (!bounds) continue;
        REQUIRE(orientation > 0);
        ++bounded;
        INFO(apollonius::ell({&e[0], &e[1], &e[2]}));
        VoronoiCircleSolver arb(e[0], e[1], e[2]);
        REQUIRE(arb.certify());
        REQUIRE(arb.refine(80));
        const VoronoiCircleEnclosure& c = arb.enclosure();
        CHECK(holds(bounds->center_x, c.center_x));
        CHECK(holds(bounds->center_y, c.center_y));
        CHECK(holds(bounds->radius, c.radius));
        double aspect = 1, size = 0, closest = HUGE_VAL;
        for (int i = 0; i < 3; ++i) {
            const double a = e[i].a().to_double(), b = e[i].b().to_double();
            aspect = std::max(aspect, std::max(a, b) / std::min(a, b));
            size = std::max({size, a, b});
            const Ellipse& o = e[(i + 1) % 3];
            closest = std::min(closest, std::hypot(e[i].xc().to_double() - o.xc().to_double(),
                                                   e[i].yc().to_double() - o.yc().to_double()));
        }
        elongated += aspect > 5;
        large += size > closest / 4;
    }
    if (verbose())
        std::printf("[bounding disks] %d bounded (%d with a site of aspect > 5, %d with a site over a quarter of "
                    "the closest distance), %d clockwise\n",
                    bounded, elongated, large, clockwise);
    CHECK(bounded >= 1000);
    CHECK(elongated >= 200);
    CHECK(large >= 100);
    CHECK(clockwise >= 500);
}

TEST_CASE("InCircle decided by the bounding disks' circle agrees with the Arb stage alone",
          "[predicates][incircle][voronoi_circle_by_bounding_disks]") {
    // Each answer of incircle_by_bounding_disks is InCircle's answer and the
    // Arb stage's; a cache of circles asked through the traits makes no
    // entry for such a question, and one for a question the disks leave open.
    Rng rng(20261201);
    int by_disks = 0, beyond = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        std::vector<Ellipse> e = random_triple(rng);
        if (bounding_disks_orientation(e[0], e[1], e[2]) < 0) std::swap(e[1], e[2]);
        Ellipse q = random_site(rng, 10, 15);
        if (!bounding_circles_apart(q, e[0]) || !bounding_circles_apart(q, e[1]) || !bounding_circles_apart(q, e[2]))
            continue;
        const VoronoiCircles count = *voronoi_circle_count(e[0], e[1], e[2]);
        if (count != VoronoiCircles::ccw_only && count != VoronoiCircles::both) continue;
        INFO(apollonius::ell({&e[0], &e[1], &e[2], &q}));
        const Decision<InCircle> disks = incircle_by_bounding_disks(e[0], e[1], e[2], q);
        const Decision<InCircle> got = incircle(e[0], e[1], e[2], q);
        InCircleOptions arb;
        arb.use_filter = false;
        const Decision<InCircle> by_arb = incircle(e[0], e[1], e[2], q, arb);
        REQUIRE(got.is_decided());
        CHECK(by_arb.stage != Stage::filter);
        CHECK(*by_arb == *got);
        EllipseDelaunayTraits traits({e[0], e[1], e[2], q});
        CHECK(traits.incircle(0, 1, 2, 3) == incircle_sign(*got));
        if (disks.is_decided()) {
            ++by_disks;
            CHECK(disks.stage == Stage::filter);
            CHECK(*disks == *got);
            CHECK(traits.cached_circles() == 0);
        } else {
            ++beyond;
            CHECK(traits.cached_circles() == 1);
        }
    }
    if (verbose()) std::printf("[bounding disks] InCircle: %d decided by the disks, %d beyond\n", by_disks, beyond);
    CHECK(by_disks >= 500);
    CHECK(beyond >= 100);
}
