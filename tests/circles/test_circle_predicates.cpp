// The closed-form circle predicates (circles/circle_predicates.hpp)
// against three independent references:
//  * ellvor's general predicates (incircle, infinite_vertex_conflict,
//    voronoi_circle_count, order_on_bisector with VoronoiCircleSolvers) on
//    random circle quadruples: identical answers wherever they decide;
//  * CGAL 5.5's Apollonius traits over exact rationals (Gmpq, the
//    Integral_domain_without_division_tag predicates): random inputs with
//    large denominators, near-collinear triples 10^-k off the line,
//    collinear centers and exactly degenerate quadruples. CGAL's
//    Vertex_conflict_2 returns a sign that depends on Q when the triple has
//    no counter-clockwise circle (ellvor: -1, CGAL's documented rule), so it
//    is compared only where that circle exists;
//  * hand cases with known answers, one for each special case of the closed
//    form, each named in its section.
// Every failure prints the sites as a replayable .ell snippet.
#include "predicates/bisector_order.hpp"
#include "circles/circle_predicates.hpp"
#include "predicates/edge_conflict.hpp"
#include "predicates/incircle.hpp"
#include "predicates/infinite_vertex_conflict.hpp"
#include "predicates/voronoi_circle_count.hpp"
#include "tests/support/circle_oracles.hpp"
#include "util/error.hpp"

#include <CGAL/Apollonius_graph_traits_2.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>
#include <catch2/catch.hpp>

#include <array>
#include <random>
#include <string>
#include <vector>

using namespace ellvor;

namespace {

using oracle::circles_apart;
using oracle::ell;
using oracle::rnd;
using oracle::rnd_pos;
using oracle::Rng;

using ExactKernel = CGAL::Simple_cartesian<CGAL::Gmpq>;
using ExactTraits = CGAL::Apollonius_graph_traits_2<ExactKernel, CGAL::Integral_domain_without_division_tag>;
using CgalSite = ExactTraits::Site_2;

CgalSite cgal_site(const Ellipse& e) {
    return CgalSite(ExactTraits::Point_2(CGAL::Gmpq(e.xc().str()), CGAL::Gmpq(e.yc().str())), CGAL::Gmpq(e.a().str()));
}
int sign_of(CGAL::Sign s) { return s == CGAL::NEGATIVE ? -1 : s == CGAL::POSITIVE ? 1 : 0; }

// CGAL's kappa3 and kappa2 on ellvor sites, exactly.
struct Cgal {
    ExactTraits traits;
    ExactTraits::Vertex_conflict_2 conflict = traits.vertex_conflict_2_object();
    int vertex_conflict(const Ellipse& a, const Ellipse& b, const Ellipse& c, const Ellipse& q) const {
        return sign_of(conflict(cgal_site(a), cgal_site(b), cgal_site(c), cgal_site(q)));
    }
    int infinite_vertex_conflict(const Ellipse& a, const Ellipse& b, const Ellipse& q) const {
        return sign_of(conflict(cgal_site(a), cgal_site(b), cgal_site(q)));
    }
};

const char* name(VoronoiCircles v) { return voronoi_circles_name(v); }
bool has_ccw(VoronoiCircles v) { return v == VoronoiCircles::ccw_only || v == VoronoiCircles::both; }


bool apart(const std::vector<Ellipse>& sites) {
    for (std::size_t i = 0; i < sites.size(); ++i)
        for (std::size_t j = i + 1; j < sites.size(); ++j) {
            const Rational dx = sites[i].xc() - sites[j].xc(), dy = sites[i].yc() - sites[j].yc(),
                           r = sites[i].a() + sites[j].a();
            if (dx * dx + dy * dy <= r * r) return false;
        }
    return true;
}

// Compares circle_vertex_conflict with CGAL's where the counter-clockwise
// circle exists, and with -1 where it does not; returns whether it existed.
bool check_conflict_against_cgal(const Cgal& cgal, const Ellipse& a, const Ellipse& b, const Ellipse& c,
                                 const Ellipse& q) {
    INFO(ell({&a, &b, &c, &q}));
    const CircleVoronoiVertex vertex(a, b, c);
    const int got = circle_vertex_conflict(vertex, q);
    CHECK(got == circle_vertex_conflict(a, b, c, q));
    if (!vertex.exists()) {
        CHECK(got == -1);
        return false;
    }
    CHECK(got == cgal.vertex_conflict(a, b, c, q));
    return true;
}

// kappa2 by the general path (the bitangent quartic), not the closed form.
int general_kappa2(const Ellipse& a, const Ellipse& b, const Ellipse& q) {
    InfiniteVertexConflictOptions general;
    general.use_circle_closed_form = false;
    return to_int(*infinite_vertex_conflict(a, b, q, general));
}

// The count of Voronoi circles from three general kappa2 signs (the rule of
// voronoi_circle_count.cpp, which takes the closed form for circles).
VoronoiCircles general_count(const Ellipse& a, const Ellipse& b, const Ellipse& c) {
    const int conflicts = (general_kappa2(a, b, c) < 0) + (general_kappa2(b, c, a) < 0) + (general_kappa2(c, a, b) < 0);
    constexpr VoronoiCircles by_conflicts[] = {VoronoiCircles::cw_only, VoronoiCircles::none, VoronoiCircles::both,
                                               VoronoiCircles::ccw_only};
    return by_conflicts[conflicts];
}

// All six orders of a triple.
std::array<std::array<const Ellipse*, 3>, 6> orders(const Ellipse& a, const Ellipse& b, const Ellipse& c) {
    return {{{&a, &b, &c}, {&b, &c, &a}, {&c, &a, &b}, {&a, &c, &b}, {&c, &b, &a}, {&b, &a, &c}}};
}

VoronoiCircles reversed(VoronoiCircles v) {
    if (v == VoronoiCircles::ccw_only) return VoronoiCircles::cw_only;
    if (v == VoronoiCircles::cw_only) return VoronoiCircles::ccw_only;
    return v;
}

// The count of every order of a triple: the rotations keep it, the
// reflections reverse it, and it agrees with the general predicate.
void check_count_all_orders(const Ellipse& a, const Ellipse& b, const Ellipse& c, VoronoiCircles want) {
    const auto all = orders(a, b, c);
    for (int i = 0; i < 6; ++i) {
        const auto& t = all[i];
        INFO("order " << i << ell({t[0], t[1], t[2]}));
        const VoronoiCircles expected = i < 3 ? want : reversed(want);
        CHECK(name(circle_voronoi_circle_count(*t[0], *t[1], *t[2])) == std::string(name(expected)));
        CHECK(name(general_count(*t[0], *t[1], *t[2])) == std::string(name(expected)));
        CHECK(CircleVoronoiVertex(*t[0], *t[1], *t[2]).exists() == has_ccw(expected));
    }
}

}  // namespace

