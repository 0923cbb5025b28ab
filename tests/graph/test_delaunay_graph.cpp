// The Delaunay graph of ellipses: structure, validity, and agreement with
// CGAL's Apollonius_graph_2 on circles (the circle special case is our
// strongest oracle).
#include "graph/delaunay_graph.hpp"
#include "sites/ellipse.hpp"
#include "sites/site_generators.hpp"
#include "tests/support/ellipse_graph.hpp"
#include "util/error.hpp"

#include <CGAL/Apollonius_graph_2.h>
#include <CGAL/Apollonius_graph_filtered_traits_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <random>
#include <tuple>
#include <vector>

using namespace ellvor;

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using AGTraits = CGAL::Apollonius_graph_filtered_traits_2<Kernel>;
using AG = CGAL::Apollonius_graph_2<AGTraits>;

struct IntCircle {
    long x, y, r;
};

using Pairs = std::vector<std::pair<SiteId, SiteId>>;

struct Summary {
    std::vector<SiteId> visible;
    Pairs hidden, edges, hull;
};

// CGAL's graph of the circles, inserted one by one in the given order.
Summary cgal_graph(const std::vector<IntCircle>& circles, const std::vector<SiteId>& order) {
    AG ag;
    std::map<std::tuple<double, double, double>, SiteId> id;
    for (SiteId i : order) {
        const IntCircle& c = circles[i];
        id[{double(c.x), double(c.y), double(c.r)}] = i;
        ag.insert(AG::Site_2(AG::Point_2(c.x, c.y), c.r));
    }
    auto site_id = [&](const AG::Site_2& s) {
        return id.at({CGAL::to_double(s.point().x()), CGAL::to_double(s.point().y()), CGAL::to_double(s.weight())});
    };
    Summary out;
    for (auto v = ag.finite_vertices_begin(); v != ag.finite_vertices_end(); ++v) {
        out.visible.push_back(site_id(v->site()));
        for (auto h = v->hidden_sites_begin(); h != v->hidden_sites_end(); ++h)
            out.hidden.push_back({site_id(*h), site_id(v->site())});
    }
    for (auto e = ag.finite_edges_begin(); e != ag.finite_edges_end(); ++e) {
        const auto f = e->first;
        const int i = e->second;
        const SiteId a = site_id(f->vertex(ellvor::ccw(i))->site()), b = site_id(f->vertex(ellvor::cw(i))->site());
        out.edges.push_back({std::min(a, b), std::max(a, b)});
    }
    if (ag.number_of_vertices() >= 3) {
        for (auto f = ag.all_faces_begin(); f != ag.all_faces_end(); ++f) {
            if (!ag.is_infinite(f)) continue;
            const int k = f->index(ag.infinite_vertex());
            out.hull.push_back({site_id(f->vertex(ellvor::ccw(k))->site()), site_id(f->vertex(ellvor::cw(k))->site())});
        }
    }
    std::sort(out.visible.begin(), out.visible.end());
    std::sort(out.hidden.begin(), out.hidden.end());
    std::sort(out.edges.begin(), out.edges.end());
    std::sort(out.hull.begin(), out.hull.end());
    return out;
}

Summary ellvor_graph(const std::vector<IntCircle>& circles, const std::vector<SiteId>& order, bool brute_force) {
    std::vector<Ellipse> sites;
    for (const IntCircle& c : circles) sites.push_back(Ellipse::circle(c.x, c.y, c.r));
    DelaunayGraph g = test::ellipse_graph(sites);
    for (SiteId i : order) g.insert(i);
    const std::string problem = brute_force ? g.brute_force_check() : g.validate();
    std::string data;
    if (!problem.empty()) {
        for (const IntCircle& c : circles) data += std::to_string(c.x) + " " + std::to_string(c.y) + " " + std::to_string(c.r) + "\n";
        data += "order";
        for (SiteId i : order) data += " " + std::to_string(i);
    }
    INFO(problem << "\n" << data);
    CHECK(problem.empty());
    Summary out{g.visible_sites(), g.hidden(), g.edges(), {}};
    if (g.visible_sites().size() >= 3) out.hull = g.hull();
    return out;
}

