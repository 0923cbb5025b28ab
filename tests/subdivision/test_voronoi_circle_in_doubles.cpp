// The Voronoi circle certified in double intervals
// (subdivision/voronoi_circle_in_doubles.hpp) against the Arb solver, the
// oracle here: on random and on near-degenerate triples the double stage
// either certifies a circle that Arb also certifies and whose enclosure meets
// Arb's, or hands over. It never certifies a circle where there is none (by
// the kappa2 signs of predicates/voronoi_circle_count.hpp).
#include "graph/delaunay_graph.hpp"
#include "traits/ellipse_delaunay_traits.hpp"
#include "predicates/voronoi_circle_count.hpp"
#include "sites/packing_generator.hpp"
#include "subdivision/voronoi_circle.hpp"
#include "subdivision/voronoi_circle_in_doubles.hpp"
#include "tests/support/apollonius_oracle.hpp"
#include "tests/support/random_sites.hpp"
#include "tests/support/diagnostics.hpp"
#include "tests/support/huge_hull_triple.hpp"
#include "predicates/incircle.hpp"

#include <catch2/catch.hpp>

#include <cfenv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

using namespace ellvor;
using ellvor::test::show;
using ellvor::test::verbose;

namespace {

using Rng = std::mt19937_64;
using ellvor::test::bounding_circles_apart;
using ellvor::test::random_fraction;


bool meets(const Interval& a, const Interval& b) { return !(a.hi < b.lo || b.hi < a.lo); }

std::string show(const Interval& x) {
    char buf[80];
    std::snprintf(buf, sizeof buf, "[%.17g, %.17g]", x.lo, x.hi);
    return buf;
}

struct Tally {
    int triples = 0, by_arb = 0, by_doubles = 0, by_distances = 0, no_circle = 0;
};

// Whether the box holds the ball (Arb's enclosure, refined far below the
// box's width): a strict test of the box, where meeting is a weak one.
bool holds(const Interval& box, const Ball& b) {
    const Interval e = enclose(b);
    return box.lo <= e.lo && e.hi <= box.hi;
}

// One triple: the double certificate against Arb's.
void compare_with_arb(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3, Tally& tally) {
    ++tally.triples;
    const std::optional<DoubleVoronoiCircle> d = certify_voronoi_circle_in_doubles(e1, e2, e3);
    INFO(apollonius::ell({&e1, &e2, &e3}));
    // Whether the circle exists: from the kappa2 signs (exact at the end),
    // cheaper than Arb's exhaustive search for proving that it does not.
    const VoronoiCircles count = *voronoi_circle_count(e1, e2, e3);
    if (count == VoronoiCircles::none || count == VoronoiCircles::cw_only) {
        ++tally.no_circle;
        CHECK(!d.has_value());  // a certificate where there is no circle: contradiction
        return;
    }
    ++tally.by_arb;
    VoronoiCircleSolver arb(e1, e2, e3);
    REQUIRE(arb.certify());
    if (!d) return;  // handed over
    ++tally.by_doubles;
    const VoronoiCircleEnclosure& c = arb.enclosure();
    INFO("doubles: x " << show(d->center_x) << " y " << show(d->center_y) << " radius " << show(d->radius));
    INFO("Arb: x " << c.center_x.str(20) << " y " << c.center_y.str(20) << " radius " << c.radius.str(20));
    // Both hold the unique counter-clockwise circle: the enclosures meet.
    CHECK(meets(d->center_x, enclose(c.center_x)));
    CHECK(meets(d->center_y, enclose(c.center_y)));
    CHECK(meets(d->radius, enclose(c.radius)));
    for (int i = 0; i < 3; ++i) {
        // Tangency parameters, in the same chart, or else as t_i (unless one
        // of them holds the i-point, where t_i is unbounded).
        if (d->flipped[i] == c.flipped[i]) {
            CHECK(meets(d->parameter[i], enclose(c.parameter[i])));
        } else {
            const Ball t = c.tangency_parameter(i, 64);
            if (d->parameter[i].contains_zero() || !arb_is_finite(t.get())) continue;
            const Interval td = d->flipped[i] ? Interval(-1.0) / d->parameter[i] : d->parameter[i];
            CHECK(meets(td, enclose(t)));
        }
    }
    // The enclosure is tight: in doubles the plane's coordinates, not the
    // circle's size, set the rounding (a triple 10^12 from the origin gets
    // a radius to about 10^-3), and nearly collinear triples are ill-conditioned:
    // a circle R times its smallest site loses about log2(R / size) more bits
    // (10^7 times: ten times wider).
    const double size =
        std::fmax(std::fabs(d->radius.lo), std::fabs(d->radius.hi)) + std::fabs(d->center_x.hi) + std::fabs(d->center_y.hi);
    double smallest = HUGE_VAL;
    for (const Ellipse* e : {&e1, &e2, &e3}) smallest = std::min({smallest, e->enclosure().a.lo, e->enclosure().b.lo});
    const double condition = std::fmax(1.0, d->radius.lo / smallest / 1e6);
    INFO("radius / smallest semi-axis " << d->radius.lo / smallest);
    CHECK(d->radius.hi - d->radius.lo <= 1e-6 * condition * size);
    if (!d->by_distances) return;
    // The certificate by distances (rho > 0) encloses the circle: Arb's, at
    // 80 correct bits, lies inside each of its intervals.
    ++tally.by_distances;
    CHECK(d->radius.lo > 0);
    REQUIRE(arb.refine(80));
    CHECK(holds(d->center_x, c.center_x));
    CHECK(holds(d->center_y, c.center_y));
    CHECK(holds(d->radius, c.radius));
    for (int i = 0; i < 3; ++i)
        if (d->flipped[i] == c.flipped[i]) CHECK(holds(d->parameter[i], c.parameter[i]));
}

Ellipse random_site(Rng& rng, long half_box, long max_axis_tenths, long min_axis_tenths = 2) {
    const long den_center = 1000;
    if (std::uniform_int_distribution<int>(0, 4)(rng) == 0)
        return Ellipse::circle(random_fraction(rng, -half_box * den_center, half_box * den_center, den_center),
                               random_fraction(rng, -half_box * den_center, half_box * den_center, den_center),
                               random_fraction(rng, min_axis_tenths, max_axis_tenths, 10));
    return Ellipse(random_fraction(rng, min_axis_tenths, max_axis_tenths, 10),
                   random_fraction(rng, min_axis_tenths, max_axis_tenths, 10), random_fraction(rng, -300, 300, 97),
                   random_fraction(rng, -half_box * den_center, half_box * den_center, den_center),
                   random_fraction(rng, -half_box * den_center, half_box * den_center, den_center));
}

// Three random sites (random_site, box 15, axes to 4) with their bounding
// circles apart.
std::vector<Ellipse> random_triple_apart(Rng& rng) {
    std::vector<Ellipse> e;
    while (e.size() < 3) {
        Ellipse s = random_site(rng, 15, 40);
        bool apart = true;
        for (const Ellipse& o : e) apart = apart && bounding_circles_apart(o, s);
        if (apart) e.push_back(s);
    }
    return e;
}

}  // namespace

