// The slab certificate of sites/separating_slab.hpp: against the exact
// distance and largest scale of two circles, on offset thin ellipses that the
// line of the centers does not separate, and never on crossing, nested or
// tangent pairs.
#include "sites/separating_slab.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

using namespace ellvor;

TEST_CASE("separating slab: circles, against the exact distance and scale", "[slab]") {
    std::mt19937_64 rng(5);
    std::uniform_int_distribution<long> coordinate(-1000, 1000), radius(1, 400);
    long apart = 0;
    for (int i = 0; i < 400; ++i) {
        const Ellipse c1 = Ellipse::circle(Rational(coordinate(rng), 100), Rational(coordinate(rng), 100),
                                           Rational(radius(rng), 100));
        const Ellipse c2 = Ellipse::circle(Rational(coordinate(rng), 100), Rational(coordinate(rng), 100),
                                           Rational(radius(rng), 100));
        const double dx = (c2.xc() - c1.xc()).to_double(), dy = (c2.yc() - c1.yc()).to_double();
        const double d = std::hypot(dx, dy), r1 = c1.a().to_double(), r2 = c2.a().to_double();
        const double distance = d - r1 - r2;  // for circles the slab along the centers is the best one
        const double width = certified_separation(SlabSite::of(c1), SlabSite::of(c2), 1e300);
        INFO("distance " << distance << ", width " << width);
        CHECK(width <= distance + 1e-12);
        if (distance > 1e-9) {
            ++apart;
            CHECK(width > distance - 1e-9);
        }
        const double gap = 1e-3, scale = (d - r2 - gap) / r1;
        const double certified = certified_separating_scale(SlabSite::of(c1), SlabSite::of(c2), gap, gap, 1e300);
        CHECK(certified <= std::max(scale, 0.0) + 1e-12);
        if (scale > 1e-6) CHECK(certified > scale - 1e-9);
    }
    CHECK(apart > 100);
}

TEST_CASE("separating slab: offset thin ellipses, separated off the line of the centers", "[slab]") {
    // Two needles 4 by 1/4 side by side, one 3 along and 1/2 + 1/1000 above
    // the other: their extents along the line of the centers overlap. Their
    // distance (about 0.0383) from 3000 x 3000 boundary points: an upper bound
    // within 2e-5.
    const Ellipse low(4, Rational(1, 4), 0, 0, 0), high(4, Rational(1, 4), 0, 3, Rational(501, 1000));
    double sampled = 1e300;
    const int n = 3000;
    for (int i = 0; i < n; ++i) {
        const double s = 2 * M_PI * i / n, x1 = 4 * std::cos(s), y1 = 0.25 * std::sin(s);
        for (int j = 0; j < n; ++j) {
            const double t = 2 * M_PI * j / n, x2 = 3 + 4 * std::cos(t), y2 = 0.501 + 0.25 * std::sin(t);
            sampled = std::min(sampled, std::hypot(x2 - x1, y2 - y1));
        }
    }
    const double width = certified_separation(SlabSite::of(low), SlabSite::of(high), 1e300);
    INFO("sampled distance " << sampled << ", certified width " << width);
    CHECK(width > sampled - 2e-5);
    CHECK(width <= sampled + 1e-12);
    const SlabSite a = SlabSite::of(low), b = SlabSite::of(high);
    const double nx = 3, ny = 0.501;  // along the centers: overlapping extents
    CHECK((nx * (b.xc - a.xc) + ny * (b.yc - a.yc) - support_enclosure(a, nx, ny) - support_enclosure(b, nx, ny)).hi <
          0);
    // the largest scale of the low needle keeping it 10^-3 away: more than 1, and it would
    // not fit at twice its size
    const double scale = certified_separating_scale(a, b, 1e-3, 1e-3, 1e300);
    CHECK(scale > 1);
    CHECK(scale < 2);
    // and with the gap at the distance (the width), about 1
    CHECK(certified_separating_scale(a, b, width, width, 1e300) < 1.001);
    CHECK(certified_separating_scale(a, b, width, width, 1e300) > 0.999);
}

TEST_CASE("separating slab: nothing proven for tangent, crossing and nested pairs", "[slab]") {
    const Ellipse low(4, Rational(1, 4), 0, 0, 0);
    const Ellipse tangent(4, Rational(1, 4), 0, 0, Rational(1, 2));  // touching at (0, 1/4)
    const Ellipse crossing(4, Rational(1, 4), 0, 1, Rational(1, 4));
    const Ellipse inside(1, Rational(1, 8), Rational(1, 3), 0, 0);
    for (const Ellipse* other : {&tangent, &crossing, &inside}) {
        CHECK(certified_separation(SlabSite::of(low), SlabSite::of(*other), 1e300) <= 0);
        CHECK(certified_separation(SlabSite::of(*other), SlabSite::of(low), 1e300) <= 0);
        CHECK(certified_separating_scale(SlabSite::of(low), SlabSite::of(*other), 0, 0, 1e300) < 1);
    }
}
