// The exact stage of kappa3 incircle(E1, E2, E3, Q): exactly degenerate
// quadruples (Q externally tangent to the Voronoi circle of E1 E2 E3, built
// by symmetry so that the answer is known) must come back `tangent` from the
// exact stage; their perturbations by 10^-k must get the strict sign, from
// the subdivision stage under the default cap and through the exact stage
// (proof of non-tangency, then separation) under a low cap. Small bit sizes
// only: the exact stage's cost grows with the bit size of Q.
//
// Constructions (all exact rationals):
//  (a) E = (2, 1, w=0) at (5, 0) and its quarter turns about the origin: all
//      touch the circle |x| = 3 at a-vertices, i.e. at their i-points.
//  (b) unit circles at distance 6 from the origin at the rational points
//      (6,0), (0,6), (-6,0), 6 (3/5, -4/5): all tangent to |x| = 5.
//  (c) a generic ellipse E, a rational point P = E(t0) with t0 = 1/2 (no
//      i-point), V = P + lambda n with n the outward normal at P: P is the
//      nearest point of the convex E to V, so the circle about V through P is
//      externally tangent to E. The copies of E rotated about V by angles
//      with rational tan(phi/2) are rational ellipses tangent to the same
//      circle, at the same parameter t0.
#include "predicates/incircle.hpp"
#include "subdivision/voronoi_circle_enclosure.hpp"
#include "sites/site_generators.hpp"
#include "tests/support/diagnostics.hpp"

#include <catch2/catch.hpp>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

using namespace ellvor;
using ellvor::test::show;
using ellvor::test::verbose;

namespace {



std::string ell(const std::vector<const Ellipse*>& sites) {
    std::string s;
    for (const Ellipse* e : sites) s += "\n  " + e->str();
    return s;
}

// A degenerate quadruple: E1 E2 E3 counter-clockwise around their Voronoi
// circle, Q tangent to it; `out` is a rational direction from the circle's
// center toward Q's contact point (moving Q's center along +out moves Q away).
struct Degenerate {
    std::string name;
    Ellipse e1, e2, e3, q;
    Rational out_x, out_y;
};

// Q moved by eps * out / max(|out_x|, |out_y|): away (dir > 0) or toward.
Ellipse moved(const Degenerate& c, const Rational& eps, int dir) {
    Rational m = c.out_x.sign() < 0 ? -c.out_x : c.out_x;
    const Rational my = c.out_y.sign() < 0 ? -c.out_y : c.out_y;
    if (my > m) m = my;
    const Rational s = (dir > 0 ? eps : -eps) / m;
    return Ellipse(c.q.a(), c.q.b(), c.q.w(), c.q.xc() + s * c.out_x, c.q.yc() + s * c.out_y);
}

// Rotation of e about (vx, vy) by phi with tan(phi/2) = s (s rational; the
// caller avoids w s = 1).
Ellipse rotated(const Ellipse& e, const Rational& vx, const Rational& vy, const Rational& s) {
    const Rational d = Rational(1) + s * s;
    const Rational c = (Rational(1) - s * s) / d, sn = Rational(2) * s / d;
    const Rational dx = e.xc() - vx, dy = e.yc() - vy;
    const Rational w = (e.w() + s) / (Rational(1) - e.w() * s);
    return Ellipse(e.a(), e.b(), w, vx + c * dx - sn * dy, vy + sn * dx + c * dy);
}

Degenerate case_a() {
    return {"(a) ellipses, i-point contacts", Ellipse(2, 1, 0, 5, 0), Ellipse(2, 1, 1, 0, 5), Ellipse(2, 1, 0, -5, 0),
            Ellipse(2, 1, 1, 0, -5), Rational(0), Rational(-1)};
}

Degenerate case_b() {
    return {"(b) unit circles, Pythagorean point", Ellipse::circle(6, 0, 1), Ellipse::circle(0, 6, 1),
            Ellipse::circle(-6, 0, 1), Ellipse::circle(Rational(18, 5UL), Rational(-24, 5UL), 1), Rational(3),
            Rational(-4)};
}

Degenerate case_c() {
    // E = (2, 1, 1/3) at (0, 0); P = E(1/2); outward normal from the tangent.
    const Ellipse e(2, 1, Rational(1, 3UL), 0, 0);
    const Rational t0(1, 2UL);
    const Point p = e.point_at(t0);
    // Tangent direction at t0 (homogeneous formula; positive multiple of dP/dt).
    const Rational tx = Rational(e.tangent_x().coeff(0)) + t0 * Rational(e.tangent_x().coeff(1)) +
                        t0 * t0 * Rational(e.tangent_x().coeff(2));
    const Rational ty = Rational(e.tangent_y().coeff(0)) + t0 * Rational(e.tangent_y().coeff(1)) +
                        t0 * t0 * Rational(e.tangent_y().coeff(2));
    // The boundary runs counter-clockwise in t, so the outward normal is (ty, -tx).
    Rational nx = ty, ny = -tx;
    // lambda: make the radius ~ 6 (|n| bounded by max-norm scaling).
    Rational m = nx.sign() < 0 ? -nx : nx;
    const Rational my = ny.sign() < 0 ? -ny : ny;
    if (my > m) m = my;
    nx = nx / m;
    ny = ny / m;
    const Rational vx = p.x + Rational(6) * nx, vy = p.y + Rational(6) * ny;
    // Copies at phi = 0, ~100 deg (s = 6/5), ~199 deg (s = -6), ~290 deg (s = -7/10).
    const Ellipse e2 = rotated(e, vx, vy, Rational(6, 5UL)), e3 = rotated(e, vx, vy, Rational(-6)),
                  q = rotated(e, vx, vy, Rational(-7, 10UL));
    const Point pq = q.point_at(t0);
    return {"(c) generic ellipse rotated about V, contacts at t = 1/2", e, e2, e3, q, pq.x - vx, pq.y - vy};
}

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

TEST_CASE("incircle exact stage: construction (c) is exactly tangent", "[predicates][incircle][exact]") {
    // Sanity of the construction itself: the contact points of all four copies
    // are at the same distance from V (checked exactly), and each copy has
    // P on its boundary.
    const Degenerate c = case_c();
    const Rational t0(1, 2UL);
    const Point p1 = c.e1.point_at(t0), p2 = c.e2.point_at(t0), p3 = c.e3.point_at(t0), p4 = c.q.point_at(t0);
    const Rational vx = p4.x - c.out_x, vy = p4.y - c.out_y;
    auto d2 = [&](const Point& p) { return (p.x - vx) * (p.x - vx) + (p.y - vy) * (p.y - vy); };
    CHECK(d2(p1) == d2(p4));
    CHECK(d2(p2) == d2(p4));
    CHECK(d2(p3) == d2(p4));
    for (const Ellipse* e : {&c.e1, &c.e2, &c.e3, &c.q}) {
        const Point p = e->point_at(t0);
        CHECK(e->side_of_point(p.x, p.y) == 0);
        CHECK(e->side_of_point(vx, vy) == 1);
    }
    const Ellipse* s[4] = {&c.e1, &c.e2, &c.e3, &c.q};
    for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j) CHECK(bounding_circles_separated(*s[i], *s[j]));
}

