// Cells in a box (walls) and in a periodic box (the torus): the area
// identity (sum of lo <= box area <= sum of hi) on random ellipses, nested
// sets, circles, a dense packing and a degenerate grid; periodic sets
// invariant under a translation; the exact mirrors; bad input.
#include "cells/box_mirrors.hpp"
#include "cells/cell_tessellation.hpp"
#include "cells/periodic_copies.hpp"
#include "predicates/relative_position.hpp"
#include "sites/packing_generator.hpp"
#include "sites/site_generators.hpp"
#include "tests/support/random_sites.hpp"
#include "util/error.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

using namespace ellvor;

namespace {

CellDomain rectangle(CellDomain::Kind kind, const Rational& x0, const Rational& y0, const Rational& x1, const Rational& y1) {
    CellDomain d;
    d.kind = kind;
    d.x0 = x0;
    d.y0 = y0;
    d.x1 = x1;
    d.y1 = y1;
    return d;
}

// Sum of lo <= (x1 - x0)(y1 - y0) <= sum of hi, exactly (Arb's endpoints are dyadic).
void check_area_identity(const CellTessellation& t, double tolerance) {
    Ball sum;
    for (const Cell& c : t.cells) {
        INFO("site " << c.site << " area " << c.area.str(20));
        REQUIRE(arb_is_finite(c.area.get()));
        if (c.visible) {
            CHECK(c.bounded);
            CHECK(2 * c.area.radius_double() <= tolerance * (c.area.mid_double() - c.area.radius_double()));
            CHECK(!c.ring.empty());
        }
        arb_add(sum.get(), sum.get(), c.area.get(), 256);
    }
    const Rational box = (t.domain.x1 - t.domain.x0) * (t.domain.y1 - t.domain.y0);
    INFO("sum " << sum.str(30) << " box " << box.str());
    CHECK(sum.contains(box));
}

std::vector<Ellipse> random_ellipses(std::uint64_t seed, long count, Rational nested = Rational(0),
                                     Rational box = Rational(100)) {
    GeneratorOptions o;
    o.count = count;
    o.seed = seed;
    o.box = box;
    o.nested_fraction = nested;
    return generate_sites(o);
}

}  // namespace

TEST_CASE("box mirrors are exact reflections of the conic", "[cells]") {
    const Ellipse e(Rational(3), Rational(1, 3), Rational(2, 7), Rational(5, 2), Rational(-1, 4));
    const CellDomain box = rectangle(CellDomain::Kind::box, Rational(-4), Rational(-3), Rational(9), Rational(11, 2));
    for (Wall w : {Wall::left, Wall::bottom, Wall::right, Wall::top}) {
        const Ellipse m = mirror_across(e, wall_line(w, box));
        const bool vertical = w == Wall::left || w == Wall::right;
        const Rational c = wall_line(w, box).c;
        // A x^2 + 2B xy + C y^2 + 2D x + 2E y + F with x -> 2c - x (or y -> 2c - y).
        const auto& q = e.conic();
        std::array<Rational, 6> r;
        if (vertical) {
            r = {q[0], -q[1], q[2], Rational(-1) * (q[3] + Rational(2) * c * q[0]), q[4] + Rational(2) * c * q[1],
                 q[5] + Rational(4) * c * c * q[0] + Rational(4) * c * q[3]};
        } else {
            r = {q[0], -q[1], q[2], q[3] + Rational(2) * c * q[1], Rational(-1) * (q[4] + Rational(2) * c * q[2]),
                 q[5] + Rational(4) * c * c * q[2] + Rational(4) * c * q[4]};
        }
        INFO(wall_name(w));
        for (int k = 0; k < 6; ++k) CHECK(m.conic()[k] == r[k]);
        // And reflecting twice gives the site back.
        CHECK(mirror_across(m, wall_line(w, box)) == e);
        const std::optional<AxisLine> line = mirror_line(e, m);
        REQUIRE(line);
        CHECK(line->vertical == vertical);
        CHECK(line->c == c);
    }
}

