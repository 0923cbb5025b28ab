// An internal Voronoi circle centered exactly on a site's medial axis without
// a mirror symmetry (docs/DESIGN.md §4.2, "On a medial axis"): the proof that
// V lies on the axis (subdivision/medial_axis_circle.hpp with
// exact/medial_axis_tangency.hpp) lets the certificate accept it; without it
// the search ends at its cap. Oracles: the exact construction of the triple
// (V and rho known as rationals), MPFR signed distances
// (tests/support/signed_distance_oracle.hpp), the exact tangency of a circle
// built tangent.
#include "exact/medial_axis_tangency.hpp"
#include "exact/real_roots.hpp"
#include "graph/delaunay_graph.hpp"
#include "predicates/incircle.hpp"
#include "subdivision/voronoi_circle.hpp"
#include "subdivision/voronoi_circle_enclosure.hpp"
#include "tests/support/ellipse_graph.hpp"
#include "tests/support/signed_distance_oracle.hpp"
#include "util/error.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

using namespace ellvor;

namespace {

// E_i: a = 5, b = 3 (c = 4); in its frame V = (12/5, 0) lies on the medial
// axis (|h| < c^2/a = 16/5) and s(12/5) = 9 (1 - 144/400) = (12/5)^2. E_j, E_k:
// circles of radius 4 holding the disk of radius 12/5 about V and touching it
// at distinct, non-mirror points (centers V + (8/5) u, u = (3/5, -4/5) and
// (5/13, 12/13)). The whole is turned by w = 1/3 (cos 4/5, sin 3/5) and moved
// by (7/3, -11/7): no line of it is axis-parallel.
struct AxisTriple {
    Rational cos = Rational(4, 5), sin = Rational(3, 5), tx = Rational(7, 3), ty = Rational(-11, 7);
    Rational map_x(const Rational& x, const Rational& y) const { return cos * x - sin * y + tx; }
    Rational map_y(const Rational& x, const Rational& y) const { return sin * x + cos * y + ty; }
    Rational vx() const { return map_x(Rational(12, 5), 0); }
    Rational vy() const { return map_y(Rational(12, 5), 0); }
    // E_i as given (a-axis major), or the same point set with b the major
    // semi-axis (a = 3, b = 5, turned a quarter back, w = -1/2: its b-axis
    // (-sin, cos) = (4/5, 3/5) is the major axis, in the same direction).
    Ellipse axis_site(bool b_major = false) const {
        return b_major ? Ellipse(3, 5, Rational(-1, 2), tx, ty) : Ellipse(5, 3, Rational(1, 3), tx, ty);
    }
    // The circle of radius r centered V + (r - 12/5) u (internally tangent to
    // V's circle for r > 12/5), its center's x moved by dx.
    Ellipse touching(const Rational& ux, const Rational& uy, const Rational& r = 4, const Rational& dx = 0) const {
        const Rational off = r - Rational(12, 5), x = Rational(12, 5) + off * ux, y = off * uy;
        return Ellipse::circle(map_x(x, y) + dx, map_y(x, y), r);
    }
    Ellipse site_j() const { return touching(Rational(3, 5), Rational(-4, 5)); }
    Ellipse site_k(const Rational& dx = 0) const { return touching(Rational(5, 13), Rational(12, 13), 4, dx); }
};

const Rational kAxisH(12, 5);  // V's coordinate along E_i's major axis, from its center

// P's distinct real roots within 2^-200 intervals near h (within 10^-20).
std::vector<IsolatingInterval> roots_near(const IntPolynomial& p, const Rational& h) {
    std::vector<IsolatingInterval> near;
    for (IsolatingInterval iv : isolate_real_roots(p)) {
        if (iv.hi < h - power_of_ten(-20) || h + power_of_ten(-20) < iv.lo) continue;
        refine(squarefree_part(p), iv, 200);
        near.push_back(iv);
    }
    return near;
}

// The proof's claim checked independently: delta(V, E) = rho for each site (MPFR).
void check_signed_distances(const std::array<const Ellipse*, 3>& sites, const VoronoiCircleEnclosure& c) {
    const test::RealPoint v{test::Real(c.center_x.mid_double()), test::Real(c.center_y.mid_double())};
    for (const Ellipse* e : sites)
        CHECK(std::abs(test::OracleEllipse(*e).signed_distance_value(v).to_double() - c.radius.mid_double()) < 1e-12);
}

}  // namespace

