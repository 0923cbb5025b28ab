// VoronoiCircleSolver: the certified enclosure of the counter-clockwise
// Voronoi circle of an ordered triple. Oracles: the closed-form Apollonius
// solution for circles (tests/support/apollonius_oracle.hpp, Arb at 4096
// bits), symmetric ellipse configurations whose circle is known exactly, and
// self-consistency (nested enclosures across precisions, tangency points on
// the ellipses along the outward normals).
#include "predicates/voronoi_circle_count.hpp"
#include "predicates/relative_position.hpp"
#include "subdivision/voronoi_circle_enclosure.hpp"
#include "tests/support/circle_oracles.hpp"
#include "tests/support/apollonius_oracle.hpp"

#include "tests/support/random_sites.hpp"
#include "tests/support/diagnostics.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

using namespace ellvor;
using ellvor::test::show;
using ellvor::test::verbose;

namespace {

using Rng = std::mt19937_64;

Rational rnd(Rng& rng, long lo, long hi, long den) {
    std::uniform_int_distribution<long> n(lo * den, hi * den);
    return Rational(n(rng), static_cast<unsigned long>(den));
}
// Uniform in [lo, hi] with lo > 0.
Rational rnd_pos(Rng& rng, long lo_num, long hi_num, long den) {
    std::uniform_int_distribution<long> n(lo_num, hi_num);
    return Rational(n(rng), static_cast<unsigned long>(den));
}


using ellvor::test::bounding_circles_apart;

bool contains(const Ball& big, const Ball& small) { return arb_contains(big.get(), small.get()) != 0; }

// Three random ellipses (semi-axes 1/5 .. 4, centers within 12 of the
// origin) into e; false when their bounding circles are not pairwise apart.
bool random_separated_triple(Rng& rng, std::vector<Ellipse>& e) {
    e.clear();
    for (int i = 0; i < 3; ++i)
        e.push_back(Ellipse(rnd_pos(rng, 2, 40, 10), rnd_pos(rng, 2, 40, 10), rnd(rng, -3, 3, 13), rnd(rng, -12, 12, 11),
                            rnd(rng, -12, 12, 7)));
    return bounding_circles_apart(e[0], e[1]) && bounding_circles_apart(e[0], e[2]) && bounding_circles_apart(e[1], e[2]);
}

// The oracle circle lies in the enclosure (both components and the radius).
void check_against_oracle(const VoronoiCircleEnclosure& enc, const apollonius::Solution& o) {
    INFO(show(enc) << "oracle x " << o.x.str(25) << " y " << o.y.str(25) << " radius " << o.radius.str(25));
    CHECK(contains(enc.center_x, o.x));
    CHECK(contains(enc.center_y, o.y));
    CHECK(contains(enc.radius, o.radius));
}

Ball sub(const Ball& a, const Ball& b, long prec) { Ball r; arb_sub(r.get(), a.get(), b.get(), prec); return r; }
Ball add(const Ball& a, const Ball& b, long prec) { Ball r; arb_add(r.get(), a.get(), b.get(), prec); return r; }
Ball mul(const Ball& a, const Ball& b, long prec) { Ball r; arb_mul(r.get(), a.get(), b.get(), prec); return r; }

// log2 of a ball's radius (very negative = tight); +inf-ish for exact zero radius handled by caller.
double log2_radius(const Ball& b) {
    if (mag_is_zero(arb_radref(b.get()))) return -1e9;
    return mag_get_d_log2_approx(arb_radref(b.get()));
}

}  // namespace

