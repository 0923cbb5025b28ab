// The decimal text of balls: printed bounds enclose the ball (checked by
// reading them back exactly), are tight, and "certain digits" are within one
// unit of their last digit of every point of the ball.
#include "output/outward_decimal.hpp"
#include "sites/rational_parse.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <string>

using namespace ellvor;

namespace {

// A ball mid +- rad with mid = m * 2^e1 and rad = r * 2^e2 (exact dyadics).
Ball ball(long m, long e1, long r, long e2) {
    Ball b;
    arf_set_si_2exp_si(arb_midref(b.get()), m, e1);
    mag_set_ui_2exp_si(arb_radref(b.get()), static_cast<ulong>(r), e2);
    return b;
}

// One unit of the last digit written in `text` (no trailing zeros dropped).
Rational last_digit_unit(const std::string& text) {
    const std::size_t e = text.find('e');
    const std::string mantissa = text.substr(0, e);
    const std::size_t dot = mantissa.find('.');
    const long fraction_digits = dot == std::string::npos ? 0 : static_cast<long>(mantissa.size() - dot - 1);
    const long exponent = e == std::string::npos ? 0 : std::stol(text.substr(e + 1));
    return power_of_ten(exponent - fraction_digits);
}

}  // namespace

TEST_CASE("decimal_bounds: the printed bounds enclose the ball and are tight", "[output][decimal]") {
    std::mt19937_64 rng(7);
    std::uniform_int_distribution<long> mantissa(-(1L << 52), 1L << 52), exponent(-220, 160);
    std::uniform_int_distribution<long> radius(0, 1L << 20), radius_exponent(-80, 0);
    for (int k = 0; k < 2000; ++k) {
        const long e1 = exponent(rng);
        const Ball b = ball(mantissa(rng), e1, radius(rng), e1 + 52 + radius_exponent(rng) - 20);
        Rational lo, hi;
        ball_endpoints(b, lo, hi);
        const DecimalBounds text = decimal_bounds(b);
        const Rational printed_lo = parse_rational(text.lo), printed_hi = parse_rational(text.hi);
        INFO(b.str() << " -> " << text.lo << " " << text.hi);
        REQUIRE(printed_lo <= lo);
        REQUIRE(hi <= printed_hi);
        // 17 significant digits at least: each bound moved by < 1e-16 of itself.
        const Rational slack = Rational(1, 10000000000000000UL);
        const Rational size_lo = lo.sign() < 0 ? -lo : lo, size_hi = hi.sign() < 0 ? -hi : hi;
        CHECK(lo - printed_lo <= size_lo * slack);
        CHECK(printed_hi - hi <= size_hi * slack);
        // The doubles are outward too.
        const auto [dlo, dhi] = double_bounds(b);
        Rational qlo, qhi;
        Arf x;
        arf_set_d(x.get(), dlo);
        arf_get_fmpq(qlo.get(), x.get());
        arf_set_d(x.get(), dhi);
        arf_get_fmpq(qhi.get(), x.get());
        CHECK(qlo <= lo);
        CHECK(hi <= qhi);
    }
}

TEST_CASE("decimal_bounds: a width of 1e-30 stays visible; special balls", "[output][decimal]") {
    // 1 +- 2^-100 (about 8e-31): more than 30 digits are printed.
    const Ball b = ball(1, 0, 1, -100);
    const DecimalBounds t = decimal_bounds(b);
    CHECK(t.lo.size() > 32);
    CHECK(parse_rational(t.lo) < Rational(1));
    CHECK(parse_rational(t.hi) > Rational(1));
    // The width is 2^-99 (1.58e-30): printed within 2e-30.
    CHECK(parse_rational(t.hi) - parse_rational(t.lo) < Rational(2) * power_of_ten(-30));

    Ball inf;
    arb_pos_inf(inf.get());
    CHECK(decimal_bounds(inf).lo == "inf");
    CHECK(decimal_bounds(inf).hi == "inf");
    Ball none;
    arb_indeterminate(none.get());
    CHECK(decimal_bounds(none).lo == "nan");
    CHECK(std::isnan(double_bounds(none).first));
    CHECK(certain_digits(none) == "nan");
    CHECK(decimal_bounds(Ball(Rational(0), 64)).lo == "0");
    CHECK(decimal_bounds(Ball(Rational(-5, 4UL), 64)).lo == "-1.25");
    CHECK(decimal_text(round_decimal(Rational(3, 1UL) * power_of_ten(25), 17, Rounding::up)) == "3e25");
    CHECK(decimal_text(round_decimal(Rational(31, 100000UL), 17, Rounding::down)) == "0.00031");
    CHECK(decimal_text(round_decimal(Rational(-2, 3UL), 3, Rounding::down)) == "-0.667");
    CHECK(decimal_text(round_decimal(Rational(-2, 3UL), 3, Rounding::up)) == "-0.666");
}

TEST_CASE("certain_digits: every point of the ball within one unit of the last digit", "[output][decimal]") {
    std::mt19937_64 rng(11);
    std::uniform_int_distribution<long> mantissa(1, 1L << 52), exponent(-120, 120), radius_exponent(-90, 0);
    for (int k = 0; k < 2000; ++k) {
        const long e1 = exponent(rng);
        const Ball b = ball(mantissa(rng), e1, 1, e1 + radius_exponent(rng));
        Rational lo, hi;
        ball_endpoints(b, lo, hi);
        const std::string text = certain_digits(b);
        INFO(b.str() << " -> " << text);
        REQUIRE(text != "nan");
        const Rational d = parse_rational(text), unit = last_digit_unit(text);
        REQUIRE(d - unit <= lo);
        REQUIRE(hi <= d + unit);
    }
    // pi to Arb's 128 bits: 17 certain digits, the first of them those of pi.
    Ball pi;
    arb_const_pi(pi.get(), 128);
    CHECK(certain_digits(pi) == "3.1415926535897932");
    // A wide ball: few digits.
    CHECK(certain_digits(ball(3, 0, 1, -4)) == "3.0");
}
