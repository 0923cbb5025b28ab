// The packing generator (sites/packing_generator.hpp), checked independently of
// its own certificates: every pair separated by the exact relative position
// (predicates/relative_position.hpp), every pair at distance >= the gap by a
// sampling of the boundary with the MPFR signed distance of
// tests/support/signed_distance_oracle.hpp and a slab at the nearest sample, every site inside the box exactly,
// the fraction reached >= the one asked with pi from MPFR, aspect ratios in
// range exactly, the same sites on every run; bad options are errors.
#include <catch2/catch.hpp>

#include "predicates/relative_position.hpp"
#include "sites/packing_generator.hpp"
#include "sites/site_io.hpp"
#include "tests/support/signed_distance_oracle.hpp"
#include "util/error.hpp"

#include <sstream>
#include <vector>

using namespace ellvor;
using test::OracleEllipse;
using test::Real;

namespace {

std::string text(const std::vector<Ellipse>& sites) {
    std::ostringstream out;
    write_ell(out, sites);
    return out.str();
}

PackingOptions options(long count, Rational fraction, Rational gap, std::uint64_t seed = 1) {
    PackingOptions o;
    o.count = count;
    o.fraction = fraction;
    o.gap = gap;
    o.seed = seed;
    return o;
}

Rational largest_axis(const Ellipse& e) { return e.a() < e.b() ? e.b() : e.a(); }

// The bounding circles (radius the larger semi-axis) come within `gap`:
// otherwise the pair is trivially that far apart.
bool near(const Ellipse& e1, const Ellipse& e2, const Rational& gap) {
    const Rational dx = e1.xc() - e2.xc(), dy = e1.yc() - e2.yc();
    const Rational reach = largest_axis(e1) + largest_axis(e2) + gap;
    return dx * dx + dy * dy <= reach * reach;
}

// The width of the slab between e1 and e2 normal to the unit direction m
// (pointing from e1 to e2), in MPFR: m.(c2 - c1) - h1(m) - h2(m), h the
// support functions of the centered ellipses. A width >= gap proves the
// distance >= gap; it is <= the distance for every m.
Real slab_width(const Ellipse& e1, const Ellipse& e2, const Real& mx, const Real& my) {
    auto support = [&](const Ellipse& e) {
        const Real c(e.cos_rotation()), s(e.sin_rotation()), a(e.a()), b(e.b());
        const Real mu = mx * c + my * s, mv = my * c - mx * s;
        return sqrt(a * a * mu * mu + b * b * mv * mv);
    };
    return mx * (Real(e2.xc()) - Real(e1.xc())) + my * (Real(e2.yc()) - Real(e1.yc())) - support(e1) - support(e2);
}

// The distance of two disjoint convex sites is >= gap, checked independently
// of the generator (MPFR at 192 bits, the oracle's own nearest points):
//  - the slab along the line of the centers, when that suffices (far pairs);
//  - otherwise the boundary of e1 sampled (48 angles, then a golden-section
//    search about the nearest), the oracle's distance to e2 at every sample >=
//    gap (a sample closer would be a counterexample), and the slab normal to
//    e2's outward normal at the nearest sample's foot of width >= gap (the
//    proof). Margins of 10^-40 cover the rounding to 192 bits.
bool at_least_gap_apart(const Ellipse& e1, const Ellipse& e2, const Rational& gap, long* sampled = nullptr) {
    const Real G = Real(gap) - Real(1e-40);
    const Real dx = Real(e2.xc()) - Real(e1.xc()), dy = Real(e2.yc()) - Real(e1.yc()), len = hypot(dx, dy);
    if (slab_width(e1, e2, dx / len, dy / len) >= G) return true;
    if (sampled) ++*sampled;
    const OracleEllipse o1(e1), o2(e2);
    auto distance = [&](const Real& theta) { return o2.signed_distance(o1.boundary_point(theta)); };
    const Real two_pi = Real(2) * Real::pi();
    const int samples = 48;
    int best = 0;
    Real best_value;
    for (int i = 0; i < samples; ++i) {
        const Real d = distance(two_pi * Real(i) / Real(samples)).value;
        if (d < G) return false;
        if (i == 0 || d < best_value) best = i, best_value = d;
    }
    Real lo = two_pi * Real(best - 1) / Real(samples), hi = two_pi * Real(best + 1) / Real(samples);
    const Real r(0.6180339887498949);
    Real t1 = hi - r * (hi - lo), t2 = lo + r * (hi - lo);
    Real v1 = distance(t1).value, v2 = distance(t2).value;
    for (int it = 0; it < 70; ++it) {
        if (v1 < G || v2 < G) return false;
        if (v1 < v2) hi = t2, t2 = t1, v2 = v1, t1 = hi - r * (hi - lo), v1 = distance(t1).value;
        else lo = t1, t1 = t2, v1 = v2, t2 = lo + r * (hi - lo), v2 = distance(t2).value;
    }
    const test::SignedDistance nearest = distance(v1 < v2 ? t1 : t2);
    if (nearest.value < G) return false;
    // e2's outward normal at the foot points back to e1
    return slab_width(e1, e2, -nearest.normal.x, -nearest.normal.y) >= G;
}

long box_side(long count) {
    long side = 0;
    while (side * side < count) ++side;
    return side;
}

// The site lies in [0, L]^2, exactly: its extent about the center along x is
// sqrt(a^2 cos^2 + b^2 sin^2) (and along y with cos and sin swapped).
bool inside_box(const Ellipse& e, long side) {
    const Rational &c = e.cos_rotation(), &s = e.sin_rotation();
    const Rational ex2 = e.a() * e.a() * c * c + e.b() * e.b() * s * s;
    const Rational ey2 = e.a() * e.a() * s * s + e.b() * e.b() * c * c;
    const Rational L(side);
    auto within = [&](const Rational& v, const Rational& extent2) {
        const Rational up = L - v;
        return v.sign() > 0 && up.sign() > 0 && v * v >= extent2 && up * up >= extent2;
    };
    return within(e.xc(), ex2) && within(e.yc(), ey2);
}

}  // namespace