void compare_with_cgal(const std::vector<IntCircle>& circles, const std::vector<SiteId>& order,
                       bool brute_force = false) {
    const Summary want = cgal_graph(circles, order);
    Summary got;
    try {
        got = ellvor_graph(circles, order, brute_force);
    } catch (const Error& e) {
        std::string data;
        for (const IntCircle& c : circles) data += std::to_string(c.x) + " " + std::to_string(c.y) + " " + std::to_string(c.r) + "\n";
        std::string ord;
        for (SiteId i : order) ord += std::to_string(i) + " ";
        FAIL_CHECK(e.what() << "\ncircles (x y r):\n" << data << "order: " << ord);
        return;
    }
    CHECK(got.visible == want.visible);
    CHECK(got.hidden == want.hidden);
    CHECK(got.edges == want.edges);
    CHECK(got.hull == want.hull);
}

std::vector<SiteId> identity(std::size_t n) {
    std::vector<SiteId> v(n);
    for (std::size_t i = 0; i < n; ++i) v[i] = i;
    return v;
}

// Random pairwise disjoint or nested circles (no tangency), integer data.
std::vector<IntCircle> random_circles(std::mt19937_64& rng, std::size_t n, long box, long rmax, double nest_rate) {
    std::vector<IntCircle> out;
    std::uniform_int_distribution<long> coord(-box, box), radius(1, rmax);
    std::uniform_real_distribution<double> u(0, 1);
    std::size_t attempts = 0;
    while (out.size() < n && ++attempts < 100000) {
        IntCircle c{coord(rng), coord(rng), radius(rng)};
        if (!out.empty() && u(rng) < nest_rate) {  // inside a random existing circle
            const IntCircle& o = out[rng() % out.size()];
            if (o.r < 3) continue;
            std::uniform_int_distribution<long> rr(1, o.r / 2), d(-o.r / 3, o.r / 3);
            c = {o.x + d(rng), o.y + d(rng), rr(rng)};
        }
        bool ok = true;
        for (const IntCircle& o : out) {
            const long dx = c.x - o.x, dy = c.y - o.y, d2 = dx * dx + dy * dy;
            const long sum = c.r + o.r, diff = c.r - o.r;
            if (d2 <= sum * sum && d2 >= diff * diff) ok = false;  // intersecting or tangent
        }
        if (ok) out.push_back(c);
    }
    return out;
}

}  // namespace

TEST_CASE("graph: small cases match CGAL", "[graph]") {
    // CGAL test_ag_three_sites_2: collinear centers, middle on / not on the hull.
    const std::vector<std::vector<IntCircle>> cases = {
        {{100, 100, 5}, {150, 150, 10}, {200, 200, 15}},
        {{100, 100, 20}, {150, 150, 20}, {200, 200, 20}},
        {{100, 100, 20}, {150, 150, 25}, {200, 200, 20}},
        {{100, 100, 20}, {150, 150, 15}, {200, 200, 20}},
        {{100, 100, 20}, {150, 150, 5}, {200, 200, 20}},
        {{0, 0, 10}, {100, 0, 10}, {50, 80, 10}},
        {{0, 0, 10}, {100, 0, 10}, {50, -80, 10}},
        {{0, 0, 10}, {100, 0, 10}, {50, 1, 3}},
        {{0, 0, 50}, {10, 0, 5}, {-10, 3, 4}},
        {{0, 0, 5}, {1, 0, 50}},
        {{0, 0, 5}},
    };
    for (const auto& c : cases) {
        std::vector<SiteId> order = identity(c.size());
        do {
            INFO("case of " << c.size() << " sites, first " << c[0].x << " " << c[0].y << " " << c[0].r);
            compare_with_cgal(c, order, true);
        } while (std::next_permutation(order.begin(), order.end()));
    }
}