TEST_CASE("Voronoi circle enclosure contains the closed-form circle of 300+ random circle triples",
          "[subdivision][voronoi_circle_enclosure]") {
    Rng rng(20240611);
    int with_ccw = 0, without_ccw = 0, oracle_uncertain = 0, both = 0, refused = 0;
    for (int iter = 0; iter < 3000 && (with_ccw - refused < 320 || without_ccw < 150); ++iter) {
        apollonius::Circle c[3];
        for (auto& ci : c) ci = {rnd(rng, -12, 12, 37), rnd(rng, -12, 12, 41), rnd_pos(rng, 10, 160, 43)};
        const Ellipse e1 = c[0].ellipse(), e2 = c[1].ellipse(), e3 = c[2].ellipse();
        if (!bounding_circles_apart(e1, e2) || !bounding_circles_apart(e1, e3) || !bounding_circles_apart(e2, e3)) continue;
        INFO(apollonius::ell({&e1, &e2, &e3}));
        const apollonius::Result o = apollonius::voronoi_circles(c[0], c[1], c[2], 4096);
        if (!o.certain) {
            ++oracle_uncertain;
            continue;
        }
        REQUIRE(o.ccw_count() <= 1);
        REQUIRE(o.cw_count() <= 1);
        // ellvor's kappa2-based count agrees with the closed form.
        const VoronoiCircles count = *voronoi_circle_count(e1, e2, e3);
        const VoronoiCircles want = o.ccw_count() ? (o.cw_count() ? VoronoiCircles::both : VoronoiCircles::ccw_only)
                                                  : (o.cw_count() ? VoronoiCircles::cw_only : VoronoiCircles::none);
        INFO("count " << voronoi_circles_name(count) << " oracle " << voronoi_circles_name(want));
        CHECK(count == want);

        VoronoiCircleSolver solver(e1, e2, e3);
        const bool ok = solver.certify();
        const apollonius::Solution* s = o.ccw();
        if (!s) {
            ++without_ccw;
            CHECK_FALSE(ok);  // never certifies a clockwise (or nonexistent) circle
            continue;
        }
        ++with_ccw;
        both += o.cw_count();
        if (!ok) {
            // certify() is complete (guesses, then the exhaustive search):
            // false would claim that the existing circle does not exist.
            ++refused;
            if (verbose()) std::printf("[enclosure/circles] refused:%s", apollonius::ell({&e1, &e2, &e3}).c_str());
            continue;
        }
        CHECK(solver.certified());
        check_against_oracle(solver.enclosure(), *s);
        for (long bits : {200L, 2000L}) {
            INFO("refine to " << bits);
            REQUIRE(solver.refine(bits));
            CHECK(solver.enclosure().correct_bits() >= bits);
            check_against_oracle(solver.enclosure(), *s);
        }
    }
    if (verbose())
        std::printf("[enclosure/circles] with ccw %d (both %d), refused %d, without %d, oracle uncertain %d\n",
                    with_ccw, both, refused, without_ccw, oracle_uncertain);
    CHECK(with_ccw >= 300);
    CHECK(refused == 0);
    CHECK(without_ccw >= 100);
    CHECK(both >= 10);
}

TEST_CASE("Voronoi circle enclosure: hand-made circle triples", "[subdivision][voronoi_circle_enclosure]") {
    // Three unit circles at (6,0), (0,6), (-6,0): the circle of radius 5 at the origin.
    const Ellipse e1 = Ellipse::circle(6, 0, 1), e2 = Ellipse::circle(0, 6, 1), e3 = Ellipse::circle(-6, 0, 1);
    {
        INFO(apollonius::ell({&e1, &e2, &e3}));
        VoronoiCircleSolver s(e1, e2, e3);
        REQUIRE(s.certify());
        CHECK(s.enclosure().center_x.contains(0));
        CHECK(s.enclosure().center_y.contains(0));
        CHECK(s.enclosure().radius.contains(5));
        REQUIRE(s.refine(1000));
        CHECK(s.enclosure().center_x.contains(0));
        CHECK(s.enclosure().center_y.contains(0));
        CHECK(s.enclosure().radius.contains(5));
        CHECK(s.enclosure().correct_bits() >= 1000);
        CHECK_FALSE(s.enclosure().radius.contains(Rational(5) + Rational(1, 1UL << 60)));
    }
    {
        // Reversed order: equal radii force V to be equidistant from the
        // three centers, so the circle at the origin is the only tangent one,
        // and it is clockwise for (e3, e2, e1): no CCW circle, no certificate.
        INFO(apollonius::ell({&e3, &e2, &e1}));
        const apollonius::Result o = apollonius::voronoi_circles({-6, 0, 1}, {0, 6, 1}, {6, 0, 1});
        REQUIRE(o.certain);
        VoronoiCircleSolver s(e3, e2, e1);
        const bool ok = s.certify();
        if (const apollonius::Solution* c = o.ccw()) {
            REQUIRE(ok);
            check_against_oracle(s.enclosure(), *c);
        } else {
            CHECK_FALSE(ok);
        }
    }
}