// ------------------------------------------------ against ellvor's cascade --

TEST_CASE("circle predicates agree with ellvor's general predicates on 1000 random quadruples",
          "[circle-predicates]") {
    Rng rng(1618);
    int n = 0, ordered = 0, counts[4] = {}, conflicts[3] = {};
    while (n < 1000) {
        // Crowded rational circles (so that every count occurs), and every
        // fourth quadruple with integers.
        std::vector<oracle::Circle> c(4);
        for (auto& k : c)
            k = n % 4 == 3 ? oracle::Circle{rnd(rng, -20, 20, 1), rnd(rng, -20, 20, 1), rnd_pos(rng, 5, 1)}
                           : oracle::Circle{rnd(rng, -10, 10, 97), rnd(rng, -10, 10, 89), rnd_pos(rng, 4, 53)};
        bool ok = true;
        for (int i = 0; i < 4; ++i)
            for (int j = i + 1; j < 4; ++j) ok = ok && circles_apart(c[i], c[j]);
        if (!ok) continue;
        ++n;
        const Ellipse e1 = c[0].ellipse(), e2 = c[1].ellipse(), e3 = c[2].ellipse(), q = c[3].ellipse();
        INFO(ell({&e1, &e2, &e3, &q}));

        const VoronoiCircles count = circle_voronoi_circle_count(e1, e2, e3);
        ++counts[static_cast<int>(count)];
        CHECK(name(count) == std::string(name(general_count(e1, e2, e3))));

        CHECK(circle_infinite_vertex_conflict(e1, e2, q) == general_kappa2(e1, e2, q));
        CHECK(circle_infinite_vertex_conflict(q, e3, e1) == general_kappa2(q, e3, e1));

        const CircleVoronoiVertex vertex(e1, e2, e3);
        CHECK(vertex.exists() == has_ccw(count));
        InCircleOptions general_path;
        general_path.use_circle_closed_form = false;
        const Decision<InCircle> general = incircle(e1, e2, e3, q, general_path);
        REQUIRE(general.is_decided());
        CHECK(general.stage != Stage::exact);  // not by the closed form (nor by resultants, on random data)
        const int got = circle_vertex_conflict(vertex, q);
        ++conflicts[got + 1];
        CHECK(got == to_int(incircle_sign(*general)));

        // Order along the bisector of (E1, E2) of the vertices (E1, E2, E3)
        // and (E1, Q, E2) -- the ends of a Voronoi edge in kappa4.
        const CircleVoronoiVertex other(e1, q, e2);
        if (vertex.exists() && other.exists()) {
            ++ordered;
            BisectorFrame frame(e1, e2);
            VoronoiCircleSolver a(e1, e2, e3), b(e1, q, e2);
            const int want = to_int(*order_on_bisector(frame, a, 0, b, 0, RefinementOptions{}));
            CHECK(circle_order_on_bisector(e1, e2, vertex, other) == want);
            CHECK(circle_order_on_bisector(e1, e2, other, vertex) == -want);
            // The bisector of (E2, E1) runs the other way.
            CHECK(circle_order_on_bisector(e2, e1, vertex, other) == -want);
            // A rotated triple is the same vertex.
            CHECK(circle_order_on_bisector(e1, e2, CircleVoronoiVertex(e2, e3, e1), other) == want);
        }
    }
    INFO("counts none " << counts[0] << " ccw " << counts[1] << " cw " << counts[2] << " both " << counts[3]
                        << "; conflicts " << conflicts[0] << " tangent " << conflicts[1] << " free " << conflicts[2]
                        << "; ordered pairs " << ordered);
    for (int k = 0; k < 4; ++k) CHECK(counts[k] > 20);
    CHECK(conflicts[0] > 200);
    CHECK(conflicts[2] > 200);
    CHECK(ordered > 150);
}

