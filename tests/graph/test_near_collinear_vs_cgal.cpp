// Nearly collinear circles (rows of grains, perturbed lines: offsets of
// 10^-k, k = 12 .. 40): ellvor's Delaunay graph against CGAL's
// Apollonius_graph_2 with exact rational traits (Gmpq, the ring method), which
// decides the same exact predicates with its own algebra. The Voronoi circles
// of these sets reach 10^40 times the sites' size; ellvor decides them with
// the circle closed forms, and its graph must equal CGAL's and validate.
#include "tests/support/ellipse_graph.hpp"

#include <CGAL/Apollonius_graph_2.h>
#include <CGAL/Apollonius_graph_traits_2.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>
#include <catch2/catch.hpp>

#include <algorithm>
#include <utility>
#include <vector>

using namespace ellvor;

namespace {

using Kernel = CGAL::Simple_cartesian<CGAL::Gmpq>;
using Traits = CGAL::Apollonius_graph_traits_2<Kernel, CGAL::Integral_domain_without_division_tag>;
using AG = CGAL::Apollonius_graph_2<Traits>;
using Pairs = std::vector<std::pair<SiteId, SiteId>>;

struct Graph {
    std::vector<SiteId> visible;
    Pairs hidden, edges, hull;
};


Graph cgal_graph(const std::vector<Ellipse>& sites) {
    AG ag;
    for (const Ellipse& e : sites)
        ag.insert(AG::Site_2(AG::Point_2(CGAL::Gmpq(e.xc().str()), CGAL::Gmpq(e.yc().str())), CGAL::Gmpq(e.a().str())));
    Graph g;
    auto site_id = [&](const AG::Site_2& s) {
        for (SiteId i = 0; i < sites.size(); ++i)
            if (CGAL::Gmpq(sites[i].xc().str()) == s.point().x() && CGAL::Gmpq(sites[i].yc().str()) == s.point().y() &&
                CGAL::Gmpq(sites[i].a().str()) == s.weight())
                return i;
        FAIL("a CGAL site that is not an input site");
        return SiteId(0);
    };
    for (auto v = ag.finite_vertices_begin(); v != ag.finite_vertices_end(); ++v) {
        g.visible.push_back(site_id(v->site()));
        for (auto h = v->hidden_sites_begin(); h != v->hidden_sites_end(); ++h)
            g.hidden.push_back({site_id(*h), site_id(v->site())});
    }
    for (auto e = ag.finite_edges_begin(); e != ag.finite_edges_end(); ++e) {
        const SiteId a = site_id(e->first->vertex(ellvor::ccw(e->second))->site());
        const SiteId b = site_id(e->first->vertex(ellvor::cw(e->second))->site());
        g.edges.push_back({std::min(a, b), std::max(a, b)});
    }
    for (auto f = ag.all_faces_begin(); f != ag.all_faces_end(); ++f) {
        if (!ag.is_infinite(f)) continue;
        const int k = f->index(ag.infinite_vertex());
        g.hull.push_back({site_id(f->vertex(ellvor::ccw(k))->site()), site_id(f->vertex(ellvor::cw(k))->site())});
    }
    for (auto* v : {&g.hidden, &g.edges, &g.hull}) std::sort(v->begin(), v->end());
    std::sort(g.visible.begin(), g.visible.end());
    return g;
}

// A row of n unit circles with centers C0 + 3 i d (d a unit direction with
// rational coordinates), each moved off the line by (+-1 .. 9) 10^-k along
// the normal; in two parallel rows when `rows` is 2.
std::vector<Ellipse> row(int k, int n, const Rational& dx, const Rational& dy, int rows) {
    std::vector<Ellipse> out;
    const Rational eps = power_of_ten(-k);
    for (int r = 0; r < rows; ++r)
        for (int i = 0; i < n; ++i) {
            const Rational along(3 * i), across = Rational(5 * r) + Rational(((i * 7 + r) % 9) + 1) * eps *
                                                                         Rational(i % 2 ? 1 : -1);
            out.push_back(Ellipse::circle(along * dx - across * dy, along * dy + across * dx, 1));
        }
    return out;
}

}  // namespace

TEST_CASE("nearly collinear circle rows, k = 12 .. 40: the graph equals CGAL's under exact rational traits",
          "[graph][near-collinear]") {
    for (int k : {12, 16, 20, 30, 40}) {
        for (const auto& [dx, dy] : {std::pair{Rational(1), Rational(0)}, {Rational(3, 5UL), Rational(4, 5UL)}}) {
            for (int rows : {1, 2}) {
                const std::vector<Ellipse> sites = row(k, 12, dx, dy, rows);
                INFO("k " << k << " direction (" << dx.str() << ", " << dy.str() << ") rows " << rows);
                DelaunayGraph g = test::ellipse_graph(sites);
                g.insert_all();
                CHECK(g.validate() == "");
                CHECK(g.brute_force_check() == "");
                const Graph want = cgal_graph(sites);
                CHECK(g.visible_sites() == want.visible);
                CHECK(g.hidden() == want.hidden);
                CHECK(g.edges() == want.edges);
                CHECK(g.hull() == want.hull);
            }
        }
    }
}