TEST_CASE("doubles vs Arb: 10^4 random triples, certified or handed over, never contradicting",
          "[subdivision][voronoi_circle_in_doubles]") {
    Rng rng(20261124);
    Tally tally;
    while (tally.triples < 10000) {
        const std::vector<Ellipse> e = random_triple_apart(rng);
        compare_with_arb(e[0], e[1], e[2], tally);
    }
    if (verbose())
        std::printf("[doubles vs Arb] random: %d triples, %d with a circle, %d certified in doubles "
                    "(%d by distances), %d without\n",
                    tally.triples, tally.by_arb, tally.by_doubles, tally.by_distances, tally.no_circle);
    CHECK(tally.no_circle >= 1000);  // both kinds are exercised
    CHECK(tally.by_doubles >= 0.95 * tally.by_arb);
    // Sites apart: the circle touches each from outside, and the center's
    // distances certify it (the 6 x 6 test is the exception).
    CHECK(tally.by_distances >= 0.95 * tally.by_doubles);
}

TEST_CASE("doubles: the certificate by distances about points off the root holds Arb's circle",
          "[subdivision][voronoi_circle_in_doubles]") {
    // Tangency parameters 1e-8 to 1e-2 off the root and a center 1e-8 to
    // 1e-4 of the radius off: the normals at the parameters then miss the
    // directions to the center by up to about that angle (the test's
    // `slope`), which every enclosure must absorb (without it in the
    // gradients' and the parameters' bounds 5019 checks fail, in the
    // gradients' alone 6).
    Rng rng(20261129);
    std::uniform_real_distribution<double> exponent(0, 1), sign(-1, 1);
    int attempts = 0, certified = 0;
    while (attempts < 2000) {
        const std::vector<Ellipse> e = random_triple_apart(rng);
        const std::optional<DoubleVoronoiCircle> d = certify_voronoi_circle_in_doubles(e[0], e[1], e[2]);
        if (!d || !d->by_distances) continue;
        VoronoiCircleSolver arb(e[0], e[1], e[2]);
        REQUIRE(arb.certify());
        REQUIRE(arb.refine(80));
        const VoronoiCircleEnclosure& c = arb.enclosure();
        ++attempts;
        std::array<double, 6> m;
        const double parameter_off = std::pow(10.0, -8 + 6 * exponent(rng)), center_off = std::pow(10.0, -8 + 4 * exponent(rng));
        for (int i = 0; i < 3; ++i) m[i] = d->parameter[i].mid() + parameter_off * sign(rng);
        m[3] = d->radius.mid();
        m[4] = d->center_x.mid() + center_off * m[3] * sign(rng);
        m[5] = d->center_y.mid() + center_off * m[3] * sign(rng);
        const std::optional<DoubleVoronoiCircle> off = certify_voronoi_circle_by_distances_at(e[0], e[1], e[2], d->flipped, m);
        if (!off) continue;
        ++certified;
        INFO(apollonius::ell({&e[0], &e[1], &e[2]}));
        INFO("parameters off " << parameter_off << ", center off " << center_off << " radii");
        CHECK(off->by_distances);
        CHECK(holds(off->center_x, c.center_x));
        CHECK(holds(off->center_y, c.center_y));
        CHECK(holds(off->radius, c.radius));
        for (int i = 0; i < 3; ++i)
            if (off->flipped[i] == c.flipped[i]) CHECK(holds(off->parameter[i], c.parameter[i]));
    }
    if (verbose()) std::printf("[doubles] by distances off the root: %d of %d certified\n", certified, attempts);
    CHECK(certified >= attempts / 2);
}