TEST_CASE("cells in a box: random ellipses add up to the box area", "[cells]") {
    const std::uint64_t seed = GENERATE(1, 2);
    const std::vector<Ellipse> sites = random_ellipses(seed, 8);
    const CellDomain box = rectangle(CellDomain::Kind::box, Rational(-130), Rational(-120), Rational(125), Rational(135));
    CellOptions o;
    o.boundary_tolerance = 1;  // rings cost about perimeter / tolerance certificates
    const CellTessellation t = cell_tessellation(sites, box, o);
    check_area_identity(t, o.tolerance);
    // Walls appear, each side's neighbour is a site or a wall, never both.
    long walls = 0;
    for (const Cell& c : t.cells)
        for (const CellSide& s : c.sides) {
            CHECK((s.neighbor >= 0) == (s.wall == Wall::none));
            CHECK(s.neighbor < static_cast<long>(sites.size()));
            walls += s.wall != Wall::none;
        }
    CHECK(walls >= 4);
}

TEST_CASE("cells in a box: sites in a corner reach the walls they were not mirrored across", "[cells]") {
    // Mirrors are first made across the walls within four times the even
    // spacing (here about 300) of a site: none across the right and top
    // walls, 400 away, which the cluster's outer cells reach (unbounded
    // without them, or a reach beyond the wall). Those sites get all four
    // mirrors and the cells are made again; the identity proves the result.
    std::vector<Ellipse> sites = random_ellipses(3, 30, Rational(0), Rational(10));
    const CellDomain box = rectangle(CellDomain::Kind::box, Rational(-20), Rational(-20), Rational(400), Rational(400));
    CellOptions o;
    o.boundary_tolerance = 4;
    const CellTessellation t = cell_tessellation(sites, box, o);
    check_area_identity(t, o.tolerance);
    CHECK(t.attempts >= 2);
    long right_or_top = 0;
    for (const Cell& c : t.cells)
        for (const CellSide& side : c.sides) right_or_top += side.wall == Wall::right || side.wall == Wall::top;
    CHECK(right_or_top >= 2);
    // The cells of a few of them alone (the neighbourhood's diagram) are the same.
    CellOptions some = o;
    some.only = {0, 7, 19};
    const CellTessellation u = cell_tessellation(sites, box, some);
    for (SiteId s : some.only) CHECK(arb_overlaps(u.cells[s].area.get(), t.cells[s].area.get()));
}

TEST_CASE("cells in a box: a bounded cell past a wall its site was not mirrored across", "[cells]") {
    // 196 circles in a grid on the left (mirrors within 4 * 100 / sqrt(199)
    // = 28.4 of a wall), one circle 34 from the right wall between two near
    // its corners, 90 apart: its cell reaches the wall between them and past
    // it, bounded there by their mirrors. Its proven reach is then not below
    // the wall's distance: it gets its mirrors, and the cells are made again.
    std::vector<Ellipse> sites;
    for (long i = 0; i < 14; ++i)
        for (long j = 0; j < 14; ++j)
            sites.push_back(Ellipse::circle(Rational(4 + 7 * i, 2), Rational(7 + 14 * j, 2), Rational(1)));
    for (long y : {5L, 95L}) sites.push_back(Ellipse::circle(Rational(95), Rational(y), Rational(1)));
    sites.push_back(Ellipse::circle(Rational(66), Rational(50), Rational(1)));
    const CellDomain box = rectangle(CellDomain::Kind::box, Rational(0), Rational(0), Rational(100), Rational(100));
    CellOptions o;
    o.boundary_tolerance = 4;
    const CellTessellation t = cell_tessellation(sites, box, o);
    check_area_identity(t, o.tolerance);
    CHECK(t.attempts == 2);
    // The second try measured only the cells the first did not prove: the
    // lone one (and no more than a few), the rest kept.
    INFO("cells measured " << t.cells_measured);
    CHECK(t.cells_measured > sites.size());
    CHECK(t.cells_measured <= sites.size() + 3);
    const Cell& lone = t.cells.back();
    CHECK(std::count_if(lone.sides.begin(), lone.sides.end(), [](const CellSide& side) { return side.wall == Wall::right; }) == 1);
}

