// UpwardInterval and UpwardRoundingScope (util/upward_interval.hpp): every
// operation, computed under the upward rounding mode, against its exact
// result (Arb at 4200 bits: exact for sums and products of doubles, within
// 2^-4000 relative for quotients and roots, far below the gap between a
// double and an irrational or non-dyadic result). Random operands of every
// magnitude (overflow and subnormal results included) and sign, zero-
// straddling intervals among them. Each bound must enclose the exact one and
// be the nearest double on its side (one more step for sqrt's lower bound),
// so no wider than Interval's. The same computation in round-to-nearest
// (outside the scope) fails the check: the test sees the mode. Then the
// scope restores the mode it found, also when an exception leaves it.
//
// This file is compiled with the ROUNDING_MATH flags (Makefile).
#include "util/upward_interval.hpp"

#include <catch2/catch.hpp>

#include <cfenv>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

using namespace ellvor;

namespace {

constexpr long kPrec = 4200;  // > 2 * 1074 + 2 * 1024: sums and products of doubles are exact
const double kInf = std::numeric_limits<double>::infinity();

Ball exact(double x) {
    Ball b;
    arb_set_d(b.get(), x);
    return b;
}

// Whether x <= every point of v (x may be infinite).
bool certainly_le(double x, const Ball& v) {
    if (x == -kInf) return true;
    if (x == kInf) return false;
    return arb_le(exact(x).get(), v.get());
}
bool certainly_ge(double x, const Ball& v) {
    if (x == kInf) return true;
    if (x == -kInf) return false;
    return arb_ge(exact(x).get(), v.get());
}

// x > every point of v / x < every point (x may be infinite).
bool strictly_above(double x, const Ball& v) {
    if (x == kInf) return true;
    if (x == -kInf) return false;
    return arb_gt(exact(x).get(), v.get());
}
bool strictly_below(double x, const Ball& v) {
    if (x == -kInf) return true;
    if (x == kInf) return false;
    return arb_lt(exact(x).get(), v.get());
}

// lo <= v, and the double `steps` above lo is above v (lo is RD(v) for one step).
bool lower_bound_ok(double lo, const Ball& v, int steps = 1) {
    if (!certainly_le(lo, v)) return false;
    double next = lo;
    for (int i = 0; i < steps; ++i) next = std::nextafter(next, kInf);
    return strictly_above(next, v);
}
bool upper_bound_ok(double hi, const Ball& v, int steps = 1) {
    if (!certainly_ge(hi, v)) return false;
    double next = hi;
    for (int i = 0; i < steps; ++i) next = std::nextafter(next, -kInf);
    return strictly_below(next, v);
}

Ball add(const Ball& a, const Ball& b) { Ball r; arb_add(r.get(), a.get(), b.get(), kPrec); return r; }
Ball sub(const Ball& a, const Ball& b) { Ball r; arb_sub(r.get(), a.get(), b.get(), kPrec); return r; }
Ball mul(const Ball& a, const Ball& b) { Ball r; arb_mul(r.get(), a.get(), b.get(), kPrec); return r; }
Ball div(const Ball& a, const Ball& b) { Ball r; arb_div(r.get(), a.get(), b.get(), kPrec); return r; }
Ball root(const Ball& a) { Ball r; arb_sqrt(r.get(), a.get(), kPrec); return r; }
// Of exact (or disjoint) balls: the one that is certainly smaller / larger.
Ball smaller(const Ball& a, const Ball& b) { return arb_le(a.get(), b.get()) ? a : b; }
Ball larger(const Ball& a, const Ball& b) { return arb_ge(a.get(), b.get()) ? a : b; }
Ball min4(const Ball& a, const Ball& b, const Ball& c, const Ball& d) { return smaller(smaller(a, b), smaller(c, d)); }
Ball max4(const Ball& a, const Ball& b, const Ball& c, const Ball& d) { return larger(larger(a, b), larger(c, d)); }

// A random finite double: random sign, an exponent from `max_exponent` down
// (to the subnormals when asked), a random mantissa; now and then a zero of
// either sign or a small integer.
double random_double(std::mt19937_64& rng, int max_exponent) {
    const int kind = std::uniform_int_distribution<int>(0, 19)(rng);
    const double sign = rng() & 1 ? -1.0 : 1.0;
    if (kind == 0) return sign * 0.0;
    if (kind == 1) return sign * double(std::uniform_int_distribution<int>(1, 8)(rng));
    const double mantissa = 1.0 + double(rng() >> 12) * 0x1p-52;  // 1 + k 2^-52, k < 2^52
    const int exponent = kind == 2 ? std::uniform_int_distribution<int>(-1074, -1000)(rng)
                                   : std::uniform_int_distribution<int>(-max_exponent, max_exponent)(rng);
    return sign * std::ldexp(mantissa, exponent);
}

// An interval of two such doubles; a quarter of them forced across zero, a
// few points.
UpwardInterval random_interval(std::mt19937_64& rng, int max_exponent) {
    double a = random_double(rng, max_exponent), b = random_double(rng, max_exponent);
    const int kind = std::uniform_int_distribution<int>(0, 7)(rng);
    if (kind == 0) b = a;
    if (kind == 1 || kind == 2) a = -std::fabs(a), b = std::fabs(b);
    return {std::fmin(a, b), std::fmax(a, b)};
}

struct Count {
    long cases = 0, failures = 0;
};

// r against the exact [lo, hi]; `lo_steps` how far below RD(lo) r.lo may be.
void tally(Count& n, const UpwardInterval& r, const Ball& lo, const Ball& hi, int lo_steps = 1) {
    ++n.cases;
    if (!lower_bound_ok(r.lo, lo, lo_steps) || !upper_bound_ok(r.hi, hi)) ++n.failures;
}

// One operation on random operands: computes it (in the mode in
// force) and compares it with the exact result.
using Check = std::function<void(Count&, std::mt19937_64&, bool upward)>;

Count run(const Check& check, bool upward, int cases, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    Count n;
    for (int i = 0; i < cases; ++i) check(n, rng, upward);
    return n;
}

// The operation is computed inside a scope when `upward`, else in the
// caller's round-to-nearest.
template <class F>
UpwardInterval compute(bool upward, F f) {
    if (!upward) return f();
    const UpwardRoundingScope scope;
    return f();
}

const Check kAdd = [](Count& n, std::mt19937_64& rng, bool upward) {
    const UpwardInterval a = random_interval(rng, 1023), b = random_interval(rng, 1023);
    const UpwardInterval r = compute(upward, [&] { return a + b; });
    tally(n, r, add(exact(a.lo), exact(b.lo)), add(exact(a.hi), exact(b.hi)));
};
const Check kSubtract = [](Count& n, std::mt19937_64& rng, bool upward) {
    const UpwardInterval a = random_interval(rng, 1023), b = random_interval(rng, 1023);
    const UpwardInterval r = compute(upward, [&] { return a - b; });
    tally(n, r, sub(exact(a.lo), exact(b.hi)), sub(exact(a.hi), exact(b.lo)));
};
const Check kNegate = [](Count& n, std::mt19937_64& rng, bool upward) {
    const UpwardInterval a = random_interval(rng, 1023);
    const UpwardInterval r = compute(upward, [&] { return -a; });
    ++n.cases;
    if (!(r.lo == -a.hi && r.hi == -a.lo)) ++n.failures;
};
const Check kMultiply = [](Count& n, std::mt19937_64& rng, bool upward) {
    const UpwardInterval a = random_interval(rng, 530), b = random_interval(rng, 530);
    const UpwardInterval r = compute(upward, [&] { return a * b; });
    const Ball p1 = mul(exact(a.lo), exact(b.lo)), p2 = mul(exact(a.lo), exact(b.hi)),
               p3 = mul(exact(a.hi), exact(b.lo)), p4 = mul(exact(a.hi), exact(b.hi));
    tally(n, r, min4(p1, p2, p3, p4), max4(p1, p2, p3, p4));
};
const Check kScale = [](Count& n, std::mt19937_64& rng, bool upward) {
    const double c = random_double(rng, 530);
    const UpwardInterval b = random_interval(rng, 530);
    const UpwardInterval r = compute(upward, [&] { return c * b; });
    const Ball p1 = mul(exact(c), exact(b.lo)), p2 = mul(exact(c), exact(b.hi));
    tally(n, r, smaller(p1, p2), larger(p1, p2));
};
const Check kDivide = [](Count& n, std::mt19937_64& rng, bool upward) {
    const UpwardInterval a = random_interval(rng, 530);
    UpwardInterval b;
    do b = random_interval(rng, 530);
    while (b.contains_zero());
    const UpwardInterval r = compute(upward, [&] { return a / b; });
    const Ball q1 = div(exact(a.lo), exact(b.lo)), q2 = div(exact(a.lo), exact(b.hi)),
               q3 = div(exact(a.hi), exact(b.lo)), q4 = div(exact(a.hi), exact(b.hi));
    tally(n, r, min4(q1, q2, q3, q4), max4(q1, q2, q3, q4));
};
const Check kReciprocal = [](Count& n, std::mt19937_64& rng, bool upward) {
    UpwardInterval b;
    do b = random_interval(rng, 1023);
    while (b.contains_zero());
    const UpwardInterval r = compute(upward, [&] { return b.reciprocal(); });
    tally(n, r, div(exact(1.0), exact(b.hi)), div(exact(1.0), exact(b.lo)));
};
const Check kSquare = [](Count& n, std::mt19937_64& rng, bool upward) {
    const UpwardInterval a = random_interval(rng, 530);
    const UpwardInterval r = compute(upward, [&] { return a.square(); });
    const Ball l = mul(exact(a.lo), exact(a.lo)), h = mul(exact(a.hi), exact(a.hi));
    if (a.contains_zero()) {
        ++n.cases;  // [0, max]: the lower bound is exactly 0
        if (!(r.lo == 0 && upper_bound_ok(r.hi, larger(l, h)))) ++n.failures;
        return;
    }
    tally(n, r, smaller(l, h), larger(l, h));
};
const Check kTwice = [](Count& n, std::mt19937_64& rng, bool upward) {
    const UpwardInterval a = random_interval(rng, 1023);
    const UpwardInterval r = compute(upward, [&] { return a.twice(); });
    tally(n, r, mul(exact(2.0), exact(a.lo)), mul(exact(2.0), exact(a.hi)));
};
// Of the nonnegative part: operands mostly nonnegative, some with lo < 0.
const Check kSqrt = [](Count& n, std::mt19937_64& rng, bool upward) {
    UpwardInterval a = random_interval(rng, 1023);
    if (a.hi < 0) a = -a;
    const UpwardInterval r = compute(upward, [&] { return a.sqrt(); });
    if (a.lo <= 0) {
        ++n.cases;
        if (!(r.lo == 0 && upper_bound_ok(r.hi, root(exact(a.hi))))) ++n.failures;
        return;
    }
    // The lower bound steps down from RU(sqrt(lo)): RD(sqrt(lo)) or the double below it.
    tally(n, r, root(exact(a.lo)), root(exact(a.hi)), 2);
};

}  // namespace

