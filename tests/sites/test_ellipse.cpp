#include "sites/ellipse.hpp"
#include "util/error.hpp"
#include "util/interval.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <thread>
#include <vector>

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

namespace {
// n / 2^k, |n| < 2^53, 0 <= k <= 61: a small dyadic rational (an exact double).
Rational random_dyadic(std::mt19937_64& rng, bool positive) {
    const int bits = static_cast<int>(rng() % 53), k = static_cast<int>(rng() % 62);
    long n = static_cast<long>(rng() >> (64 - bits - 1)) >> 1;  // below 2^bits
    if (positive) n = std::max(n, 1L);
    else if (rng() % 2) n = -n;
    Rational q(n, 1);
    fmpq_div_2exp(q.get(), q.get(), static_cast<ulong>(k));
    return q;
}
}  // namespace

TEST_CASE("a circle kept as its doubles gives back its exact parameters", "[sites][ellipse]") {
    // A circle of rotation 0 with small dyadic radius and center keeps only
    // doubles until an exact stage asks; everything read from it must equal
    // what an ellipse keeping its rationals gives: the parameters, the
    // enclosures, and (independently) the conic and the point-set key of
    // the same circle given a rotation, which keeps its rationals.
    std::mt19937_64 rng(64);
    for (int trial = 0; trial < 300; ++trial) {
        const Rational r = random_dyadic(rng, true), x = random_dyadic(rng, false), y = random_dyadic(rng, false);
        REQUIRE(r.is_small_dyadic());
        const Ellipse c = Ellipse::circle(x, y, r);
        const Ellipse copy = c;  // before anything exact was made
        CHECK(c.is_circle());
        CHECK(c.is_dyadic_circle());
        const Ellipse::Enclosure k = c.enclosure();
        CHECK((k.a.lo == enclose(r).lo && k.a.hi == enclose(r).hi && k.b.lo == k.a.lo && k.b.hi == k.a.hi));
        CHECK((k.xc.lo == enclose(x).lo && k.xc.hi == enclose(x).hi && k.yc.lo == enclose(y).lo && k.yc.hi == enclose(y).hi));
        CHECK((k.cos.lo == enclose(Rational(1)).lo && k.cos.hi == enclose(Rational(1)).hi));
        CHECK((k.sin.lo == enclose(Rational(0)).lo && k.sin.hi == enclose(Rational(0)).hi));
        const Ellipse rotated(r, r, Rational(1, 3), x, y);  // the same point set, rationals kept
        CHECK(rotated.is_dyadic_circle());
        CHECK(c.point_set_key() == rotated.point_set_key());  // before the parameters are made
        CHECK(c.a() == r);
        CHECK(c.b() == r);
        CHECK(c.w().is_zero());
        CHECK(c.xc() == x);
        CHECK(c.yc() == y);
        CHECK(c.str() == r.str() + " " + r.str() + " 0 " + x.str() + " " + y.str());
        CHECK(c.conic() == rotated.conic());
        CHECK(c.point_set_key() == rotated.point_set_key());
        // Copies made before and after, assignment and unshared() agree.
        Ellipse assigned = rotated;
        assigned = copy;
        for (const Ellipse* e : {&copy, static_cast<const Ellipse*>(&assigned)}) {
            CHECK(*e == c);
            CHECK(e->xc() == x);
            CHECK(e->str() == c.str());
        }
        const Ellipse own = c.unshared();
        CHECK(own == c);
        CHECK(&own.a() != &c.a());
        CHECK(own.conic() == c.conic());
        // Equality is of the parameters: the rotated circle is another tuple,
        // and a circle one ulp larger another circle.
        CHECK(c != rotated);
        CHECK(rotated != c);
        CHECK(c != Ellipse::circle(x, y, r + r));
    }
}

TEST_CASE("circles that keep their rationals: not dyadic, or rotated", "[sites][ellipse]") {
    const Ellipse third = Ellipse::circle(Rational(1, 3), Rational(-2), Rational(1, 3));
    CHECK(third.is_circle());
    CHECK(!third.is_dyadic_circle());
    CHECK(third.str() == "1/3 1/3 0 1/3 -2");
    const Ellipse turned(Rational(1, 2), Rational(1, 2), Rational(3, 4), Rational(5), Rational(6));
    CHECK(turned.is_dyadic_circle());
    CHECK(turned.w() == Rational(3, 4));
    CHECK(turned.str() == "1/2 1/2 3/4 5 6");
    const Ellipse unturned = Ellipse::circle(Rational(5), Rational(6), Rational(1, 2));
    CHECK(turned.point_set_key() == unturned.point_set_key());
    CHECK(turned.conic() == unturned.conic());
    CHECK(turned != unturned);
    const Ellipse e(Rational(3), Rational(2), Rational(1, 5), Rational(1, 7), Rational(2));
    const Ellipse own = e.unshared();
    CHECK(own == e);
    CHECK(&own.a() != &e.a());
    CHECK(own.conic() == e.conic());
    // make_own: a copy gets its own parameters; a sole holder keeps them.
    Ellipse shared = e, sole(Rational(3), Rational(2), Rational(1, 5), Rational(1, 7), Rational(2));
    const Rational* before = &sole.a();
    shared.make_own();
    sole.make_own();
    CHECK(&shared.a() != &e.a());
    CHECK(shared == e);
    CHECK(&sole.a() == before);
    // The copy keeps the enclosures (copied, not remade): the same bits.
    const auto same_bits = [](const Interval& x, const Interval& y) { return x.lo == y.lo && x.hi == y.hi; };
    const Ellipse::Enclosure k = e.enclosure(), m = shared.enclosure();
    CHECK((same_bits(k.a, m.a) && same_bits(k.b, m.b) && same_bits(k.cos, m.cos) && same_bits(k.sin, m.sin) &&
           same_bits(k.xc, m.xc) && same_bits(k.yc, m.yc)));
    // unshared_copies: each equal, none sharing; a compact circle stays compact (its doubles).
    const std::vector<Ellipse> sites = {e, third, unturned, turned, e};
    const std::vector<Ellipse> copies = Ellipse::unshared_copies(sites);
    REQUIRE(copies.size() == sites.size());
    for (std::size_t k = 0; k < sites.size(); ++k) {
        CHECK(copies[k] == sites[k]);
        CHECK(&copies[k].a() != &sites[k].a());
    }
}

TEST_CASE("threads asking a circle's parameters at once agree", "[sites][ellipse]") {
    // The first exact question makes them (compare and swap): every thread
    // must get the one kept, whichever made it.
    for (int trial = 0; trial < 20; ++trial) {
        const Ellipse c = Ellipse::circle(Rational(trial, 4), Rational(-3), Rational(2 * trial + 1, 8));
        std::vector<const Rational*> seen(4, nullptr);
        std::vector<std::array<Rational, 6>> conics(4);
        std::vector<std::thread> threads;
        for (int t = 0; t < 4; ++t)
            threads.emplace_back([&, t] {
                seen[t] = &c.a();
                conics[t] = c.conic();
            });
        for (std::thread& t : threads) t.join();
        for (int t = 0; t < 4; ++t) {
            CHECK(seen[t] == &c.a());
            CHECK(conics[t] == c.conic());
        }
        CHECK(*seen[0] == Rational(2 * trial + 1, 8));
    }
}
