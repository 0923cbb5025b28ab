#include "sites/ellipse.hpp"
#include "util/error.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

using namespace ellvor;

namespace {
Rational random_rational(std::mt19937_64& rng, long num_range, unsigned long den_max) {
    std::uniform_int_distribution<long> n(-num_range, num_range);
    std::uniform_int_distribution<unsigned long> d(1, den_max);
    return Rational(n(rng), d(rng));
}
}  // namespace

TEST_CASE("ellipse boundary points lie on the implicit conic, including the i-point", "[sites][ellipse]") {
    std::mt19937_64 rng(7);
    for (int trial = 0; trial < 200; ++trial) {
        Rational a(std::uniform_int_distribution<long>(1, 50)(rng), 7);
        Rational b(std::uniform_int_distribution<long>(1, 50)(rng), 5);
        Ellipse e(a, b, random_rational(rng, 30, 11), random_rational(rng, 100, 13), random_rational(rng, 100, 3));
        for (int k = 0; k < 5; ++k) {
            Point p = e.point_at(random_rational(rng, 40, 9));
            REQUIRE(e.conic_value(p.x, p.y).is_zero());
        }
        Point ip = e.i_point();
        REQUIRE(e.side_of_point(ip.x, ip.y) == 0);
        REQUIRE(e.side_of_point(e.xc(), e.yc()) == -1);
        // Far away is outside.
        REQUIRE(e.side_of_point(e.xc() + Rational(1000), e.yc()) == 1);
    }
}

TEST_CASE("ellipse parametrization matches the trigonometric form", "[sites][ellipse]") {
    // a = 3, b = 1, w = 1/2 (omega = 2 atan(1/2)), center (1, -2)
    Ellipse e(3, 1, Rational(1, 2), 1, -2);
    const double omega = 2 * std::atan(0.5);
    for (double t : {-3.0, -0.5, 0.0, 0.25, 2.0}) {
        const double theta = 2 * std::atan(t);
        const double x = 1 + 3 * std::cos(omega) * std::cos(theta) - 1 * std::sin(omega) * std::sin(theta);
        const double y = -2 + 3 * std::sin(omega) * std::cos(theta) + 1 * std::cos(omega) * std::sin(theta);
        Rational tq(static_cast<long>(t * 4), 4);
        Point p = e.point_at(tq);
        CHECK(p.x.to_double() == Approx(x).margin(1e-12));
        CHECK(p.y.to_double() == Approx(y).margin(1e-12));
        BallPoint pb = e.point_at(Ball(tq, 128), 128);
        CHECK(pb.x.contains(p.x));
        CHECK(pb.y.contains(p.y));
    }
    Point ip = e.i_point();
    CHECK(ip.x.to_double() == Approx(1 - 3 * std::cos(omega)));
    CHECK(ip.y.to_double() == Approx(-2 - 3 * std::sin(omega)));
}

TEST_CASE("ellipse rejects non-positive axes", "[sites][ellipse]") {
    CHECK_THROWS_AS(Ellipse(0, 1, 0, 0, 0), Error);
    CHECK_THROWS_AS(Ellipse(1, Rational(-1, 2), 0, 0, 0), Error);
}

TEST_CASE("point_set_key is equal exactly for the same point set", "[sites][ellipse]") {
    std::mt19937_64 rng(11);
    for (int trial = 0; trial < 50; ++trial) {
        const Rational a = Rational(1 + trial % 7, 1 + trial % 3), b = a + Rational(1, 1 + trial % 5);
        Rational w = random_rational(rng, 5, 4);
        if (w == Rational(1) || w.sign() == 0) w = Rational(1, 3);
        const Rational x = random_rational(rng, 100, 7), y = random_rational(rng, 100, 7);
        const Ellipse e(a, b, w, x, y);
        // A half turn (w -> -1/w) and swapped axes with a quarter turn (w -> (1 + w) / (1 - w)).
        CHECK(Ellipse(a, b, Rational(-1) / w, x, y).point_set_key() == e.point_set_key());
        CHECK(Ellipse(b, a, (Rational(1) + w) / (Rational(1) - w), x, y).point_set_key() == e.point_set_key());
        // Another rotation, size, axis ratio or center is another point set.
        CHECK(Ellipse(a, b, w + Rational(1, 2), x, y).point_set_key() != e.point_set_key());
        CHECK(Ellipse(a * Rational(2), b * Rational(2), w, x, y).point_set_key() != e.point_set_key());
        CHECK(Ellipse(a, b + Rational(1), w, x, y).point_set_key() != e.point_set_key());
        CHECK(Ellipse(a, b, w, x, y + Rational(1, 1000)).point_set_key() != e.point_set_key());
    }
    // A circle's rotation does not matter.
    CHECK(Ellipse(Rational(2), Rational(2), Rational(3), Rational(1), Rational(1)).point_set_key() ==
          Ellipse::circle(Rational(1), Rational(1), Rational(2)).point_set_key());
}