// ----------------------------------------------------------- against CGAL --

TEST_CASE("the infinite-edge conflict of circles in closed form agrees with the general path", "[circle-predicates]") {
    // Random quadruples (hull neighbours or not: the predicate is defined for
    // any four separated circles), and the degenerate ones of a row of equal
    // circles, where bitangent contacts coincide and the ends decide.
    Rng rng(5150);
    int n = 0, ties = 0;
    auto check = [&](const Ellipse& c2, const Ellipse& c3, const Ellipse& c4, const Ellipse& q) {
        for (bool b : {false, true}) {
            INFO(ell({&c2, &c3, &c4, &q}) << "b " << b);
            const Decision<bool> general = infinite_edge_interior_conflict(c2, c3, c4, q, b, false);
            const Decision<bool> closed = infinite_edge_interior_conflict(c2, c3, c4, q, b);
            CHECK(closed.stage == Stage::exact);
            CHECK(*closed == *general);
            CHECK(circle_infinite_edge_interior_conflict(c2, c3, c4, q, b) == *general);
        }
    };
    while (n < 400) {
        std::vector<oracle::Circle> c(4);
        for (auto& k : c) k = {rnd(rng, -10, 10, 7), rnd(rng, -10, 10, 5), rnd_pos(rng, 3, 4)};
        bool ok = true;
        for (int i = 0; i < 4; ++i)
            for (int j = i + 1; j < 4; ++j) ok = ok && circles_apart(c[i], c[j]);
        if (!ok) continue;
        ++n;
        check(c[0].ellipse(), c[1].ellipse(), c[2].ellipse(), c[3].ellipse());
    }
    // A row of equal circles on the x-axis: the bitangents of neighbours are the
    // same lines y = +-1.
    std::vector<Ellipse> row;
    for (int i = 0; i < 5; ++i) row.push_back(Ellipse::circle(3 * i, 0, 1));
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 5; ++j)
            for (int k = 0; k < 5; ++k)
                for (int m = 0; m < 5; ++m)
                    if (i != j && i != k && i != m && j != k && j != m && k != m) {
                        ++ties;
                        check(row[i], row[j], row[k], row[m]);
                    }
    CHECK(ties == 120);
}

TEST_CASE("circle predicates agree with CGAL's exact Apollonius traits on random rational circles",
          "[circle-predicates]") {
    // Three kinds of large rationals, all exact in CGAL's Gmpq: centers and
    // radii with ~20-bit prime denominators plus 10^-12 offsets; on a grid of
    // 10^-30 around small fractions; and (every tenth quadruple) on a grid of
    // 10^-300 (about a thousand bits).
    Rng rng(2718);
    const Cgal cgal;
    int n = 0, with_ccw = 0, conflict_signs[3] = {}, kappa2_conflicts = 0;
    while (n < 1000) {
        std::vector<Ellipse> s;
        for (int i = 0; i < 4; ++i) {
            if (n % 10 == 9) {
                const Rational grid = power_of_ten(-300);
                auto offset = [&] { return grid * Rational(Integer(static_cast<long>(rng() >> 1)), Integer(1)); };
                s.push_back(Ellipse::circle(rnd(rng, -10, 10, 7) + offset(), rnd(rng, -10, 10, 3) + offset(),
                                            rnd_pos(rng, 4, 5) + offset()));
            } else if (n % 2 == 0) {
                s.push_back(Ellipse::circle(rnd(rng, -10, 10, 1000003) + power_of_ten(-12) * rnd(rng, 0, 1, 1009),
                                            rnd(rng, -10, 10, 999983), rnd_pos(rng, 4, 1000033)));
            } else {
                const Rational grid = power_of_ten(-30);
                s.push_back(Ellipse::circle(Rational(rnd(rng, -10, 10, 7)) + grid * rnd(rng, -1000, 1000, 1),
                                            rnd(rng, -10, 10, 3) + grid * rnd(rng, -1000, 1000, 1),
                                            rnd_pos(rng, 4, 5) + grid * rnd(rng, 0, 1000, 1)));
            }
        }
        if (!apart(s)) continue;
        ++n;
        with_ccw += check_conflict_against_cgal(cgal, s[0], s[1], s[2], s[3]);
        conflict_signs[circle_vertex_conflict(s[0], s[1], s[2], s[3]) + 1]++;
        INFO(ell({&s[0], &s[1], &s[3]}));
        const int k2 = circle_infinite_vertex_conflict(s[0], s[1], s[3]);
        CHECK(k2 == cgal.infinite_vertex_conflict(s[0], s[1], s[3]));
        kappa2_conflicts += k2 < 0;
    }
    INFO("with a ccw circle " << with_ccw << ", signs " << conflict_signs[0] << " " << conflict_signs[1] << " "
                              << conflict_signs[2] << ", kappa2 conflicts " << kappa2_conflicts);
    CHECK(with_ccw > 300);
    CHECK(conflict_signs[2] > 100);
    CHECK(kappa2_conflicts > 100);
    CHECK(n - kappa2_conflicts > 100);
}

