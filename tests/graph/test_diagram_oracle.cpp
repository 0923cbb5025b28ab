// The independent diagram checker of tests/support/signed_distance_oracle.hpp:
// first its signed distance (closed forms, properties, thin ellipses, points
// at the medial axis), then the checker on the graphs ellvor builds from the
// inputs it accepts today -- disjoint ellipses (thin ones too), nested ones,
// crossing circles, after removals -- and on corrupted claims, which it must
// reject.
#include "graph/delaunay_graph.hpp"
#include "sites/ellipse.hpp"
#include "sites/packing_generator.hpp"
#include "sites/site_generators.hpp"
#include "tests/support/ellipse_graph.hpp"
#include "tests/support/graph_shape.hpp"
#include "tests/support/random_sites.hpp"
#include "tests/support/signed_distance_oracle.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <utility>
#include <vector>

using namespace ellvor;
using test::OracleEllipse;
using test::Real;
using test::RealPoint;

namespace {

RealPoint exact(const Point& p) { return {Real(p.x), Real(p.y)}; }

double delta(const OracleEllipse& e, const Point& p) { return e.signed_distance_value(exact(p)).to_double(); }

// C + s U + t V for the ellipse's rotation u = (cos, sin), v = (-sin, cos):
// exact rationals, so that points on the axes are exactly on them.
Point in_frame(const Ellipse& e, const Rational& s, const Rational& t) {
    const Rational &c = e.cos_rotation(), &n = e.sin_rotation();
    return {e.xc() + s * c - t * n, e.yc() + s * n + t * c};
}

// An ellipse with aspect ratio up to 100, rotated, anywhere in [-50, 50]^2.
Ellipse random_ellipse(std::mt19937_64& rng) {
    const Rational a = test::random_fraction(rng, 100, 1000, 100);
    const Rational b = a / test::random_fraction(rng, 1, 100, 1);
    const Rational w = test::random_fraction(rng, -1000, 1000, 1000);
    return Ellipse(a, b, w, test::random_fraction(rng, -5000, 5000, 100), test::random_fraction(rng, -5000, 5000, 100));
}

// n boundary points in doubles, evenly spread in the angle (for a brute-force
// nearest point, to double precision).
std::vector<std::pair<double, double>> boundary_samples(const Ellipse& e, int n) {
    const double a = e.a().to_double(), b = e.b().to_double(), c = e.cos_rotation().to_double(),
                 s = e.sin_rotation().to_double(), xc = e.xc().to_double(), yc = e.yc().to_double();
    std::vector<std::pair<double, double>> out;
    for (int i = 0; i < n; ++i) {
        const double t = 2 * M_PI * i / n, u = a * std::cos(t), v = b * std::sin(t);
        out.emplace_back(xc + u * c - v * s, yc + u * s + v * c);
    }
    return out;
}

Real length(const RealPoint& p, const RealPoint& q) { return hypot(p.x - q.x, p.y - q.y); }

std::string check_built(const std::vector<Ellipse>& sites) {
    DelaunayGraph g = test::ellipse_graph(sites);
    g.insert_all();
    return test::check_diagram(sites, g);
}

std::vector<Ellipse> generated(SiteKind kind, long count, std::uint64_t seed, Rational nested, Rational crossing) {
    GeneratorOptions o;
    o.kind = kind;
    o.count = count;
    o.seed = seed;
    o.nested_fraction = nested;
    o.crossing_fraction = crossing;
    return generate_sites(o);
}

// Disjoint thin ellipses (aspect ratio 10 to 100), by rejection.
std::vector<Ellipse> thin_ellipses(std::size_t count, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::vector<Ellipse> sites;
    while (sites.size() < count) {
        const Rational a = test::random_fraction(rng, 200, 800, 100);
        const Ellipse e(a, a / test::random_fraction(rng, 10, 100, 1), test::random_fraction(rng, -1000, 1000, 1000),
                        test::random_fraction(rng, -6000, 6000, 100), test::random_fraction(rng, -6000, 6000, 100));
        bool apart = true;
        for (const Ellipse& o : sites) apart = apart && test::bounding_circles_apart(e, o);
        if (apart) sites.push_back(e);
    }
    return sites;
}

Ellipse circle(long x, long y, long r) { return Ellipse::circle(x, y, r); }

// Circles with integer data overlapping freely (the box about as wide as they
// cover): crossing, nested and tangent pairs, internal Voronoi circles. Only
// identical circles, which the input refuses, are left out.
std::vector<Ellipse> overlapping_circles(std::size_t count, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    const long rmax = 20, box = static_cast<long>(0.6 * rmax * std::sqrt(double(count)));
    std::uniform_int_distribution<long> coordinate(-box, box), radius(1, rmax);
    std::vector<Ellipse> sites;
    while (sites.size() < count) {
        const Ellipse c = circle(coordinate(rng), coordinate(rng), radius(rng));
        if (std::find(sites.begin(), sites.end(), c) == sites.end()) sites.push_back(c);
    }
    return sites;
}

}  // namespace