TEST_CASE("Voronoi circle of a four-fold symmetric ellipse triple is known exactly",
          "[subdivision][voronoi_circle_enclosure]") {
    // E1 = (a, b, 0, (d, 0)), E2 = E1 rotated by 90 degrees about the origin
    // (w = 1, center (0, d)), E3 = (a, b, 0, (-d, 0)). The origin lies on the
    // a-axis of each; its nearest point is the vertex at distance d - a (for
    // a > b since d > (a^2 - b^2)/a; for a < b always). The circle at the
    // origin of radius d - a touches E1, E2, E3 at (d-a, 0), (0, d-a),
    // (-(d-a), 0): counter-clockwise, so it is the Voronoi circle.
    struct Case { Rational a, b, d; };
    const Case cases[] = {{2, 1, 5}, {3, Rational(1, 2UL), 7}, {1, 3, 7}, {Rational(5, 3UL), Rational(4, 7UL), Rational(31, 6UL)},
                          {Rational(1, 10UL), Rational(1, 20UL), Rational(1, 3UL)}, {7, 2, 11}};
    for (const Case& c : cases) {
        const Ellipse e1(c.a, c.b, 0, c.d, 0), e2(c.a, c.b, 1, 0, c.d), e3(c.a, c.b, 0, -c.d, 0);
        REQUIRE(bounding_circles_apart(e1, e2));
        INFO(apollonius::ell({&e1, &e2, &e3}));
        VoronoiCircleSolver s(e1, e2, e3);
        REQUIRE(s.certify());
        const Rational rho = c.d - c.a;
        for (long bits : {0L, 300L, 2000L}) {
            INFO("bits " << bits << "\n" << show(s.enclosure()));
            if (bits) REQUIRE(s.refine(bits));
            CHECK(s.enclosure().correct_bits() >= std::max(bits, 40L));
            CHECK(s.enclosure().center_x.contains(0));
            CHECK(s.enclosure().center_y.contains(0));
            CHECK(s.enclosure().radius.contains(rho));
            // Tangency parameters: E1 at theta = pi (t = infinity, the i-point),
            // E2 at theta = pi as well (its a-axis points up), E3 at theta = 0.
            const Ball t3 = s.enclosure().tangency_parameter(2, s.enclosure().precision);
            CHECK(t3.contains(0));
        }
        // (E1, E3, E2) is clockwise: its circle is not the one at the origin;
        // whatever ellvor certifies must not be that circle.
        VoronoiCircleSolver r(e1, e3, e2);
        if (r.certify()) {
            INFO(show(r.enclosure()));
            CHECK_FALSE((r.enclosure().center_x.contains(0) && r.enclosure().center_y.contains(0) &&
                         r.enclosure().radius.contains(rho)));
        }
    }
}

TEST_CASE("Voronoi circle of a mirror-symmetric ellipse triple is centered on the axis",
          "[subdivision][voronoi_circle_enclosure]") {
    // E2 is E1 mirrored across the y-axis (w -> -w, x -> -x); E3 is symmetric
    // about the y-axis (w = 0 or 1, center on it) and below the two. Mirroring
    // maps the CCW circle of (E1, E2, E3) to the CCW circle of (E1, E2, E3)
    // again, so by uniqueness its center has x = 0.
    Rng rng(77);
    int done = 0;
    for (int iter = 0; iter < 400 && done < 40; ++iter) {
        const Rational a = rnd_pos(rng, 5, 30, 10), b = rnd_pos(rng, 5, 30, 10), w = rnd(rng, -3, 3, 7);
        const Rational x0 = rnd_pos(rng, 10, 80, 10), y0 = rnd(rng, -5, 5, 9);
        const Rational a3 = rnd_pos(rng, 5, 30, 10), b3 = rnd_pos(rng, 5, 30, 10);
        const Rational w3 = (iter % 2) ? Rational(1) : Rational(0);
        const Rational y3 = y0 - rnd_pos(rng, 10, 80, 10);
        const Ellipse e1(a, b, w, x0, y0), e2(a, b, -w, -x0, y0), e3(a3, b3, w3, 0, y3);
        if (!bounding_circles_apart(e1, e2) || !bounding_circles_apart(e1, e3) || !bounding_circles_apart(e2, e3)) continue;
        const VoronoiCircles count = *voronoi_circle_count(e1, e2, e3);
        INFO(apollonius::ell({&e1, &e2, &e3}) << "count " << voronoi_circles_name(count));
        VoronoiCircleSolver s(e1, e2, e3);
        const bool ok = s.certify();
        if (count == VoronoiCircles::none || count == VoronoiCircles::cw_only) {
            CHECK_FALSE(ok);
            continue;
        }
        REQUIRE(ok);
        ++done;
        CHECK(s.enclosure().center_x.contains(0));
        REQUIRE(s.refine(600));
        INFO(show(s.enclosure()));
        CHECK(s.enclosure().center_x.contains(0));
        CHECK(log2_radius(s.enclosure().center_x) < -550);
        // The tangency parameters of E1 and E2 are mirror images: the boundary
        // points have opposite x and equal y.
        const long prec = s.enclosure().precision;
        const Ball t1 = s.enclosure().tangency_parameter(0, prec), t2 = s.enclosure().tangency_parameter(1, prec);
        if (arb_is_finite(t1.get()) && arb_is_finite(t2.get())) {
            const BallPoint p1 = e1.point_at(t1, prec), p2 = e2.point_at(t2, prec);
            CHECK(arb_contains_zero(add(p1.x, p2.x, prec).get()));
            CHECK(arb_contains_zero(sub(p1.y, p2.y, prec).get()));
        }
    }
    CHECK(done >= 30);
}

