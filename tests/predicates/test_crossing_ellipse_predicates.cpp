// The predicates on crossing ellipses that differ from disjoint ones
// (docs/DESIGN.md §9): the count of Voronoi circles when a site of the triple
// is covered by the other two, and InCircle of an internal circle against a
// site holding its center. Oracles: the configuration's geometry (a needle
// covered by two disks), and signed distances in MPFR
// (tests/support/signed_distance_oracle.hpp).
#include "predicates/covered_site.hpp"
#include "predicates/incircle.hpp"
#include "predicates/infinite_vertex_conflict.hpp"
#include "predicates/relative_position.hpp"
#include "predicates/voronoi_circle_count.hpp"
#include "sites/rational_parse.hpp"
#include "subdivision/voronoi_circle_enclosure.hpp"
#include "tests/support/random_sites.hpp"
#include "tests/support/signed_distance_oracle.hpp"
#include "tests/support/ellipse_graph.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <random>

using namespace ellvor;
using ellvor::test::ellipse;
using test::OracleEllipse;
using test::Real;
using test::RealPoint;

namespace {


RealPoint midpoint(const Ball& x, const Ball& y) { return {Real(x.mid_double()), Real(y.mid_double())}; }

}  // namespace

TEST_CASE("voronoi circle count: a site covered by the other two has no circle although k = 2",
          "[predicates][voronoi_circle_count][crossing]") {
    // Which circles exist, by the complete solver, for an independent answer.
    auto by_solver = [](const Ellipse& a, const Ellipse& b, const Ellipse& c) {
        const bool ccw = VoronoiCircleSolver(a, b, c).certify(), cw = VoronoiCircleSolver(a, c, b).certify();
        return ccw ? (cw ? VoronoiCircles::both : VoronoiCircles::ccw_only) : (cw ? VoronoiCircles::cw_only : VoronoiCircles::none);
    };
    // How many sites conflict with the infinite vertex of the other two: the
    // kappa2 rule of docs/DESIGN.md §2 says "both" for 2.
    auto kappa2_conflicts = [](const Ellipse& a, const Ellipse& b, const Ellipse& c) {
        return (*infinite_vertex_conflict(a, b, c) == Sign::negative) + (*infinite_vertex_conflict(b, c, a) == Sign::negative) +
               (*infinite_vertex_conflict(c, a, b) == Sign::negative);
    };
    // The needle between two disks (the example), in all six orders:
    // its cell is empty, so no circle touches all three.
    const std::array<Ellipse, 3> covered = {ellipse("10", "1/10", "0", "0", "0"), Ellipse::circle(-5, 0, 6),
                                            Ellipse::circle(5, 0, 6)};
    // A fatter needle, also inside the union of two disks, but they are
    // shallow at its middle (depth 1/2 there, against the needle's 1): it
    // owns its middle, and both circles exist.
    const std::array<Ellipse, 3> visible = {ellipse("21/2", "1", "0", "0", "0"), ellipse("6", "6", "0", "-11/2", "0"),
                                            ellipse("6", "6", "0", "11/2", "0")};
    // The disks apart at the middle: a point of the needle is certainly
    // outside both, so the solver is not needed.
    const std::array<Ellipse, 3> uncovered = {ellipse("10", "1/10", "0", "0", "0"), ellipse("6", "6", "0", "-13/2", "0"),
                                              ellipse("6", "6", "0", "13/2", "0")};
    for (const auto* triple : {&covered, &visible, &uncovered}) {
        for (int j = 1; j < 3; ++j) {
            REQUIRE(*relative_position((*triple)[0], (*triple)[j]) == RelativePosition::intersecting);
            REQUIRE(crossing_pair_problem((*triple)[0], (*triple)[j]).empty());
        }
        std::array<int, 3> order = {0, 1, 2};
        do {
            const Ellipse &a = (*triple)[order[0]], &b = (*triple)[order[1]], &c = (*triple)[order[2]];
            INFO("triple " << (triple == &covered ? "covered" : triple == &visible ? "visible" : "uncovered") << ", order "
                           << order[0] << order[1] << order[2]);
            const VoronoiCircles count = *voronoi_circle_count(a, b, c);
            CHECK(count == by_solver(a, b, c));
            if (triple == &covered) {
                CHECK(kappa2_conflicts(a, b, c) == 2);  // the rule alone would say "both"
                CHECK(count == VoronoiCircles::none);
            }
        } while (std::next_permutation(order.begin(), order.end()));
    }
    CHECK(*voronoi_circle_count(visible[0], visible[1], visible[2]) == VoronoiCircles::both);
}