TEST_CASE("doubles vs Arb: elongated sites that nearly touch (a dense packing), by the damped retry",
          "[subdivision][voronoi_circle_in_doubles][packing]") {
    // Three sites of `ellvor generate packing --count 300 --packing-fraction
    // 0.58 --seed 1` (ids 6, 52, 232; aspect ratios 2.8 to 3.4, 10^-3 to 10^-2
    // apart): Newton from the models' starts cycles; the damped retry
    // converges, and the circle agrees with Arb's.
    const Ellipse e1(Rational(Integer(27848240823L), Integer(17179869184L)), Rational(9781609, 16777216UL),
                     Rational(77873, 1048576UL), Rational(Integer(6089526189711L), Integer(549755813888L)),
                     Rational(Integer(11929442458627L), Integer(1099511627776L)));
    const Ellipse e2(Rational(Integer(14952985333L), Integer(17179869184L)), Rational(6509789, 16777216UL),
                     Rational(-163465, 1048576UL), Rational(Integer(12905923714211L), Integer(1099511627776L)),
                     Rational(Integer(5355100314917L), Integer(549755813888L)));
    const Ellipse e3(Rational(Integer(13908859551L), Integer(34359738368L)), Rational(2054181, 16777216UL),
                     Rational(256819, 1048576UL), Rational(Integer(6765470505987L), Integer(549755813888L)),
                     Rational(Integer(5650561932395L), Integer(549755813888L)));
    REQUIRE(certify_voronoi_circle_in_doubles(e1, e2, e3).has_value());
    Tally one;
    compare_with_arb(e1, e2, e3, one);
    CHECK(one.by_doubles == 1);
    // Every face of the packing's graph: at least 99% certified in doubles
    // (97.4% before the retry), none contradicting Arb.
    PackingOptions o;
    o.count = 300;
    o.fraction = Rational(58, 100);
    o.seed = 1;
    const std::vector<Ellipse> sites = generate_packing(o).sites;
    DelaunayGraph g(std::make_unique<EllipseDelaunayTraits>(sites));
    g.insert_all();
    Tally tally;
    for (const auto& f : g.faces()) compare_with_arb(sites[f[0]], sites[f[1]], sites[f[2]], tally);
    CHECK(tally.by_arb > 500);
    CHECK(tally.by_doubles >= 0.99 * tally.by_arb);
}