TEST_CASE("Voronoi circle enclosures of random ellipse triples are nested and tangent",
          "[subdivision][voronoi_circle_enclosure]") {
    Rng rng(9001);
    std::vector<Ellipse> e;
    int certified = 0, refused = 0, no_ccw = 0, skipped_ipoint = 0;
    const long prec = 1000;
    for (int iter = 0; iter < 1500 && certified < 110; ++iter) {
        if (!random_separated_triple(rng, e)) continue;
        INFO(apollonius::ell({&e[0], &e[1], &e[2]}));
        const VoronoiCircles count = *voronoi_circle_count(e[0], e[1], e[2]);
        INFO("count " << voronoi_circles_name(count));
        VoronoiCircleSolver s(e[0], e[1], e[2]);
        const bool ok = s.certify();
        if (count == VoronoiCircles::none || count == VoronoiCircles::cw_only) {
            ++no_ccw;
            CHECK_FALSE(ok);
            continue;
        }
        if (!ok) {
            ++refused;
            continue;
        }
        ++certified;
        const VoronoiCircleEnclosure low = s.enclosure();
        CHECK(low.correct_bits() >= 16);  // "about 64 bits" of working precision; ill-conditioned triples lose some
        REQUIRE(s.refine(prec));
        const VoronoiCircleEnclosure& high = s.enclosure();
        INFO("low\n" << show(low) << "high\n" << show(high));
        CHECK(high.correct_bits() >= prec);
        CHECK(contains(low.center_x, high.center_x));
        CHECK(contains(low.center_y, high.center_y));
        CHECK(contains(low.radius, high.radius));
        for (int i = 0; i < 3; ++i) {
            CHECK(low.flipped[i] == high.flipped[i]);
            if (low.flipped[i] == high.flipped[i]) CHECK(contains(low.parameter[i], high.parameter[i]));
        }
        CHECK(high.radius.certain_sign() == 1);
        // Tangency points: on E_i at distance rho from V, along the outward normal.
        const long wp = high.precision + 64;
        Ball px[3], py[3];
        bool all_finite = true;
        for (int i = 0; i < 3; ++i) {
            const Ball t = high.tangency_parameter(i, wp);
            if (!arb_is_finite(t.get())) {
                all_finite = false;
                ++skipped_ipoint;
                break;
            }
            const BallPoint p = e[i].point_at(t, wp);
            px[i] = p.x;
            py[i] = p.y;
            const Ball dx = sub(high.center_x, p.x, wp), dy = sub(high.center_y, p.y, wp);
            Ball dist;
            arb_hypot(dist.get(), dx.get(), dy.get(), wp);
            const Ball gap = sub(dist, high.radius, wp);
            INFO("site " << i << " |V - P| - rho = " << gap.str(10));
            CHECK(arb_contains_zero(gap.get()));
            CHECK(log2_radius(gap) < -900);
            // Outward normal: the gradient of the conic (negative inside).
            const auto& q = e[i].conic();
            auto rb = [&](const Rational& r) { return Ball(r, wp); };
            const Ball gx = add(add(mul(rb(q[0]), p.x, wp), mul(rb(q[1]), p.y, wp), wp), rb(q[3]), wp);
            const Ball gy = add(add(mul(rb(q[1]), p.x, wp), mul(rb(q[2]), p.y, wp), wp), rb(q[4]), wp);
            const Ball cross = sub(mul(dx, gy, wp), mul(dy, gx, wp), wp);
            const Ball dot = add(mul(dx, gx, wp), mul(dy, gy, wp), wp);
            CHECK(arb_contains_zero(cross.get()));
            CHECK(log2_radius(cross) < -900);
            CHECK(dot.certain_sign() == 1);
        }
        if (all_finite) {
            const Ball orient = sub(mul(sub(px[1], px[0], wp), sub(py[2], py[0], wp), wp),
                                    mul(sub(py[1], py[0], wp), sub(px[2], px[0], wp), wp), wp);
            CHECK(orient.certain_sign() == 1);  // tangency points counter-clockwise
        }
    }
    if (verbose())
        std::printf("[enclosure/ellipses] certified %d, refused %d, no ccw %d, i-point skipped %d\n", certified, refused,
                    no_ccw, skipped_ipoint);
    CHECK(certified >= 100);
    CHECK(refused == 0);  // certify() is complete: it never gives up on an existing circle
    CHECK(no_ccw >= 20);
}

