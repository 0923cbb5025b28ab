// Interval::up / down (util/interval.hpp): the next double above / below, as
// std::nextafter gives it (the oracle), on the special values and on random
// bit patterns of every exponent and sign; the outward rounding of every
// interval operation rests on them.
#include "util/interval.hpp"
#include "util/positive_divisor.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>

using namespace ellvor;

namespace {

void check_steps(double x) {
    const double inf = std::numeric_limits<double>::infinity();
    INFO("x = " << x);
    if (std::isnan(x)) {
        CHECK(std::isnan(Interval::up(x)));
        CHECK(std::isnan(Interval::down(x)));
        return;
    }
    // +inf stays, as -inf does going down; elsewhere nextafter's answer.
    const double want_up = x == inf ? inf : std::nextafter(x, inf);
    const double want_down = x == -inf ? -inf : std::nextafter(x, -inf);
    CHECK(Interval::up(x) == want_up);
    CHECK(Interval::down(x) == want_down);
}

}  // namespace

TEST_CASE("Interval::up and down step to the neighbouring double", "[interval]") {
    using limits = std::numeric_limits<double>;
    for (double x : {0.0, -0.0, 1.0, -1.0, 0.5, -0.5, limits::infinity(), -limits::infinity(), limits::quiet_NaN(),
                     limits::denorm_min(), -limits::denorm_min(), limits::min(), -limits::min(), limits::max(),
                     -limits::max()})
        check_steps(x);
    // The sign of zero does not matter: both step to the least subnormal.
    CHECK(Interval::up(-0.0) == limits::denorm_min());
    CHECK(Interval::down(0.0) == -limits::denorm_min());
    std::mt19937_64 rng(20261127);
    for (int n = 0; n < 1000000; ++n) {
        const std::uint64_t bits = rng();
        double x;
        std::memcpy(&x, &bits, sizeof x);
        check_steps(x);
    }
}

TEST_CASE("Interval products: the NaN-ignoring hull of the four endpoint products, rounded outward", "[interval]") {
    // The oracle: std::fmin / std::fmax (a NaN operand yields the other one,
    // so 0 * inf is ignored) of the four products, then nextafter outward.
    using limits = std::numeric_limits<double>;
    const double inf = limits::infinity();
    const double endpoints[] = {0.0, -0.0, 1.0, -1.0, 3.5, -2.25, inf, -inf, limits::denorm_min(), -limits::max(), 1e300};
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> uniform(-10, 10);
    auto pick = [&](int n) { return n < 11 ? endpoints[n] : uniform(rng); };
    std::uniform_int_distribution<int> choice(0, 14);
    int with_nan_product = 0;
    for (int n = 0; n < 200000; ++n) {
        double a0 = pick(choice(rng)), a1 = pick(choice(rng)), b0 = pick(choice(rng)), b1 = pick(choice(rng));
        const Interval a(std::fmin(a0, a1), std::fmax(a0, a1)), b(std::fmin(b0, b1), std::fmax(b0, b1));
        const double p[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
        double lo = p[0], hi = p[0];
        for (double x : p) lo = std::fmin(lo, x), hi = std::fmax(hi, x);
        with_nan_product += std::isnan(p[0]) || std::isnan(p[1]) || std::isnan(p[2]) || std::isnan(p[3]);
        const Interval c = a * b;
        INFO(a.lo << " " << a.hi << " times " << b.lo << " " << b.hi);
        if (std::isnan(lo)) {  // every product 0 * inf
            CHECK(std::isnan(c.lo));
            CHECK(std::isnan(c.hi));
            continue;
        }
        CHECK(c.lo == (lo == -inf ? -inf : std::nextafter(lo, -inf)));
        CHECK(c.hi == (hi == inf ? inf : std::nextafter(hi, inf)));
    }
    CHECK(with_nan_product > 1000);  // the 0 * inf path is exercised
}

TEST_CASE("divide_by_positive is operator/ by a positive divisor, bit for bit", "[interval]") {
    // Two quotients instead of operator/'s four (ArrivalNormalBox's hot
    // path): the very doubles, on special and random endpoints, infinite and
    // signed-zero ones included (inf / inf goes to operator/).
    using limits = std::numeric_limits<double>;
    const double inf = limits::infinity();
    const double endpoints[] = {0.0, -0.0, 1.0, -1.0, 3.5, -2.25, inf, -inf, limits::denorm_min(), -limits::max(), 1e300};
    const double positive[] = {limits::denorm_min(), 1.0, 3.5, 1e300, limits::max(), inf};
    auto bits_of = [](double x) {
        std::uint64_t b;
        std::memcpy(&b, &x, sizeof b);
        return b;
    };
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> uniform(-10, 10), above_zero(1e-3, 10);
    std::uniform_int_distribution<int> choice(0, 14), positive_choice(0, 8);
    auto pick = [&](int n) { return n < 11 ? endpoints[n] : uniform(rng); };
    auto pick_positive = [&](int n) { return n < 6 ? positive[n] : above_zero(rng); };
    for (int n = 0; n < 200000; ++n) {
        const double a0 = pick(choice(rng)), a1 = pick(choice(rng)), b0 = pick_positive(positive_choice(rng)),
                     b1 = pick_positive(positive_choice(rng));
        const Interval a(std::fmin(a0, a1), std::fmax(a0, a1)), b(std::fmin(b0, b1), std::fmax(b0, b1));
        const Interval fast = divide_by_positive(a, b), general = a / b;
        INFO(a.lo << " " << a.hi << " over " << b.lo << " " << b.hi);
        CHECK(bits_of(fast.lo) == bits_of(general.lo));
        CHECK(bits_of(fast.hi) == bits_of(general.hi));
    }
}

TEST_CASE("Interval::around is {down(x), up(x)}, bit for bit", "[interval]") {
    // around() steps the bit pattern itself (the fast path of an Ellipse's
    // enclosures); it must give the very doubles down() and up() give, on
    // random patterns (subnormals, huge, negative) and on the edge cases.
    auto bits_of = [](double x) {
        std::uint64_t b;
        std::memcpy(&b, &x, sizeof b);
        return b;
    };
    auto same = [&](double x) {
        const Interval r = Interval::around(x);
        return bits_of(r.lo) == bits_of(Interval::down(x)) && bits_of(r.hi) == bits_of(Interval::up(x));
    };
    std::mt19937_64 rng(52);
    for (int k = 0; k < 200000; ++k) {
        const std::uint64_t b = rng();
        double x;
        std::memcpy(&x, &b, sizeof x);
        if (x != x) continue;  // NaN: checked below
        INFO("x = " << x);
        REQUIRE(same(x));
        REQUIRE(same(x / 0x1p1000));  // toward the subnormals
    }
    const double inf = std::numeric_limits<double>::infinity();
    for (double x : {0.0, -0.0, std::numeric_limits<double>::denorm_min(), -std::numeric_limits<double>::denorm_min(),
                     std::numeric_limits<double>::min(), std::numeric_limits<double>::max(),
                     -std::numeric_limits<double>::max(), 1.0, -1.0, 0.5, inf, -inf})
        CHECK(same(x));
    const Interval n = Interval::around(std::nan(""));
    CHECK((n.lo != n.lo && n.hi != n.hi));
}