TEST_CASE("doubles vs Arb: near-degenerate triples", "[subdivision][voronoi_circle_in_doubles]") {
    Rng rng(77);
    Tally tally;
    auto q = [](long n, unsigned long d) { return Rational(n, d); };
    std::vector<std::array<Ellipse, 3>> triples;
    for (int k = 2; k <= 14; k += 2) {
        const Rational eps = power_of_ten(-k);
        // Nearly collinear centers: huge circles (radius ~ 10^k).
        triples.push_back({Ellipse::circle(-10, 0, 1), Ellipse::circle(0, eps, 1), Ellipse::circle(10, 0, 1)});
        triples.push_back({Ellipse(2, 1, 0, -10, 0), Ellipse(2, 1, q(1, 3), 0, eps), Ellipse(2, 1, 0, 10, 0)});
        // Sites 10^-k apart: tiny gaps.
        triples.push_back({Ellipse(1, q(1, 2), 0, 0, 0), Ellipse(1, q(1, 2), 0, Rational(2) + eps, 0),
                           Ellipse(1, q(1, 2), 1, 1, Rational(2) + eps)});
        // Needles: axis ratio 10^k / 100.
        triples.push_back({Ellipse(5, Rational(100) * eps + eps, 0, 0, 0), Ellipse(1, 1, 0, 0, 3),
                           Ellipse(1, q(1, 3), q(1, 2), 4, -4)});
        // Far from the origin: 10^k offsets.
        const Rational far = power_of_ten(k);
        triples.push_back({Ellipse(2, 1, 0, far, far), Ellipse(1, 1, 0, far + 5, far), Ellipse(1, 2, q(1, 5), far, far + 6)});
        // Cocircular (Q-free, but the triple is symmetric) at growing scales.
        triples.push_back({Ellipse(2, 1, 0, 5 * far, 0), Ellipse(2, 1, 1, 0, 5 * far), Ellipse(2, 1, 0, -5 * far, 0)});
    }
    // Random near-collinear triples with ellipses of very different sizes.
    while (triples.size() < 400) {
        const Rational eps = power_of_ten(-std::uniform_int_distribution<int>(1, 12)(rng));
        const Ellipse a = random_site(rng, 2, 30), b = random_site(rng, 2, 30);
        const Ellipse e1(a.a(), a.b(), a.w(), a.xc() - 20, a.yc());
        const Ellipse e2(b.a() / 100, b.b() / 100, b.w(), b.xc() / 100, eps);
        const Ellipse e3(b.a(), b.b(), a.w(), b.xc() + 20, b.yc());
        if (!bounding_circles_apart(e1, e2) || !bounding_circles_apart(e2, e3) || !bounding_circles_apart(e1, e3)) continue;
        triples.push_back({e1, e2, e3});
    }
    for (const auto& t : triples)
        for (int rotation = 0; rotation < 2; ++rotation) {
            // Both orientations: one of them usually has no circle.
            if (rotation == 0) compare_with_arb(t[0], t[1], t[2], tally);
            else compare_with_arb(t[0], t[2], t[1], tally);
        }
    if (verbose())
        std::printf("[doubles vs Arb] near-degenerate: %d triples, %d with a circle, %d certified in doubles "
                    "(%d by distances), %d without\n",
                    tally.triples, tally.by_arb, tally.by_doubles, tally.by_distances, tally.no_circle);
    CHECK(tally.by_doubles > 0);
    CHECK(tally.by_doubles < tally.by_arb);  // some are beyond doubles and handed over
}

TEST_CASE("VoronoiCircle: the double certificate once, the solver only on demand",
          "[subdivision][voronoi_circle_in_doubles]") {
    const Ellipse e1 = Ellipse::circle(6, 0, 1), e2 = Ellipse::circle(0, 6, 1), e3 = Ellipse::circle(-6, 0, 1);
    VoronoiCircle circle(e1, e2, e3);
    CHECK(!circle.has_solver());
    const DoubleVoronoiCircle* d = circle.in_doubles();
    REQUIRE(d != nullptr);
    CHECK(circle.in_doubles() == d);
    CHECK(!circle.has_solver());
    // The circle is centered at the origin with radius 5.
    CHECK(d->center_x.contains_zero());
    CHECK(d->center_y.contains_zero());
    CHECK(meets(d->radius, Interval(5.0)));
    CHECK(d->radius.hi - d->radius.lo < 1e-12);
    // The reversed triple has no counter-clockwise circle: never certified.
    VoronoiCircle reversed(e1, e3, e2);
    CHECK(reversed.in_doubles() == nullptr);
    REQUIRE(!reversed.solver().certify());
    CHECK(reversed.has_solver());
}

