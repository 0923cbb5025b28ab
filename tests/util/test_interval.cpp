// Interval::up / down (util/interval.hpp): the next double above / below, as
// std::nextafter gives it (the oracle), on the special values and on random
// bit patterns of every exponent and sign; the outward rounding of every
// interval operation rests on them.
#include "util/interval.hpp"

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