TEST_CASE("Voronoi circle solver: after release_charts a refinement rebuilds them and stays nested",
          "[subdivision][voronoi_circle_enclosure]") {
    Rng rng(4242);
    std::vector<Ellipse> e;
    int done = 0;
    for (int iter = 0; iter < 400 && done < 20; ++iter) {
        if (!random_separated_triple(rng, e)) continue;
        VoronoiCircleSolver released(e[0], e[1], e[2]), kept(e[0], e[1], e[2]);
        if (!released.certify()) continue;
        REQUIRE(kept.certify());
        INFO(apollonius::ell({&e[0], &e[1], &e[2]}));
        const VoronoiCircleEnclosure low = released.enclosure();
        released.release_charts();
        // Reading the enclosure needs no charts; refining rebuilds them.
        CHECK(released.enclosure().correct_bits() == low.correct_bits());
        REQUIRE(released.refine(300));
        REQUIRE(kept.refine(300));
        const VoronoiCircleEnclosure& high = released.enclosure();
        CHECK(high.correct_bits() >= 300);
        CHECK(contains(low.radius, high.radius));
        CHECK(contains(low.center_x, high.center_x));
        CHECK(contains(low.center_y, high.center_y));
        CHECK(arb_overlaps(high.radius.get(), kept.enclosure().radius.get()));
        released.release_charts();
        REQUIRE(released.refine(600));
        CHECK(contains(high.radius, released.enclosure().radius));
        ++done;
    }
    CHECK(done == 20);
}

// Regression (found by this suite against the tree of 72e9dbf/c32597e, fixed
// by 978734a "certification escalates precision"):
//  (a) ellipse triples whose counter-clockwise Voronoi circle exists
//      (voronoi_circle_count says ccw_only/both, and an independent
//      multistart Newton on the tritangent system finds it, values below)
//      but guess_voronoi_circle() returned nullopt, so certify() failed and
//      incircle() reported undecided with 0 Newton steps;
//  (b) a circle triple with a large CCW circle (radius ~972, tangency points
//      close together): the guess was right to 7 digits but certify() ran
//      Krawczyk at 64 bits only and gave up.
// Reference values: independent double-precision multistart Newton (not a
// certificate; compared with a 1e-6 relative tolerance only).
TEST_CASE("Voronoi circle solver certifies non-degenerate triples it once refused",
          "[subdivision][voronoi_circle_enclosure]") {
    struct Case { Ellipse e1, e2, e3; double x, y, rho; };
    auto q = [](long n, unsigned long d) { return Rational(n, d); };
    const Case cases[] = {
        {Ellipse(q(3, 10), q(2, 5), q(-28, 11), q(-21, 13), q(-2, 7)), Ellipse(q(9, 10), 3, q(19, 11), q(-5, 13), q(-55, 7)),
         Ellipse(q(13, 5), q(14, 5), -2, q(-101, 13), q(52, 7)), 83.9704312, 44.5506014, 96.3110336},
        {Ellipse(q(5, 2), q(21, 10), q(-8, 11), q(61, 13), q(17, 7)), Ellipse(q(3, 5), q(3, 5), q(7, 11), q(-50, 13), q(-10, 7)),
         Ellipse(q(27, 10), 1, q(8, 11), q(129, 13), q(20, 7)), 10.3105897, -43.6085741, 43.8923141},
        {Ellipse(q(14, 5), 3, q(21, 11), q(-40, 13), q(-46, 7)), Ellipse(q(14, 5), q(9, 10), q(-17, 11), q(118, 13), q(39, 7)),
         Ellipse(q(2, 5), q(9, 5), q(-29, 11), -9, q(-60, 7)), -34.6648008, 45.1196831, 57.7779125},
        {Ellipse::circle(q(-251, 37), q(9, 41), q(152, 43)), Ellipse::circle(q(394, 37), q(-215, 41), q(137, 43)),
         Ellipse::circle(q(163, 37), q(-215, 41), q(60, 43)), -272.007722224, -938.884674401, 972.303428094},
    };
    for (const Case& c : cases) {
        INFO(apollonius::ell({&c.e1, &c.e2, &c.e3}));
        const VoronoiCircles count = *voronoi_circle_count(c.e1, c.e2, c.e3);
        CHECK((count == VoronoiCircles::ccw_only || count == VoronoiCircles::both));
        VoronoiCircleSolver s(c.e1, c.e2, c.e3);
        const bool ok = s.certify();
        CHECK(ok);
        if (!ok) continue;
        INFO(show(s.enclosure()));
        CHECK(std::fabs(s.enclosure().center_x.mid_double() - c.x) < 1e-6 * c.rho);
        CHECK(std::fabs(s.enclosure().center_y.mid_double() - c.y) < 1e-6 * c.rho);
        CHECK(std::fabs(s.enclosure().radius.mid_double() - c.rho) < 1e-6 * c.rho);
    }
}