TEST_CASE("packing: pairs separated (exactly) and at least the gap apart (MPFR sampling and slabs)",
          "[packing][generator]") {
    for (const Rational& gap : {Rational(1, 1000), Rational(1, 1000000)}) {
        const PackingOptions o = options(200, Rational(58, 100), gap, 3);
        const Packing p = generate_packing(o);
        REQUIRE(p.sites.size() == 200);
        long sampled = 0;  // pairs the line of the centers does not separate
        long close_pairs = 0;  // pairs that even 4 gaps + 1% of the size cannot separate: the growth makes some
        for (std::size_t i = 0; i < p.sites.size(); ++i)
            for (std::size_t j = i + 1; j < p.sites.size(); ++j) {
                const Ellipse &e1 = p.sites[i], &e2 = p.sites[j];
                if (!near(e1, e2, gap)) continue;
                INFO("sites " << i << " and " << j << ", gap " << gap.str());
                const Decision<RelativePosition> rp = relative_position(e1, e2);
                REQUIRE(rp.is_decided());
                REQUIRE(rp.value() == RelativePosition::separated);
                REQUIRE(at_least_gap_apart(e1, e2, gap, &sampled));
                if (!packing_pair_certified(e1, e2, gap * Rational(4) + Rational(1, 100) * e1.b())) ++close_pairs;
            }
        CHECK(close_pairs > 20);
        CHECK(sampled > 20);
    }
}