namespace {

std::vector<Ellipse> shifted_sites(const std::vector<Ellipse>& sites, const Rational& dx, const Rational& dy) {
    std::vector<Ellipse> out;
    for (const Ellipse& e : sites) out.emplace_back(e.a(), e.b(), e.w(), e.xc() + dx, e.yc() + dy);
    return out;
}

// The distance from q to the closed polyline `ring`, in long double.
long double distance_to_ring(const std::array<double, 2>& q, const std::vector<std::array<double, 2>>& ring) {
    long double best = INFINITY;
    for (std::size_t k = 0; k < ring.size(); ++k) {
        const auto &a = ring[k], &b = ring[(k + 1) % ring.size()];
        const long double ux = b[0] - a[0], uy = b[1] - a[1], wx = q[0] - a[0], wy = q[1] - a[1];
        const long double len2 = ux * ux + uy * uy;
        const long double t = len2 > 0 ? std::clamp((wx * ux + wy * uy) / len2, 0.0L, 1.0L) : 0.0L;
        best = std::min(best, std::hypot(wx - t * ux, wy - t * uy));
    }
    return best;
}

}  // namespace

TEST_CASE("cells far from the origin: the cells at the origin, moved, in doubles", "[cells]") {
    // Sites of size about 1 near 10^9: the double stages would lose 30 bits
    // there; the cells are computed about the box's middle and moved back.
    const std::vector<Ellipse> sites = random_ellipses(6, 7);
    const Rational dx = Rational(1000000000) + Rational(1, 7), dy(-300000000);
    CellOptions o;
    o.boundary_tolerance = 1;
    const CellTessellation near =
        cell_tessellation(sites, rectangle(CellDomain::Kind::box, Rational(-130), Rational(-120), Rational(125), Rational(135)), o);
    const CellDomain far_box =
        rectangle(CellDomain::Kind::box, Rational(-130) + dx, Rational(-120) + dy, Rational(125) + dx, Rational(135) + dy);
    const CellTessellation far = cell_tessellation(shifted_sites(sites, dx, dy), far_box, o);
    CHECK(far.domain.x0 == far_box.x0);
    check_area_identity(far, o.tolerance);
    std::size_t in_doubles = 0, by_arb = 0;
    for (std::size_t i = 0; i < sites.size(); ++i) {
        const Cell &a = near.cells[i], &b = far.cells[i];
        INFO("site " << i);
        REQUIRE(a.sides.size() == b.sides.size());
        for (std::size_t k = 0; k < a.sides.size(); ++k) CHECK(a.sides[k].neighbor == b.sides[k].neighbor);
        CHECK(arb_overlaps(a.area.get(), b.area.get()));
        CHECK(arb_overlaps(a.perimeter.get(), b.perimeter.get()));
        for (int k = 0; k < 3; ++k) CHECK(arb_overlaps(a.second_moments[k].get(), b.second_moments[k].get()));
        const Rational shift[2] = {dx, dy};
        for (int k = 0; k < 2; ++k) {
            Ball moved;
            arb_sub(moved.get(), b.centroid[k].get(), Ball(shift[k], 256).get(), 256);
            CHECK(arb_overlaps(moved.get(), a.centroid[k].get()));
        }
        // Both rings within the boundary tolerance of the one boundary.
        for (const auto& q : b.ring) {
            const std::array<double, 2> back = {static_cast<double>(q[0] - 1000000000.0L - 1.0L / 7),
                                                static_cast<double>(q[1] + 300000000.0L)};
            CHECK(distance_to_ring(back, a.ring) <= 2 * o.boundary_tolerance + 1e-6);
        }
        in_doubles += b.edges_in_doubles;
        by_arb += b.edges_by_arb + b.edges_by_nodes_in_arb;
    }
    CHECK(in_doubles > 0);
    CHECK(by_arb == 0);
    // Ring points near 10^15 are doubles 2^-52 * 10^15 (about 0.2) apart:
    // not within a boundary tolerance of 0.1 (an input error with a box).
    const Rational huge(1000000000000000L);
    const CellDomain huge_box =
        rectangle(CellDomain::Kind::box, Rational(-130) + huge, Rational(-120), Rational(125) + huge, Rational(135));
    o.boundary_tolerance = 0.1;
    CHECK_THROWS_AS(cell_tessellation(shifted_sites(sites, huge, Rational(0)), huge_box, o), InputError);
    CHECK_THROWS_WITH(cell_tessellation(shifted_sites(sites, huge, Rational(0)), huge_box, o),
                      Catch::Contains("the boundary tolerance 0.1 is finer than doubles can hold"));
    // The plane has no box to tell beforehand: the ring points are checked.
    CHECK_THROWS_WITH(cell_tessellation(shifted_sites(sites, huge, Rational(0)), CellDomain{}, o),
                      Catch::Contains("cannot be held in doubles within the boundary tolerance 0.1"));
    o.boundary_tolerance = 1;
    CHECK_NOTHROW(cell_tessellation(shifted_sites(sites, huge, Rational(0)), huge_box, o));
}

