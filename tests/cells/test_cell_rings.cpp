// The cells' rings (cells/voronoi_edge_cover.hpp) against independent
// computations: every ring vertex is within the boundary tolerance D of the
// cell's boundary, by the signed distances of the MPFR oracle
// (tests/support/signed_distance_oracle.hpp: none of ellvor's solvers), and
// every Voronoi vertex of the cell is within D of a ring vertex.
#include "cells/cell_tessellation.hpp"
#include "sites/site_generators.hpp"
#include "tests/support/signed_distance_oracle.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace ellvor;

namespace {

// A point within D/2 of the boundary of p's cell (a point where p ties with
// its nearest other site, signed distances 1-Lipschitz) has
// |min over q != p of delta(x, q) - delta(x, p)| <= D; check it in MPFR.
void check_ring(const std::vector<Ellipse>& sites, const CellTessellation& t, const Cell& c) {
    std::vector<test::OracleEllipse> oracle;
    for (const Ellipse& e : sites) oracle.emplace_back(e);
    const double D = t.boundary_tolerance;
    // The ring's vertices and points along its segments (a segment may be a
    // long chord of the second-order cover: it must stay near the boundary too).
    // (At most about 150 segments a cell, evenly spread: the oracle is slow.)
    const std::size_t stride = std::max<std::size_t>(1, c.ring.size() / 150);
    for (std::size_t k = 0; k < c.ring.size(); k += stride) {
        const auto &a = c.ring[k], &b = c.ring[(k + 1) % c.ring.size()];
        for (double f : {0.0, 0.5}) {
            const double vx = a[0] + f * (b[0] - a[0]), vy = a[1] + f * (b[1] - a[1]);
            const test::RealPoint x{test::Real(vx), test::Real(vy)};
            const test::Real own = oracle[c.site].signed_distance_value(x);
            test::Real nearest(INFINITY);
            for (std::size_t q = 0; q < sites.size(); ++q)
                if (q != c.site) {
                    const test::Real d = oracle[q].signed_distance_value(x);
                    if (d < nearest) nearest = d;
                }
            INFO("site " << c.site << " ring point (" << vx << ", " << vy << ")");
            CHECK(std::fabs((nearest - own).to_double()) <= D);
        }
    }
    // Every vertex of the cell is near the ring (the other half of the Hausdorff bound, at the vertices).
    for (const CellSide& s : c.sides) {
        const CellVertex& w = t.vertices.at(static_cast<std::size_t>(s.from));
        double best = INFINITY;
        for (const auto& v : c.ring) best = std::min(best, std::hypot(v[0] - w.x.mid_double(), v[1] - w.y.mid_double()));
        CHECK(best <= D);
    }
}

}  // namespace

TEST_CASE("cell rings lie within the boundary tolerance of the cells", "[cells]") {
    GeneratorOptions g;
    g.kind = GENERATE(SiteKind::circles, SiteKind::ellipses);
    g.count = 8;
    g.seed = 11;
    const std::vector<Ellipse> sites = generate_sites(g);
    CellOptions o;
    // 1e-6 on sites some 10 wide about 100 from the origin: the covers ask the
    // vertices to more bits than the circles certified in doubles hold.
    o.boundary_tolerance = GENERATE(0.1, 1e-6);
    const CellTessellation t = cell_tessellation(sites, CellDomain{}, o);
    CHECK(t.boundary_tolerance == o.boundary_tolerance);
    long bounded = 0;
    for (const Cell& c : t.cells) {
        if (!c.bounded) {
            CHECK(c.ring.empty());
            continue;
        }
        ++bounded;
        REQUIRE(c.ring.size() >= 3);
        check_ring(sites, t, c);
        // Neighbours' rings have the same points along their common edge (its
        // polyline is made once): at least its two ends, the same doubles,
        // in one run of the ring (a point of the edge in one ring only would
        // split the run).
        for (const CellSide& side : c.sides) {
            if (side.neighbor < 0 || side.from < 0 || side.to < 0) continue;
            const Cell& n = t.cells.at(static_cast<std::size_t>(side.neighbor));
            if (!n.bounded) continue;
            const std::size_t m = c.ring.size();
            std::vector<char> shared(m);
            for (std::size_t i = 0; i < m; ++i)
                shared[i] = std::find(n.ring.begin(), n.ring.end(), c.ring[i]) != n.ring.end();
            long runs = 0;
            for (std::size_t i = 0; i < m; ++i) runs += shared[i] && !shared[(i + 1) % m];
            CHECK(std::count(shared.begin(), shared.end(), 1) >= 2);
            CHECK(runs == 1);
        }
    }
    CHECK(bounded >= 1);
}