TEST_CASE("packing: the independent gap check rejects pairs closer than the gap", "[packing][generator]") {
    // Two unit circles 1/1000 apart: at least 1/2000, not 1/500.
    const Ellipse c1 = Ellipse::circle(0, 0, 1), c2 = Ellipse::circle(Rational(2001, 1000), 0, 1);
    CHECK(at_least_gap_apart(c1, c2, Rational(1, 2000)));
    CHECK_FALSE(at_least_gap_apart(c1, c2, Rational(1, 500)));
    CHECK(packing_pair_certified(c1, c2, Rational(1, 2000)));
    CHECK_FALSE(packing_pair_certified(c1, c2, Rational(1, 500)));
    // A needle's tip 10^-4 from a disk, off the line of the centers: the tip is found.
    const Ellipse needle(4, Rational(1, 4), Rational(1, 10), 0, 0);
    const Rational tx = Rational(4) * needle.cos_rotation(), ty = Rational(4) * needle.sin_rotation();
    const Ellipse disk = Ellipse::circle(Rational(50001, 10000) * tx / Rational(4) + Rational(1, 3),
                                         Rational(50001, 10000) * ty / Rational(4) - Rational(2), 1);
    const bool far = at_least_gap_apart(needle, disk, Rational(1, 20000));
    CHECK(far == packing_pair_certified(needle, disk, Rational(1, 20000)));
    CHECK_FALSE(at_least_gap_apart(needle, disk, Rational(3)));
    CHECK_FALSE(packing_pair_certified(needle, disk, Rational(3)));
    const Ellipse touching_tip(4, Rational(1, 4), 0, 0, 0), beyond = Ellipse::circle(Rational(50001, 10000), 0, 1);
    CHECK(at_least_gap_apart(touching_tip, beyond, Rational(1, 20000)));
    CHECK_FALSE(at_least_gap_apart(touching_tip, beyond, Rational(2, 10000)));
    CHECK_FALSE(at_least_gap_apart(beyond, touching_tip, Rational(2, 10000)));
    CHECK(packing_pair_certified(touching_tip, beyond, Rational(1, 20000)));
    CHECK_FALSE(packing_pair_certified(touching_tip, beyond, Rational(2, 10000)));
}

TEST_CASE("packing: fraction reached, box, aspect ratios, grids", "[packing][generator]") {
    for (const auto& [count, fraction, lo, hi] :
         {std::tuple<long, Rational, Rational, Rational>{400, Rational(58, 100), Rational(1), Rational(4)},
          {300, Rational(6, 10), Rational(1), Rational(1)},
          {200, Rational(1, 10), Rational(2), Rational(3)}}) {
        PackingOptions o = options(count, fraction, Rational(1, 1000), 7);
        o.aspect_lo = lo;
        o.aspect_hi = hi;
        const Packing p = generate_packing(o);
        REQUIRE(static_cast<long>(p.sites.size()) == count);
        REQUIRE(p.box_side == box_side(count));
        Rational area_sum;  // sum of a b
        for (const Ellipse& e : p.sites) {
            CHECK(inside_box(e, p.box_side));
            CHECK(e.a() >= lo * e.b());
            CHECK(e.a() <= hi * e.b());
            area_sum = area_sum + e.a() * e.b();
        }
        if (lo == Rational(1) && hi == Rational(1))
            for (const Ellipse& e : p.sites) CHECK(e.is_circle());
        // The fraction with pi from MPFR (rounded down to 192 bits, the sum
        // rounded down as well): at least the asked one, and within the
        // generator's certified bounds.
        Real lower = Real::pi();
        mpfr_t sum;
        mpfr_init2(sum, test::kOracleBits);
        fmpq_get_mpfr(sum, area_sum.get(), MPFR_RNDD);
        mpfr_mul(lower.get(), lower.get(), sum, MPFR_RNDD);
        mpfr_div_si(lower.get(), lower.get(), p.box_side * p.box_side, MPFR_RNDD);
        mpfr_clear(sum);
        CHECK(lower >= Real(fraction) - Real(1e-40));
        CHECK(Real(p.fraction_lower) <= lower + Real(1e-40));
        CHECK(Real(p.fraction_upper) >= lower);
        CHECK(p.fraction_lower >= fraction);
        // a grown packing does not overshoot much: the last pass stops at F
        CHECK(p.fraction_lower <= fraction + Rational(1, 100));
    }
}