TEST_CASE("incircle exact stage: degenerate quadruples are tangent", "[predicates][incircle][exact]") {
    for (const Degenerate& c : {case_a(), case_b(), case_c()}) {
        INFO(c.name << ell({&c.e1, &c.e2, &c.e3, &c.q}));
        const auto start = std::chrono::steady_clock::now();
        const Decision<InCircle> d = incircle(c.e1, c.e2, c.e3, c.q);
        const double s = seconds_since(start);
        INFO(show(d) << " in " << s << " s");
        if (verbose()) std::printf("[incircle exact] %s: %s, %.3f s\n", c.name.c_str(), show(d).c_str(), s);
        CHECK((*d) == InCircle::tangent);
        CHECK(d.stage == Stage::exact);
        CHECK(d.precision <= 4096);
        // A lower cap reaches the exact stage sooner, same answer.
        InCircleOptions low;
        low.use_circle_closed_form = false;  // the general path on circles
        low.refinement.cap = 256;
        const Decision<InCircle> dl = incircle(c.e1, c.e2, c.e3, c.q, low);
        INFO("cap 256: " << show(dl));
        CHECK((*dl) == InCircle::tangent);
        CHECK(dl.stage == Stage::exact);
        // Subdivision only: the honest answer is undecided at the cap.
        InCircleOptions no_exact;
        no_exact.use_circle_closed_form = false;  // the general path on circles
        no_exact.refinement.exact_stage = false;
        no_exact.refinement.cap = 512;
        const Decision<InCircle> du = incircle(c.e1, c.e2, c.e3, c.q, no_exact);
        INFO("no exact stage: " << show(du));
        CHECK(!du.is_decided());
        CHECK(du.stage == Stage::subdivision);
        CHECK(du.precision >= 512);
    }
}

TEST_CASE("incircle exact stage: rotations of the degenerate quadruples stay tangent", "[predicates][incircle][exact]") {
    // The same four sites with another one as the query (the triple keeps its
    // counter-clockwise order).
    for (const Degenerate& c : {case_a(), case_c()}) {
        const Ellipse* s[4] = {&c.e1, &c.e2, &c.e3, &c.q};
        for (int rot = 1; rot < 4; ++rot) {
            const Ellipse &a = *s[rot], &b = *s[(rot + 1) % 4], &e = *s[(rot + 2) % 4], &q = *s[(rot + 3) % 4];
            INFO(c.name << " rotation " << rot << ell({&a, &b, &e, &q}));
            InCircleOptions low;
            low.use_circle_closed_form = false;  // the general path on circles
            low.refinement.cap = 256;
            const Decision<InCircle> d = incircle(a, b, e, q, low);
            INFO(show(d));
            CHECK((*d) == InCircle::tangent);
            CHECK(d.stage == Stage::exact);
        }
    }
}

