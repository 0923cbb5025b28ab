// ellvor's Delaunay graph against CGAL's Apollonius_graph_2 on circles: the
// visible sites, the [hidden, hiding] pairs, the finite edges as a multiset of
// sorted pairs and the hull must be identical when both insert the same
// circles in the same order. All data are small integers, so the doubles CGAL
// sees are exact and both programs answer the same exact predicates.
//
// On failure the input is printed as a replay line:
//   replay: circles {{x,y,r},...} order {i,...}
// which can be pasted into `replay_case` below.
#include "graph/delaunay_graph.hpp"
#include "sites/ellipse.hpp"
#include "tests/support/ellipse_graph.hpp"
#include "util/error.hpp"

#include <CGAL/Apollonius_graph_2.h>
#include <CGAL/Apollonius_graph_filtered_traits_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

using namespace ellvor;

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using AG = CGAL::Apollonius_graph_2<CGAL::Apollonius_graph_filtered_traits_2<Kernel>>;
using Pairs = std::vector<std::pair<SiteId, SiteId>>;

struct Circle {
    long x, y, r;
};

struct Graph {
    std::vector<SiteId> visible;
    Pairs hidden, edges, hull;
    std::size_t faces = 0;
};

std::string replay(const std::vector<Circle>& c, const std::vector<SiteId>& order) {
    std::ostringstream s;
    s << "replay: circles {";
    for (std::size_t i = 0; i < c.size(); ++i) s << (i ? "," : "") << "{" << c[i].x << "," << c[i].y << "," << c[i].r << "}";
    s << "} order {";
    for (std::size_t i = 0; i < order.size(); ++i) s << (i ? "," : "") << order[i];
    s << "}";
    return s.str();
}

std::string show(const Pairs& p) {
    std::ostringstream s;
    for (auto& e : p) s << "(" << e.first << "," << e.second << ") ";
    return s.str();
}

// CGAL's graph after inserting `order` and then removing the sites of
// `removals` that are visible when their turn comes (CGAL removes vertices
// only); those are returned in `removed`, in order.
std::string show_ids(const std::vector<SiteId>& ids) {
    std::ostringstream s;
    for (SiteId i : ids) s << i << " ";
    return s.str();
}

Graph cgal_graph(const std::vector<Circle>& circles, const std::vector<SiteId>& order,
                 const std::vector<SiteId>& removals = {}, std::vector<SiteId>* removed = nullptr) {
    AG ag;
    std::map<std::tuple<double, double, double>, SiteId> id;
    for (SiteId i : order) {
        const Circle& c = circles[i];
        id[{double(c.x), double(c.y), double(c.r)}] = i;
        ag.insert(AG::Site_2(AG::Point_2(double(c.x), double(c.y)), double(c.r)));
    }
    auto sid = [&](const AG::Site_2& s) {
        return id.at({CGAL::to_double(s.point().x()), CGAL::to_double(s.point().y()), CGAL::to_double(s.weight())});
    };
    for (SiteId r : removals)
        for (auto v = ag.finite_vertices_begin(); v != ag.finite_vertices_end(); ++v)
            if (sid(v->site()) == r) {
                ag.remove(v);
                removed->push_back(r);
                break;
            }
    Graph g;
    for (auto v = ag.finite_vertices_begin(); v != ag.finite_vertices_end(); ++v) {
        g.visible.push_back(sid(v->site()));
        for (auto h = v->hidden_sites_begin(); h != v->hidden_sites_end(); ++h) g.hidden.push_back({sid(*h), sid(v->site())});
    }
    for (auto e = ag.finite_edges_begin(); e != ag.finite_edges_end(); ++e) {
        const SiteId a = sid(e->first->vertex(ccw(e->second))->site()), b = sid(e->first->vertex(cw(e->second))->site());
        g.edges.push_back({std::min(a, b), std::max(a, b)});
    }
    if (ag.number_of_vertices() >= 3) {
        for (auto f = ag.all_faces_begin(); f != ag.all_faces_end(); ++f) {
            if (!ag.is_infinite(f)) {
                ++g.faces;
                continue;
            }
            const int k = f->index(ag.infinite_vertex());
            g.hull.push_back({sid(f->vertex(ccw(k))->site()), sid(f->vertex(cw(k))->site())});
        }
    }
    std::sort(g.visible.begin(), g.visible.end());
    std::sort(g.hidden.begin(), g.hidden.end());
    std::sort(g.edges.begin(), g.edges.end());
    std::sort(g.hull.begin(), g.hull.end());
    return g;
}

