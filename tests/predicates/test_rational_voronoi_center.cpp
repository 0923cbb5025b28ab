// The rational-center certificate of the exact stage (docs/DESIGN.md §4.5,
// predicates/rational_voronoi_center.hpp) and its use by ContactComparison
// (voronoi_vertex_equality.hpp): proven on the exactly degenerate cells of a
// grid of equal ellipses (the issue-10 input), on i-point contacts and on
// circles; refused for clockwise triples, for points and sites moved by
// 10^-k, and for a degenerate quadruple whose common center is irrational
// (there the resultants decide).
#include "graph/delaunay_graph.hpp"
#include "predicates/incircle.hpp"
#include "predicates/rational_voronoi_center.hpp"
#include "predicates/voronoi_vertex_equality.hpp"
#include "tests/support/ellipse_graph.hpp"

#include <catch2/catch.hpp>

#include <array>
#include <vector>

using namespace ellvor;

namespace {

// One cell of the grid "2 1 0 6i 4j": four equal ellipses whose Voronoi
// circle is centered at the cell's center (the cell's two reflections fix it
// and permute the sites), counter-clockwise A -> B -> C -> D.
struct Cell {
    Ellipse a, b, c, d;
    Point center;
};

Cell cell(const Rational& x, const Rational& y) {
    auto site = [](const Rational& cx, const Rational& cy) { return Ellipse(2, 1, 0, cx, cy); };
    return {site(x, y), site(x + 6, y), site(x + 6, y + 4), site(x, y + 4), {x + 3, y + 2}};
}

Ellipse moved(const Ellipse& e, const Rational& dx, const Rational& dy) {
    return Ellipse(e.a(), e.b(), e.w(), e.xc() + dx, e.yc() + dy);
}

// (E1, E2, E3, Q) tangent to one circle about an irrational center: two
// mirror pairs about the x-axis, E2 (upper right), E1 (upper left), E1'
// (lower left), E2' (lower right) counter-clockwise. The circle's center is
// the point of the x-axis equidistant from E1 and E2 (a root of a
// high-degree equation), so there is no short rational center to find.
std::array<Ellipse, 4> mirror_quadruple() {
    return {Ellipse(3, 1, Rational(1, 2UL), 6, 4), Ellipse(2, 1, 0, -5, 3), Ellipse(2, 1, 0, -5, -3),
            Ellipse(3, 1, Rational(-1, 2UL), 6, -4)};
}

}  // namespace

TEST_CASE("rational center: the grid cell's center is proven, exactly and only there", "[predicates][rational-center]") {
    for (const Rational& offset : {Rational(0), Rational(-42), power_of_ten(20)}) {
        const Cell c = cell(offset, Rational(2) * offset);
        INFO("cell at " << c.a.str());
        RationalCenter center(c.center);
        // Every counter-clockwise triple of the four sites.
        CHECK(center.is_center_of({&c.a, &c.b, &c.c}));
        CHECK(center.is_center_of({&c.b, &c.c, &c.d}));
        CHECK(center.is_center_of({&c.c, &c.d, &c.a}));
        CHECK(center.is_center_of({&c.a, &c.b, &c.d}));
        // Clockwise: the circle of (A, C, B) is another one (if any).
        CHECK_FALSE(center.is_center_of({&c.a, &c.c, &c.b}));
        CHECK_FALSE(center.is_center_of({&c.d, &c.c, &c.b}));
    }
    const Cell c = cell(0, 0);
    for (int k : {3, 30, 300}) {
        const Rational eps = power_of_ten(-k);
        INFO("k " << k);
        // The point moved off the center.
        RationalCenter off({c.center.x + eps, c.center.y});
        CHECK_FALSE(off.is_center_of({&c.a, &c.b, &c.c}));
        RationalCenter off_y({c.center.x, c.center.y - eps});
        CHECK_FALSE(off_y.is_center_of({&c.a, &c.b, &c.d}));
        // A site moved: its triples lose the center, the others keep it.
        const Ellipse d = moved(c.d, eps, eps);
        RationalCenter center(c.center);
        CHECK_FALSE(center.is_center_of({&c.a, &c.b, &d}));
        CHECK(center.is_center_of({&c.a, &c.b, &c.c}));
    }
    // A point inside a site is no Voronoi center.
    RationalCenter inside(Point{1, 0});
    CHECK_FALSE(inside.is_center_of({&c.a, &c.b, &c.c}));
}