TEST_CASE("graph: three-site structures (degree 2, repeated faces)", "[graph]") {
    auto build = [](std::vector<IntCircle> c) {
        std::vector<Ellipse> s;
        for (auto& x : c) s.push_back(Ellipse::circle(x.x, x.y, x.r));
        DelaunayGraph g = test::ellipse_graph(s);
        g.insert_all();
        REQUIRE(g.validate().empty());
        return g;
    };
    {  // middle on the hull: no Voronoi vertex
        DelaunayGraph g = build({{100, 100, 20}, {150, 150, 25}, {200, 200, 20}});
        CHECK(g.faces().empty());
        CHECK(g.edges() == Pairs{{0, 1}, {1, 2}});
        CHECK(g.hull().size() == 4);
    }
    {  // middle not on the hull: two Voronoi vertices, edge 0-2 twice
        DelaunayGraph g = build({{100, 100, 20}, {150, 150, 15}, {200, 200, 20}});
        CHECK(g.faces().size() == 2);
        CHECK(g.edges() == Pairs{{0, 1}, {0, 2}, {0, 2}, {1, 2}});
        CHECK(g.hull() == Pairs{{0, 2}, {2, 0}});
    }
}

TEST_CASE("graph: random circle sets match CGAL's Apollonius graph", "[graph]") {
    std::mt19937_64 rng(20240601);
    int sets = 0;
    for (int round = 0; round < 40; ++round) {
        const std::size_t n = 10 + rng() % (round < 30 ? 60 : 190);
        const double nest = (round % 3 == 0) ? 0.2 : 0.0;
        const long rmax = (round % 4 == 0) ? 200 : 40;
        auto circles = random_circles(rng, n, 1000, rmax, nest);
        INFO("round " << round << ", " << circles.size() << " circles");
        std::vector<SiteId> order = identity(circles.size());
        std::shuffle(order.begin(), order.end(), rng);
        compare_with_cgal(circles, order, circles.size() <= 40);
        ++sets;
    }
    CHECK(sets == 40);
}

// Collinear centers with radii that make exact degeneracies (e.g. three
// circles tangent to the same two lines, a zero-length hull edge). They once
// exposed an infinite-edge conflict that treated a zero-length arc as the
// whole circle, and Voronoi circles of collinear sites that could not be
// certified; both fixed, kept as regression tests.
TEST_CASE("graph: collinear circle sweeps match CGAL", "[graph][graph-degenerate]") {
    std::mt19937_64 rng(7);
    for (int round = 0; round < 12; ++round) {
        std::vector<IntCircle> c;
        // Circles with centers on a line, varying radii: many degree-2 vertices.
        const std::size_t n = 4 + round;
        for (std::size_t i = 0; i < n; ++i) c.push_back({long(100 * i), long(100 * i) * (round % 2), long(5 + rng() % 40)});
        // Plus a few off the line.
        if (round >= 6) c.push_back({250, -300, 30}), c.push_back({450, 700, 10});
        std::vector<SiteId> order = identity(c.size());
        for (int k = 0; k < 3; ++k) {
            std::shuffle(order.begin(), order.end(), rng);
            INFO("round " << round << " shuffle " << k);
            compare_with_cgal(c, order, true);
        }
    }
}