TEST_CASE("incircle of an internal circle against a site holding its center: the depth decides",
          "[predicates][incircle][crossing]") {
    // Four pairwise crossing ellipses (found by the first random crossing
    // sets): the circle of (E0, E1, E3) is internal (rho = -1.848) and its
    // center lies in E2 at depth 1.719 only, so E2 does not conflict.
    const Ellipse e0 = ellipse("47/10", "23/5", "-47/50", "91/5", "116/5"), e1 = ellipse("84/5", "49/5", "1/50", "5", "137/5"),
                  e2 = ellipse("92/5", "10", "-13/50", "261/10", "58/5"), e3 = ellipse("3", "63/10", "-7/10", "25/2", "41/2");
    VoronoiCircleSolver solver(e0, e1, e3);
    REQUIRE(solver.certify());
    const VoronoiCircleEnclosure& c = solver.enclosure();
    REQUIRE(c.radius.certain_sign() < 0);
    const RealPoint v = midpoint(c.center_x, c.center_y);
    const double depth_in_e2 = OracleEllipse(e2).signed_distance_value(v).to_double();
    CHECK(depth_in_e2 < 0);
    CHECK(depth_in_e2 > c.radius.mid_double());
    const Decision<InCircle> r = incircle(e0, e1, e3, e2);
    CHECK(*r == InCircle::no_conflict);
    CHECK(r.stage == Stage::subdivision);

    // A large ellipse around that circle holds its center deeper than the
    // radius: a conflict (its inscribed disk about its center holds the circle).
    const Ellipse large = ellipse("40", "30", "0", "16", "22");
    const Decision<InCircle> filtered = incircle(e0, e1, e3, large);
    CHECK(*filtered == InCircle::conflict);
}

TEST_CASE("incircle of internal circles on random crossing quadruples agrees with the MPFR signed distance",
          "[predicates][incircle][crossing]") {
    // Three ellipses around a common point (so they overlap there) and a
    // fourth one near it; whenever the triple has an internal circle, the
    // answer must be the sign of delta(V, Q) - rho.
    std::mt19937_64 rng(11);
    int internal = 0, inside_q = 0, deeper = 0;  // deeper: inside Q deeper than the circle (a conflict)
    for (int k = 0; k < 400 && internal < 60; ++k) {
        std::array<Ellipse, 4> s{Ellipse::circle(0, 0, 1), Ellipse::circle(0, 0, 1), Ellipse::circle(0, 0, 1),
                                 Ellipse::circle(0, 0, 1)};
        for (Ellipse& e : s)
            e = Ellipse(test::random_fraction(rng, 20, 60, 10), test::random_fraction(rng, 10, 40, 10),
                        test::random_fraction(rng, -99, 99, 100), test::random_fraction(rng, -30, 30, 10),
                        test::random_fraction(rng, -30, 30, 10));
        bool pseudo_circles = true;
        for (int i = 0; i < 4 && pseudo_circles; ++i)
            for (int j = i + 1; j < 4 && pseudo_circles; ++j) {
                const RelativePosition r = *relative_position(s[i], s[j]);
                pseudo_circles = r == RelativePosition::intersecting ? crossing_pair_problem(s[i], s[j]).empty()
                                                                     : r == RelativePosition::separated;
            }
        if (!pseudo_circles) continue;
        VoronoiCircleSolver solver(s[0], s[1], s[2]);
        if (!solver.certify() || solver.enclosure().radius.certain_sign() >= 0) continue;
        ++internal;
        solver.refine(100);
        const VoronoiCircleEnclosure& c = solver.enclosure();
        const RealPoint v = midpoint(c.center_x, c.center_y);
        const double delta = OracleEllipse(s[3]).signed_distance_value(v).to_double();
        inside_q += delta < 0;
        const double gap = delta - c.radius.mid_double();
        if (std::abs(gap) < 1e-9) continue;  // too near a tangency for the double oracle
        deeper += gap < 0 && delta < 0;
        const Decision<InCircle> r = incircle(s[0], s[1], s[2], s[3]);
        INFO("quadruple " << k << ": delta " << delta << ", rho " << c.radius.mid_double());
        CHECK(*r == (gap < 0 ? InCircle::conflict : InCircle::no_conflict));
    }
    WARN(internal << " internal circles, " << inside_q << " with the center inside Q, " << deeper
                  << " of them deeper in Q than the circle");
    CHECK(internal >= 20);
    CHECK(deeper >= 2);
    CHECK(inside_q - deeper >= 2);
}