TEST_CASE("doubles: the certificate leaves the caller's rounding mode as it found it",
          "[subdivision][voronoi_circle_in_doubles][upward-interval]") {
    // Krawczyk's test runs under FE_UPWARD (util/upward_interval.hpp); the
    // Newton iteration and the rest run in the caller's mode, whatever it is
    // (Interval's one-ulp widening holds in every mode). The same triple,
    // certified from each mode, gives a box that holds Arb's circle.
    const Ellipse e1(2, 1, Rational(1, 3), 0, 0), e2 = Ellipse::circle(7, 1, 2), e3(3, Rational(1, 2), -1, 2, 6);
    VoronoiCircleSolver arb(e1, e2, e3);
    REQUIRE(arb.certify());
    const Interval radius = enclose(arb.enclosure().radius);
    for (int mode : {FE_TONEAREST, FE_DOWNWARD, FE_TOWARDZERO, FE_UPWARD}) {
        INFO("mode " << mode);
        REQUIRE(std::fesetround(mode) == 0);
        const std::optional<DoubleVoronoiCircle> d = certify_voronoi_circle_in_doubles(e1, e2, e3);
        const int after = std::fegetround();
        std::fesetround(FE_TONEAREST);
        CHECK(after == mode);
        REQUIRE(d.has_value());
        CHECK(meets(d->radius, radius));
    }
}

TEST_CASE("doubles: a huge circle of nearly collinear sites, from the tangent-line starts", "[subdivision][voronoi_circle_in_doubles]") {
    // Three ellipses ~0.3 wide, ~50 apart, nearly on a line (from a random
    // set of 3000): the counter-clockwise circle has radius ~27027; the
    // circle models' starts lead Newton to the clockwise one, the tangent
    // line of a pair leads it to the right one.
    const Ellipse e1(Rational(77, 201), Rational(15, 43), Rational(75, 158), Rational(382, 29), Rational(-1241, 13));
    const Ellipse e2(Rational(36, 121), Rational(104, 253), Rational(-2, 3), Rational(4034, 189), Rational(-3657, 38));
    const Ellipse e3(Rational(20, 53), Rational(31, 232), Rational(-122, 247), Rational(4733, 87), Rational(-199, 2));
    const std::optional<DoubleVoronoiCircle> d = certify_voronoi_circle_in_doubles(e1, e2, e3);
    REQUIRE(d.has_value());
    CHECK(d->from_tangent_line);
    CHECK(d->radius.lo > 27000);
    Tally tally;
    compare_with_arb(e1, e2, e3, tally);  // agrees with Arb
    CHECK(tally.by_doubles == 1);
    // VoronoiCircle hands the double box to its Arb solver, which starts
    // certified there (certify_near) and holds the same circle.
    VoronoiCircle circle(e1, e2, e3);
    REQUIRE(circle.in_doubles() != nullptr);
    VoronoiCircleSolver& solver = circle.solver();
    CHECK(solver.certified());
    CHECK(meets(circle.in_doubles()->radius, enclose(solver.enclosure().radius)));
    CHECK(meets(circle.in_doubles()->center_x, enclose(solver.enclosure().center_x)));
}

TEST_CASE("doubles: hull circles of sites in a row along a packing's wall, from the tangent-line starts",
          "[subdivision][voronoi_circle_in_doubles][packing]") {
    // Faces of `ellvor generate packing --count 2000 --packing-fraction 0.58
    // --seed 1`: sites along the box's wall, circles 14 and 190 times the
    // largest semi-axis away. The circle models of the first triple have no
    // Apollonius circle; those of the second lead Newton to another root. The
    // tangent-line starts from 2^3 sizes on certify both, as Arb does.
    auto q = [](long num, long den) { return Rational(Integer(num), Integer(den)); };
    const Ellipse a1(q(25110794051L, 34359738368L), q(4599889, 8388608), q(507647, 1048576),
                     q(9836711759407L, 274877906944L), q(48634812075005L, 1099511627776L));
    const Ellipse a2(q(74725386171L, 68719476736L), q(5783251, 16777216), q(-900759, 1048576),
                     q(22467072843067L, 549755813888L), q(24064735880157L, 549755813888L));
    const Ellipse a3(q(828592707L, 2147483648L), q(146059, 524288), q(872607, 1048576),
                     q(38435925520643L, 1099511627776L), q(24495072094723L, 549755813888L));
    const Ellipse b2(q(10350545205L, 34359738368L), q(1445405, 8388608), q(163629, 262144),
                     q(40627477479465L, 1099511627776L), q(24509465583549L, 549755813888L));
    const Ellipse b3(q(10500467431L, 17179869184L), q(1026539, 4194304), q(135973, 1048576),
                     q(42854867327667L, 1099511627776L), q(24372593497143L, 549755813888L));
    for (const auto& [e1, e2, e3, radius] : {std::tuple{&a1, &a2, &a3, 95.2}, {&a2, &b2, &b3, 6.87}}) {
        INFO("radius " << radius);
        const std::optional<DoubleVoronoiCircle> d = certify_voronoi_circle_in_doubles(*e1, *e2, *e3);
        REQUIRE(d.has_value());
        CHECK(d->from_tangent_line);
        CHECK(d->radius.lo > radius * (1 - 1e-3));
        CHECK(d->radius.hi < radius * (1 + 1e-3));
        Tally tally;
        compare_with_arb(*e1, *e2, *e3, tally);  // holds Arb's circle
        CHECK(tally.by_doubles == 1);
    }
}