TEST_CASE("graph: random ellipses are valid (local and brute force)", "[graph]") {
    std::mt19937_64 rng(99);
    int validated = 0, undecided = 0;
    for (int round = 0; round < 8; ++round) {
        std::vector<Ellipse> sites;
        std::vector<std::array<long, 3>> disks;  // bounding disks (x, y, R) to keep sites disjoint or nested
        const std::size_t n = round < 2 ? 30 : 60;
        std::uniform_int_distribution<long> coord(-500, 500), axis(3, 40), rot(-3, 3);
        std::size_t attempts = 0;
        while (sites.size() < n && ++attempts < 20000) {
            long a = axis(rng), b = axis(rng), x = coord(rng), y = coord(rng);
            long R = std::max(a, b);
            bool nested = false;
            if (round % 2 == 1 && !disks.empty() && rng() % 4 == 0) {  // inside an earlier site's inner disk
                const std::size_t k = rng() % disks.size();
                const auto& o = disks[k];
                const long inner = std::min(sites[k].a().to_double(), sites[k].b().to_double());
                if (inner < 8) continue;
                a = 1 + long(rng() % (inner / 3)), b = 1 + long(rng() % (inner / 3));
                x = o[0] + long(rng() % 3) - 1, y = o[1] + long(rng() % 3) - 1;
                R = std::max(a, b);
                nested = true;
            }
            bool ok = true;
            for (std::size_t k = 0; k < disks.size() && ok; ++k) {
                const auto& o = disks[k];
                const long dx = x - o[0], dy = y - o[1], d2 = dx * dx + dy * dy;
                const long inner = std::lround(std::min(sites[k].a().to_double(), sites[k].b().to_double()));
                const bool apart = d2 > (R + o[2]) * (R + o[2]);
                const bool inside = nested && d2 < (inner - R) * (inner - R) && inner > R;
                ok = apart || inside;
            }
            if (!ok) continue;
            sites.push_back(Ellipse(a, b, Rational(rot(rng), 4), x, y));
            disks.push_back({x, y, R});
        }
        DelaunayGraph g = test::ellipse_graph(sites);
        std::string problem;
        try {
            g.insert_all();
            problem = g.brute_force_check();
        } catch (const Error& e) {
            std::string data;
            for (const Ellipse& e : sites) data += e.str() + "\n";
            // An undecided predicate is reported, never guessed (predicate layer).
            if (std::string(e.what()).find("undecided predicate") != std::string::npos) {
                WARN("round " << round << ": " << e.what() << "\n" << data);
                ++undecided;
                continue;
            }
            FAIL_CHECK("round " << round << ": " << e.what() << "\n" << data);
            continue;
        }
        ++validated;
        INFO("round " << round << ": " << problem);
        CHECK(problem.empty());
        if (round % 2 == 1) CHECK(!g.hidden().empty());
    }
    // Seed 99: 5 of 8 sets validated; 3 hit an undecided kappa3 in the
    // predicate layer (reported with the data, never guessed).
    CHECK(validated >= 5);
}

TEST_CASE("graph: the traits keep the Voronoi circles of live faces only", "[graph][cache]") {
    // Each insertion's conflict faces die; their cached solvers go with them
    // (forget_face), so the cache never exceeds the faces of the graph. It
    // once kept every triple ever asked about: about 5 per site.
    for (long nested : {0L, 5L}) {
        GeneratorOptions o;
        o.count = 300;
        o.seed = 17 + static_cast<std::uint64_t>(nested);
        o.nested_fraction = Rational(nested, 100UL);
        auto traits = std::make_unique<EllipseDelaunayTraits>(generate_sites(o));
        const EllipseDelaunayTraits* t = traits.get();
        DelaunayGraph g(std::move(traits));
        g.insert_all();
        INFO("nested " << nested << "%, faces " << g.faces().size() << ", cached " << t->cached_circles()
                       << ", kappa3 calls " << g.predicate_stats()[Predicate::incircle].calls);
        CHECK(t->cached_circles() > 0);
        CHECK(t->cached_circles() <= g.faces().size());
        CHECK(g.predicate_stats()[Predicate::incircle].calls > 2 * g.faces().size());
        if (nested) CHECK(!g.hidden().empty());
        CHECK(g.validate().empty());
        CHECK(g.brute_force_check().empty());
    }
}

// Circles jittered off a line (degree-2 vertices, nearly collinear Voronoi
// circles); round 9 shuffle 2 once failed validate() because such a circle
// could not be certified.
TEST_CASE("graph: circles off a line (degree-2 vertices) match CGAL", "[graph][graph-degenerate]") {
    std::mt19937_64 rng(11);
    for (int round = 0; round < 10; ++round) {
        // Nearly collinear centers with random radii: many degree-2 vertices
        // and repeated faces, but no exact degeneracy (centers jittered).
        std::vector<IntCircle> c;
        const std::size_t n = 5 + round;
        for (std::size_t i = 0; i < n; ++i)
            c.push_back({long(100 * i) + long(rng() % 7), long(rng() % 9) - 4, long(5 + rng() % 40)});
        std::vector<SiteId> order = identity(c.size());
        for (int k = 0; k < 3; ++k) {
            std::shuffle(order.begin(), order.end(), rng);
            INFO("round " << round << " shuffle " << k);
            compare_with_cgal(c, order, true);
        }
    }
}