TEST_CASE("incircle exact stage: perturbations by 10^-k get the strict sign", "[predicates][incircle][exact]") {
    for (const Degenerate& c : {case_a(), case_b(), case_c()}) {
        for (int k : {6, 30, 100}) {
            const Rational eps = power_of_ten(-k);
            for (int dir : {1, -1}) {
                const Ellipse q = moved(c, eps, dir);
                const InCircle want = dir > 0 ? InCircle::no_conflict : InCircle::conflict;
                INFO(c.name << " k " << k << (dir > 0 ? " away" : " toward") << ell({&c.e1, &c.e2, &c.e3, &q}));
                // Default cap: the subdivision separates (10^-100 needs ~340 bits).
                // (For four circles the closed-form filter may decide first, in
                // doubles; it is switched off to watch the subdivision.)
                InCircleOptions no_filter;
                no_filter.use_circle_closed_form = false;  // the general path on circles
                no_filter.use_filter = false;
                const Decision<InCircle> d = incircle(c.e1, c.e2, c.e3, q, no_filter);
                INFO("default: " << show(d));
                CHECK((*d) == want);
                CHECK(d.stage == Stage::subdivision);
                CHECK(d.precision > 3.32 * k);
                CHECK(*incircle(c.e1, c.e2, c.e3, q) == want);  // with the filter
                // Cap below the precision needed: the exact stage proves
                // non-tangency, then the subdivision resumes and separates.
                // 10^-100 under cap 256 for (b) and (c); for (a), whose i-point
                // contacts need the twin charts' resultants (~10 s with the
                // 333-bit center of Q), 10^-30 under cap 64 keeps it fast.
                const bool ipoints = c.name[1] == 'a';
                if (k == (ipoints ? 30 : 100)) {
                    InCircleOptions low;
                    low.use_circle_closed_form = false;  // the general path on circles
                    low.refinement.cap = ipoints ? 64 : 256;
                    const auto start = std::chrono::steady_clock::now();
                    const Decision<InCircle> dl = incircle(c.e1, c.e2, c.e3, q, low);
                    const double s = seconds_since(start);
                    INFO("cap " << low.refinement.cap << ": " << show(dl));
                    if (verbose())
                        std::printf("[incircle exact] %s k %d %s cap %ld: %s, %.3f s\n", c.name.c_str(), k,
                                    dir > 0 ? "away" : "toward", low.refinement.cap, show(dl).c_str(), s);
                    CHECK((*dl) == want);
                    CHECK(dl.stage == Stage::exact);
                    CHECK(dl.precision > low.refinement.cap);
                    // Without the exact stage the same cap leaves it undecided.
                    InCircleOptions no_exact = low;
                    no_exact.refinement.exact_stage = false;
                    CHECK(!incircle(c.e1, c.e2, c.e3, q, no_exact).is_decided());
                }
            }
        }
    }
}

TEST_CASE("incircle exact: a hidden query through a vertex of radius 0 on its host is tangent (fuzz F4)",
          "[incircle][exact][crossing]") {
    // Three circles of radius 5 and the ellipse (5, 55) at (5, 0) pass through the origin: the
    // faces of those sites have the Voronoi circle of radius 0 there. The circle of radius 5 at
    // (5, 0) lies in the ellipse (tangent to it at the origin) and passes through the origin too:
    // tangent. The exact stage used to pair the query with its host, which has no Voronoi
    // circle with it, and answered "distinct" (then "not separated": an internal error).
    const Ellipse left = Ellipse::circle(-5, 0, 5), below = Ellipse::circle(0, -5, 5), above = Ellipse::circle(0, 5, 5);
    const Ellipse host(Rational(5), Rational(55), Rational(0), Rational(5), Rational(0));
    const Ellipse hidden = Ellipse::circle(5, 0, 5);
    int tangent = 0;
    for (const Ellipse* first : {&left, &below})
        for (const auto& t : {std::array<const Ellipse*, 3>{first, &host, &above},
                              std::array<const Ellipse*, 3>{first, &above, &host}}) {
            const Decision<InCircle> d = incircle(*t[0], *t[1], *t[2], hidden);
            REQUIRE(d.is_decided());
            if (*d == InCircle::no_circle) continue;
            // The circle at the origin (radius 0) is tangent to the hidden circle; another one
            // (some triples' counter-clockwise circle lies elsewhere) is decided as usual.
            VoronoiCircleSolver solver(*t[0], *t[1], *t[2]);
            REQUIRE(solver.refine(64));
            if (std::fabs(solver.enclosure().radius.mid_double()) > 1e-9) {
                CHECK(*d != InCircle::tangent);
                continue;
            }
            CHECK(*d == InCircle::tangent);
            CHECK(d.stage == Stage::exact);
            ++tangent;
        }
    CHECK(tangent >= 1);
}
