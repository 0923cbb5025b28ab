// Scale and translation invariance: every predicate answers the same on a set
// of sites and on its image under x -> s x + t, for translations by 10^+-30
// and scalings by 10^+-100 (exact rationals, not powers of two); whole graphs
// are the same too. (The time per decision of the transformed sets is
// measured by experiments/near_degenerate.cpp.)
#include "predicates/edge_conflict.hpp"
#include "predicates/incircle.hpp"
#include "predicates/infinite_vertex_conflict.hpp"
#include "predicates/relative_position.hpp"
#include "predicates/side_of_bisector.hpp"
#include "predicates/voronoi_circle_count.hpp"
#include "sites/site_generators.hpp"
#include "tests/support/ellipse_graph.hpp"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

using namespace ellvor;

namespace {


struct Similarity {
    std::string name;
    Rational scale, shift;
    Ellipse operator()(const Ellipse& e) const {
        return Ellipse(e.a() * scale, e.b() * scale, e.w(), e.xc() * scale + shift, e.yc() * scale - shift);
    }
    Point operator()(const Point& p) const { return {p.x * scale + shift, p.y * scale - shift}; }
};

std::vector<Similarity> similarities() {
    return {{"translated by 10^30", Rational(1), power_of_ten(30)},
            {"translated by 10^-30", Rational(1), power_of_ten(-30)},
            {"scaled by 10^100", power_of_ten(100), Rational(0)},
            {"scaled by 10^-100", power_of_ten(-100), Rational(0)}};
}

std::vector<Ellipse> mapped(const Similarity& f, const std::vector<Ellipse>& sites) {
    std::vector<Ellipse> out;
    for (const Ellipse& e : sites) out.push_back(f(e));
    return out;
}

std::string ell(const std::vector<Ellipse>& sites) {
    std::string s = "\n# .ell\n";
    for (const Ellipse& e : sites) s += e.str() + "\n";
    return s;
}

// Every predicate on four sites e[0..3]; the answers as one string.
std::string answers(const std::vector<Ellipse>& e) {
    std::string s;
    auto add = [&](const std::string& label, int v) { s += label + "=" + std::to_string(v) + " "; };
    add("relpos", static_cast<int>(*relative_position(e[0], e[3])));
    add("k1", to_int(*side_of_bisector(e[0], e[1], e[3].center())));
    add("k2", to_int(*infinite_vertex_conflict(e[0], e[1], e[3])));
    add("k2r", to_int(*infinite_vertex_conflict(e[1], e[0], e[3])));
    add("count", static_cast<int>(*voronoi_circle_count(e[0], e[1], e[2])));
    add("k3", static_cast<int>(*incircle(e[0], e[1], e[2], e[3])));
    add("k3r", static_cast<int>(*incircle(e[0], e[2], e[1], e[3])));
    for (bool b : {false, true}) add(b ? "k4b" : "k4", *finite_edge_interior_conflict(e[0], e[1], e[2], e[3], b));
    return s;
}

}  // namespace

TEST_CASE("invariance: every predicate answers the same on translated and scaled quadruples",
          "[predicates][invariance]") {
    int compared = 0;
    for (SiteKind kind : {SiteKind::ellipses, SiteKind::circles}) {
        for (std::uint64_t seed = 1; seed <= 30; ++seed) {
            GeneratorOptions o;
            o.kind = kind;
            o.count = 4;
            o.seed = 7000 + seed;
            o.box = Rational(12);
            const std::vector<Ellipse> sites = generate_sites(o);
            const std::string want = answers(sites);
            for (const Similarity& f : similarities()) {
                const std::vector<Ellipse> image = mapped(f, sites);
                INFO(f.name << ell(sites));
                CHECK(answers(image) == want);
                ++compared;
            }
        }
    }
    CHECK(compared == 240);
}

TEST_CASE("invariance: graphs of translated and scaled sets are the same", "[graph][invariance]") {
    for (SiteKind kind : {SiteKind::ellipses, SiteKind::circles}) {
        GeneratorOptions o;
        o.kind = kind;
        o.count = 40;
        o.seed = 99;
        o.nested_fraction = Rational(1, 8UL);
        const std::vector<Ellipse> sites = generate_sites(o);
        DelaunayGraph reference = test::ellipse_graph(sites);
        reference.insert_all();
        REQUIRE(reference.validate() == "");
        for (const Similarity& f : similarities()) {
            INFO(f.name);
            DelaunayGraph g = test::ellipse_graph(mapped(f, sites));
            g.insert_all();
            CHECK(g.validate() == "");
            CHECK(g.edges() == reference.edges());
            CHECK(g.faces() == reference.faces());
            CHECK(g.hull() == reference.hull());
            CHECK(g.hidden() == reference.hidden());
        }
    }
}