TEST_CASE("cells in a periodic box: random ellipses add up to the box area", "[cells]") {
    const std::vector<Ellipse> sites = random_ellipses(3, 7);
    const CellDomain torus = rectangle(CellDomain::Kind::periodic, Rational(-100), Rational(-100), Rational(100), Rational(100));
    CellOptions o;
    o.boundary_tolerance = 1;
    const CellTessellation t = cell_tessellation(sites, torus, o);
    check_area_identity(t, o.tolerance);
    for (const Cell& c : t.cells)
        for (const CellSide& s : c.sides) {
            CHECK(s.wall == Wall::none);
            CHECK(s.neighbor >= 0);
        }
}

TEST_CASE("cells in a box: nested sites and circles add up to the box area", "[cells]") {
    CellOptions o;
    o.boundary_tolerance = 1;
    SECTION("nested ellipses: the hidden sites have area 0") {
        const std::vector<Ellipse> sites = random_ellipses(4, 9, Rational(1, 4));
        const CellTessellation t =
            cell_tessellation(sites, rectangle(CellDomain::Kind::box, Rational(-140), Rational(-125), Rational(130), Rational(120)), o);
        check_area_identity(t, o.tolerance);
        long hidden = 0;
        for (const Cell& c : t.cells)
            if (!c.visible) {
                ++hidden;
                CHECK(arb_is_zero(c.area.get()));
            }
        CHECK(hidden >= 1);
    }
    SECTION("circles of several radii at 1e-15") {
        o.tolerance = 1e-15;
        GeneratorOptions g;
        g.kind = SiteKind::circles;
        g.count = 8;
        g.seed = 5;
        const CellTessellation t = cell_tessellation(
            generate_sites(g), rectangle(CellDomain::Kind::box, Rational(-130), Rational(-130), Rational(130), Rational(130)), o);
        check_area_identity(t, o.tolerance);
    }
}

TEST_CASE("cells in a box: a dense packing adds up to the box area", "[cells]") {
    PackingOptions p;
    p.count = 30;  // the generator's smallest
    p.fraction = Rational(11, 20);
    p.seed = 2;
    const Packing packing = generate_packing(p);
    CellOptions o;
    o.boundary_tolerance = 1;
    // The left third of the packing's box, with the sites strictly inside it
    // (about 10: cells cost a fraction of a second each).
    const CellDomain box = rectangle(CellDomain::Kind::box, Rational(0), Rational(0), Rational(packing.box_side, 3), Rational(packing.box_side));
    std::vector<Ellipse> sites;
    for (const Ellipse& e : packing.sites)
        if (e.xc() < box.x1 && strictly_beside(e, wall_line(Wall::right, box))) sites.push_back(e);
    REQUIRE(sites.size() >= 6);
    const CellTessellation t = cell_tessellation(sites, box, o);
    check_area_identity(t, o.tolerance);
}