TEST_CASE("rational center: i-point contacts and circles", "[predicates][rational-center]") {
    // (2, 1) ellipses at distance 5 around the origin, a-axes pointing at it:
    // the circle |x| = 3 touches each at an a-vertex, one of them an i-point
    // (the foot-point quartic loses degree there).
    const Ellipse e1(2, 1, 0, 5, 0), e2(2, 1, 1, 0, 5), e3(2, 1, 0, -5, 0), e4(2, 1, 1, 0, -5);
    RationalCenter origin(Point{0, 0});
    CHECK(origin.is_center_of({&e1, &e2, &e3}));
    CHECK(origin.is_center_of({&e2, &e3, &e4}));
    CHECK_FALSE(origin.is_center_of({&e3, &e2, &e1}));
    // Unit circles at distance 6 from the origin, one at a Pythagorean point.
    const Ellipse c1 = Ellipse::circle(6, 0, 1), c2 = Ellipse::circle(0, 6, 1),
                  c3 = Ellipse::circle(Rational(18, 5UL), Rational(-24, 5UL), 1);
    CHECK(origin.is_center_of({&c1, &c2, &c3}));
    const Ellipse c3_moved = Ellipse::circle(Rational(18, 5UL), Rational(-24, 5UL) - power_of_ten(-40), 1);
    CHECK_FALSE(origin.is_center_of({&c1, &c2, &c3_moved}));
}

TEST_CASE("rational center: the simplest rational in a ball", "[predicates][rational-center]") {
    // 3 and -7/5 from balls of 200 bits around them.
    for (const Rational& q : {Rational(3), Rational(-7, 5UL), Rational(1) + power_of_ten(-20)}) {
        Ball b(q, 200);
        Ball r;
        arb_set_str(r.get(), "+/- 1e-55", 200);
        arb_add(b.get(), b.get(), r.get(), 200);
        const auto s = simplest_rational_in(b, 100);
        REQUIRE(s);
        CHECK(*s == q);
    }
    // sqrt(2) to 256 bits: its simplest rational has about 128 bits.
    Ball root2;
    arb_sqrt_ui(root2.get(), 2, 256);
    CHECK_FALSE(simplest_rational_in(root2, 64));
    CHECK(simplest_rational_in(root2, 200));
    Ball unbounded;
    arb_indeterminate(unbounded.get());
    CHECK_FALSE(simplest_rational_in(unbounded, 64));
}

TEST_CASE("contact comparison: the grid takes the rational center, the resultants agree",
          "[predicates][rational-center][exact]") {
    const Cell c = cell(0, 0);
    // The circles of (A, B, C) and (A, B, D) are the cell's circle: the same
    // contact point on A.
    VoronoiCircleSolver abc(c.a, c.b, c.c), abd(c.a, c.b, c.d);
    abc.refine_existing(256);
    for (const bool use_rational_center : {true, false}) {
        ContactComparison same({abc.sites(), &abc, 0}, {abd.sites(), &abd, 0}, use_rational_center);
        CHECK(same.same_contact_point(256));
        CHECK(same.proof() == (use_rational_center ? ContactComparison::Proof::rational_center
                                                   : ContactComparison::Proof::resultants));
    }
    // D moved by 2^-130: another circle, whose enclosure (certified at about
    // 124 bits) still holds the cell's center; the rational center is refused
    // and the resultants tell the contacts apart (about 1 s: 130-bit data).
    Rational eps(1);
    for (int i = 0; i < 130; ++i) eps = eps * Rational(1, 2UL);
    const Ellipse d = moved(c.d, eps, 0);
    VoronoiCircleSolver abd_moved(c.a, c.b, d);
    ContactComparison other({abc.sites(), &abc, 0}, {abd_moved.sites(), &abd_moved, 0});
    CHECK_FALSE(other.same_contact_point(64));
    CHECK(other.proof() == ContactComparison::Proof::resultants);
    // Moved by 10^-3: the enclosures are apart at once.
    const Ellipse far = moved(c.d, power_of_ten(-3), 0);
    VoronoiCircleSolver abd_far(c.a, c.b, far);
    ContactComparison apart({abc.sites(), &abc, 0}, {abd_far.sites(), &abd_far, 0});
    CHECK_FALSE(apart.same_contact_point(64));
    CHECK(apart.proof() == ContactComparison::Proof::enclosures);
}