// ---- The signed distance ------------------------------------------------------------------------------------

TEST_CASE("oracle distance: circles in closed form", "[oracle]") {
    const Ellipse c = Ellipse::circle(Rational(3, 2), Rational(-7), Rational(5, 4));
    const OracleEllipse o(c);
    CHECK(delta(o, c.center()) == Approx(-1.25).margin(1e-15));
    std::mt19937_64 rng(1);
    for (int k = 0; k < 200; ++k) {
        const Point p{test::random_fraction(rng, -1000, 1000, 100), test::random_fraction(rng, -1000, 1000, 100)};
        const double expected = std::hypot((p.x - c.xc()).to_double(), (p.y - c.yc()).to_double()) - 1.25;
        CHECK(delta(o, p) == Approx(expected).margin(1e-13));
    }
}

TEST_CASE("oracle distance: points on the axes of an ellipse", "[oracle]") {
    // With A > B and D = A² - B²: on the long axis at s, -B sqrt(1 - s²/D)
    // while |s| < D/A (two feet: the point is on the medial axis), then |s| - A;
    // on the short axis at t, |t| - B. medial_axis_point(s) is the point s D/A
    // of the long axis, at -B sqrt(B² + (1 - s²) D) / A (-B²/A at the ends).
    for (const Ellipse& e : {Ellipse(5, 3, Rational(1, 3), 2, -1), Ellipse(Rational(1, 5), 20, Rational(-2, 7), 0, 0),
                             Ellipse(100, 1, 0, 10, 10), Ellipse(100, 1, Rational(3, 10), 0, 0)}) {
        INFO(e.str());
        const OracleEllipse o(e);
        const bool long_a = e.b() < e.a();
        const double A = std::max(e.a().to_double(), e.b().to_double()), B = std::min(e.a().to_double(), e.b().to_double());
        const double D = A * A - B * B;
        // A point at `along` on the long axis, `across` on the short one.
        auto axes_point = [&](const Rational& along, const Rational& across) {
            return long_a ? in_frame(e, along, across) : in_frame(e, across, along);
        };
        for (int k = -60; k <= 60; ++k) {
            const Rational s = Rational(k, 50) * Rational(long_a ? e.a() : e.b());
            const double sd = s.to_double();
            const double expected = std::fabs(sd) < D / A ? -B * std::sqrt(1 - sd * sd / D) : std::fabs(sd) - A;
            CHECK(delta(o, axes_point(s, 0)) == Approx(expected).epsilon(1e-13).margin(1e-13));
            const Rational t = Rational(k, 50) * Rational(long_a ? e.b() : e.a());
            CHECK(delta(o, axes_point(0, t)) == Approx(std::fabs(t.to_double()) - B).epsilon(1e-13).margin(1e-13));
        }
        for (int k = -10; k <= 10; ++k) {
            const double s = k / 10.0;
            CHECK(o.signed_distance_value(o.medial_axis_point(Real(s))).to_double() ==
                  Approx(-B * std::sqrt(B * B + (1 - s * s) * D) / A).epsilon(1e-13));
        }
    }
}

TEST_CASE("oracle distance: boundary points are at distance 0", "[oracle]") {
    std::mt19937_64 rng(2);
    for (int k = 0; k < 50; ++k) {
        const Ellipse e = random_ellipse(rng);
        const OracleEllipse o(e);
        const double scale = std::max(e.a().to_double(), 50.0);
        CHECK(std::fabs(delta(o, e.i_point())) < 1e-50 * scale);
        const Real theta = test::random_fraction(rng, 0, 6283, 1000).to_double();
        CHECK(std::fabs(o.signed_distance_value(o.boundary_point(theta)).to_double()) < 1e-50 * scale);
        for (int j = 0; j < 20; ++j) {
            const Rational t = test::random_fraction(rng, -3000, 3000, 1000);
            CHECK(std::fabs(delta(o, e.point_at(t))) < 1e-50 * scale);
        }
    }
}