TEST_CASE("cells in a box: a packing with gaps of 10^-6, in doubles with the signed tie", "[cells]") {
    // Neighbours 10^-6 apart: with the squared tie the certified pieces
    // shrink to the gap where an edge passes between two sites (some 26,000
    // a cell, seconds each; before the 2^18 budget, minutes a cell by Arb).
    // With the signed tie of close pairs (NormalRayBisector::uses_signed_tie)
    // a few hundred.
    PackingOptions p;
    p.count = 30;
    p.fraction = Rational(29, 50);
    p.gap = Rational(1, 1000000);
    p.seed = 3;
    const Packing packing = generate_packing(p);
    CellOptions o;
    o.rings = false;
    const CellDomain box =
        rectangle(CellDomain::Kind::box, Rational(0), Rational(0), Rational(packing.box_side), Rational(packing.box_side));
    const CellTessellation t = cell_tessellation(packing.sites, box, o);
    Ball sum;
    for (const Cell& c : t.cells) {
        INFO("site " << c.site << " area " << c.area.str(20) << " pieces " << c.quadrature.pieces);
        REQUIRE(c.bounded);
        CHECK(2 * c.area.radius_double() <= o.tolerance * (c.area.mid_double() - c.area.radius_double()));
        CHECK(c.edges_by_arb == 0);
        CHECK(c.quadrature.pieces < 3000);
        arb_add(sum.get(), sum.get(), c.area.get(), 256);
    }
    CHECK(sum.contains(Rational(packing.box_side * packing.box_side)));
}

TEST_CASE("cells in a box: a grid of equal circles has unit square cells", "[cells]") {
    // Degree-4 vertices everywhere: inside (cocircular grid points) and on the walls (mirrors).
    std::vector<Ellipse> sites;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) sites.push_back(Ellipse::circle(Rational(i), Rational(j), Rational(1, 4)));
    CellOptions o;
    o.boundary_tolerance = 0.01;
    const CellTessellation t =
        cell_tessellation(sites, rectangle(CellDomain::Kind::box, Rational(-1, 2), Rational(-1, 2), Rational(5, 2), Rational(5, 2)), o);
    check_area_identity(t, o.tolerance);
    for (const Cell& c : t.cells) {
        INFO("site " << c.site);
        CHECK(c.area.contains(Rational(1)));
        // The ring is within the tolerance of the square [i - 1/2, i + 1/2] x [j - 1/2, j + 1/2].
        const double x = sites[c.site].xc().to_double(), y = sites[c.site].yc().to_double();
        for (const auto& v : c.ring) {
            const double d = std::max(std::fabs(v[0] - x), std::fabs(v[1] - y));
            CHECK(std::fabs(d - 0.5) <= o.boundary_tolerance);
        }
        // Each square side is a neighbour or a wall: four sides.
        CHECK(c.sides.size() >= 4);
    }
}