TEST_CASE("contact comparison: i-point contacts, by the rational center and by the twin charts' resultants",
          "[predicates][rational-center][exact]") {
    // The circle |x| = 3 touches each site at an a-vertex; on E1 = (2, 1, 0)
    // at (5, 0) that is its i-point, so the resultants use E1's twin.
    const Ellipse e1(2, 1, 0, 5, 0), e2(2, 1, 1, 0, 5), e3(2, 1, 0, -5, 0), e4(2, 1, 1, 0, -5);
    VoronoiCircleSolver first(e1, e2, e3), second(e1, e2, e4);
    for (const bool use_rational_center : {true, false}) {
        ContactComparison same({first.sites(), &first, 0}, {second.sites(), &second, 0}, use_rational_center);
        CHECK(same.same_contact_point(64));
        CHECK(same.proof() == (use_rational_center ? ContactComparison::Proof::rational_center
                                                   : ContactComparison::Proof::resultants));
    }
}

TEST_CASE("contact comparison: an irrational common center falls back to the resultants",
          "[predicates][rational-center][exact]") {
    const std::array<Ellipse, 4> s = mirror_quadruple();
    // (E2, E1, E1') and (E2, E1, E2') are both counter-clockwise around the
    // common circle: the same contact point on E2.
    VoronoiCircleSolver first(s[0], s[1], s[2]), second(s[0], s[1], s[3]);
    ContactComparison same({first.sites(), &first, 0}, {second.sites(), &second, 0});
    CHECK(same.same_contact_point(64));
    CHECK(same.proof() == ContactComparison::Proof::resultants);
    // The incircle predicate, end to end: tangent, from the exact stage
    // (the mirror pairs make it the symmetry stage's unless that is off).
    InCircleOptions no_symmetry;
    no_symmetry.use_symmetry = false;
    const Decision<InCircle> d = incircle(s[0], s[1], s[2], s[3], no_symmetry);
    CHECK(*d == InCircle::tangent);
    CHECK(d.stage == Stage::exact);
    const Decision<InCircle> by_symmetry = incircle(s[0], s[1], s[2], s[3]);
    CHECK(*by_symmetry == InCircle::tangent);
    CHECK(by_symmetry.stage == Stage::symmetry);
}

TEST_CASE("incircle on grid cells: tangent from the exact stage, perturbations strict",
          "[predicates][rational-center][exact]") {
    const Cell c = cell(6, -8);
    // The grid's mirror symmetry decides it first; without that stage, the exact stage.
    CHECK(incircle(c.a, c.b, c.c, c.d).stage == Stage::symmetry);
    InCircleOptions no_symmetry;
    no_symmetry.use_symmetry = false;
    const Decision<InCircle> d = incircle(c.a, c.b, c.c, c.d, no_symmetry);
    CHECK(*d == InCircle::tangent);
    CHECK(d.stage == Stage::exact);
    for (int k : {6, 30}) {
        INFO("k " << k);
        // D moved away from the circle's center / toward it.
        for (const int dir : {1, -1}) {
            const Ellipse d_moved = moved(c.d, -dir * power_of_ten(-k), dir * power_of_ten(-k));
            const InCircle want = dir > 0 ? InCircle::no_conflict : InCircle::conflict;
            const Decision<InCircle> strict = incircle(c.a, c.b, c.c, d_moved);
            CHECK(*strict == want);
            CHECK(strict.stage != Stage::exact);
            // Under a cap below the 100 bits that 10^-30 needs, the exact stage
            // proves non-tangency (rational center refused, resultants) and
            // the subdivision resumes.
            if (k == 30) {
                InCircleOptions low;
                low.refinement.cap = 64;
                const Decision<InCircle> dl = incircle(c.a, c.b, c.c, d_moved, low);
                CHECK(*dl == want);
                CHECK(dl.stage == Stage::exact);
                CHECK(dl.precision > 64);
            }
        }
    }
}

TEST_CASE("graph: the 8 x 8 grid of equal ellipses is valid, its cells decided exactly",
          "[graph][rational-center]") {
    std::vector<Ellipse> sites;
    for (int i = 0; i < 8; ++i)
        for (int j = 0; j < 8; ++j) sites.emplace_back(2, 1, 0, 6 * i, 4 * j);
    DelaunayGraph g = test::ellipse_graph(sites);
    g.insert_all();
    CHECK(g.validate().empty());
    CHECK(g.brute_force_check().empty());
    // One tangent InCircle per cell (7 x 7), each proven exactly: by the
    // grid's mirror symmetry (two columns or rows are mirror images).
    const auto& stages = g.predicate_stats()[Predicate::incircle].stages;
    CHECK(stages[Stage::symmetry] + stages[Stage::exact] >= 49);
}