// Builds both graphs and checks that they are equal; validate() (and the brute
// force check for small inputs) on ellvor's. True when everything agreed.
bool check_against_cgal(const std::vector<Circle>& circles, const std::vector<SiteId>& order, bool brute_force,
                        Graph* out = nullptr, const std::vector<SiteId>& removals = {}) {
    std::vector<SiteId> removed;
    const Graph want = cgal_graph(circles, order, removals, &removed);
    std::vector<Ellipse> sites;
    for (const Circle& c : circles) sites.push_back(Ellipse::circle(Rational(c.x), Rational(c.y), Rational(c.r)));
    Graph got;
    std::string problem;
    try {
        DelaunayGraph g = test::ellipse_graph(sites);
        for (SiteId i : order) g.insert(i);
        for (SiteId r : removed) g.remove(r);
        problem = g.validate();
        if (problem.empty() && brute_force) problem = g.brute_force_check();
        got.visible = g.visible_sites();
        got.hidden = g.hidden();
        got.edges = g.edges();
        got.faces = g.faces().size();
        if (got.visible.size() >= 3) got.hull = g.hull();
    } catch (const std::exception& e) {
        FAIL_CHECK("exception: " << e.what() << "\n" << replay(circles, order));
        return false;
    }
    INFO(replay(circles, order));
    INFO("removed: " << show_ids(removed));
    INFO("validate / brute force: " << (problem.empty() ? "ok" : problem));
    CHECK(problem.empty());
    const bool same = got.visible == want.visible && got.hidden == want.hidden && got.edges == want.edges &&
                      got.hull == want.hull;
    if (!same) {
        INFO("ellvor edges: " << show(got.edges) << "\nCGAL edges:   " << show(want.edges));
        INFO("ellvor hidden: " << show(got.hidden) << "\nCGAL hidden:   " << show(want.hidden));
        INFO("ellvor hull: " << show(got.hull) << "\nCGAL hull:   " << show(want.hull));
        CHECK(got.visible == want.visible);
        CHECK(got.hidden == want.hidden);
        CHECK(got.edges == want.edges);
        CHECK(got.hull == want.hull);
    }
    if (out) *out = got;
    return same && problem.empty();
}

std::vector<SiteId> identity(std::size_t n) {
    std::vector<SiteId> v(n);
    for (std::size_t i = 0; i < n; ++i) v[i] = i;
    return v;
}

// Our own draws (rng() modulo a small range) so that a seed means the same
// data everywhere; the tiny modulo bias is irrelevant here.
long draw(std::mt19937_64& rng, long lo, long hi) { return lo + static_cast<long>(rng() % static_cast<std::uint64_t>(hi - lo + 1)); }

void shuffle(std::vector<SiteId>& v, std::mt19937_64& rng) {
    for (std::size_t i = v.size(); i > 1; --i) std::swap(v[i - 1], v[rng() % i]);
}