TEST_CASE("oracle distance: random points near, inside and far from thin ellipses", "[oracle]") {
    // Properties of a signed distance: sign from the exact implicit equation,
    // the foot on the boundary at |δ| (and x = foot + δ normal), no boundary
    // point nearer (4096 samples, in doubles), 1-Lipschitz, and δ falling at rate 1 from
    // the foot to its medial point (the normal segment belongs to that foot).
    std::mt19937_64 rng(3);
    for (int k = 0; k < 100; ++k) {
        const Ellipse e = random_ellipse(rng);
        INFO(e.str());
        const OracleEllipse o(e);
        const Rational A = std::max(e.a(), e.b()), B = std::min(e.a(), e.b());
        const Rational D = A * A - B * B;
        const bool long_a = e.b() < e.a();
        const double scale = A.to_double();
        const std::vector<std::pair<double, double>> samples = boundary_samples(e, 4096);
        std::vector<Point> points;
        for (int j = 0; j < 10; ++j) {
            // Near the medial axis (offsets down to 2^-54 of it), near the
            // boundary, anywhere within 3 A.
            const Rational s = test::random_fraction(rng, -999, 999, 1000) * D / A;
            const Rational off = test::random_fraction(rng, -1000, 1000, 1000) * Rational(1, 1UL << (6 * j));
            points.push_back(long_a ? in_frame(e, s, off * B) : in_frame(e, off * B, s));
            const Point b = e.point_at(test::random_fraction(rng, -2000, 2000, 1000));
            points.push_back({b.x + off * B, b.y - off * B});
            points.push_back({e.xc() + test::random_fraction(rng, -3000, 3000, 1000) * A,
                              e.yc() + test::random_fraction(rng, -3000, 3000, 1000) * A});
        }
        for (const Point& p : points) {
            const RealPoint x = exact(p);
            const test::SignedDistance d = o.signed_distance(x);
            const double value = d.value.to_double();
            if (std::fabs(value) > 1e-40 * scale) CHECK((value < 0 ? -1 : 1) == e.side_of_point(p.x, p.y));
            CHECK(abs(length(x, d.foot) - abs(d.value)).to_double() < 1e-40 * scale);
            CHECK(abs(o.signed_distance_value(d.foot)).to_double() < 1e-40 * scale);
            const RealPoint back{d.foot.x + d.value * d.normal.x, d.foot.y + d.value * d.normal.y};
            CHECK(length(back, x).to_double() < 1e-40 * scale);
            double nearest_sample = INFINITY;
            for (const auto& [bx, by] : samples)
                nearest_sample = std::min(nearest_sample, std::hypot(x.x.to_double() - bx, x.y.to_double() - by));
            CHECK(nearest_sample >= std::fabs(value) - 1e-12 * scale);
            CHECK(abs(o.signed_distance_value(d.medial) + length(d.medial, d.foot)).to_double() < 1e-35 * scale);
            const RealPoint y{x.x + Real(1e-3 * scale), x.y - Real(2e-3 * scale)};
            CHECK(abs(d.value - o.signed_distance_value(y)) <= length(x, y) + Real(1e-40 * scale));
        }
    }
}

// ---- The checker on built graphs ----------------------------------------------------------------------------

TEST_CASE("oracle: graphs of random disjoint ellipses", "[oracle]") {
    // 1 and 2 sites: no faces; a witness on the medial axis.
    for (long count : {1L, 2L, 3L, 10L, 40L, 100L})
        for (std::uint64_t seed : {1, 2, 3, 4, 5}) {
            INFO(count << " ellipses, seed " << seed);
            CHECK(check_built(generated(SiteKind::ellipses, count, seed, 0, 0)) == "");
        }
}