TEST_CASE("near-collinear triples 10^-k off the line: exact answers and CGAL agree", "[circle-predicates]") {
    // Unit circles at (0,0), (6,0), (3, 10^-k): the numeric Voronoi-circle
    // search fails at k = 20; here every k is exact. The counter-clockwise
    // circle of ((0,0), (6,0), (3, eps)) is huge (radius ~ 9 / (2 eps)),
    // centered far below: it holds the lower half-plane up to ~eps.
    // Unequal radii: (0,0) r 1, (7,0) r 2, (3, eps) r 1/2.
    const Cgal cgal;
    for (int k : {12, 16, 20, 30, 40}) {
        const Rational eps = power_of_ten(-k);
        // Equal radii: one circle, the circumcircle, of the centers'
        // orientation; a small middle site leaves room on both sides.
        struct Triple { Ellipse a, b, c; VoronoiCircles want; };
        const Triple triples[] = {
            {Ellipse::circle(0, 0, 1), Ellipse::circle(6, 0, 1), Ellipse::circle(3, eps, 1), VoronoiCircles::ccw_only},
            {Ellipse::circle(0, 0, 1), Ellipse::circle(7, 0, 2), Ellipse::circle(3, eps, Rational(1, 2UL)),
             VoronoiCircles::both},
            {Ellipse::circle(0, 0, 1), Ellipse::circle(6, 0, 1), Ellipse::circle(3, -eps, 1), VoronoiCircles::cw_only},
        };
        const std::vector<Ellipse> queries = {
            Ellipse::circle(3, -5, 1),  Ellipse::circle(3, 5, 1),   Ellipse::circle(-5, 1, 1),
            Ellipse::circle(12, -1, 1), Ellipse::circle(3, -3, Rational(1, 2UL)), Ellipse::circle(3, 3, Rational(1, 2UL)),
            Ellipse::circle(3, Rational(-3, 2UL), Rational(1, 4UL)),
            Ellipse::circle(-3, 0, 1),  // on the line of the centers
        };
        for (const Triple& t : triples) {
            INFO("k " << k);
            check_count_all_orders(t.a, t.b, t.c, t.want);
            for (const auto& o : orders(t.a, t.b, t.c))
                for (const Ellipse& q : queries) {
                    if (!apart({*o[0], *o[1], *o[2], q})) continue;
                    check_conflict_against_cgal(cgal, *o[0], *o[1], *o[2], q);
                    INFO(ell({o[0], o[1], &q}));
                    CHECK(circle_infinite_vertex_conflict(*o[0], *o[1], q) ==
                          cgal.infinite_vertex_conflict(*o[0], *o[1], q));
                }
        }
        // The huge circle itself: center (3, y) with y ~ -9 / (2 eps), and
        // Q = (3, -5) r 1 inside its disk, (3, 5) outside.
        const Ellipse a = Ellipse::circle(0, 0, 1), b = Ellipse::circle(6, 0, 1), c = Ellipse::circle(3, eps, 1);
        const CircleVoronoiVertex v(a, b, c);
        REQUIRE(v.exists());
        CHECK(v.center_x() == QuadraticNumber(Rational(3)));
        CHECK(compare(v.center_y(), QuadraticNumber(Rational(-4) / eps)) < 0);
        CHECK(circle_vertex_conflict(v, Ellipse::circle(3, -5, 1)) == -1);
        CHECK(circle_vertex_conflict(v, Ellipse::circle(3, 5, 1)) == 1);
    }
}