TEST_CASE("internal Voronoi circles of crossing ellipses, deep ones included, are signed distances",
          "[subdivision][voronoi_circle_enclosure][overlap]") {
    // Three heavily overlapping ellipses (pairwise crossing in two points):
    // the counter-clockwise circle of one of the two orders is internal. The
    // certificate proves rho the signed distance (DESIGN.md §4.1: Blaschke
    // below min(a, b)^2 / max(a, b), disk_inside_ellipse deeper); a long-double
    // brute force confirms delta(V, E_i) = rho for the three sites.
    std::mt19937_64 rng(20261124);
    auto draw = [&](long lo, long hi, long den) {
        return Rational(Integer(lo * den + static_cast<long>(rng() % static_cast<std::uint64_t>((hi - lo) * den + 1))),
                        Integer(den));
    };
    int triples = 0, certified = 0, deep = 0, internal = 0;
    while (triples < 40) {
        std::vector<Ellipse> e;
        for (int i = 0; i < 3; ++i)
            e.emplace_back(draw(2, 4, 4), draw(1, 2, 4), draw(-1, 1, 5), draw(-1, 1, 4), draw(-1, 1, 4));
        bool pseudo = true;
        for (int i = 0; i < 3; ++i)
            pseudo = pseudo && *relative_position(e[i], e[(i + 1) % 3]) == RelativePosition::intersecting &&
                     boundary_meeting_points(e[i], e[(i + 1) % 3]) == 2;
        if (!pseudo) continue;
        ++triples;
        int found = 0;
        for (int order = 0; order < 2; ++order) {
            VoronoiCircleSolver solver(e[0], order ? e[2] : e[1], order ? e[1] : e[2]);
            if (!solver.certify()) continue;
            ++found;
            const VoronoiCircleEnclosure& c = solver.enclosure();
            INFO(e[0].str() << " | " << e[1].str() << " | " << e[2].str() << " order " << order << " rho "
                            << c.radius.str(20));
            Rational x, y, hi;
            ball_endpoints(c.center_x, x, hi);
            ball_endpoints(c.center_y, y, hi);
            const double rho = c.radius.mid_double();
            double kappa = 1e300;
            for (const Ellipse& s : e) {
                const double a = s.a().to_double(), b = s.b().to_double();
                kappa = std::min(kappa, std::min(a, b) * std::min(a, b) / std::max(a, b));
                CHECK(std::fabs(static_cast<double>(oracle::signed_distance(s, Point{x, y})) - rho) < 1e-9);
            }
            internal += rho < 0;
            deep += rho < -kappa;
        }
        certified += found > 0;  // an order may have its circle outside the sites, the other inside
    }
    INFO("certified " << certified << " of " << triples << ", internal " << internal << ", deep " << deep);
    CHECK(certified >= 30);
    CHECK(internal >= 25);
    CHECK(deep >= 10);
}