TEST_CASE("doubles: the 3e5-radius hull circle of 10^6 random ellipses certifies and holds Arb's",
          "[subdivision][voronoi_circle_in_doubles]") {
    // Before the square, doubling, negation and reciprocal shortcuts of
    // boundary_at, the one-ulp widening of the general products at rho ~ 3e5
    // kept Krawczyk's box from contracting: no certificate, Arb ran. Then
    // the tangent-line starts certified it; since the upward rounding mode
    // (no widening at all) a circle model's start, whose Newton also reaches
    // it, certifies first.
    const std::vector<Ellipse> s = ellvor::test::huge_hull_triple();
    const std::optional<DoubleVoronoiCircle> d = certify_voronoi_circle_in_doubles(s[0], s[1], s[2]);
    REQUIRE(d.has_value());
    CHECK(d->radius.lo > 3e5);
    // Arb's enclosure at 80 correct bits lies inside the double box.
    VoronoiCircleSolver arb(s[0], s[1], s[2]);
    REQUIRE(arb.refine(80));
    const VoronoiCircleEnclosure& c = arb.enclosure();
    INFO("doubles: x " << show(d->center_x) << " y " << show(d->center_y) << " radius " << show(d->radius));
    INFO("Arb: x " << c.center_x.str(20) << " y " << c.center_y.str(20) << " radius " << c.radius.str(20));
    CHECK(holds(d->center_x, c.center_x));
    CHECK(holds(d->center_y, c.center_y));
    CHECK(holds(d->radius, c.radius));
    for (int i = 0; i < 3; ++i)
        if (d->flipped[i] == c.flipped[i]) CHECK(holds(d->parameter[i], c.parameter[i]));
    // InCircle decides on the double circle (the filter stage) without
    // building the Arb solver: a site far right of the disk, one inside it.
    VoronoiCircle circle(s[0], s[1], s[2]);
    const Ellipse beyond(Rational(1, 10), Rational(1, 20), 0, 50, 0), within(Rational(1, 10), Rational(1, 20), 0, -300, 63);
    const Decision<InCircle> no = incircle(s[0], s[1], s[2], beyond, {}, &circle);
    const Decision<InCircle> yes = incircle(s[0], s[1], s[2], within, {}, &circle);
    REQUIRE(no.is_decided());
    REQUIRE(yes.is_decided());
    CHECK(*no == InCircle::no_conflict);
    CHECK(*yes == InCircle::conflict);
    CHECK(no.stage == Stage::filter);
    CHECK(yes.stage == Stage::filter);
    CHECK(!circle.has_solver());
}