// n random circles with integer data, pairwise separated or nested (never
// tangent or intersecting). With `nest` > 0 about that fraction is drawn
// inside an earlier circle (possibly inside a nested one: two levels).
// `grid` > 1 snaps centers and radii to multiples of it (more ties: equal
// radii, symmetric configurations).
std::vector<Circle> random_circles(std::mt19937_64& rng, std::size_t n, long rmax, double nest, long grid) {
    const long box = std::max<long>(200, static_cast<long>(2.2 * rmax * std::sqrt(double(n)))) / grid * grid;
    std::vector<Circle> out;
    std::size_t attempts = 0;
    while (out.size() < n && ++attempts < 200 * n + 1000) {
        Circle c{draw(rng, -box, box) / grid * grid, draw(rng, -box, box) / grid * grid,
                 std::max(grid, draw(rng, 1, rmax) / grid * grid)};
        if (!out.empty() && nest > 0 && draw(rng, 0, 999) < nest * 1000) {
            const Circle& o = out[rng() % out.size()];
            if (o.r < 6) continue;
            c.r = draw(rng, 1, o.r / 2);
            c.x = o.x + draw(rng, -o.r / 3, o.r / 3);
            c.y = o.y + draw(rng, -o.r / 3, o.r / 3);
        }
        bool ok = true;
        for (const Circle& o : out) {
            const long dx = c.x - o.x, dy = c.y - o.y, d2 = dx * dx + dy * dy, s = c.r + o.r, d = c.r - o.r;
            if (d2 <= s * s && d2 >= d * d) {  // touching or crossing (identical circles included)
                ok = false;
                break;
            }
        }
        if (ok) out.push_back(c);
    }
    return out;
}

// Whether the disk of c lies in the closed disk of o (exact, integers).
bool inside(const Circle& c, const Circle& o) {
    const long dx = c.x - o.x, dy = c.y - o.y, d = o.r - c.r;
    return d >= 0 && dx * dx + dy * dy <= d * d;
}

// A disk covered by the union of `cover` (tested at 1440 boundary points
// with a margin: it labels test data, it decides nothing).
bool covered_by_union(const Circle& c, const std::vector<Circle>& cover) {
    for (int k = 0; k < 1440; ++k) {
        const double t = 2 * M_PI * k / 1440, x = c.x + c.r * std::cos(t), y = c.y + c.r * std::sin(t);
        bool in = false;
        for (const Circle& o : cover) in = in || std::hypot(x - o.x, y - o.y) < o.r - 1e-6 * o.r;
        if (!in) return false;
    }
    return true;
}

// n random circles with integer data that overlap freely: crossing pairs
// everywhere (the box is about as wide as the circles cover), plus, each with
// a small probability, a circle nested in an earlier one, and a circle
// covered by the union of two or three new circles but contained in none of
// them (it stays visible: CGAL's manual). Only exact duplicates are left out.
// `grid` > 1 snaps centers and radii to its multiples (ties: tangencies,
// cocircular quadruples). `covered` counts the union-covered circles made.
std::vector<Circle> overlapping_circles(std::mt19937_64& rng, std::size_t n, long rmax, long grid, int* covered) {
    const long box = std::max<long>(4 * rmax, static_cast<long>(1.2 * rmax * std::sqrt(double(n)))) / grid * grid;
    std::vector<Circle> out;
    auto add = [&](const Circle& c) {
        for (const Circle& o : out)
            if (o.x == c.x && o.y == c.y && o.r == c.r) return false;
        out.push_back(c);
        return true;
    };
    auto snap = [&](long v) { return v / grid * grid; };
    while (out.size() < n) {
        const long kind = draw(rng, 0, 99);
        if (kind < 8 && !out.empty()) {  // nested in an earlier circle
            const Circle o = out[rng() % out.size()];
            if (o.r < 6) continue;
            add({o.x + draw(rng, -o.r / 3, o.r / 3), o.y + draw(rng, -o.r / 3, o.r / 3), draw(rng, 1, o.r / 2)});
        } else if (kind < 14 && out.size() + 4 <= n) {  // covered by the union of two or three
            const long r = std::max(2L, draw(rng, 2, rmax / 2)), d = r + draw(rng, 0, r / 2);
            const Circle c{snap(draw(rng, -box, box)), snap(draw(rng, -box, box)), r};
            const int parts = kind < 11 ? 2 : 3;
            std::vector<Circle> cover;
            for (int k = 0; k < parts; ++k) {
                const double t = 2 * M_PI * k / parts + 0.3 * (kind % 3);
                // Radius: covers the gaps between the parts, yet each part
                // misses c's far side (R < d + r).
                const long R = parts == 2 ? static_cast<long>(std::ceil(std::sqrt(double(d * d + r * r)))) + 1 : d + r / 2 + 1;
                cover.push_back({c.x + std::lround(d * std::cos(t)), c.y + std::lround(d * std::sin(t)), R});
            }
            bool ok = covered_by_union(c, cover);
            for (const Circle& o : cover) ok = ok && !inside(c, o);
            if (!ok) continue;
            if (add(c)) {
                *covered += 1;
                for (const Circle& o : cover) add(o);
            }
        } else {
            add({snap(draw(rng, -box, box)), snap(draw(rng, -box, box)), std::max(grid, snap(draw(rng, 1, rmax)))});
        }
    }
    out.resize(n);
    return out;
}