TEST_CASE("oracle: graphs of dense packings (gaps 10^-3 and 10^-6, packing fraction 0.58)", "[oracle][packing]") {
    for (const auto& [count, gap] : {std::pair<long, Rational>{2000, Rational(1, 1000)},
                                     std::pair<long, Rational>{300, Rational(1, 1000000)}}) {
        PackingOptions o;
        o.count = count;
        o.fraction = Rational(58, 100);
        o.gap = gap;
        o.seed = 2;
        INFO(describe(o));
        CHECK(check_built(generate_packing(o).sites) == "");
    }
}

TEST_CASE("dense packings: close pairs are decided without the exact stage", "[packing][slab]") {
    // Sites 10^-3 and 10^-6 apart (docs/DESIGN.md §3: the searched slab of
    // relative_position); is_hidden and kappa4 went to the exact stage in
    // 18% and 42% of the calls before it.
    for (const Rational& gap : {Rational(1, 1000), Rational(1, 1000000)}) {
        PackingOptions o;
        o.count = 600;
        o.fraction = Rational(58, 100);
        o.gap = gap;
        o.seed = 9;
        DelaunayGraph g = test::ellipse_graph(generate_packing(o).sites);
        g.insert_all();
        const TraitsStats& s = g.predicate_stats();
        INFO(describe(o));
        CHECK(s[Predicate::is_hidden].calls > 2000);
        CHECK(s[Predicate::is_hidden].stages[Stage::exact] == 0);
        CHECK(s[Predicate::finite_edge_interior_conflict].calls > 500);
        CHECK(s[Predicate::finite_edge_interior_conflict].stages[Stage::exact] == 0);
    }
}

TEST_CASE("oracle: graphs of thin ellipses (aspect ratio 10 to 100)", "[oracle]") {
    for (std::size_t count : {30, 100})
        for (std::uint64_t seed : {1, 2, 3}) {
            const std::vector<Ellipse> sites = thin_ellipses(count, seed);
            INFO(test::replay(sites, "seed", {SiteId(seed)}));
            CHECK(check_built(sites) == "");
        }
}

TEST_CASE("oracle: graphs of nested ellipses and circles (hidden by containment)", "[oracle]") {
    for (SiteKind kind : {SiteKind::ellipses, SiteKind::circles})
        for (std::uint64_t seed : {1, 2, 3}) {
            INFO((kind == SiteKind::circles ? "circles" : "ellipses") << ", seed " << seed);
            // One site hiding another: a single visible site.
            CHECK(check_built(generated(kind, 2, seed, Rational(1, 2), 0)) == "");
            const std::vector<Ellipse> sites = generated(kind, 60, seed, Rational(1, 4), 0);
            DelaunayGraph g = test::ellipse_graph(sites);
            g.insert_all();
            REQUIRE(g.hidden().size() == 15);
            CHECK(test::check_diagram(sites, g) == "");
        }
}

TEST_CASE("oracle: graphs of crossing circles", "[oracle]") {
    for (long count : {20L, 100L})
        for (std::uint64_t seed : {1, 2, 3}) {
            INFO(count << " circles, seed " << seed);
            CHECK(check_built(generated(SiteKind::circles, count, seed, Rational(1, 10), Rational(1, 2))) == "");
        }
    std::size_t internal_circles = 0;
    for (std::size_t count : {30, 100})
        for (std::uint64_t seed : {1, 2, 3}) {
            const std::vector<Ellipse> sites = overlapping_circles(count, seed);
            INFO(test::replay(sites, "seed", {SiteId(seed)}));
            DelaunayGraph g = test::ellipse_graph(sites);
            g.insert_all();
            const test::DiagramClaim claim = test::claim_of(g, sites);
            for (const VoronoiVertexValue& v : claim.vertices) internal_circles += v.radius < 0;
            CHECK(test::check_diagram(sites, claim) == "");
        }
    CHECK(internal_circles > 0);
    // A circle covered by a union of others (visible: it owns its centre),
    // internal Voronoi circles (negative radius), three boundaries through a
    // point (radius 0), internal tangency (hidden).
    const std::vector<std::vector<Ellipse>> cases = {
        {circle(0, 0, 5), circle(6, 0, 8), circle(-3, 5, 8), circle(-3, -5, 8)},
        {circle(0, 0, 10), circle(12, 0, 10), circle(6, 10, 10), circle(6, 4, 3)},
        {circle(-5, 0, 5), circle(5, 0, 5), circle(0, 5, 5), circle(0, -5, 5)},
        {circle(0, 0, 10), circle(5, 0, 5), circle(12, 0, 6), circle(0, 14, 7)},
    };
    for (std::size_t c = 0; c < cases.size(); ++c) {
        INFO("case " << c);
        CHECK(check_built(cases[c]) == "");
    }
}