TEST_CASE("doubles: a circle 10^6 sizes across stalls Newton; the Arb solver starts from that root",
          "[subdivision][voronoi_circle_in_doubles][packing]") {
    // Triples of a dense packing (`ellvor generate packing --count 2000
    // --packing-fraction 0.58 --gap 1e-6 --seed 1`, and --count 10000 --gap
    // 1e-3) whose circles are 4e5 and 3.6e6 across, sites of size 0.3-1:
    // Newton in doubles reaches the circle only to the rounding noise and the
    // double Krawczyk test fails. The stalled root is handed to the Arb
    // solver (StalledDoubleRoot, VoronoiCircleSolver::certify_near), which
    // otherwise started from its guesses: 25 ms each, 16% of the 2000-site
    // packing's build.
    auto site = [](const char* a, const char* b, const char* w, const char* x, const char* y) {
        auto q = [](const char* s) {
            Rational r;
            REQUIRE(fmpq_set_str(r.get(), s, 10) == 0);
            return r;
        };
        return Ellipse(q(a), q(b), q(w), q(x), q(y));
    };
    const std::vector<std::array<Ellipse, 3>> triples = {
        {site("70523124705/68719476736", "4576155/16777216", "294677/524288", "11838897136595/274877906944",
              "48342688393311/1099511627776"),
         site("5173268627/17179869184", "1769849/8388608", "-776747/1048576", "13290563396493/549755813888",
              "49106507242867/1099511627776"),
         site("9806144377/34359738368", "2538479/16777216", "993501/1048576", "28833610019487/1099511627776",
              "49104800787277/1099511627776")},
        {site("7472763529/8589934592", "3346513/8388608", "-385727/1048576", "54420054025767/549755813888",
              "3143751011919/549755813888"),
         site("29268844825/68719476736", "5979335/16777216", "-176531/1048576", "27360451358863/274877906944",
              "88275168053915/1099511627776"),
         site("8005599115/8589934592", "1197905/2097152", "271633/1048576", "108916004910591/1099511627776",
              "76154578344281/1099511627776")}};
    auto text = [](const Ellipse& e) {
        return e.a().str() + " " + e.b().str() + " " + e.w().str() + " " + e.xc().str() + " " + e.yc().str() + "\n";
    };
    for (const auto& [e1, e2, e3] : triples) {
        INFO(text(e1) << text(e2) << text(e3));
        std::optional<StalledDoubleRoot> stalled;
        REQUIRE(!certify_voronoi_circle_in_doubles(e1, e2, e3, &stalled));
        REQUIRE(stalled.has_value());
        // The stalled root is the counter-clockwise circle, to 1e-5 of its
        // radius (Arb's, certified from its own starts).
        VoronoiCircleSolver fresh(e1, e2, e3);
        REQUIRE(fresh.certify());
        const VoronoiCircleEnclosure& c = fresh.enclosure();
        const double radius = enclose(c.radius).mid();
        CHECK(radius > 4e5);
        CHECK(std::fabs(stalled->x[3] - radius) < 1e-5 * radius);
        CHECK(std::fabs(stalled->x[4] - enclose(c.center_x).mid()) < 1e-5 * radius);
        CHECK(std::fabs(stalled->x[5] - enclose(c.center_y).mid()) < 1e-5 * radius);
        for (int i = 0; i < 3; ++i) CHECK(stalled->flipped[i] == c.flipped[i]);
        // VoronoiCircle: no double certificate, and its solver is certified
        // as it is made (from the stalled root; without one it is made bare).
        VoronoiCircle circle(e1, e2, e3);
        CHECK(circle.in_doubles() == nullptr);
        CHECK(circle.solver().certified());
        const VoronoiCircleEnclosure& near = circle.solver().enclosure();
        CHECK(arb_overlaps(near.radius.get(), c.radius.get()));
        CHECK(arb_overlaps(near.center_x.get(), c.center_x.get()));
        CHECK(arb_overlaps(near.center_y.get(), c.center_y.get()));
        // Reversed, the second triple has only this circle, clockwise: the
        // doubles offer no stalled root (the orientation in doubles rejects
        // it) and the solver proves that there is no counter-clockwise circle.
        if (&e1 == &triples[1][0]) {
            std::optional<StalledDoubleRoot> none;
            CHECK(!certify_voronoi_circle_in_doubles(e1, e3, e2, &none));
            CHECK(!none.has_value());
            VoronoiCircle reversed(e1, e3, e2);
            CHECK(reversed.in_doubles() == nullptr);
            CHECK(!reversed.solver().certified());
            CHECK(!reversed.solver().certify());
        }
    }
}