TEST_CASE("cells in a periodic box: a translated set has the same cells", "[cells]") {
    // Six ellipses in a 120 x 100 torus; the same set moved by a random
    // rational vector, its centers taken back into the box (sites straddle
    // the boundary after the move: site 0 is put across the left edge).
    const std::vector<Ellipse> sites = random_ellipses(6, 6, Rational(0), Rational(45));
    const CellDomain torus = rectangle(CellDomain::Kind::periodic, Rational(-60), Rational(-50), Rational(60), Rational(50));
    std::mt19937_64 rng(7);
    const Rational dx = torus.x0 - sites[0].xc() + sites[0].a() * Rational(1, 3), dy = test::random_fraction(rng, -5000, 5000, 97);
    std::vector<Ellipse> moved;
    for (const Ellipse& e : sites) moved.push_back(Ellipse(e.a(), e.b(), e.w(), e.xc() + dx, e.yc() + dy));
    // Site 0 straddles the left edge of the box.
    CHECK(!strictly_beside(moved[0], wall_line(Wall::left, torus)));
    CellOptions o;
    o.boundary_tolerance = 1;
    const CellTessellation a = cell_tessellation(sites, torus, o), b = cell_tessellation(moved, torus, o);
    check_area_identity(a, o.tolerance);
    check_area_identity(b, o.tolerance);
    for (std::size_t i = 0; i < sites.size(); ++i) {
        INFO("site " << i << ": " << a.cells[i].area.str(20) << " and " << b.cells[i].area.str(20));
        CHECK(arb_overlaps(a.cells[i].area.get(), b.cells[i].area.get()));
        std::vector<long> na, nb;
        for (const CellSide& s : a.cells[i].sides) na.push_back(s.neighbor);
        for (const CellSide& s : b.cells[i].sides) nb.push_back(s.neighbor);
        std::sort(na.begin(), na.end());
        std::sort(nb.begin(), nb.end());
        CHECK(na == nb);
        CHECK(!na.empty());
    }
}

TEST_CASE("cells: bad domains and sites are input errors", "[cells]") {
    const std::vector<Ellipse> sites = {Ellipse(Rational(2), Rational(1), Rational(0), Rational(0), Rational(0)),
                                        Ellipse(Rational(1), Rational(1), Rational(0), Rational(6), Rational(1))};
    auto fails = [&](const std::vector<Ellipse>& s, const CellDomain& d, const char* says) {
        INFO(says);
        try {
            cell_tessellation(s, d);
            FAIL("no error");
        } catch (const InputError& e) {
            CHECK_THAT(e.what(), Catch::Contains(says));
        }
    };
    using K = CellDomain::Kind;
    fails(sites, rectangle(K::box, Rational(3), Rational(-5), Rational(3), Rational(5)), "XMIN < XMAX");
    fails(sites, rectangle(K::periodic, Rational(-3), Rational(5), Rational(10), Rational(-5)), "YMIN < YMAX");
    // Site 0 reaches x = -2: the box's left wall at -2 touches it; site 1's center is outside the next box.
    fails(sites, rectangle(K::box, Rational(-2), Rational(-5), Rational(10), Rational(5)), "site 0 is not strictly inside");
    fails(sites, rectangle(K::box, Rational(-5), Rational(-5), Rational(5), Rational(5)), "site 1 is not strictly inside");
    // A periodic box 3 wide: site 0 (4 wide) meets its own image.
    fails(sites, rectangle(K::periodic, Rational(-5), Rational(-5), Rational(-2), Rational(5)), "site 0 meets its own periodic image");
    CellOptions bad;
    bad.tolerance = 0;
    CHECK_THROWS_AS(cell_tessellation(sites, CellDomain{}, bad), InputError);
}