TEST_CASE("oracle: graphs after removals", "[oracle]") {
    const std::vector<Ellipse> sites = generated(SiteKind::ellipses, 60, 4, Rational(1, 5), 0);
    DelaunayGraph g = test::ellipse_graph(sites);
    g.insert_all();
    std::mt19937_64 rng(4);
    const std::vector<SiteId> order = test::random_order(sites.size(), rng);
    const std::vector<SiteId> removed(order.begin(), order.begin() + 20);
    for (SiteId r : removed) g.remove(r);
    INFO(test::replay(sites, "removed", removed));
    CHECK(test::check_diagram(sites, g) == "");
}

// ---- The checker can fail -----------------------------------------------------------------------------------

TEST_CASE("oracle: corrupted claims are reported", "[oracle]") {
    const std::vector<Ellipse> sites = generated(SiteKind::ellipses, 30, 5, Rational(1, 5), 0);
    DelaunayGraph g = test::ellipse_graph(sites);
    g.insert_all();
    const test::DiagramClaim claim = test::claim_of(g, sites);
    REQUIRE(test::check_diagram(sites, claim) == "");
    REQUIRE(!claim.faces.empty());
    REQUIRE(!claim.hidden.empty());

    SECTION("a Voronoi vertex moved by 1e-6") {
        test::DiagramClaim bad = claim;
        bad.vertices[0].x += 1e-6;
        const std::string problem = test::check_diagram(sites, bad);
        CHECK_THAT(problem, Catch::Contains("is off rho"));
    }
    SECTION("the Voronoi radii off by 1e-6") {
        test::DiagramClaim bad = claim;
        for (auto& v : bad.vertices) v.radius += 1e-6;
        CHECK_THAT(test::check_diagram(sites, bad), Catch::Contains("is off rho"));
    }
    SECTION("a face's vertex swapped with another's") {
        test::DiagramClaim bad = claim;
        std::swap(bad.vertices.front(), bad.vertices.back());
        CHECK_THAT(test::check_diagram(sites, bad), Catch::Contains("is off rho"));
    }
    SECTION("a hidden site claimed visible") {
        test::DiagramClaim bad = claim;
        bad.visible.push_back(bad.hidden.front().first);
        bad.hidden.erase(bad.hidden.begin());
        const std::string problem = test::check_diagram(sites, bad);
        CHECK_THAT(problem, Catch::Contains("visible site " + std::to_string(claim.hidden.front().first) + " owns no point"));
    }
    SECTION("a visible site claimed hidden: its vertices and its cell give it away") {
        // The graph of the other sites, checked as if site v were hidden in
        // one of its neighbours.
        const SiteId v = claim.faces.front()[0];
        DelaunayGraph without = test::ellipse_graph(sites);
        without.insert_all();
        without.remove(v);
        test::DiagramClaim bad = test::claim_of(without, sites);
        bad.hidden.push_back({v, claim.faces.front()[1]});
        const std::string problem = test::check_diagram(sites, bad);
        CHECK_THAT(problem, Catch::Contains("hidden site " + std::to_string(v) + " (hidden by"));
        CHECK_THAT(problem, Catch::Contains("site " + std::to_string(v) + " is nearer"));
    }
    SECTION("a face in the wrong orientation") {
        test::DiagramClaim bad = claim;
        std::swap(bad.faces[0][1], bad.faces[0][2]);
        CHECK_THAT(test::check_diagram(sites, bad), Catch::Contains("the feet are clockwise"));
    }
    SECTION("a site listed twice, a face of a hidden site") {
        test::DiagramClaim bad = claim;
        bad.visible.push_back(bad.visible.front());
        bad.faces[0][0] = claim.hidden.front().first;
        const std::string problem = test::check_diagram(sites, bad);
        CHECK_THAT(problem, Catch::Contains("is listed as visible and as visible"));
        CHECK_THAT(problem, Catch::Contains("which is not visible"));
    }
}
