// Vertex angles and vertices (cells/cell_vertex_angles.hpp): at low
// precision from the circles certified in doubles, beyond from Arb's solver. On random and
// nested ellipses, every face and each of its sites: the two balls overlap,
// each is as accurate as promised (radius at most 2^(24 - prec) for the
// first), and lifting a cell's angles works at both precisions.
#include "cells/cell_vertex_angles.hpp"
#include "cells/face_numbers.hpp"
#include "cells/voronoi_cells.hpp"
#include "sites/site_generators.hpp"
#include "tests/support/ellipse_graph.hpp"

#include <catch2/catch.hpp>

using namespace ellvor;

TEST_CASE("vertex angles: the doubles' and Arb's balls overlap, each as accurate as asked", "[cells]") {
    GeneratorOptions o;
    o.count = 40;
    o.seed = GENERATE(1, 2, 3);
    o.nested_fraction = Rational(1, 5);
    const std::vector<Ellipse> sites = generate_sites(o);
    DelaunayGraph graph = test::ellipse_graph(sites);
    graph.insert_all();
    const std::vector<std::array<SiteId, 3>> faces = graph.faces();
    CellVertexAngles coarse(graph, sites), fine(graph, sites);
    constexpr long kCoarse = 24 + 42, kFine = 24 + 100;
    for (std::size_t f = 0; f < faces.size(); ++f)
        for (SiteId s : faces[f]) {
            const Ball a = coarse.angle(static_cast<long>(f), s, kCoarse), b = fine.angle(static_cast<long>(f), s, kFine);
            INFO("face " << f << " site " << s << ": " << a.str(20) << " and " << b.str(40));
            CHECK(arb_overlaps(a.get(), b.get()));
            CHECK(mag_cmp_2exp_si(arb_radref(a.get()), -42) <= 0);
            CHECK(mag_cmp_2exp_si(arb_radref(b.get()), -90) <= 0);
        }
    const std::vector<VoronoiCell> cells = voronoi_cells(graph, face_numbers(graph));
    int lifted = 0;
    for (const VoronoiCell& c : cells)
        if (c.visible && c.bounded()) {
            const std::vector<Ball> x = coarse.lifted(c, kCoarse), y = fine.lifted(c, kFine);
            REQUIRE(x.size() == y.size());
            for (std::size_t k = 0; k < x.size(); ++k) CHECK(arb_overlaps(x[k].get(), y[k].get()));
            ++lifted;
        }
    CHECK(lifted > 5);
    // The vertices (Voronoi circles' centers) likewise, with that many correct bits.
    for (std::size_t f = 0; f < faces.size(); ++f) {
        const BallPoint a = coarse.vertex(static_cast<long>(f), kCoarse), b = fine.vertex(static_cast<long>(f), kFine);
        INFO("face " << f << ": " << a.x.str(20) << ", " << a.y.str(20) << " and " << b.x.str(40) << ", " << b.y.str(40));
        CHECK(arb_overlaps(a.x.get(), b.x.get()));
        CHECK(arb_overlaps(a.y.get(), b.y.get()));
        CHECK(arb_rel_accuracy_bits(a.x.get()) >= 42);
        CHECK(arb_rel_accuracy_bits(a.y.get()) >= 42);
        CHECK(arb_rel_accuracy_bits(b.x.get()) >= 100);
        CHECK(arb_rel_accuracy_bits(b.y.get()) >= 100);
    }
    // Which stage answered: the doubles nearly always at 42 bits, never at 100.
    CHECK(coarse.angles_from_doubles() > 3 * static_cast<long>(faces.size()) * 9 / 10);
    CHECK(fine.angles_from_doubles() == 0);
    CHECK(coarse.vertices_from_doubles() > static_cast<long>(faces.size()) * 8 / 10);
    CHECK(fine.vertices_from_doubles() == 0);
}

TEST_CASE("vertex angles: from the doubles on a dense set far from the origin (the 6 x 6 test's narrow tangency)", "[cells]") {
    // 2000 ellipses with centers in [80, 120]^2: circles about the sites'
    // size, coordinates a hundred times it. The build's certificate by
    // distances gives tangency parameters too wide for 42 bits here (none
    // of the angles); the cells ask for the 6 x 6 test's
    // (DoubleCertificate::tritangent_only), which gives 71% of them.
    GeneratorOptions o;
    o.count = 2000;
    o.seed = 7;
    o.box = Rational(20);
    std::vector<Ellipse> sites;
    for (const Ellipse& e : generate_sites(o)) sites.emplace_back(e.a(), e.b(), e.w(), e.xc() + 100, e.yc() + 100);
    DelaunayGraph graph = test::ellipse_graph(sites);
    graph.insert_all();
    const std::vector<std::array<SiteId, 3>> faces = graph.faces();
    CellVertexAngles angles(graph, sites);
    constexpr long kCoarse = 24 + 42;
    for (std::size_t f = 0; f < faces.size(); ++f)
        for (SiteId s : faces[f]) CHECK(mag_cmp_2exp_si(arb_radref(angles.angle(static_cast<long>(f), s, kCoarse).get()), -42) <= 0);
    INFO(angles.angles_from_doubles() << " of " << 3 * faces.size() << " angles from the doubles");
    CHECK(angles.angles_from_doubles() >= 3 * static_cast<long>(faces.size()) * 2 / 3);
}