// How many pairs cross (boundaries meet in two points).
std::size_t crossing_pairs(const std::vector<Circle>& c) {
    std::size_t k = 0;
    for (std::size_t i = 0; i < c.size(); ++i)
        for (std::size_t j = i + 1; j < c.size(); ++j) {
            const long dx = c[i].x - c[j].x, dy = c[i].y - c[j].y, d2 = dx * dx + dy * dy;
            const long s = c[i].r + c[j].r, d = c[i].r - c[j].r;
            k += d2 < s * s && d2 > d * d;
        }
    return k;
}

}  // namespace

// The seed can be changed for fuzzing: ELLVOR_CGAL_SEED=N build/ellvor_tests "graph vs CGAL: 200*"
TEST_CASE("graph vs CGAL: 200 random circle sets of 10 to 2000 sites", "[graph]") {
    const char* seed_env = std::getenv("ELLVOR_CGAL_SEED");
    const std::uint64_t seed = seed_env ? std::strtoull(seed_env, nullptr, 10) : 20250101;
    std::mt19937_64 rng(seed);
    struct Band {
        int sets;
        long lo, hi;
    };
    const std::vector<Band> bands = {{150, 10, 60}, {40, 60, 300}, {8, 300, 1000}, {2, 2000, 2000}};
    int set = 0, agreed = 0, nested_sets = 0, with_hidden = 0;
    for (const Band& band : bands) {
        for (int k = 0; k < band.sets; ++k, ++set) {
            const std::size_t n = static_cast<std::size_t>(draw(rng, band.lo, band.hi));
            const bool nested = set % 3 == 0;
            const long rmax = std::vector<long>{8, 40, 300}[set % 3 == 1 ? 0 : (set % 3 == 2 ? 1 : 2)];
            const long grid = (set % 5 == 4) ? 4 : 1;  // every fifth set: a coarse lattice (ties)
            const std::vector<Circle> circles = random_circles(rng, n, rmax, nested ? 0.25 : 0.0, grid);
            std::vector<SiteId> order = identity(circles.size());
            shuffle(order, rng);
            INFO("seed " << seed << ", set " << set << ": " << circles.size() << " circles, rmax " << rmax
                         << ", grid " << grid << (nested ? ", nested" : ""));
            CHECK(circles.size() == n);  // the generator placed them all
            Graph g;
            if (check_against_cgal(circles, order, circles.size() <= 40, &g)) ++agreed;
            nested_sets += nested;
            with_hidden += !g.hidden.empty();
        }
    }
    CHECK(set == 200);
    CHECK(agreed == set);
    CHECK(nested_sets >= 60);
    CHECK(with_hidden >= 50);
}

