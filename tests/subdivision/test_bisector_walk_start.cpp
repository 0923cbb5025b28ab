// The bisector walk (subdivision/bisector_walk_start.hpp): its candidates
// against Arb's certified circles, the double certificate that starts from
// them where the circle models' starts fail, and the Arb solver's start for a
// triple of needles (fuzz F11) against the MPFR signed-distance oracle.
#include "subdivision/bisector_walk_start.hpp"
#include "subdivision/voronoi_circle_enclosure.hpp"
#include "subdivision/voronoi_circle_in_doubles.hpp"
#include "sites/rational_parse.hpp"
#include "tests/support/random_sites.hpp"
#include "tests/support/signed_distance_oracle.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <tuple>
#include <vector>

using namespace ellvor;

namespace {

// Whether some candidate of the walk lies within `tolerance` (relative to
// the radius plus one) of the certified circle.
bool walk_offers(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3, const VoronoiCircleEnclosure& c,
                 double tolerance) {
    const double r = c.radius.mid_double(), x = c.center_x.mid_double(), y = c.center_y.mid_double();
    return for_each_bisector_walk_circle(e1, e2, e3, [&](const VoronoiCircleGuess& g) {
        return std::fabs(g.radius - r) <= tolerance * (1 + r) && std::hypot(g.x - x, g.y - y) <= tolerance * (1 + r);
    });
}

Ellipse site(long a, long b, long w, long x, long y, unsigned long d) {
    return Ellipse(Rational(a, d), Rational(b, d), Rational(w, 1UL << 20), Rational(x, d), Rational(y, d));
}

}  // namespace

TEST_CASE("bisector walk: a packing triple the circle models miss, certified in doubles from the walk",
          "[subdivision][voronoi_circle_in_doubles][packing]") {
    // Three sites of `ellvor generate packing --count 10000 --packing-fraction
    // 0.58 --gap 1e-6 --seed 1`, 0.03 to 0.4 apart, against sizes 0.3 to 1.8:
    // the models' starts lead Newton to the other circle or nowhere, and Arb's
    // solver found the counter-clockwise circle by its exhaustive search only
    // (30 ms); the walk offers both circles and the double certificate holds.
    auto q = [](long n, long d) { return Rational(Integer(n), Integer(d)); };
    const Ellipse a(q(30151326795L, 17179869184L), q(10100947, 16777216), q(-110845, 524288),
                    q(49593570200293L, 549755813888L), q(30101379986085L, 549755813888L));
    const Ellipse b(q(1558918229L, 1073741824L), q(4886891, 8388608), q(-242115, 524288),
                    q(6066986488985L, 68719476736L), q(1857502102351L, 34359738368L));
    const Ellipse c(q(11024738549L, 34359738368L), q(2262413, 16777216), q(-589217, 1048576),
                    q(97550745279939L, 1099511627776L), q(30081098163035L, 549755813888L));
    for (const auto& [e1, e2, e3] : {std::tuple{&a, &b, &c}, {&b, &c, &a}, {&a, &c, &b}}) {
        VoronoiCircleSolver arb(*e1, *e2, *e3);
        REQUIRE(arb.certify());
        const VoronoiCircleEnclosure& want = arb.enclosure();
        CHECK(walk_offers(*e1, *e2, *e3, want, 1e-9));
        const std::optional<DoubleVoronoiCircle> d = certify_voronoi_circle_in_doubles(*e1, *e2, *e3);
        REQUIRE(d.has_value());
        auto holds = [](const Interval& box, const Ball& b) {
            const Interval e = enclose(b);
            return box.lo <= e.hi && e.lo <= box.hi;  // both hold the one circle: they meet
        };
        CHECK(holds(d->radius, want.radius));
        CHECK(holds(d->center_x, want.center_x));
        CHECK(holds(d->center_y, want.center_y));
    }
}

TEST_CASE("bisector walk: every counter-clockwise circle of random close triples is among its candidates",
          "[subdivision]") {
    // Elongated sites (aspect 4) up to 2 long in a 6 x 6 square, their
    // bounding circles apart: each circle Arb certifies up to 8 times the
    // largest semi-axis is offered, to 1e-9.
    std::mt19937_64 rng(42);
    std::uniform_int_distribution<long> axis(200, 2000), angle(-(1L << 20), 1L << 20), place(-3000, 3000);
    int compared = 0;
    while (compared < 60) {
        const unsigned long d = 1000;
        std::vector<Ellipse> e;
        for (int i = 0; i < 3; ++i) {
            const long major = axis(rng), minor = std::max(100L, major / 4);
            e.push_back(site(major, minor, angle(rng), place(rng), place(rng), d));
        }
        bool apart = true;
        for (int i = 0; i < 3; ++i)
            for (int j = i + 1; j < 3; ++j) apart = apart && test::bounding_circles_apart(e[i], e[j]);
        if (!apart) continue;
        VoronoiCircleSolver arb(e[0], e[1], e[2]);
        if (!arb.certify()) continue;
        const double r = arb.enclosure().radius.mid_double();
        if (r > 16) continue;  // beyond 2^3 sizes: the tangent-line starts' (huge_circle_start.hpp)
        INFO("radius " << r);
        CHECK(walk_offers(e[0], e[1], e[2], arb.enclosure(), 1e-9));
        ++compared;
    }
}

TEST_CASE("bisector walk: the Arb solver's start for two needles and a small site (fuzz F11)",
          "[subdivision][needle][fuzz]") {
    // The triple of fuzz F11 in its similarity frame: a needle 1.4e8 : 1, a band of aspect 9.2e5 and
    // a small site, all within 2e-6 of each other. The guesses and the needle chains miss the
    // counter-clockwise circle (the search then ended at its cap); the walk, certified in Arb,
    // finds it. Checked against the MPFR signed distances (no solver): each site at the radius.
    auto q = [](const char* s) { return parse_rational(s); };
    const Ellipse needle(q("47/12116894962155520"), q("23/41943040"), q("-47/50"), q("3/5368709120"),
                         q("3/5368709120"));
    const Ellipse band(q("71875/65536"), q("5/4194304"), q("-13/85"), q("231/1073741824"), q("-7421/5368709120"));
    const Ellipse small(q("3/8388608"), q("63/83886080"), q("-7/18"), q("-793/1073741824"), q("-345/1073741824"));
    for (const auto& [e1, e2, e3] : {std::tuple{&needle, &band, &small}, {&band, &small, &needle}}) {
        VoronoiCircleSolver solver(*e1, *e2, *e3);
        REQUIRE(solver.certify());
        const VoronoiCircleEnclosure& found = solver.enclosure();
        CHECK(found.found_by == CircleStart::bisector_walk);
        const test::RealPoint v{test::Real(found.center_x.mid_double()), test::Real(found.center_y.mid_double())};
        const double rho = found.radius.mid_double();
        for (const Ellipse* e : {&needle, &band, &small})
            CHECK(std::fabs(test::OracleEllipse(*e).signed_distance_value(v).to_double() - rho) < 1e-9 * rho);
    }
}