TEST_CASE("the medial-axis tangency polynomial vanishes exactly at tangent circles", "[medial-axis][exact]") {
    const AxisTriple k;
    for (bool b_major : {false, true}) {
        const Ellipse e = k.axis_site(b_major);
        // Circles holding V's disk and touching it (r = 4, 7), a circle of
        // radius 1 inside it touching it, and an ellipse whose a-vertex touches
        // it from outside (a = 2, b = 1, its a-axis along u).
        const Rational ux(3, 5), uy(-4, 5), off = Rational(12, 5) + 2;
        const Ellipse external = k.touching(Rational(-5, 13), Rational(-12, 13), 1);
        // u turned by w = 1/3 is (24/25, -7/25): w = -7/25 / (1 + 24/25) = -1/7.
        const Rational x = kAxisH + off * ux, y = off * uy;
        const Ellipse vertex(2, 1, Rational(-1, 7), k.map_x(x, y), k.map_y(x, y));
        for (const Ellipse& f : {k.site_j(), k.site_k(), k.touching(ux, uy, 7), external, vertex}) {
            const IntPolynomial p = medial_circle_tangency_polynomial(e, f);
            REQUIRE(!p.is_zero());
            CHECK(sign_at_rational(p, kAxisH) == 0);
        }
        // Not tangent: the circle of radius 4 about V + (3/2) u holds V's disk strictly.
        const Rational ix = kAxisH + Rational(3, 2) * ux, iy = Rational(3, 2) * uy;
        const Ellipse inside = Ellipse::circle(k.map_x(ix, iy), k.map_y(ix, iy), 4);
        CHECK(sign_at_rational(medial_circle_tangency_polynomial(e, inside), kAxisH) != 0);
        // A circle site has no medial axis: nothing to prove.
        CHECK(medial_circle_tangency_polynomial(k.site_j(), e).is_zero());
    }
}

TEST_CASE("the exact test finds the common tangency of the triple, and none for a near miss", "[medial-axis][exact]") {
    const AxisTriple k;
    const Ellipse e = k.axis_site(), f = k.site_j(), g = k.site_k();
    const Rational lo = kAxisH - power_of_ten(-40), hi = kAxisH + power_of_ten(-40);
    CHECK(common_medial_axis_tangency(e, f, g, lo, hi, lo, hi));
    // Intervals that miss each other's root, or hold two roots of P_F, prove nothing.
    CHECK_FALSE(common_medial_axis_tangency(e, f, g, lo, hi, hi, hi + 1));
    const IntPolynomial pf = medial_circle_tangency_polynomial(e, f);
    const std::vector<IsolatingInterval> all = isolate_real_roots(pf);
    REQUIRE(all.size() >= 2);
    CHECK_FALSE(common_medial_axis_tangency(e, f, g, all.front().lo - 1, all.back().hi + 1, lo, hi));

    // E_k moved by 10^-30: its axis tangency h_k is a root of P_G near 12/5,
    // not 12/5; the gcd has no root near there, so "on the axis" is not claimed.
    const Ellipse moved = k.site_k(power_of_ten(-30));
    const IntPolynomial pg = medial_circle_tangency_polynomial(e, moved);
    const std::vector<IsolatingInterval> near = roots_near(pg, kAxisH);
    REQUIRE(near.size() == 1);
    CHECK_FALSE((near[0].lo <= kAxisH && kAxisH <= near[0].hi));
    CHECK_FALSE(common_medial_axis_tangency(e, f, moved, lo, hi, near[0].lo, near[0].hi));
    IntPolynomial common;
    fmpz_poly_gcd(common.get(), pf.get(), pg.get());
    CHECK(count_real_roots(common, kAxisH - power_of_ten(-20), kAxisH + power_of_ten(-20)) == 0);
}

TEST_CASE("a Voronoi circle centered exactly on a medial axis is certified, in every rotation of the triple",
          "[medial-axis][subdivision][crossing]") {
    const AxisTriple k;
    for (bool b_major : {false, true}) {
        const std::array<Ellipse, 3> sites{k.axis_site(b_major), k.site_j(), k.site_k()};
        for (int r = 0; r < 3; ++r) {
            INFO("b major " << b_major << ", rotation " << r);
            const std::array<const Ellipse*, 3> triple{&sites[r], &sites[(r + 1) % 3], &sites[(r + 2) % 3]};
            VoronoiCircleSolver solver(*triple[0], *triple[1], *triple[2], common_medial_axis_tangency);
            REQUIRE(solver.certify());
            const VoronoiCircleEnclosure& c = solver.enclosure();
            CHECK(c.found_by == CircleStart::guess);
            CHECK(c.on_medial_axis);
            CHECK(c.radius.contains(Rational(-12, 5)));
            CHECK(c.center_x.contains(k.vx()));
            CHECK(c.center_y.contains(k.vy()));
            check_signed_distances(triple, c);
            // Refinement certifies again (the proof at every precision).
            REQUIRE(solver.refine(200));
            CHECK(solver.enclosure().on_medial_axis);
            CHECK(solver.enclosure().center_y.contains(k.vy()));
            CHECK(solver.enclosure().correct_bits() >= 200);
        }
    }
}