TEST_CASE("collinear centers: none, both, rank 1 (equal radii, radii affine along the line)", "[circle-predicates]") {
    const Cgal cgal;
    // CGAL's collinear three-site configurations (test_voronoi_circle_count):
    // centers (100,100), (150,150), (200,200).
    struct Case { long r1, r2, r3; VoronoiCircles want; const char* special; };
    const Case cases[] = {
        {5, 10, 15, VoronoiCircles::none, "rank 1: radii affine along the line"},
        {20, 20, 20, VoronoiCircles::none, "rank 1: equal radii"},
        {15, 10, 5, VoronoiCircles::none, "rank 1: radii affine, decreasing"},
        {20, 25, 20, VoronoiCircles::none, "main case, collinear centers: both roots with R < 0"},
        {20, 15, 20, VoronoiCircles::both, "main case, collinear centers: two circles, one each side"},
    };
    for (const Case& k : cases) {
        const Ellipse a = Ellipse::circle(100, 100, k.r1), b = Ellipse::circle(150, 150, k.r2),
                      c = Ellipse::circle(200, 200, k.r3);
        INFO(k.special << ell({&a, &b, &c}));
        check_count_all_orders(a, b, c, k.want);
        for (const Ellipse& q : {Ellipse::circle(150, 100, 5), Ellipse::circle(100, 150, 5),
                                 Ellipse::circle(150, 240, 10), Ellipse::circle(0, 0, 20)})
            for (const auto& o : orders(a, b, c)) check_conflict_against_cgal(cgal, *o[0], *o[1], *o[2], q);
    }
    // Collinear on a vertical line and on a line of slope -3/4, unequal radii: both.
    for (const auto& sites : {std::array<Ellipse, 3>{Ellipse::circle(0, 0, 2), Ellipse::circle(0, 10, 1), Ellipse::circle(0, 20, 2)},
                              std::array<Ellipse, 3>{Ellipse::circle(0, 0, 3), Ellipse::circle(8, -6, 1),
                                                     Ellipse::circle(20, -15, 4)}}) {
        INFO("collinear, unequal radii" << ell({&sites[0], &sites[1], &sites[2]}));
        check_count_all_orders(sites[0], sites[1], sites[2], VoronoiCircles::both);
        for (const auto& o : orders(sites[0], sites[1], sites[2]))
            for (const Ellipse& q : {Ellipse::circle(5, 5, 1), Ellipse::circle(-6, 8, 2), Ellipse::circle(30, 0, 1)})
                if (apart({*o[0], *o[1], *o[2], q})) check_conflict_against_cgal(cgal, *o[0], *o[1], *o[2], q);
    }
}