// Deletion: both graphs remove the same sites (one, 10 %, 90 % or all of the
// visible ones, in random order; CGAL removes vertices only, so a site hidden
// when its turn comes stays) and must be equal afterwards. (In degenerate
// configurations -- the grids and rings below -- the diagonal a removal keeps
// in a degree-4 Voronoi vertex is not CGAL's choice, which replays flips;
// test_removal.cpp validates those.)
TEST_CASE("graph vs CGAL: removals from 200 random circle sets of 10 to 2000 sites", "[graph][removal]") {
    std::mt19937_64 rng(20261124);
    struct Band {
        int sets;
        long lo, hi;
    };
    const std::vector<Band> bands = {{150, 10, 60}, {40, 60, 300}, {8, 300, 1000}, {2, 2000, 2000}};
    int set = 0, agreed = 0, nested_sets = 0;
    for (const Band& band : bands) {
        for (int k = 0; k < band.sets; ++k, ++set) {
            const std::size_t n = static_cast<std::size_t>(draw(rng, band.lo, band.hi));
            const bool nested = set % 3 == 0;
            const long rmax = std::vector<long>{8, 40, 300}[set % 3];
            const long grid = (set % 5 == 4) ? 4 : 1;
            const std::vector<Circle> circles = random_circles(rng, n, rmax, nested ? 0.25 : 0.0, grid);
            std::vector<SiteId> order = identity(circles.size()), removals = identity(circles.size());
            shuffle(order, rng);
            shuffle(removals, rng);
            const double fraction = std::vector<double>{0.0, 0.1, 0.9, 1.0}[set % 4];
            removals.resize(std::max<std::size_t>(1, static_cast<std::size_t>(fraction * double(removals.size()))));
            INFO("set " << set << ": " << circles.size() << " circles, rmax " << rmax << ", grid " << grid
                        << (nested ? ", nested" : "") << ", removing " << removals.size());
            if (check_against_cgal(circles, order, circles.size() <= 40, nullptr, removals)) ++agreed;
            nested_sets += nested;
        }
    }
    CHECK(set == 200);
    CHECK(agreed == set);
    CHECK(nested_sets >= 60);
}

TEST_CASE("graph vs CGAL: degree-2 Voronoi vertices (three sites on a line)", "[graph]") {
    // Middle circle small: it is not on the hull, its two neighbours share two
    // Voronoi edges (edge 0-2 twice) and it has two Voronoi vertices of degree
    // 3 whose dual faces repeat the same triple. Middle circle big: it is on
    // the hull and there is no Voronoi vertex at all.
    const std::vector<std::vector<Circle>> cases = {
        {{0, 0, 20}, {60, 0, 3}, {120, 0, 20}},      // small middle
        {{0, 0, 20}, {60, 0, 30}, {120, 0, 20}},     // big middle
        {{0, 0, 20}, {60, 60, 1}, {120, 120, 20}},   // diagonal, tiny middle
        {{0, 0, 5}, {50, 0, 10}, {100, 0, 15}},      // growing radii
        {{0, 0, 20}, {60, 0, 3}, {120, 0, 20}, {60, 200, 10}},   // plus one off the line
        {{0, 0, 20}, {60, 0, 3}, {120, 0, 20}, {60, -50, 10}},   // plus one close below the middle
        {{0, 0, 20}, {60, 0, 3}, {120, 0, 20}, {180, 0, 3}, {240, 0, 20}},  // two small middles
    };
    for (std::size_t c = 0; c < cases.size(); ++c) {
        std::vector<SiteId> order = identity(cases[c].size());
        do {
            INFO("case " << c);
            check_against_cgal(cases[c], order, true);
        } while (std::next_permutation(order.begin(), order.end()));
    }
    Graph g;
    check_against_cgal(cases[0], identity(3), true, &g);
    CHECK(g.edges == Pairs{{0, 1}, {0, 2}, {0, 2}, {1, 2}});
    CHECK(g.faces == 2);
    check_against_cgal(cases[1], identity(3), true, &g);
    CHECK(g.edges == Pairs{{0, 1}, {1, 2}});
    CHECK(g.faces == 0);
}