TEST_CASE("the search certifies the medial-axis circle with the proof and ends at its cap without it",
          "[medial-axis][subdivision][crossing]") {
    const AxisTriple k;
    const Ellipse e = k.axis_site(), f = k.site_j(), g = k.site_k();
    VoronoiCircleSolver with_proof(e, f, g, common_medial_axis_tangency);
    REQUIRE(with_proof.certify_by_search());
    CHECK(with_proof.enclosure().found_by == CircleStart::search);
    CHECK(with_proof.enclosure().on_medial_axis);
    CHECK(with_proof.enclosure().center_x.contains(k.vx()));
    // Without it (today's solver on this triple) every box near V holds two
    // regular roots, one per foot, and none is accepted: the cap's Error.
    // (The same number of boxes that sufficed with the proof.)
    VoronoiCircleSearchOptions capped;
    capped.max_boxes = 500;
    CHECK(with_proof.enclosure().search_boxes < capped.max_boxes);
    VoronoiCircleSolver without(e, f, g);
    CHECK_THROWS_AS(without.certify_by_search(capped), Error);
}

TEST_CASE("a near miss (E_k moved by 10^-30) is certified off the axis, never claimed on it",
          "[medial-axis][subdivision][crossing]") {
    const AxisTriple k;
    const Ellipse e = k.axis_site(), f = k.site_j(), g = k.site_k(power_of_ten(-30));
    VoronoiCircleSolver solver(e, f, g, common_medial_axis_tangency);
    REQUIRE(solver.certify());
    const VoronoiCircleEnclosure& c = solver.enclosure();
    CHECK_FALSE(c.on_medial_axis);
    // The certificate had to resolve the 10^-30: its V misses the axis point.
    CHECK_FALSE((c.center_x.contains(k.vx()) && c.center_y.contains(k.vy())));
    check_signed_distances({&e, &f, &g}, c);
}

TEST_CASE("the Delaunay graph of a set holding the medial-axis triple is valid", "[medial-axis][crossing]") {
    const AxisTriple k;
    std::vector<Ellipse> sites{k.axis_site(), k.site_j(), k.site_k()};
    for (int i = 0; i < 6; ++i) {
        const double angle = i * 2 * M_PI / 6;
        sites.push_back(Ellipse(3, 2, Rational(i, 7UL), Rational(static_cast<long>(40 * std::cos(angle))),
                                Rational(static_cast<long>(40 * std::sin(angle)))));
    }
    std::vector<SiteId> order{0, 1, 2, 3, 4, 5, 6, 7, 8};
    do {
        INFO("first three inserted: " << order[0] << order[1] << order[2]);
        DelaunayGraph g = test::ellipse_graph(sites);
        for (SiteId i : order) g.insert(i);
        CHECK(g.validate() == "");
        CHECK(g.brute_force_check() == "");
        CHECK(test::check_diagram(sites, g) == "");
        // The face of the triple is there, with its circle on the axis.
        const std::vector<std::array<SiteId, 3>> faces = g.faces();
        CHECK(std::count_if(faces.begin(), faces.end(), [](const std::array<SiteId, 3>& f) {
                  return std::max({f[0], f[1], f[2]}) == 2;
              }) == 1);
    } while (std::next_permutation(order.begin(), order.begin() + 3));
}

TEST_CASE("InCircle on the medial-axis triple decides in the subdivision stage, through the axis proof",
          "[medial-axis][predicates][crossing]") {
    const AxisTriple k;
    const Ellipse e = k.axis_site(), f = k.site_j(), g = k.site_k();
    // Circles about V: delta(V, Q) = -3 < rho = -12/5 (conflict), -2 > rho (none).
    const Ellipse deeper = Ellipse::circle(k.vx(), k.vy(), 3), shallower = Ellipse::circle(k.vx(), k.vy(), 2);
    VoronoiCircle circle(e, f, g, common_medial_axis_tangency);
    const Decision<InCircle> conflict = incircle(e, f, g, deeper, {}, &circle);
    CHECK(*conflict == InCircle::conflict);
    CHECK(conflict.stage == Stage::subdivision);
    REQUIRE(circle.has_solver());
    CHECK(circle.solver().enclosure().on_medial_axis);
    const Decision<InCircle> none = incircle(e, f, g, shallower);  // its own circle, made with the proof
    CHECK(*none == InCircle::no_conflict);
    CHECK(none.stage == Stage::subdivision);
}
