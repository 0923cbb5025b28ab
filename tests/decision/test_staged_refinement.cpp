// The decision core: Decision<T>, StageCounters, and the shared "refine ->
// exact -> resume" driver, on synthetic stages whose behaviour is known (the
// predicates' own tests reach each path on geometry).
#include "decision/staged_refinement.hpp"

#include <catch2/catch.hpp>

#include <random>

using namespace ellvor;

namespace {

// A synthetic comparison: the Arb stage decides `sign` from `separation` bits
// on (never, for equal values); the exact stage answers `equal`.
struct Synthetic {
    long separation = 0;  // 0: equal values, never separated
    int sign = 1;
    bool equal = false;
    int exact_calls = 0;
    long exact_precision = -1;
    long highest_precision = 0;

    Decision<Sign> run(const RefinementOptions& options) {
        return refine_then_exact(
            "synthetic", options,
            [&](long prec) {
                highest_precision = std::max(highest_precision, prec);
                return separation > 0 && prec >= separation ? sign : 0;
            },
            [&](long prec) {
                ++exact_calls;
                exact_precision = prec;
                return equal;
            });
    }
};

long first_power_of_two_at_least(long x) {
    long p = precision::kStart;
    while (p < x) p *= 2;
    return p;
}

}  // namespace

TEST_CASE("decision: value, undecided, provenance", "[predicates][decision]") {
    const Decision<int> d = Decision<int>::decided(7, Stage::subdivision, 128);
    CHECK(d.is_decided());
    CHECK(*d == 7);
    const Decision<bool> e = d.with(true);
    CHECK(*e);
    CHECK(e.stage == Stage::subdivision);
    CHECK(e.precision == 128);

    const Decision<int> u = Decision<int>::undecided(Stage::subdivision, 4096);
    CHECK(!u.is_decided());
    CHECK_THROWS_AS(*u, Error);

    Decision<int> later = Decision<int>::decided(1, Stage::filter);
    later.depends_on(Decision<bool>::decided(false, Stage::exact, 64));
    later.depends_on(Decision<bool>::decided(false, Stage::subdivision, 512));
    CHECK(later.stage == Stage::exact);  // the latest stage
    CHECK(later.precision == 512);       // the highest precision

    CHECK(-Sign::negative == Sign::positive);
    CHECK(Sign::negative * Sign::negative == Sign::positive);
    CHECK(sign_of(-3) == Sign::negative);
    CHECK(to_int(Sign::zero) == 0);
}

TEST_CASE("decision: stage counters are indexed by the stage", "[predicates][decision]") {
    StageCounters c;
    c.record(Stage::exact);
    c.record(Stage::exact);
    c.record(Stage::filter);
    CHECK(c[Stage::filter] == 1);
    CHECK(c[Stage::subdivision] == 0);
    CHECK(c[Stage::exact] == 2);
    CHECK(c.total() == 3);
    std::uint64_t sum = 0;
    for (Stage s : kStages) sum += c[s];
    CHECK(sum == c.total());
}

TEST_CASE("staged refinement: each path of the driver", "[predicates][decision]") {
    RefinementOptions options;
    options.cap = 4096;

    SECTION("the subdivision separates below the cap") {
        Synthetic s{300, -1};
        const Decision<Sign> d = s.run(options);
        CHECK(*d == Sign::negative);
        CHECK(d.stage == Stage::subdivision);
        CHECK(d.precision == 512);
        CHECK(s.exact_calls == 0);
    }
    SECTION("equal values: the exact stage proves zero at the cap") {
        Synthetic s{0, 1, true};
        const Decision<Sign> d = s.run(options);
        CHECK(*d == Sign::zero);
        CHECK(d.stage == Stage::exact);
        CHECK(d.precision == 4096);
        CHECK(s.exact_calls == 1);
        CHECK(s.exact_precision == 4096);
        CHECK(s.highest_precision == 4096);
    }
    SECTION("distinct values beyond the cap: exact proves them distinct, the subdivision resumes") {
        Synthetic s{20000, 1, false};
        const Decision<Sign> d = s.run(options);
        CHECK(*d == Sign::positive);
        CHECK(d.stage == Stage::exact);
        CHECK(d.precision == 32768);
        CHECK(s.exact_calls == 1);
    }
    SECTION("without the exact stage the honest answer is undecided") {
        options.exact_stage = false;
        Synthetic s{20000, 1, false};
        const Decision<Sign> d = s.run(options);
        CHECK(!d.is_decided());
        CHECK(d.stage == Stage::subdivision);
        CHECK(d.precision == 4096);
        CHECK(s.exact_calls == 0);
    }
    SECTION("distinct values that never separate end with an Error, not a loop") {
        Synthetic s{0, 1, false};
        CHECK_THROWS_AS(s.run(options), Error);
        CHECK(s.highest_precision == precision::resume_limit(options.cap));
    }
    SECTION("a cap that is not a power of two") {
        options.cap = 100000;
        Synthetic s{0, 1, true};
        const Decision<Sign> d = s.run(options);
        CHECK(*d == Sign::zero);
        CHECK(s.exact_precision == 65536);
    }
}

TEST_CASE("staged refinement: every cap the CLI accepts hands over to the exact stage", "[predicates][decision]") {
    // Random caps, separations and equalities against the rule the driver
    // documents; the caps include the largest one accepted.
    std::mt19937_64 rng(97);
    std::uniform_int_distribution<long> cap_bits(6, 24), sep_bits(0, 26);
    for (int trial = 0; trial < 2000; ++trial) {
        RefinementOptions options;
        options.cap = trial == 0 ? precision::kMaxCap : (1L << cap_bits(rng)) + (trial % 3 == 0 ? 17 : 0);
        options.cap = std::min(options.cap, precision::kMaxCap);
        const long separation = trial % 5 == 0 ? 0 : (1L << sep_bits(rng)) - (trial % 7);
        Synthetic s{separation, trial % 2 ? 1 : -1, separation == 0 && trial % 3 != 0};
        INFO("cap " << options.cap << " separation " << separation << " equal " << s.equal);
        const long needed = separation > 0 ? first_power_of_two_at_least(separation) : 0;
        if (separation > 0 && needed <= options.cap) {
            const Decision<Sign> d = s.run(options);
            CHECK(d.stage == Stage::subdivision);
            CHECK(d.precision == needed);
            CHECK(s.exact_calls == 0);
        } else if (s.equal) {
            const Decision<Sign> d = s.run(options);
            CHECK(*d == Sign::zero);
            CHECK(s.exact_calls == 1);
            CHECK(s.exact_precision <= options.cap);
            CHECK(2 * s.exact_precision > options.cap);
        } else if (separation > 0 && needed <= precision::resume_limit(options.cap)) {
            const Decision<Sign> d = s.run(options);
            CHECK(to_int(*d) == s.sign);
            CHECK(d.stage == Stage::exact);
            CHECK(d.precision == needed);
            CHECK(s.exact_calls == 1);
        } else {
            CHECK_THROWS_AS(s.run(options), Error);
            CHECK(s.exact_calls == 1);
        }
    }
}
