// UpwardBall (util/upward_ball.hpp): every operation, computed under the
// upward rounding mode, encloses the exact range of the operation over its
// operand balls (Arb at 4200 bits: exact for sums and products of doubles,
// within 2^-4000 for quotients and roots), or is not finite. Random
// midpoints of every magnitude and sign, radii from zero to beyond the
// midpoint; overflow (below the range too, where rounding up stops at
// -DBL_MAX) must give a ball that is not finite.
//
// This file is compiled with the ROUNDING_MATH flags (Makefile).
#include "util/upward_ball.hpp"

#include <catch2/catch.hpp>

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <functional>
#include <random>

using namespace ellvor;

namespace {

constexpr long kPrec = 4200;

Ball exact(double x) { return Ball(Rational::of_double(x), kPrec); }

// The exact reals mid - rad and mid + rad of a ball.
struct Ends {
    Ball lo, hi;
};
Ends ends(const UpwardBall& x) {
    Ends e;
    arb_sub(e.lo.get(), exact(x.mid).get(), exact(x.rad).get(), kPrec);
    arb_add(e.hi.get(), exact(x.mid).get(), exact(x.rad).get(), kPrec);
    return e;
}

// A result and its ends, lower() and upper(), computed in the scope (they
// round too).
struct Result {
    UpwardBall ball;
    double lower = 0, upper = 0;
    bool finite() const { return ball.finite(); }
};

// The result encloses [lo, hi]: its lower end below every point of lo, its
// upper end above every point of hi.
bool encloses(const Result& r, const Ball& lo, const Ball& hi) {
    return arb_le(exact(r.lower).get(), lo.get()) && arb_ge(exact(r.upper).get(), hi.get());
}

double random_double(std::mt19937_64& rng, int max_exponent) {
    const int kind = std::uniform_int_distribution<int>(0, 19)(rng);
    const double sign = rng() & 1 ? -1.0 : 1.0;
    if (kind == 0) return sign * 0.0;
    if (kind == 1) return sign * double(std::uniform_int_distribution<int>(1, 8)(rng));
    const double mantissa = 1.0 + double(rng() >> 12) * 0x1p-52;
    const int exponent = kind == 2 ? std::uniform_int_distribution<int>(-1074, -1000)(rng)
                                   : std::uniform_int_distribution<int>(-max_exponent, max_exponent)(rng);
    return sign * std::ldexp(mantissa, exponent);
}

// A ball: a random midpoint, a radius of zero, of a few ulps of it, or of
// any size (also larger than the midpoint).
UpwardBall random_ball(std::mt19937_64& rng, int max_exponent) {
    const double m = random_double(rng, max_exponent);
    switch (std::uniform_int_distribution<int>(0, 3)(rng)) {
        case 0: return UpwardBall(m);
        case 1: return {m, std::fabs(m) * 0x1p-50};
        default: return {m, std::fabs(random_double(rng, max_exponent))};
    }
}

struct Count {
    long cases = 0, enclosing = 0, not_finite = 0;
};

void tally(Count& n, const Result& r, const Ball& lo, const Ball& hi) {
    ++n.cases;
    if (!r.finite()) {
        ++n.not_finite;
        return;
    }
    if (encloses(r, lo, hi)) ++n.enclosing;
}

template <class F>
Result upward(F f) {
    const UpwardRoundingScope scope;
    const UpwardBall b = f();
    return {b, b.lower(), b.upper()};
}

Ball smaller(const Ball& a, const Ball& b) { return arb_le(a.get(), b.get()) ? a : b; }
Ball larger(const Ball& a, const Ball& b) { return arb_ge(a.get(), b.get()) ? a : b; }

// The exact range of a product over two balls: the extremes of the four end products.
void product_range(const Ends& a, const Ends& b, Ball& lo, Ball& hi) {
    Ball p[4];
    arb_mul(p[0].get(), a.lo.get(), b.lo.get(), kPrec);
    arb_mul(p[1].get(), a.lo.get(), b.hi.get(), kPrec);
    arb_mul(p[2].get(), a.hi.get(), b.lo.get(), kPrec);
    arb_mul(p[3].get(), a.hi.get(), b.hi.get(), kPrec);
    lo = smaller(smaller(p[0], p[1]), smaller(p[2], p[3]));
    hi = larger(larger(p[0], p[1]), larger(p[2], p[3]));
}

using Check = std::function<void(Count&, std::mt19937_64&)>;

// a + b, or a - b: the exact range [lo_a + lo_b, hi_a + hi_b], or [lo_a - hi_b, hi_a - lo_b].
void check_sum(Count& n, std::mt19937_64& rng, bool difference) {
    const UpwardBall a = random_ball(rng, 1023), b = random_ball(rng, 1023);
    const Result r = upward([&] { return difference ? a - b : a + b; });
    const Ends x = ends(a), y = ends(b);
    Ball lo, hi;
    if (difference) {
        arb_sub(lo.get(), x.lo.get(), y.hi.get(), kPrec);
        arb_sub(hi.get(), x.hi.get(), y.lo.get(), kPrec);
    } else {
        arb_add(lo.get(), x.lo.get(), y.lo.get(), kPrec);
        arb_add(hi.get(), x.hi.get(), y.hi.get(), kPrec);
    }
    tally(n, r, lo, hi);
}
const Check kAdd = [](Count& n, std::mt19937_64& rng) { check_sum(n, rng, false); };
const Check kSubtract = [](Count& n, std::mt19937_64& rng) { check_sum(n, rng, true); };
const Check kMultiply = [](Count& n, std::mt19937_64& rng) {
    const UpwardBall a = random_ball(rng, 530), b = random_ball(rng, 530);
    const Result r = upward([&] { return a * b; });
    Ball lo, hi;
    product_range(ends(a), ends(b), lo, hi);
    tally(n, r, lo, hi);
};
const Check kScale = [](Count& n, std::mt19937_64& rng) {
    const double c = random_double(rng, 530);
    const UpwardBall b = random_ball(rng, 530);
    const Result r = upward([&] { return c * b; });
    Ball lo, hi;
    product_range(ends(UpwardBall(c)), ends(b), lo, hi);
    tally(n, r, lo, hi);
};
const Check kSquare = [](Count& n, std::mt19937_64& rng) {
    const UpwardBall a = random_ball(rng, 530);
    const Result r = upward([&] { return a.square(); });
    Ball lo, hi;
    product_range(ends(a), ends(a), lo, hi);  // encloses the square's range
    tally(n, r, lo, hi);
};
const Check kTwice = [](Count& n, std::mt19937_64& rng) {
    const UpwardBall a = random_ball(rng, 1023);
    const Result r = upward([&] { return a.twice(); });
    const Ends x = ends(a);
    Ball lo, hi;
    arb_mul_2exp_si(lo.get(), x.lo.get(), 1);
    arb_mul_2exp_si(hi.get(), x.hi.get(), 1);
    tally(n, r, lo, hi);
};
const Check kReciprocal = [](Count& n, std::mt19937_64& rng) {
    const UpwardBall a = random_ball(rng, 1023);
    const Result r = upward([&] { return a.reciprocal(); });
    const Ends x = ends(a);
    if (!arb_is_positive(x.lo.get()) && !arb_is_negative(x.hi.get())) {  // reaches zero: NaN
        ++n.cases;
        if (!r.finite()) ++n.not_finite;
        return;
    }
    Ball lo, hi;
    arb_inv(lo.get(), x.hi.get(), kPrec);
    arb_inv(hi.get(), x.lo.get(), kPrec);
    tally(n, r, lo, hi);
};
const Check kSqrt = [](Count& n, std::mt19937_64& rng) {
    UpwardBall a = random_ball(rng, 1023);
    a.mid = std::fabs(a.mid);
    const Result r = upward([&] { return a.sqrt(); });
    const Ends x = ends(a);
    if (!arb_is_positive(x.lo.get())) {  // reaches zero: NaN
        ++n.cases;
        if (!r.finite()) ++n.not_finite;
        return;
    }
    Ball lo, hi;
    arb_sqrt(lo.get(), x.lo.get(), kPrec);
    arb_sqrt(hi.get(), x.hi.get(), kPrec);
    tally(n, r, lo, hi);
};

}  // namespace

