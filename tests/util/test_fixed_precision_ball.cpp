// FixedPrecisionBall (util/fixed_precision_ball.hpp): every operation holds
// the exact result of its operands (random doubles, exact balls carrying 53
// to 300 bits, against Arb at 2000 bits: exact for sums and products,
// within 2^-1990 for quotients and roots) and rounds once, to the larger
// operand's precision: its radius is at most 2^(1 - prec) of the result. A
// double meets a ball at the ball's precision, two doubles at 106 bits. The
// square root of a ball that is not positive is indeterminate.
#include "util/fixed_precision_ball.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <random>
#include <string>

using namespace ellvor;

namespace {

constexpr long kExact = 2000;

Ball exact(double x) { return Ball(Rational::of_double(x), kExact); }

}  // namespace

TEST_CASE("FixedPrecisionBall: each operation holds the exact result, rounded once at the larger operand's precision",
          "[util][fixed-precision-ball]") {
    std::mt19937_64 rng(29);
    std::uniform_int_distribution<long> precision(53, 300);
    std::uniform_real_distribution<double> mantissa(1, 2), exponent(-30, 30);
    const auto random_double = [&](bool positive) {
        const double x = std::ldexp(mantissa(rng), static_cast<int>(exponent(rng)));
        return positive || rng() % 2 ? x : -x;
    };
    struct Operation {
        std::string name;
        bool unary;
        std::function<FixedPrecisionBall(const FixedPrecisionBall&, const FixedPrecisionBall&)> ball;
        std::function<void(arb_t, const arb_t, const arb_t, long)> exact;
    };
    const Operation operations[] = {
        {"+", false, [](auto& x, auto& y) { return x + y; }, arb_add},
        {"-", false, [](auto& x, auto& y) { return x - y; }, arb_sub},
        {"*", false, [](auto& x, auto& y) { return x * y; }, arb_mul},
        {"/", false, [](auto& x, auto& y) { return x / y; }, arb_div},
        {"square", true, [](auto& x, auto&) { return square(x); },
         [](arb_t r, const arb_t x, const arb_t, long p) { arb_sqr(r, x, p); }},
        {"root_of", true, [](auto& x, auto&) { return root_of(x); },
         [](arb_t r, const arb_t x, const arb_t, long p) { arb_sqrt(r, x, p); }},
        {"negation", true, [](auto& x, auto&) { return -x; }, [](arb_t r, const arb_t x, const arb_t, long) { arb_neg(r, x); }},
    };
    for (const Operation& op : operations)
        for (int trial = 0; trial < 5000; ++trial) {
            const double a = random_double(true), b = random_double(false);
            const long pa = precision(rng), pb = precision(rng);
            const FixedPrecisionBall x(a, pa), y(b, pb);
            const FixedPrecisionBall r = op.ball(x, y);
            Ball truth;
            op.exact(truth.get(), exact(a).get(), exact(b).get(), kExact);
            INFO(op.name << " of " << a << " at " << pa << " bits and " << b << " at " << pb << " bits");
            CHECK(arb_contains(r.ball().get(), truth.get()));
            const long p = op.unary ? pa : std::max(pa, pb);
            CHECK(r.precision() == p);
            CHECK(r.ball().radius_double() <= std::ldexp(std::fabs(r.ball().mid_double()), static_cast<int>(1 - p)));
        }
}

TEST_CASE("FixedPrecisionBall: doubles convert exactly and meet at 106 bits; roots of non-positive balls are indeterminate",
          "[util][fixed-precision-ball]") {
    const FixedPrecisionBall third(Ball(Rational(1, 3), 200), 200);
    CHECK((third * 0.1).precision() == 200);
    CHECK((2.0 * third).precision() == 200);
    const FixedPrecisionBall product = FixedPrecisionBall(0.1) * FixedPrecisionBall(0.7);
    CHECK(product.precision() == 106);
    CHECK(arb_is_exact(product.ball().get()));  // two doubles' product: exact at 106 bits
    CHECK(FixedPrecisionBall(0.1, 80).precision() == 80);
    CHECK(arb_is_exact(FixedPrecisionBall(0.1).ball().get()));
    CHECK(!arb_is_finite(root_of(FixedPrecisionBall(-1.0, 64)).ball().get()));
    CHECK(!arb_is_finite(root_of(third - third).ball().get()));  // contains zero
    CHECK(arb_is_finite(root_of(third).ball().get()));
}