TEST_CASE("four ellipse boundaries through one point: rho = 0, the fourth tangent, decided exactly",
          "[predicates][incircle][crossing][exact]") {
    // Four pairwise crossing ellipses whose boundaries pass through the origin
    // (each center is minus a rational boundary point of its shape): every
    // triple's Voronoi circle is the point itself (rho = 0), and the fourth
    // site passes through it: InCircle is ZERO, which only the exact stage
    // (the degree-184 resultant) can say.
    const Ellipse e0 = ellipse("14/5", "9/10", "-1/10", "18/101", "891/1010"),
                  e1 = ellipse("37/10", "1/2", "1/10", "-10589/5050", "-84/101"),
                  e2 = ellipse("13/5", "7/10", "3/10", "42/109", "-637/1090"),
                  e3 = ellipse("29/10", "13/10", "3/10", "11037/5450", "244/2725");
    for (const Ellipse* e : {&e0, &e1, &e2, &e3}) CHECK(e->side_of_point(Rational(0), Rational(0)) == 0);
    VoronoiCircleSolver solver(e0, e1, e3);
    REQUIRE(solver.certify());
    CHECK(arb_contains_zero(solver.enclosure().radius.get()));
    const Decision<InCircle> r = incircle(e0, e1, e3, e2);
    CHECK(*r == InCircle::tangent);
    CHECK(r.stage == Stage::exact);
}

TEST_CASE("incircle on an internal circle centered exactly on a needle's medial axis, every rotation, against MPFR",
          "[predicates][incircle][crossing][medial-axis]") {
    // Two circles of radius 10 at (0, 0) and (12, 0) and the needle (11/30, 10) at (6, 10): the internal
    // circle touches the needle at two mirror feet (DESIGN.md §4.2). The oracle finds V on the axis
    // x = 6 by bisection in MPFR (delta(V, circle) = delta(V, needle)), independently of the solver.
    const Ellipse c1 = Ellipse::circle(0, 0, 10), c2 = Ellipse::circle(12, 0, 10);
    const Ellipse needle(Rational(11, 30UL), Rational(10), Rational(0), Rational(6), Rational(10));
    const OracleEllipse o1(c1), on(needle);
    Real lo(7), hi(8);  // delta(V, c1) - delta(V, needle) changes sign between y = 7 and 8
    auto gap = [&](const Real& y) { return o1.signed_distance_value({Real(6), y}) - on.signed_distance_value({Real(6), y}); };
    REQUIRE(gap(lo).sign() * gap(hi).sign() < 0);
    for (int k = 0; k < 150; ++k) {
        const Real mid = (lo + hi) * Real(0.5);
        (gap(mid).sign() == gap(lo).sign() ? lo : hi) = mid;
    }
    const RealPoint v{Real(6), lo};
    const double rho = o1.signed_distance_value(v).to_double();
    CHECK(std::abs(rho + 0.3554852164925021) < 1e-12);
    // Queries: holding V deeper than |rho| (a conflict), holding it less deep, beside it, far below.
    const std::vector<Ellipse> queries = {ellipse("1/2", "1/2", "0", "59/10", "38/5"), ellipse("1/5", "1/5", "0", "6", "38/5"),
                                          ellipse("1", "1/4", "1/3", "13/2", "8"), ellipse("3", "1", "0", "6", "-5")};
    int conflicts = 0;
    for (const Ellipse& q : queries) {
        const double expected_gap = OracleEllipse(q).signed_distance_value(v).to_double() - rho;
        REQUIRE(std::abs(expected_gap) > 1e-6);
        conflicts += expected_gap < 0;
        const std::array<const Ellipse*, 3> triple{&c1, &c2, &needle};
        for (int r = 0; r < 3; ++r) {
            INFO("rotation " << r << ", query " << q.str() << ", delta - rho " << expected_gap);
            const Decision<InCircle> d = incircle(*triple[r], *triple[(r + 1) % 3], *triple[(r + 2) % 3], q);
            REQUIRE(d.is_decided());
            CHECK(*d == (expected_gap < 0 ? InCircle::conflict : InCircle::no_conflict));
            // No double certificate reaches so deep into the needle (Blaschke's bound): Arb's, with the mirror.
            CHECK(d.stage == Stage::subdivision);
        }
    }
    CHECK(conflicts == 1);
    // The diagram of the three with two far sites: valid, and the MPFR oracle agrees with it.
    const std::vector<Ellipse> sites = {c1, c2, needle, Ellipse::circle(30, 30, 2), ellipse("1", "3", "0", "-20", "10")};
    DelaunayGraph g = test::ellipse_graph(sites);
    g.insert_all();
    CHECK(g.validate() == "");
    CHECK(g.brute_force_check() == "");
    const auto faces = g.faces();
    CHECK(std::find(faces.begin(), faces.end(), std::array<SiteId, 3>{0, 1, 2}) != faces.end());
    CHECK(test::check_diagram(sites, test::claim_of(g, sites)) == "");
}