TEST_CASE("graph vs CGAL: a site hiding several earlier sites", "[graph]") {
    // Small circles first, then one big circle around some of them: the big
    // one hides them (CGAL removes their vertices and keeps them as hidden
    // sites of the new vertex). With 0, 1, 2 and more sites left outside, which
    // exercises the "all hidden / all but one hidden" paths too.
    const std::vector<Circle> inner = {{0, 0, 5}, {20, 3, 4}, {-18, 6, 6}, {4, 22, 3}, {-6, -21, 5}, {15, -14, 2}};
    const std::vector<Circle> outer = {{200, 0, 10}, {-150, 120, 20}, {30, -220, 15}, {-90, -140, 8}, {120, 160, 12}};
    const Circle big{0, 0, 60};
    for (std::size_t outside = 0; outside <= outer.size(); ++outside) {
        for (std::size_t inside = 1; inside <= inner.size(); ++inside) {
            std::vector<Circle> c(inner.begin(), inner.begin() + inside);
            c.insert(c.end(), outer.begin(), outer.begin() + outside);
            c.push_back(big);
            const SiteId hider = c.size() - 1;
            std::vector<SiteId> order = identity(c.size());  // the big one last
            INFO(inside << " inside, " << outside << " outside");
            Graph g;
            check_against_cgal(c, order, true, &g);
            CHECK(g.hidden.size() == inside);
            for (const auto& h : g.hidden) CHECK(h.second == hider);
            // Interleaved: outside sites after the big one, too.
            std::vector<SiteId> order2;
            for (SiteId i = 0; i < inside; ++i) order2.push_back(i);
            order2.push_back(hider);
            for (SiteId i = inside; i < hider; ++i) order2.push_back(i);
            check_against_cgal(c, order2, true);
        }
    }
    // A nested chain: a small circle hidden inside a medium one, which the big
    // one then hides (the hidden list moves to the big one).
    std::vector<Circle> chain = {{0, 0, 3}, {0, 0, 10}, {100, 0, 5}, {-80, 50, 5}, {10, -90, 4}, {0, 0, 40}};
    for (int rot = 0; rot < 6; ++rot) {
        std::vector<SiteId> order = identity(chain.size());
        std::rotate(order.begin(), order.begin() + rot, order.end());
        check_against_cgal(chain, order, true);
    }
}

TEST_CASE("graph vs CGAL: 5x5 grid of equal circles (degree-4 Voronoi vertices)", "[graph]") {
    // Every unit square of centers makes four cocircular-like sites (one
    // Voronoi circle tangent to four circles): the diagonal each graph keeps
    // depends on the tie-breaking of exact degenerate predicates and on the
    // insertion order. Both must make the same choice (same algorithm, exact
    // predicates on both sides) and ellvor's graph must be valid.
    std::mt19937_64 rng(5);
    for (int variant = 0; variant < 3; ++variant) {
        std::vector<Circle> c;
        for (long i = 0; i < 5; ++i)
            for (long j = 0; j < 5; ++j) {
                const long r = variant == 2 ? ((i + j) % 2 ? 10 : 20) : (variant == 1 ? 7 : 10);
                c.push_back({100 * i, 100 * j, r});
            }
        std::vector<std::vector<SiteId>> orders = {identity(c.size())};
        orders.push_back(orders[0]);
        std::reverse(orders[1].begin(), orders[1].end());
        for (int k = 0; k < 4; ++k) {
            orders.push_back(orders[0]);
            shuffle(orders.back(), rng);
        }
        for (std::size_t o = 0; o < orders.size(); ++o) {
            INFO("variant " << variant << ", order " << o);
            check_against_cgal(c, orders[o], true);
        }
    }
}