TEST_CASE("UpwardInterval: each operation encloses the exact result, to the nearest double", "[upward-interval]") {
    const std::pair<const char*, const Check*> operations[] = {
        {"+", &kAdd},         {"-", &kSubtract},        {"negation", &kNegate}, {"*", &kMultiply},
        {"double *", &kScale}, {"/", &kDivide},          {"reciprocal", &kReciprocal},
        {"square", &kSquare}, {"twice", &kTwice},       {"sqrt", &kSqrt}};
    std::uint64_t seed = 20261127;
    for (const auto& [name, check] : operations) {
        INFO("operation " << name);
        REQUIRE(std::fegetround() == FE_TONEAREST);
        const Count n = run(*check, true, 20000, ++seed);
        CHECK(n.cases == 20000);
        CHECK(n.failures == 0);
    }
}

TEST_CASE("UpwardInterval: computed in round-to-nearest, the same formulas fail (the check sees the mode)",
          "[upward-interval]") {
    // Without the scope, a lower bound -((-x) - y) is RN(x + y), below the
    // exact sum only about half the time: the oracle above is not blind.
    const std::pair<const char*, const Check*> operations[] = {
        {"+", &kAdd}, {"-", &kSubtract}, {"*", &kMultiply}, {"/", &kDivide}, {"reciprocal", &kReciprocal}};
    std::uint64_t seed = 7;
    for (const auto& [name, check] : operations) {
        INFO("operation " << name);
        const Count n = run(*check, false, 4000, ++seed);
        CHECK(n.failures > n.cases / 10);
    }
}