TEST_CASE("cells in a box and a periodic box: crossing and touching sites add up to the box area", "[cells]") {
    CellOptions o;
    o.boundary_tolerance = 1;
    SECTION("touching circles: rectangles, exactly") {
        // Equal circles: the cells are the centres' (docs/DESIGN.md §9); the
        // edges of touching ones pass through the point they share (s = 0 there).
        const std::vector<Ellipse> sites = {Ellipse::circle(0, 0, 1), Ellipse::circle(2, 0, 1), Ellipse::circle(5, 0, 1)};
        const CellTessellation t =
            cell_tessellation(sites, rectangle(CellDomain::Kind::box, Rational(-3), Rational(-3), Rational(8), Rational(3)), o);
        check_area_identity(t, o.tolerance);
        const long expected[3] = {24, 15, 27};
        for (int i = 0; i < 3; ++i) CHECK(t.cells[static_cast<std::size_t>(i)].area.contains(Rational(expected[i])));
    }
    SECTION("crossing ellipses, in a box and on the torus") {
        // Three fat ellipses, 0 and 1 crossing shallowly (their lens is far from both medial axes).
        const std::vector<Ellipse> sites = {Ellipse(Rational(3), Rational(2), Rational(1, 5), Rational(0), Rational(0)),
                                            Ellipse(Rational(5, 2), Rational(2), Rational(-1, 3), Rational(5), Rational(1, 2)),
                                            Ellipse(Rational(2), Rational(3, 2), Rational(0), Rational(2), Rational(4))};
        REQUIRE(*relative_position(sites[0], sites[1]) == RelativePosition::intersecting);
        for (CellDomain::Kind kind : {CellDomain::Kind::box, CellDomain::Kind::periodic}) {
            const CellTessellation t = cell_tessellation(sites, rectangle(kind, Rational(-6), Rational(-5), Rational(10), Rational(9)), o);
            check_area_identity(t, o.tolerance);
            bool neighbours = false;  // 0 and 1 are neighbours (their edge crosses both)
            for (const CellSide& s : t.cells[0].sides) neighbours = neighbours || s.neighbor == 1;
            CHECK(neighbours);
        }
    }
}

TEST_CASE("cells in a periodic box: a grid of equal circles has unit square cells", "[cells]") {
    // Cocircular copies everywhere: every vertex has degree 4. Centers given
    // outside the box are taken into it by whole periods.
    std::vector<Ellipse> sites;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 2; ++j) sites.push_back(Ellipse::circle(Rational(i + 3 * j), Rational(j - 2), Rational(1, 3)));
    CellOptions o;
    o.boundary_tolerance = 0.01;
    const CellTessellation t =
        cell_tessellation(sites, rectangle(CellDomain::Kind::periodic, Rational(-1, 2), Rational(-1, 2), Rational(5, 2), Rational(3, 2)), o);
    check_area_identity(t, o.tolerance);
    for (const Cell& c : t.cells) {
        INFO("site " << c.site);
        CHECK(c.area.contains(Rational(1)));
        // Four neighbours across the square's sides (two of them copies of one site when the box is 2 high).
        long across = 0;
        for (const CellSide& s : c.sides) across += s.shift[0] != 0 || s.shift[1] != 0;
        CHECK(c.sides.size() >= 4);
        CHECK(across >= 1);
    }
}

TEST_CASE("cells in a periodic box: two small sites in a long box (cells far larger than the sites)", "[cells]") {
    // Each cell spans the box's height and half its length: the copies must
    // reach several periods along the short side.
    const std::vector<Ellipse> sites = {Ellipse(Rational(3), Rational(1), Rational(1, 5), Rational(10), Rational(8)),
                                        Ellipse(Rational(2), Rational(2, 3), Rational(-3, 4), Rational(61), Rational(17))};
    CellOptions o;
    o.boundary_tolerance = 1;
    const CellTessellation t =
        cell_tessellation(sites, rectangle(CellDomain::Kind::periodic, Rational(0), Rational(0), Rational(100), Rational(20)), o);
    check_area_identity(t, o.tolerance);
    // Both cells meet both copies of the other across the long side.
    for (const Cell& c : t.cells) CHECK(c.sides.size() >= 2);
}