TEST_CASE("packing: the same sites on every run, other seeds differ", "[packing][generator]") {
    const PackingOptions o = options(300, Rational(58, 100), Rational(1, 1000), 11);
    const std::string first = text(generate_packing(o).sites);
    CHECK(text(generate_packing(o).sites) == first);
    PackingOptions other = o;
    other.seed = 12;
    CHECK(text(generate_packing(other).sites) != first);
    // The header line of describe() names every option.
    CHECK(describe(o) == "ellvor generate packing --count 300 --packing-fraction 29/50 --gap 1/1000 --aspect 1..4 --seed 11");
}

TEST_CASE("packing: a small box whose first random sequential addition jams starts again lower",
          "[packing][generator]") {
    // 40 sites in a 7 x 7 box at 0.55: with seed 1 the seventh site found no room at the first start.
    const PackingOptions o = options(40, Rational(55, 100), Rational(1, 1000), 1);
    const Packing p = generate_packing(o);
    REQUIRE(p.sites.size() == 40);
    CHECK(p.fraction_lower >= o.fraction);
    for (std::size_t i = 0; i < p.sites.size(); ++i) {
        CHECK(inside_box(p.sites[i], p.box_side));
        for (std::size_t j = i + 1; j < p.sites.size(); ++j) {
            if (!near(p.sites[i], p.sites[j], o.gap)) continue;
            INFO("sites " << i << " and " << j);
            const Decision<RelativePosition> rp = relative_position(p.sites[i], p.sites[j]);
            REQUIRE(rp.is_decided());
            CHECK(rp.value() == RelativePosition::separated);
            CHECK(at_least_gap_apart(p.sites[i], p.sites[j], o.gap));
        }
    }
}

TEST_CASE("packing: bad options and unreachable fractions are errors", "[packing][generator]") {
    CHECK_THROWS_AS(generate_packing(options(100, Rational(0), Rational(1, 1000))), Error);
    CHECK_THROWS_AS(generate_packing(options(100, Rational(-1, 2), Rational(1, 1000))), Error);
    CHECK_THROWS_AS(generate_packing(options(100, Rational(9, 10), Rational(1, 1000))), Error);
    CHECK_THROWS_AS(generate_packing(options(100, Rational(1, 2), Rational(-1, 1000))), Error);
    CHECK_THROWS_AS(generate_packing(options(100, Rational(1, 2), Rational(1, 5))), Error);
    CHECK_THROWS_AS(generate_packing(options(29, Rational(1, 2), Rational(1, 1000))), Error);
    PackingOptions bad_aspect = options(100, Rational(1, 2), Rational(1, 1000));
    bad_aspect.aspect_lo = Rational(1, 2);
    CHECK_THROWS_AS(generate_packing(bad_aspect), Error);
    bad_aspect.aspect_lo = Rational(3);
    bad_aspect.aspect_hi = Rational(2);
    CHECK_THROWS_AS(generate_packing(bad_aspect), Error);
    bad_aspect.aspect_lo = bad_aspect.aspect_hi = Rational(1, 3) + Rational(2);  // no multiple of 1/4096
    CHECK_THROWS_AS(generate_packing(bad_aspect), Error);
    // 0.84 jams: the message says the fraction reached, which is below it.
    try {
        generate_packing(options(100, Rational(84, 100), Rational(1, 1000)));
        FAIL("0.84 reached");
    } catch (const Error& e) {
        const std::string message = e.what();
        CHECK_THAT(message, Catch::Contains("not reached") && Catch::Contains("jammed at 0."));
        const std::string reached = message.substr(message.find("jammed at ") + 10, 6);
        CHECK(std::stod(reached) < 0.84);
        CHECK(std::stod(reached) > 0.58);
    }
}