TEST_CASE("UpwardBall: each operation encloses the exact range over its operands, or is not finite",
          "[upward-interval][upward-ball]") {
    std::uint64_t seed = 0;
    for (const auto& [name, check] : {std::pair{"add", &kAdd}, {"subtract", &kSubtract}, {"multiply", &kMultiply},
                                      {"scale", &kScale}, {"square", &kSquare}, {"twice", &kTwice},
                                      {"reciprocal", &kReciprocal}, {"sqrt", &kSqrt}}) {
        std::mt19937_64 rng(++seed);
        Count n;
        for (int i = 0; i < 20000; ++i) (*check)(n, rng);
        INFO(name << ": " << n.cases << " cases, " << n.enclosing << " enclosing, " << n.not_finite << " not finite");
        CHECK(n.enclosing + n.not_finite == n.cases);
        CHECK(n.enclosing > n.cases / 2);  // most results are finite
    }
}

TEST_CASE("UpwardBall: overflow below the range is not finite, where the midpoint stops at -DBL_MAX",
          "[upward-interval][upward-ball]") {
    // Rounded up, -2 DBL_MAX and -DBL_MAX^2 become -DBL_MAX: no bound.
    const UpwardBall big(-DBL_MAX), half(DBL_MAX / 2), two(2.0);
    CHECK(!upward([&] { return big * two; }).finite());
    CHECK(!upward([&] { return big + big; }).finite());
    CHECK(!upward([&] { return big.twice(); }).finite());
    CHECK(!upward([&] { return big - half - half - half; }).finite());
    CHECK(!upward([&] { return UpwardBall(-0x1p-1074).reciprocal(); }).finite());
    // Within the range but for an ulp or two of DBL_MAX: finite, the
    // midpoint exact; DBL_MAX itself counts as an overflow.
    const Result r = upward([&] { return UpwardBall(DBL_MAX / 4) * two; });
    CHECK(r.finite());
    CHECK(r.ball.mid == DBL_MAX / 2);
    CHECK(!upward([&] { return half * two; }).finite());
    // A ball around an interval holds it.
    const Result around = upward([] { return UpwardBall::around(UpwardInterval(-3.0, 0x1p-60)); });
    CHECK(around.lower <= -3.0);
    CHECK(around.upper >= 0x1p-60);
}