TEST_CASE("graph vs CGAL: cocircular rings and collinear equal circles", "[graph]") {
    // The 12 integer points of x^2 + y^2 = 25, scaled by 20: twelve equal
    // circles tangent to one circle centered at the origin (a Voronoi vertex of
    // degree 12); with and without a small circle at the center, and with
    // alternating radii (still one common tangent circle: no, then the ring is
    // generic). Then equal circles on a line (no Voronoi vertex at all).
    const std::vector<std::pair<long, long>> ring = {{5, 0}, {4, 3}, {3, 4}, {0, 5}, {-3, 4}, {-4, 3},
                                                     {-5, 0}, {-4, -3}, {-3, -4}, {0, -5}, {3, -4}, {4, -3}};
    std::mt19937_64 rng(12);
    for (int variant = 0; variant < 4; ++variant) {
        std::vector<Circle> c;
        for (std::size_t k = 0; k < ring.size(); ++k)
            c.push_back({20 * ring[k].first, 20 * ring[k].second, variant == 2 ? long(5 + 3 * (k % 2)) : 5});
        if (variant == 1) c.push_back({0, 0, 7});
        if (variant == 3) c = {{0, 0, 6}, {40, 0, 6}, {80, 0, 6}, {120, 0, 6}, {160, 0, 6}, {200, 0, 6}};
        std::vector<SiteId> order = identity(c.size());
        for (int k = 0; k < 6; ++k) {
            INFO("variant " << variant << ", order " << k);
            check_against_cgal(c, order, true);
            shuffle(order, rng);
        }
    }
}

// Intersecting circles: signed distances |x - c| - r, internal Voronoi circles
// (negative radius), hidden = contained in one other circle (tangency
// included); a circle covered by a union of others stays visible.
TEST_CASE("graph vs CGAL: 200 random sets of 10 to 2000 overlapping circles", "[graph][overlap]") {
    std::mt19937_64 rng(20261124);
    struct Band {
        int sets;
        long lo, hi;
    };
    const std::vector<Band> bands = {{150, 10, 60}, {40, 60, 300}, {8, 300, 1000}, {2, 2000, 2000}};
    int set = 0, agreed = 0, with_hidden = 0, with_covered = 0, covered = 0;
    std::size_t crossings = 0;
    for (const Band& band : bands) {
        for (int k = 0; k < band.sets; ++k, ++set) {
            const std::size_t n = static_cast<std::size_t>(draw(rng, band.lo, band.hi));
            const long rmax = std::vector<long>{12, 40, 300}[set % 3];
            const long grid = (set % 5 == 4) ? 4 : 1;
            int covered_here = 0;
            const std::vector<Circle> circles = overlapping_circles(rng, n, rmax, grid, &covered_here);
            std::vector<SiteId> order = identity(circles.size());
            shuffle(order, rng);
            INFO("set " << set << ": " << circles.size() << " circles, rmax " << rmax << ", grid " << grid);
            Graph g;
            if (check_against_cgal(circles, order, circles.size() <= 40, &g)) ++agreed;
            with_hidden += !g.hidden.empty();
            with_covered += covered_here > 0;
            covered += covered_here;
            if (circles.size() <= 300) crossings += crossing_pairs(circles);
        }
    }
    CHECK(set == 200);
    CHECK(agreed == set);
    CHECK(with_hidden >= 100);
    CHECK(with_covered >= 100);
    CHECK(crossings >= 5000);
    WARN("overlapping circles: " << covered << " union-covered circles, " << crossings
                                 << " crossing pairs in the sets of <= 300");
}

TEST_CASE("graph vs CGAL: removals from 100 sets of overlapping circles", "[graph][overlap][removal]") {
    std::mt19937_64 rng(20261125);
    int agreed = 0;
    for (int set = 0; set < 100; ++set) {
        const std::size_t n = static_cast<std::size_t>(set < 90 ? draw(rng, 10, 80) : draw(rng, 300, 1000));
        int covered = 0;
        const std::vector<Circle> circles = overlapping_circles(rng, n, std::vector<long>{12, 40, 300}[set % 3],
                                                                set % 5 == 4 ? 4 : 1, &covered);
        std::vector<SiteId> order = identity(circles.size()), removals = identity(circles.size());
        shuffle(order, rng);
        shuffle(removals, rng);
        const double fraction = std::vector<double>{0.0, 0.1, 0.5, 1.0}[set % 4];
        removals.resize(std::max<std::size_t>(1, static_cast<std::size_t>(fraction * double(removals.size()))));
        INFO("set " << set << ": " << circles.size() << " circles, removing " << removals.size());
        if (check_against_cgal(circles, order, circles.size() <= 40, nullptr, removals)) ++agreed;
    }
    CHECK(agreed == 100);
}