TEST_CASE("cells in a periodic box: one site near a corner needs a second ring of copies", "[cells]") {
    // Its cell reaches about 76 from its center, the first ring's missing
    // copies start 104 away: 2 * 76 > 104 - 3 + 1, so only the second ring
    // proves the cell (the whole torus: its area is the box's).
    const std::vector<Ellipse> sites = {Ellipse(Rational(3), Rational(1), Rational(1, 5), Rational(5), Rational(4))};
    CellOptions o;
    o.boundary_tolerance = 1;
    const CellTessellation t =
        cell_tessellation(sites, rectangle(CellDomain::Kind::periodic, Rational(0), Rational(0), Rational(100), Rational(100)), o);
    check_area_identity(t, o.tolerance);
    CHECK(t.attempts == 2);
    CHECK(t.cells_measured == 2);  // the first try did not prove it
    // Its neighbours are its own copies.
    for (const CellSide& s : t.cells[0].sides) {
        CHECK(s.neighbor == 0);
        CHECK((s.shift[0] != 0 || s.shift[1] != 0));
    }
}

TEST_CASE("cells in a periodic box: copies near the box first, farther where a cell reaches past them", "[cells]") {
    // 196 circles on the left half, one on the right: the copies are first
    // made within 4 * 100 / sqrt(197) + 2 = 30.5 of the box (not whole rings:
    // eight times the sites), where the lone cell, a lens some 30 from its
    // center between the cluster and its copies one period right, is not
    // proven (twice its reach is past 30.5 + 25 + 1 - 1); with the margin
    // doubled it is. The retry measures only the cells not proven.
    std::vector<Ellipse> sites;
    for (long i = 0; i < 14; ++i)
        for (long j = 0; j < 14; ++j)
            sites.push_back(Ellipse::circle(Rational(4 + 7 * i, 2), Rational(7 + 14 * j, 2), Rational(1)));
    sites.push_back(Ellipse::circle(Rational(75), Rational(50), Rational(1)));
    CellOptions o;
    o.boundary_tolerance = 4;
    const CellDomain box = rectangle(CellDomain::Kind::periodic, Rational(0), Rational(0), Rational(100), Rational(100));
    const CellTessellation t = cell_tessellation(sites, box, o);
    check_area_identity(t, o.tolerance);
    CHECK(t.attempts == 2);
    INFO("cells measured " << t.cells_measured);
    CHECK(t.cells_measured > sites.size());
    CHECK(t.cells_measured < 2 * sites.size());
    // The lone cell's neighbours: cluster circles and their copies one period right.
    long copies = 0;
    for (const CellSide& s : t.cells.back().sides) copies += s.shift[0] == 1;
    CHECK(copies >= 2);

    // The copies at a margin: exactly those with their centers within it, and
    // every other copy (brute force over two rings) no nearer any site's
    // center than distance_to_missing_copies says.
    const CopyMargin margin = {Rational(61, 2), Rational(20)};
    const PeriodicCopies c = periodic_copies(sites, box, margin);
    REQUIRE(c.sites.size() == c.original.size());
    REQUIRE(c.sites.size() == c.shift.size());
    std::size_t within = 0;
    for (long i = -2; i <= 2; ++i)
        for (long j = -2; j <= 2; ++j)
            for (SiteId s = 0; s < sites.size(); ++s) {
                if (i == 0 && j == 0) continue;
                const Rational x = sites[s].xc() + Rational(100 * i), y = sites[s].yc() + Rational(100 * j);
                const bool inside = !(x < -margin[0]) && x < Rational(100) + margin[0] && !(y < -margin[1]) &&
                                    y < Rational(100) + margin[1];
                within += inside;
                if (inside) continue;
                for (SiteId p = 0; p < sites.size(); p += 13) {
                    const double dx = (x - sites[p].xc()).to_double(), dy = (y - sites[p].yc()).to_double();
                    CHECK(std::hypot(dx, dy) >= distance_to_missing_copies(sites[p], box, margin).to_double() * (1 - 1e-12));
                }
            }
    CHECK(c.sites.size() == sites.size() + within);
    for (SiteId s = sites.size(); s < c.sites.size(); ++s) {
        const Ellipse& o = sites[c.original[s]];
        CHECK(c.sites[s].xc() == o.xc() + Rational(100 * c.shift[s][0]));
        CHECK(c.sites[s].yc() == o.yc() + Rational(100 * c.shift[s][1]));
    }
}