TEST_CASE("cells of some sites (only) are their cells among all and their reach bounds them", "[cells]") {
    GeneratorOptions g;
    g.kind = SiteKind::ellipses;
    g.count = 10;
    g.seed = 5;
    const std::vector<Ellipse> sites = generate_sites(g);
    CellDomain box;
    box.kind = GENERATE(CellDomain::Kind::plane, CellDomain::Kind::box);
    if (box.kind == CellDomain::Kind::box) {
        box.x0 = Rational(-200), box.y0 = Rational(-200), box.x1 = Rational(200), box.y1 = Rational(200);
    }
    CellOptions all;
    all.boundary_tolerance = 0.25;
    const CellTessellation whole = cell_tessellation(sites, box, all);
    CellOptions some;
    some.rings = false;
    // The reach from the areas' quadrature, or (Arb's integrator gives none)
    // from covers of the edges.
    some.arb_integrator_only = GENERATE(false, true);
    // In doubles, or (past 44 bits) the same pieces with the nodes in Arb.
    some.tolerance = GENERATE(1e-9, 1e-15);
    some.boundary_tolerance = 0.5;
    some.only = {2, 7};
    const CellTessellation part = cell_tessellation(sites, box, some);
    long bounded = 0;
    for (SiteId s = 0; s < sites.size(); ++s) {
        const Cell &w = whole.cells[s], &p = part.cells[s];
        CHECK(p.site == s);
        if (s != 2 && s != 7) {  // not asked for: left empty
            CHECK_FALSE(p.visible);
            CHECK(p.sides.empty());
            CHECK(std::isinf(p.reach));
            continue;
        }
        CHECK(p.visible == w.visible);
        CHECK(p.bounded == w.bounded);
        REQUIRE(p.sides.size() == w.sides.size());
        for (std::size_t k = 0; k < p.sides.size(); ++k) {
            CHECK(p.sides[k].neighbor == w.sides[k].neighbor);
            CHECK(p.sides[k].wall == w.sides[k].wall);
            // The vertex is named by its face, which holds the cell's own site.
            const CellVertex& v = part.vertices.at(static_cast<std::size_t>(p.sides[k].from));
            CHECK(std::count_if(v.face.begin(), v.face.end(), [&](const CellSiteImage& f) {
                      return f.site == static_cast<long>(s) && f.wall == Wall::none;
                  }) == 1);
        }
        if (!w.bounded) {
            CHECK(std::isinf(p.reach));
            continue;
        }
        ++bounded;
        CHECK(arb_overlaps(p.area.get(), w.area.get()));
        // The ring (within 0.25 of the boundary) against the reach (covers within 0.5).
        double far = 0;
        for (const auto& x : w.ring)
            far = std::max(far, std::hypot(x[0] - sites[s].xc().to_double(), x[1] - sites[s].yc().to_double()));
        CHECK(p.reach >= far - 0.25 - 1e-9);
        CHECK((p.edges_by_arb > 0) == some.arb_integrator_only);
        CHECK((p.edges_in_doubles + p.edges_by_nodes_in_arb > 0) == !some.arb_integrator_only);
        CHECK((p.edges_by_nodes_in_arb == 0 || some.tolerance < 1e-12));
        if (some.arb_integrator_only)
            CHECK(p.reach <= far + 0.25 + 0.5 + 1e-9);  // the polyline's points and the cover radius
        else  // the pieces' models over these few huge cells: their second-order terms, 3-5%
            CHECK(p.reach <= 1.06 * (far + 0.25));
    }
    CHECK(bounded >= 1);
}

TEST_CASE("cell rings and areas: threads do not change them; rings across chunks hold too", "[cells]") {
    GeneratorOptions g;
    g.count = 60;
    g.seed = 5;
    const std::vector<Ellipse> sites = generate_sites(g);
    const auto tessellation = [&](unsigned threads) {
        CellOptions o;
        o.boundary_tolerance = 0.5;
        o.threads = threads;
        o.chunk = 8;  // several chunks: edges shared within them, covered twice across
        return cell_tessellation(sites, CellDomain{}, o);
    };
    const CellTessellation one = tessellation(1), three = tessellation(3);
    std::size_t bounded = 0;
    for (std::size_t s = 0; s < sites.size(); ++s) {
        const Cell &a = one.cells[s], &b = three.cells[s];
        CHECK(a.ring == b.ring);
        CHECK(a.reach == b.reach);
        CHECK(arb_equal(a.area.get(), b.area.get()));
        // The rings of some cells against the oracle (slow: not all).
        if (a.bounded && bounded++ % 8 == 0) check_ring(sites, one, a);
    }
    CHECK(bounded >= 30);
}