TEST_CASE("exactly degenerate quadruples: four circles on a square, six on a hexagon, and their perturbations",
          "[circle-predicates]") {
    const Cgal cgal;
    // Unit circles on the corners of squares of side 3 (the 30 x 30 grid's
    // cells) and of side 2 (neighbours externally tangent): the Voronoi
    // circle of any three touches the fourth. CGAL says ZERO too.
    for (long side : {3L, 2L}) {
        INFO("square of side " << side);
        const std::array<Ellipse, 4> corners = {Ellipse::circle(0, 0, 1), Ellipse::circle(side, 0, 1),
                                                Ellipse::circle(side, side, 1), Ellipse::circle(0, side, 1)};
        for (int i = 0; i < 4; ++i) {
            const Ellipse &a = corners[i], &b = corners[(i + 1) % 4], &c = corners[(i + 2) % 4],
                          &q = corners[(i + 3) % 4];
            INFO(ell({&a, &b, &c, &q}));
            CHECK(circle_vertex_conflict(a, b, c, q) == 0);
            CHECK(cgal.vertex_conflict(a, b, c, q) == 0);
            // Equal radii, the square's center: (side/2, side/2), radius side / sqrt 2 - 1.
            const CircleVoronoiVertex v(a, b, c);
            CHECK(v.center_x() == QuadraticNumber(Rational(side, 2UL)));
            CHECK(v.center_y() == QuadraticNumber(Rational(side, 2UL)));
            CHECK(v.radius() == QuadraticNumber(Rational(-1), Rational(side, 2UL), Rational(2)));
            // The vertices (a, b, c) and (a, b, q) are the same circle: order 0
            // along the bisector of (a, b), in different fields Q(sqrt D).
            const CircleVoronoiVertex w(q, a, b);
            CHECK(circle_order_on_bisector(a, b, v, w) == 0);
            // Q's radius changed by 10^-40: smaller -> no conflict; bigger ->
            // conflict (only for side 3: with side 2 a bigger Q would cut its
            // neighbours).
            const Rational eps = power_of_ten(-40);
            const Ellipse bigger = Ellipse::circle(q.xc(), q.yc(), Rational(1) + eps),
                          smaller = Ellipse::circle(q.xc(), q.yc(), Rational(1) - eps);
            CHECK(circle_vertex_conflict(v, smaller) == 1);
            CHECK(cgal.vertex_conflict(a, b, c, smaller) == 1);
            if (side == 3) {
                CHECK(circle_vertex_conflict(v, bigger) == -1);
                CHECK(cgal.vertex_conflict(a, b, c, bigger) == -1);
            }
        }
    }
    // The 30 x 30 grid of unit circles with spacing 3: every cell is such a
    // square, and along the bisector of two horizontal neighbours the vertex
    // of the cell below comes before the vertex of the cell above (the
    // bisector runs upward, J = (B - A) turned by +90 degrees).
    std::vector<Ellipse> grid;
    for (long i = 0; i < 30; ++i)
        for (long j = 0; j < 30; ++j) grid.push_back(Ellipse::circle(3 * i, 3 * j, 1));
    auto at = [&](long i, long j) -> const Ellipse& { return grid[static_cast<std::size_t>(30 * i + j)]; };
    int grid_tangent = 0;
    for (long i = 0; i + 1 < 30; ++i)
        for (long j = 1; j + 1 < 30; ++j) {
            const Ellipse &a = at(i, j), &b = at(i + 1, j), &above = at(i + 1, j + 1), &below = at(i, j - 1);
            const CircleVoronoiVertex up(a, b, above), down(a, below, b);
            INFO(ell({&a, &b, &above, &below}));
            CHECK(circle_vertex_conflict(up, at(i, j + 1)) == 0);
            CHECK(circle_vertex_conflict(down, at(i + 1, j - 1)) == 0);
            CHECK(circle_order_on_bisector(a, b, down, up) == -1);
            grid_tangent += 2;
        }
    CHECK(grid_tangent == 2 * 29 * 28);
    // Six unit circles on the hexagon (25,0), (15,20), (-15,20), (-25,0),
    // (-15,-20), (15,-20), all on the circle of radius 25: every triple in
    // counter-clockwise order has the Voronoi circle of radius 24 about the
    // origin, tangent to the other three.
    const std::vector<Ellipse> hexagon = {Ellipse::circle(25, 0, 1),   Ellipse::circle(15, 20, 1),
                                          Ellipse::circle(-15, 20, 1), Ellipse::circle(-25, 0, 1),
                                          Ellipse::circle(-15, -20, 1), Ellipse::circle(15, -20, 1)};
    int tangent = 0;
    for (int i = 0; i < 6; ++i)
        for (int j = i + 1; j < 6; ++j)
            for (int k = j + 1; k < 6; ++k) {
                const CircleVoronoiVertex v(hexagon[i], hexagon[j], hexagon[k]);
                REQUIRE(v.exists());
                CHECK(v.radius() == QuadraticNumber(Rational(24)));
                CHECK(!CircleVoronoiVertex(hexagon[i], hexagon[k], hexagon[j]).exists());
                for (int l = 0; l < 6; ++l) {
                    if (l == i || l == j || l == k) continue;
                    INFO(ell({&hexagon[i], &hexagon[j], &hexagon[k], &hexagon[l]}));
                    CHECK(circle_vertex_conflict(v, hexagon[l]) == 0);
                    CHECK(cgal.vertex_conflict(hexagon[i], hexagon[j], hexagon[k], hexagon[l]) == 0);
                    ++tangent;
                }
                // Every vertex of the hexagon is the same circle: along the
                // bisector of sites 0 and 1, order 0 with (0, 1, 2).
                if (i == 0 && j == 1) {
                    const CircleVoronoiVertex first(hexagon[0], hexagon[1], hexagon[2]);
                    CHECK(circle_order_on_bisector(hexagon[0], hexagon[1], first, v) == 0);
                }
            }
    CHECK(tangent == 60);
}

// ----------------------------------------------------------- special cases --