TEST_CASE("covered_without_circle: a site in the union of two others, no circle in any order (fuzz F6)",
          "[predicates][crossing][covered]") {
    // F6: a needle (minor semi-axis 10^-6) and its copy with the minor semi-axis 10/37, sharing the
    // tips to 10^-35; the needle pokes out of its copy at one tip only, which lies in the third site.
    const Ellipse needle = ellipse("345/127", "10e-7", "-6/35", "17909/230", "11267/144");
    const Ellipse third = ellipse("2", "363/161", "-43/82", "9731/121", "2128/27");
    const Ellipse fat = ellipse("345/127", "10/37", "-6/35",
                                "77.8652173913043478260869565217391304000000000000000000000000000000000000000000004010161755154"
                                "250351",
                                "11267/144");
    // The union-hidden needle between two disks.
    const Ellipse thin = ellipse("10", "1/10", "0", "0", "0"), left = Ellipse::circle(-5, 0, 6), right = Ellipse::circle(5, 0, 6);
    for (const auto& [x, y, z] : {std::array<const Ellipse*, 3>{&needle, &fat, &third}, {&thin, &left, &right}}) {
        CHECK(covered_without_circle(*x, *y, *z));
        CHECK(covered_without_circle(*x, *z, *y));
        for (const auto& order : {std::array<const Ellipse*, 3>{x, y, z}, {x, z, y}, {y, x, z}, {y, z, x}, {z, x, y}, {z, y, x}}) {
            const Decision<VoronoiCircles> count = voronoi_circle_count(*order[0], *order[1], *order[2]);
            CHECK(*count == VoronoiCircles::none);
            CHECK(count.stage == Stage::exact);  // the latest folded in: the crossing pairs' intersection quartics
        }
    }
    // The diagrams: the covered site hidden, checked by brute force and by the MPFR oracle
    // (hidden sites own no point of their medial axis).
    for (const std::vector<Ellipse>& sites : {std::vector<Ellipse>{needle, third, fat}, {thin, left, right}}) {
        DelaunayGraph g = test::ellipse_graph(sites);
        g.insert_all();
        CHECK(g.validate() == "");
        CHECK(g.brute_force_check() == "");
        CHECK(g.hidden().size() == 1);
        CHECK(test::check_diagram(sites, test::claim_of(g, sites)) == "");
    }

    // Not proven where it is false. A disk covered by two larger crossing disks still owns its
    // center and the triple has an internal circle (boundary inside the union, but the depths
    // meet near the middle); a needle sticking out of both has a point outside.
    const Ellipse small = Ellipse::circle(0, 0, 1), big_left = ellipse("10", "10", "0", "-19/2", "0"),
                  big_right = ellipse("10", "10", "0", "19/2", "0");
    CHECK_FALSE(covered_without_circle(small, big_left, big_right));
    CHECK(*voronoi_circle_count(small, big_left, big_right) != VoronoiCircles::none);
    const Ellipse sticking = ellipse("12", "1/10", "0", "0", "0");
    CHECK_FALSE(covered_without_circle(sticking, left, right));
}

TEST_CASE("covered_without_circle: a thin site crossing a band 10^6 times longer and a third site (fuzz F10)",
          "[predicates][crossing][covered]") {
    // F10: the site x (4.7 x 0.04) crosses the band (8.4e6 x 9.8) and the ellipse z; its axis
    // leaves the band's depth band [-2r, r] (r = 0.04) where it is 0.3 deep in z, and z's where
    // it is 0.4 deep in the band. (B)'s depth test on a piece 0.01 long, about the piece as a box,
    // blurred the distance quartic by the piece's width times z's size and proved neither depth:
    // the count went to the search, which never excluded (its cap). About the piece's midpoint
    // with the radius widened by the piece it proves them.
    const Ellipse x = ellipse("47/10", "03/74", "-47/49", "91/5", "116/5");
    const Ellipse band = ellipse("84E5", "49/5", "1/05", "5", "137/5");
    const Ellipse z = ellipse("92/5", "10", "-13/50", "206/11", "58/5");
    CHECK(covered_without_circle(x, band, z));
    CHECK(covered_without_circle(x, z, band));
    for (const auto& order : {std::array<const Ellipse*, 3>{&x, &band, &z}, {&x, &z, &band}, {&band, &x, &z},
                              {&band, &z, &x}, {&z, &x, &band}, {&z, &band, &x}}) {
        const Decision<VoronoiCircles> count = voronoi_circle_count(*order[0], *order[1], *order[2]);
        CHECK(*count == VoronoiCircles::none);
        CHECK(count.stage == Stage::exact);  // the crossing pairs' intersection quartics, not the search
    }
    // The diagram: x hidden by the union, checked by brute force and by the MPFR oracle.
    const std::vector<Ellipse> sites{x, band, z};
    DelaunayGraph g = test::ellipse_graph(sites);
    g.insert_all();
    CHECK(g.validate() == "");
    CHECK(g.brute_force_check() == "");
    REQUIRE(g.hidden().size() == 1);
    CHECK(test::check_diagram(sites, test::claim_of(g, sites)) == "");
}