TEST_CASE("graph vs CGAL: a circle covered by two or three others stays visible", "[graph][overlap]") {
    // The disk of radius 5 at the origin lies in the union of the two (three)
    // larger disks but in none of them: its cell is not empty (it owns its
    // center) in every insertion order.
    const std::vector<std::vector<Circle>> cases = {
        {{0, 0, 5}, {-6, 0, 8}, {6, 0, 8}},
        {{0, 0, 5}, {6, 0, 8}, {-3, 5, 8}, {-3, -5, 8}},
        {{0, 0, 5}, {-6, 0, 8}, {6, 0, 8}, {0, 40, 3}, {30, -30, 6}},
    };
    for (std::size_t c = 0; c < cases.size(); ++c) {
        REQUIRE(covered_by_union(cases[c][0], {cases[c].begin() + 1, cases[c].begin() + (c == 1 ? 4 : 3)}));
        std::vector<SiteId> order = identity(cases[c].size());
        do {
            INFO("case " << c);
            Graph g;
            check_against_cgal(cases[c], order, true, &g);
            CHECK(std::count(g.visible.begin(), g.visible.end(), SiteId(0)) == 1);
            CHECK(g.hidden.empty());
        } while (std::next_permutation(order.begin(), order.end()));
    }
}

TEST_CASE("graph vs CGAL: internal Voronoi circles and tangencies of overlapping circles", "[graph][overlap]") {
    // Three pairwise crossing circles with a common point inside all three
    // (an internal Voronoi circle, negative radius); a fourth through it;
    // circles through one common point (three boundaries meet: radius 0);
    // internally and externally tangent pairs among crossing ones; equal
    // circles on a lattice (cocircular internal circles).
    const std::vector<std::vector<Circle>> cases = {
        {{0, 0, 10}, {12, 0, 10}, {6, 10, 10}},
        {{0, 0, 10}, {12, 0, 10}, {6, 10, 10}, {6, 4, 3}},
        {{-5, 0, 5}, {5, 0, 5}, {0, 5, 5}, {0, -5, 5}},          // four circles through the origin
        {{0, 0, 5}, {8, 0, 5}, {4, 3, 5}, {4, -3, 5}, {4, 1, 1}},  // shared points (4, +-3), a small one inside two
        {{0, 0, 10}, {20, 0, 10}, {10, 0, 4}, {10, 8, 6}},        // tangent pairs among crossing ones
        {{0, 0, 10}, {5, 0, 5}, {12, 0, 6}, {0, 14, 7}},          // internally tangent: hidden
    };
    for (std::size_t c = 0; c < cases.size(); ++c) {
        std::vector<SiteId> order = identity(cases[c].size());
        do {
            INFO("case " << c);
            check_against_cgal(cases[c], order, true);
        } while (std::next_permutation(order.begin(), order.end()));
    }
    std::vector<Circle> lattice;
    for (long i = 0; i < 6; ++i)
        for (long j = 0; j < 6; ++j) lattice.push_back({12 * i, 12 * j, 9});
    std::mt19937_64 rng(3);
    std::vector<SiteId> order = identity(lattice.size());
    for (int k = 0; k < 4; ++k) {
        INFO("lattice order " << k);
        check_against_cgal(lattice, order, true);
        shuffle(order, rng);
    }
}

// Paste a replay line here to debug one failure.
TEST_CASE("graph vs CGAL: replay", "[graph]") {
    const std::vector<Circle> circles = {{0, 0, 10}, {100, 0, 10}, {50, 80, 10}, {50, 30, 2}};
    const std::vector<SiteId> order = {3, 0, 1, 2};
    check_against_cgal(circles, order, true);
}