TEST_CASE("special case <k, k> = 0: three circles with a common tangent line", "[circle-predicates]") {
    // (0,3) r 3, (5,1) r 1, (10,3) r 3 all touch y = 0 from above. The
    // lifted line is parallel to a generator of the cone: one circle is the
    // line, the other is rational: center (5, 33/8), radius 17/8 (distances
    // 25/8 = 17/8 + 1 and 41/8 = 17/8 + 3).
    const Ellipse a = Ellipse::circle(0, 3, 3), b = Ellipse::circle(5, 1, 1), c = Ellipse::circle(10, 3, 3);
    INFO(ell({&a, &b, &c}));
    check_count_all_orders(a, b, c, VoronoiCircles::ccw_only);
    // Radii growing along the line y = 0: the finite root has R < 0 in one
    // orientation and the wrong orientation in the other: no circle.
    check_count_all_orders(Ellipse::circle(0, 1, 1), Ellipse::circle(4, 2, 2), Ellipse::circle(10, 3, 3),
                           VoronoiCircles::none);
    const CircleVoronoiVertex v(a, b, c);
    REQUIRE(v.exists());
    CHECK(v.radius().is_rational());  // the linear branch (the main branch has a square-root part)
    CHECK(v.center_x() == QuadraticNumber(Rational(5)));
    CHECK(v.center_y() == QuadraticNumber(Rational(33, 8UL)));
    CHECK(v.radius() == QuadraticNumber(Rational(17, 8UL)));
    const Cgal cgal;
    for (const Ellipse& q : {Ellipse::circle(5, 7, 1), Ellipse::circle(5, 8, 1), Ellipse::circle(5, 9, 1),
                             Ellipse::circle(20, 20, 5), Ellipse::circle(5, -4, 1)})
        for (const auto& o : orders(a, b, c)) check_conflict_against_cgal(cgal, *o[0], *o[1], *o[2], q);
    // Q = (5, 29/4) r 1 touches the circle from outside: 29/4 - 33/8 = 25/8 = R + 1.
    CHECK(circle_vertex_conflict(v, Ellipse::circle(5, Rational(29, 4UL), 1)) == 0);
    CHECK(cgal.vertex_conflict(a, b, c, Ellipse::circle(5, Rational(29, 4UL), 1)) == 0);
    // kappa2 ties: y = 0 is the external bitangent of (c, a) (tangency
    // points (10,0), (0,0): H below). b touches it from the sites' side,
    // between the contact points: -1 by CGAL's tie-break; a far circle
    // touching it outside (20, 2) r 2: +1.
    CHECK(circle_infinite_vertex_conflict(c, a, b) == -1);
    CHECK(cgal.infinite_vertex_conflict(c, a, b) == -1);
    CHECK(circle_infinite_vertex_conflict(c, a, Ellipse::circle(20, 2, 2)) == 1);
    CHECK(cgal.infinite_vertex_conflict(c, a, Ellipse::circle(20, 2, 2)) == 1);
    CHECK(circle_infinite_vertex_conflict(c, a, Ellipse::circle(-9, 2, 2)) == 1);
    CHECK(general_kappa2(c, a, b) == -1);
    // The vertex with a rational center against one in Q(sqrt D) along the
    // bisector of (a, b): the other end of their Voronoi edge, below.
    const Ellipse d = Ellipse::circle(2, -3, 1);
    const CircleVoronoiVertex w(a, d, b);
    REQUIRE(w.exists());
    CHECK(!w.radius().is_rational());
    BisectorFrame frame(a, b);
    VoronoiCircleSolver sv(a, b, c), sw(a, d, b);
    CHECK(circle_order_on_bisector(a, b, v, w) == to_int(*order_on_bisector(frame, sv, 0, sw, 0, RefinementOptions{})));
}