TEST_CASE("UpwardInterval: overflow, subnormals, signed zeros and NaN", "[upward-interval]") {
    const double max = std::numeric_limits<double>::max(), tiny = std::numeric_limits<double>::denorm_min();
    const UpwardRoundingScope scope;
    // A sum beyond the range: the upper bound +inf, the lower DBL_MAX (a
    // negative one: lower -inf, upper -DBL_MAX).
    const UpwardInterval big(max, max), sum = big + big, negative = (-big) + (-big);
    CHECK(sum.lo == max);
    CHECK(sum.hi == kInf);
    CHECK(negative.lo == -kInf);
    CHECK(negative.hi == -max);
    CHECK((-big).twice().lo == -kInf);  // not -DBL_MAX, which RU(2 lo) would give
    // Subnormal products: the least subnormal above a positive tiny result, 0 below.
    const UpwardInterval small(tiny, tiny), product = small * small;
    CHECK(product.lo == 0);
    CHECK(product.hi == tiny);
    // x - x is +0 in this mode, so the lower bound of [x, x] - [x, x] is
    // -(x - x) = -0: both zeros compare equal, and sqrt takes it as 0.
    const UpwardInterval x(1.5, 2.5), difference = UpwardInterval(1.5) - UpwardInterval(1.5);
    CHECK(difference.lo == 0);
    CHECK(std::signbit(difference.lo));
    CHECK(difference.hi == 0);
    CHECK(!std::signbit(difference.hi));
    CHECK(difference.contains_zero());
    CHECK(difference.sqrt().lo == 0);
    CHECK(difference.sqrt().hi == 0);
    CHECK(UpwardInterval(-0.0, 4.0).sqrt().lo == 0);
    CHECK(UpwardInterval(-0.0, 4.0).sqrt().hi == 2);
    CHECK(UpwardInterval(-0.0, 0.0).contains_zero());
    // 0 * inf is ignored as in Interval; a NaN operand makes a NaN bound,
    // which no comparison proves anything from.
    const UpwardInterval zero(0.0), unbounded(1.0, kInf), nan_product = zero * unbounded;
    CHECK(nan_product.lo == 0);
    CHECK(nan_product.hi == 0);
    const UpwardInterval with_nan = UpwardInterval(std::nan(""), 1.0) + x;
    CHECK(!with_nan.finite());
    CHECK(!with_nan.positive());
    CHECK(!with_nan.negative());
}

TEST_CASE("UpwardRoundingScope restores the mode it found, also on an exception", "[upward-interval]") {
    for (int mode : {FE_TONEAREST, FE_DOWNWARD, FE_TOWARDZERO, FE_UPWARD}) {
        INFO("mode " << mode);
        REQUIRE(std::fesetround(mode) == 0);
        {
            const UpwardRoundingScope scope;
            CHECK(std::fegetround() == FE_UPWARD);
            {
                const UpwardRoundingScope nested;
                CHECK(std::fegetround() == FE_UPWARD);
            }
            CHECK(std::fegetround() == FE_UPWARD);
        }
        CHECK(std::fegetround() == mode);
        bool caught = false;
        try {
            const UpwardRoundingScope scope;
            CHECK(std::fegetround() == FE_UPWARD);
            throw std::runtime_error("leaving the scope");
        } catch (const std::runtime_error&) {
            caught = true;
        }
        CHECK(caught);
        CHECK(std::fegetround() == mode);
    }
    std::fesetround(FE_TONEAREST);
}