TEST_CASE("doubles: no root at all for a circle 10^11 sizes across; the Arb solver starts from the tangent lines",
          "[subdivision][voronoi_circle_in_doubles][packing]") {
    // Sites in a row along the wall of a dense packing (`ellvor generate
    // packing --count 100000 --packing-fraction 0.58 --gap 1e-3 --seed 1`):
    // their circle's radius is 1.3e11 (sizes 0.3-1), beyond doubles even as a
    // stalled root. VoronoiCircle then tries the tangent-line starts before
    // the guesses (a fresh solver's certify() spends 44 ms in its guesses;
    // the tangent lines certify in 1 ms).
    auto q = [](const char* s) {
        Rational r;
        REQUIRE(fmpq_set_str(r.get(), s, 10) == 0);
        return r;
    };
    const Ellipse e1(q("10299703085/17179869184"), q("3944735/8388608"), q("-63669/524288"), q("347893310261643/1099511627776"), q("46545901366373/549755813888")), e2(q("40384073077/68719476736"), q("5449207/16777216"), q("45135/524288"), q("86976407168995/274877906944"), q("157910089549185/549755813888")),
        e3(q("9062355577/17179869184"), q("2649037/16777216"), q("61385/1048576"), q("21748050055377/68719476736"), q("117504476416055/549755813888"));
    std::optional<StalledDoubleRoot> stalled;
    REQUIRE(!certify_voronoi_circle_in_doubles(e1, e2, e3, &stalled));
    CHECK(!stalled.has_value());
    VoronoiCircle circle(e1, e2, e3);
    CHECK(circle.in_doubles() == nullptr);
    REQUIRE(circle.solver().certified());
    const VoronoiCircleEnclosure& near = circle.solver().enclosure();
    CHECK(near.found_by == CircleStart::tangent_line);
    VoronoiCircleSolver fresh(e1, e2, e3);
    REQUIRE(fresh.certify());
    const VoronoiCircleEnclosure& c = fresh.enclosure();
    CHECK(enclose(c.radius).lo > 1e11);
    CHECK(arb_overlaps(near.radius.get(), c.radius.get()));
    CHECK(arb_overlaps(near.center_x.get(), c.center_x.get()));
    CHECK(arb_overlaps(near.center_y.get(), c.center_y.get()));
    for (int i = 0; i < 3; ++i) CHECK(arb_overlaps(near.parameter[i].get(), c.parameter[i].get()));
    // Reversed, (E1, E3, E2) has its own counter-clockwise circle (the
    // triple has both): what the tangent lines certify is the complete
    // solver's circle there too.
    VoronoiCircleSolver reversed(e1, e3, e2), reversed_fresh(e1, e3, e2);
    const bool by_lines = reversed.certify_from_tangent_lines();
    CHECK(by_lines == reversed.certified());
    REQUIRE(reversed_fresh.certify());
    if (by_lines) {
        CHECK(arb_overlaps(reversed.enclosure().radius.get(), reversed_fresh.enclosure().radius.get()));
        CHECK(arb_overlaps(reversed.enclosure().center_x.get(), reversed_fresh.enclosure().center_x.get()));
        CHECK(!arb_overlaps(reversed.enclosure().radius.get(), c.radius.get()));
    }
}

TEST_CASE("doubles: a center inside the sites (crossing sites, rho < 0) is certified by the 6 x 6 test, not by distances",
          "[subdivision][voronoi_circle_in_doubles]") {
    // Three ellipses that cross one another around the origin: the circle's
    // center lies inside all three, where the distance certificate proves
    // nothing (no point outside a site); the tritangent test with
    // Blaschke's bound certifies the internal circle, as Arb does.
    const Ellipse e1(Rational(8, 5), Rational(7, 5), 0, 1, 0);
    const Ellipse e2(Rational(8, 5), Rational(7, 5), Rational(1, 2), Rational(-1, 2), Rational(7, 8));
    const Ellipse e3(Rational(8, 5), Rational(7, 5), Rational(-1, 3), Rational(-1, 2), Rational(-7, 8));
    const std::optional<DoubleVoronoiCircle> d = certify_voronoi_circle_in_doubles(e1, e2, e3);
    REQUIRE(d.has_value());
    CHECK(!d->by_distances);
    CHECK(d->radius.hi < 0);
    Tally tally;
    compare_with_arb(e1, e2, e3, tally);
    CHECK(tally.by_doubles == 1);
    CHECK(tally.by_distances == 0);
    // Moved apart, the same shapes' circle is certified by distances.
    const Ellipse f1(Rational(8, 5), Rational(7, 5), 0, 5, 0);
    const Ellipse f2(Rational(8, 5), Rational(7, 5), Rational(1, 2), Rational(-5, 2), Rational(35, 8));
    const Ellipse f3(Rational(8, 5), Rational(7, 5), Rational(-1, 3), Rational(-5, 2), Rational(-35, 8));
    compare_with_arb(f1, f2, f3, tally);
    CHECK(tally.by_doubles == 2);
    CHECK(tally.by_distances == 1);
}