TEST_CASE("special cases: equal radii, externally tangent pairs, clockwise only, none", "[circle-predicates]") {
    const Cgal cgal;
    SECTION("equal radii: the Voronoi circle is the circumcircle of the centers") {
        // Unit circles at (0,0), (8,0), (0,6): circumcenter (4,3), radius 5 - 1.
        const Ellipse a = Ellipse::circle(0, 0, 1), b = Ellipse::circle(8, 0, 1), c = Ellipse::circle(0, 6, 1);
        check_count_all_orders(a, b, c, VoronoiCircles::ccw_only);
        const CircleVoronoiVertex v(a, b, c);
        CHECK(v.center_x() == QuadraticNumber(Rational(4)));
        CHECK(v.center_y() == QuadraticNumber(Rational(3)));
        CHECK(v.radius() == QuadraticNumber(Rational(4)));
        // clockwise only for the reversed order, and then -1 for every Q (CGAL's rule)
        CHECK(name(circle_voronoi_circle_count(a, c, b)) == std::string("cw"));
        CHECK(circle_vertex_conflict(a, c, b, Ellipse::circle(100, 100, 1)) == -1);
        Rng rng(99);
        for (int i = 0; i < 200; ++i) {
            const Rational r = rnd_pos(rng, 2, 7);
            std::vector<Ellipse> s;
            for (int j = 0; j < 4; ++j) s.push_back(Ellipse::circle(rnd(rng, -10, 10, 3), rnd(rng, -10, 10, 2), r));
            if (!apart(s)) continue;
            check_conflict_against_cgal(cgal, s[0], s[1], s[2], s[3]);
            INFO(ell({&s[0], &s[1], &s[2]}));
            CHECK(name(circle_voronoi_circle_count(s[0], s[1], s[2])) == std::string(name(general_count(s[0], s[1], s[2]))));
        }
    }
    SECTION("externally tangent pairs") {
        // Radii 2, 1, 3 on the 3-4-5 right triangle (0,0), (3,0), (3,4):
        // pairwise externally tangent. The circle in the curved gap exists
        // (counter-clockwise), the other tangent circle encloses them.
        const Ellipse a = Ellipse::circle(0, 0, 2), b = Ellipse::circle(3, 0, 1), c = Ellipse::circle(3, 4, 3);
        INFO(ell({&a, &b, &c}));
        check_count_all_orders(a, b, c, VoronoiCircles::ccw_only);
        const CircleVoronoiVertex v(a, b, c);
        // The inner Soddy circle: curvature 1/2 + 1 + 1/3 + 2 sqrt(1/2 + 1/6 + 1/3) = 23/6: radius 6/23.
        CHECK(v.radius() == QuadraticNumber(Rational(6, 23UL)));
        for (const Ellipse& q : {Ellipse::circle(2, 1, Rational(1, 10UL)), Ellipse::circle(-5, -5, 1),
                                 Ellipse::circle(Rational(9, 2UL), -2, Rational(1, 2UL))})
            for (const auto& o : orders(a, b, c))
                if (apart({*o[0], *o[1], *o[2], q})) check_conflict_against_cgal(cgal, *o[0], *o[1], *o[2], q);
        // kappa2 on a tangent pair, against the general predicate and CGAL.
        for (const Ellipse& q : {Ellipse::circle(0, -5, 1), Ellipse::circle(2, -4, 1), Ellipse::circle(10, 10, 1)}) {
            INFO(ell({&a, &b, &q}));
            CHECK(circle_infinite_vertex_conflict(a, b, q) == general_kappa2(a, b, q));
            CHECK(circle_infinite_vertex_conflict(a, b, q) == cgal.infinite_vertex_conflict(a, b, q));
            CHECK(circle_infinite_vertex_conflict(b, a, q) == cgal.infinite_vertex_conflict(b, a, q));
        }
        // Q externally tangent to the Voronoi circle: a fourth coin in the
        // square's corner (unit circles at the corners of a side-2 square).
        const Ellipse s1 = Ellipse::circle(0, 0, 1), s2 = Ellipse::circle(2, 0, 1), s3 = Ellipse::circle(2, 2, 1),
                      s4 = Ellipse::circle(0, 2, 1);
        CHECK(circle_vertex_conflict(s1, s2, s3, s4) == 0);
    }
    SECTION("none: a site between the other two blocks every circle") {
        // A big circle between two small ones on a line: the tangent circles
        // would have to pass through it.
        const Ellipse a = Ellipse::circle(0, 0, 1), b = Ellipse::circle(10, 0, 5), c = Ellipse::circle(20, 1, 1);
        INFO(ell({&a, &b, &c}));
        check_count_all_orders(a, b, c, VoronoiCircles::none);
        CHECK(circle_vertex_conflict(a, b, c, Ellipse::circle(10, 30, 1)) == -1);
        CHECK_THROWS_AS(CircleVoronoiVertex(a, b, c).radius(), Error);
    }
    SECTION("both: the middle circle small") {
        const Ellipse a = Ellipse::circle(0, 0, 3), b = Ellipse::circle(10, 1, 1), c = Ellipse::circle(20, 0, 3);
        INFO(ell({&a, &b, &c}));
        check_count_all_orders(a, b, c, VoronoiCircles::both);
    }
}

TEST_CASE("circle predicates reject what they cannot answer", "[circle-predicates]") {
    const Ellipse a = Ellipse::circle(0, 0, 1), b = Ellipse::circle(5, 0, 1), c = Ellipse::circle(0, 5, 1);
    const Ellipse ellipse(Rational(2), Rational(1), Rational(0), Rational(10), Rational(10));
    CHECK_THROWS_AS(CircleVoronoiVertex(a, b, ellipse), Error);
    CHECK_THROWS_AS(circle_vertex_conflict(a, b, c, ellipse), Error);
    CHECK_THROWS_AS(circle_infinite_vertex_conflict(a, ellipse, c), Error);
    CHECK_THROWS_AS(circle_voronoi_circle_count(ellipse, b, c), Error);
    // A site inside another (the powers p_i <= 0).
    const Ellipse inner = Ellipse::circle(Rational(1, 2UL), 0, Rational(1, 4UL));
    CHECK_THROWS_AS(CircleVoronoiVertex(a, inner, c), Error);
    CHECK_THROWS_AS(circle_voronoi_circle_count(b, a, inner), Error);  // p_23 <= 0
    CHECK_THROWS_AS(circle_infinite_vertex_conflict(a, inner, c), Error);
    // Order: a vertex that does not exist, or whose triple lacks a site of the bisector.
    const CircleVoronoiVertex v(a, b, c), reversed(a, c, b);
    REQUIRE(v.exists());
    REQUIRE(!reversed.exists());
    CHECK_THROWS_AS(circle_order_on_bisector(a, b, v, reversed), Error);
    CHECK_THROWS_AS(circle_order_on_bisector(a, Ellipse::circle(-9, -9, 1), v, v), Error);
    CHECK(circle_order_on_bisector(a, b, v, v) == 0);
    // The bisector's sites are matched by value, not only by address.
    CHECK(circle_order_on_bisector(Ellipse::circle(0, 0, 1), Ellipse::circle(5, 0, 1), v, v) == 0);
}
