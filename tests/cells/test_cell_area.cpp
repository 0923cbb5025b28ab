// Certified cell areas against independent computations: equal circles (the
// cells are exactly the point-Voronoi cells of the centres: polygons clipped
// in exact rationals), unequal circles (the polar radius of the cell around
// a centre in closed form, integrated by adaptive Simpson in long double),
// ellipses (the normal segments swept in doubles, adaptive Simpson); and
// the widths hi - lo <= T * area for T = 1e-9, 1e-15, 1e-30.
#include "cells/cell_area.hpp"
#include "cells/face_numbers.hpp"
#include "predicates/relative_position.hpp"
#include "subdivision/ellipse_shape.hpp"
#include "sites/site_generators.hpp"
#include "subdivision/voronoi_circle_enclosure.hpp"
#include "tests/support/ellipse_graph.hpp"
#include "tests/support/random_sites.hpp"
#include "util/error.hpp"

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <functional>
#include <random>
#include <vector>

using namespace ellvor;

namespace {

bool contains(const Ball& b, const Rational& q) { return b.contains(q); }

double relative_width(const Ball& b) {
    return 2 * b.radius_double() / (b.mid_double() - b.radius_double());
}

std::vector<CellArea> built_areas(const std::vector<Ellipse>& sites, double tolerance,
                                  bool arb_integrator_only = false) {
    DelaunayGraph graph = test::ellipse_graph(sites);
    graph.insert_all();
    CellAreaOptions o;
    o.tolerance = tolerance;
    o.arb_integrator_only = arb_integrator_only;
    return cell_areas(graph, sites, o);
}

// The point-Voronoi cell of centre i clipped to [-L, L]^2, in exact rationals.
struct Polygon {
    std::vector<Point> points;
    bool touches_frame = false;
    Rational area() const {
        Rational twice(0);
        for (std::size_t k = 0; k < points.size(); ++k) {
            const Point &a = points[k], &b = points[(k + 1) % points.size()];
            twice = twice + a.x * b.y - a.y * b.x;
        }
        return twice * Rational(1, 2);
    }
    // Integrals of x, y (first) and x^2, x y, y^2 (second) over the polygon,
    // by the exact shoelace-type formulas.
    void moments(std::array<Rational, 2>& first, std::array<Rational, 3>& second) const {
        first = {Rational(0), Rational(0)};
        second = {Rational(0), Rational(0), Rational(0)};
        for (std::size_t k = 0; k < points.size(); ++k) {
            const Point &a = points[k], &b = points[(k + 1) % points.size()];
            const Rational cross = a.x * b.y - b.x * a.y;
            first[0] = first[0] + cross * (a.x + b.x) * Rational(1, 6);
            first[1] = first[1] + cross * (a.y + b.y) * Rational(1, 6);
            second[0] = second[0] + cross * (a.x * a.x + a.x * b.x + b.x * b.x) * Rational(1, 12);
            second[1] = second[1] + cross * (a.x * b.y + Rational(2) * a.x * a.y + Rational(2) * b.x * b.y + b.x * a.y) *
                                        Rational(1, 24);
            second[2] = second[2] + cross * (a.y * a.y + a.y * b.y + b.y * b.y) * Rational(1, 12);
        }
    }
    // The perimeter, a ball at 200 bits (square roots of exact squares).
    Ball perimeter() const {
        Ball sum(Rational(0), 200);
        for (std::size_t k = 0; k < points.size(); ++k) {
            const Point &a = points[k], &b = points[(k + 1) % points.size()];
            Ball side((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y), 200);
            arb_sqrt(side.get(), side.get(), 200);
            arb_add(sum.get(), sum.get(), side.get(), 200);
        }
        return sum;
    }
};

// Two certified enclosures of one number must meet.
bool overlap(const Ball& a, const Ball& b) { return arb_overlaps(a.get(), b.get()); }

// The centroid and central second moments of a polygon, exactly.
void polygon_shape(const Polygon& poly, std::array<Rational, 2>& centroid, std::array<Rational, 3>& central) {
    std::array<Rational, 2> first;
    std::array<Rational, 3> second;
    poly.moments(first, second);
    const Rational area = poly.area();
    centroid = {first[0] / area, first[1] / area};
    central = {second[0] - first[0] * centroid[0], second[1] - first[0] * centroid[1],
               second[2] - first[1] * centroid[1]};
}

Polygon point_voronoi_cell(const std::vector<Point>& centres, std::size_t i, const Rational& L) {
    Polygon poly;
    poly.points = {{-L, -L}, {L, -L}, {L, L}, {-L, L}};
    for (std::size_t j = 0; j < centres.size(); ++j) {
        if (j == i) continue;
        // Keep 2 (cj - ci) . x <= |cj|^2 - |ci|^2.
        const Rational ax = Rational(2) * (centres[j].x - centres[i].x), ay = Rational(2) * (centres[j].y - centres[i].y);
        const Rational c = centres[j].x * centres[j].x + centres[j].y * centres[j].y - centres[i].x * centres[i].x -
                           centres[i].y * centres[i].y;
        std::vector<Point> out;
        const auto& p = poly.points;
        for (std::size_t k = 0; k < p.size(); ++k) {
            const Point &a = p[k], &b = p[(k + 1) % p.size()];
            const Rational fa = ax * a.x + ay * a.y - c, fb = ax * b.x + ay * b.y - c;
            if (fa.sign() <= 0) out.push_back(a);
            if ((fa.sign() < 0 && fb.sign() > 0) || (fa.sign() > 0 && fb.sign() < 0)) {
                const Rational t = fa / (fa - fb);
                out.push_back({a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)});
            }
        }
        poly.points = out;
    }
    for (const Point& q : poly.points)
        if (q.x == L || q.x == -L || q.y == L || q.y == -L) poly.touches_frame = true;
    return poly;
}

}  // namespace

TEST_CASE("cell areas: equal circles have the point-Voronoi cells of their centres", "[cells]") {
    // Signed distances |x - c_i| - r: the diagram of equal circles is that of
    // their centres, apart or crossing (docs/DESIGN.md §9); the edges between
    // crossing circles pass through both and run where s < 0 (the signed tie).
    const bool crossing = GENERATE(false, true);
    std::mt19937_64 rng(crossing ? 7 : 1);
    const Rational r = crossing ? Rational(3) : Rational(1, 2);
    const long range = crossing ? 560 : 800;
    std::vector<Ellipse> sites;
    std::vector<Point> centres;
    while (sites.size() < 9) {
        const Ellipse c = Ellipse::circle(test::random_fraction(rng, -range, range, 64), test::random_fraction(rng, -range, range, 64), r);
        bool accepted = true;
        for (const Ellipse& e : sites)
            accepted = accepted && (crossing ? !(e.xc() == c.xc() && e.yc() == c.yc()) : test::bounding_circles_apart(c, e));
        if (!accepted) continue;
        sites.push_back(c);
        centres.push_back(c.center());
    }
    int crossing_pairs = 0;
    for (std::size_t i = 0; i < sites.size(); ++i)
        for (std::size_t j = i + 1; j < sites.size(); ++j)
            crossing_pairs += *relative_position(sites[i], sites[j]) == RelativePosition::intersecting;
    CHECK((crossing ? crossing_pairs >= 3 : crossing_pairs == 0));
    // 1e-9: every edge by the double-interval stage; 1e-15: every edge with its nodes in Arb.
    const double T = GENERATE(1e-9, 1e-15);
    const std::vector<CellArea> areas = built_areas(sites, T);
    int bounded = 0;
    for (std::size_t i = 0; i < sites.size(); ++i) {
        const Polygon cell = point_voronoi_cell(centres, i, Rational(1000000));
        INFO("site " << i << " area " << areas[i].area.str(25));
        REQUIRE(areas[i].visible);
        REQUIRE(areas[i].bounded == !cell.touches_frame);
        if (!areas[i].bounded) {
            CHECK(!arb_is_finite(areas[i].area.get()));
            continue;
        }
        ++bounded;
        CHECK((T > 1e-12 ? areas[i].edges_by_nodes_in_arb : areas[i].edges_in_doubles) == 0);
        CHECK(areas[i].edges_by_arb == 0);
        // Nodes in Arb from their pieces' disk proofs (densities_in_balls).
        CHECK(areas[i].quadrature.ball_nodes_from_disks == (T > 1e-12 ? 0 : areas[i].quadrature.nodes));
        CHECK(contains(areas[i].area, cell.area()));
        CHECK(relative_width(areas[i].area) <= T);
        // The other measures: balls that contain the polygon's, reasonably tight.
        CHECK(overlap(areas[i].perimeter, cell.perimeter()));
        CHECK(relative_width(areas[i].perimeter) <= 1e3 * T);
        std::array<Rational, 2> centroid;
        std::array<Rational, 3> central;
        polygon_shape(cell, centroid, central);
        for (int k = 0; k < 2; ++k) {
            CHECK(contains(areas[i].centroid[k], centroid[k]));
            CHECK(areas[i].centroid[k].radius_double() <= 1e3 * T * std::sqrt(areas[i].area.mid_double()));
        }
        for (int k = 0; k < 3; ++k) {
            CHECK(contains(areas[i].second_moments[k], central[k]));
            CHECK(areas[i].second_moments[k].radius_double() <= 1e3 * T * areas[i].area.mid_double() * areas[i].area.mid_double());
        }
    }
    CHECK(bounded >= 2);
}

TEST_CASE("cell areas: a grid of equal circles, its zero-length edges in doubles", "[cells]") {
    // Four cocircular circles about each square of the grid: a Voronoi vertex
    // of degree 4, split into two faces with one circle, so a cell has an edge
    // of length zero whose ends come from two circles certified in doubles,
    // and a rounding apart in either order (the quadrature then integrates it
    // backwards). Non-dyadic coordinates, so that the roundings differ.
    std::vector<Ellipse> sites;
    std::vector<Point> centres;
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 5; ++j) {
            const Ellipse c = Ellipse::circle(Rational(7 * i, 3) + Rational(1, 7), Rational(7 * j, 3) - Rational(1, 11),
                                              Rational(1, 3));
            sites.push_back(c);
            centres.push_back(c.center());
        }
    const std::vector<CellArea> areas = built_areas(sites, 1e-9);
    QuadratureCounts work;
    int bounded = 0;
    for (std::size_t i = 0; i < sites.size(); ++i) {
        const Polygon cell = point_voronoi_cell(centres, i, Rational(1000000));
        INFO("site " << i << " area " << areas[i].area.str(25));
        REQUIRE(areas[i].bounded == !cell.touches_frame);
        if (!areas[i].bounded) continue;
        ++bounded;
        work += areas[i].quadrature;
        CHECK(areas[i].edges_by_nodes_in_arb == 0);
        CHECK(areas[i].edges_by_arb == 0);
        CHECK(contains(areas[i].area, cell.area()));
        CHECK(relative_width(areas[i].area) <= 1e-9);
    }
    CHECK(bounded == 9);
    CHECK(work.reversed_edges >= 1);
}

namespace {

// The polar radius around the centre of circle i of its cell: along the ray
// u from c_i the point c_i + R u is as near to circle j as to i iff
// R = (|d|^2 - (rj - ri)^2) / (2 (u.d + rj - ri)), d = c_j - c_i (when the
// denominator is positive; else circle j never wins on that ray).
long double polar_radius(const std::vector<Ellipse>& sites, std::size_t i, long double t) {
    long double best = INFINITY;
    const long double xi = sites[i].xc().to_double(), yi = sites[i].yc().to_double(), ri = sites[i].a().to_double();
    const long double ux = std::cos(t), uy = std::sin(t);
    for (std::size_t j = 0; j < sites.size(); ++j) {
        if (j == i) continue;
        const long double dx = sites[j].xc().to_double() - xi, dy = sites[j].yc().to_double() - yi;
        const long double delta = sites[j].a().to_double() - ri;
        const long double den = 2 * (ux * dx + uy * dy + delta);
        if (den > 0) best = std::min(best, (dx * dx + dy * dy - delta * delta) / den);
    }
    return best;
}

long double adaptive_simpson(const std::function<long double(long double)>& f, long double a, long double b,
                             long double fa, long double fm, long double fb, long double whole, long double eps, int depth) {
    const long double m = (a + b) / 2, lm = (a + m) / 2, rm = (m + b) / 2;
    const long double flm = f(lm), frm = f(rm);
    const long double left = (m - a) / 6 * (fa + 4 * flm + fm), right = (b - m) / 6 * (fm + 4 * frm + fb);
    if (depth <= 0 || std::fabs(left + right - whole) <= 15 * eps) return left + right + (left + right - whole) / 15;
    return adaptive_simpson(f, a, m, fa, flm, fm, left, eps / 2, depth - 1) +
           adaptive_simpson(f, m, b, fm, frm, fb, right, eps / 2, depth - 1);
}

// The area of circle i's cell, integral of R(t)^2 / 2 over a turn (Simpson to eps).
double polar_cell_area(const std::vector<Ellipse>& sites, std::size_t i, long double eps) {
    auto f = [&](long double t) { const long double R = polar_radius(sites, i, t); return R * R / 2; };
    const long double a = 0, b = 2 * 3.14159265358979323846264338327950288L;
    const long double fa = f(a), fm = f((a + b) / 2), fb = f(b);
    const long double whole = (b - a) / 6 * (fa + 4 * fm + fb);
    return static_cast<double>(adaptive_simpson(f, a, b, fa, fm, fb, whole, eps, 40));
}

}  // namespace

TEST_CASE("cell areas: unequal circles against the polar closed form", "[cells]") {
    std::mt19937_64 rng(GENERATE(4));
    std::vector<Ellipse> sites;
    while (sites.size() < 9) {
        const Ellipse c = Ellipse::circle(test::random_fraction(rng, -400, 400, 32), test::random_fraction(rng, -400, 400, 32),
                                          test::random_fraction(rng, 8, 64, 32));
        bool apart = true;
        for (const Ellipse& e : sites) apart = apart && test::bounding_circles_apart(c, e);
        if (apart) sites.push_back(c);
    }
    const std::vector<CellArea> areas = built_areas(sites, 1e-12);
    int checked = 0;
    for (std::size_t i = 0; i < sites.size(); ++i) {
        if (!areas[i].bounded) continue;
        const double independent = polar_cell_area(sites, i, 1e-13L);
        INFO("site " << i << " certified " << areas[i].area.str(20) << " polar " << independent);
        // Simpson in long double is not a proof: a margin of 1e-10 relative.
        CHECK(std::fabs(areas[i].area.mid_double() - independent) <= 1e-10 * std::fabs(independent));
        CHECK(relative_width(areas[i].area) <= 1e-12);
        ++checked;
    }
    CHECK(checked >= 1);
}

TEST_CASE("cell areas: ellipses against a floating-point integration of the normal segments", "[cells]") {
    GeneratorOptions o;
    o.count = 12;
    o.seed = GENERATE(1);
    o.nested_fraction = Rational(1, 5);
    const std::vector<Ellipse> sites = generate_sites(o);
    DelaunayGraph graph = test::ellipse_graph(sites);
    graph.insert_all();
    const std::vector<CellArea> areas = cell_areas(graph, sites);
    const std::vector<VoronoiCell> cells = voronoi_cells(graph, face_numbers(graph));
    const auto faces = graph.faces();
    // The tangency angle of a face's circle on one of its sites, in doubles.
    auto angle = [&](long face, SiteId site) {
        const auto& f = faces[static_cast<std::size_t>(face)];
        VoronoiCircleSolver solver(sites[f[0]], sites[f[1]], sites[f[2]]);
        solver.refine_existing(53);
        const int i = static_cast<int>(std::find(f.begin(), f.end(), site) - f.begin());
        const double t = solver.enclosure().parameter[i].mid_double();
        return solver.enclosure().flipped[i] ? 3.14159265358979323846 + 2 * std::atan(t) : 2 * std::atan(t);
    };
    int checked = 0;
    for (const VoronoiCell& c : cells) {
        const CellArea& a = areas[c.site];
        if (!c.visible) {
            CHECK(a.area.mid_double() == 0);
            CHECK(a.area.radius_double() == 0);
            continue;
        }
        if (!c.bounded()) {
            CHECK(!arb_is_finite(a.area.get()));
            continue;
        }
        // pi a b plus, edge by edge, the normal segments [0, rho(theta)] swept
        // in doubles: rho by the tracer's bisection-Newton (no Arb, no
        // certificate), the area element in the form rho |P'| + kappa |P'| rho^2 / 2,
        // integrated by adaptive Simpson.
        const EllipseShape p = EllipseShape::of(sites[c.site]);
        long double independent = 3.14159265358979323846L * p.a * p.b;
        for (const CellEdge& e : c.edges) {
            const EllipseShape q = EllipseShape::of(sites[e.neighbor]);
            const long double t0 = angle(e.from, c.site);
            long double t1 = angle(e.to, c.site);
            while (t1 < t0) t1 += 2 * 3.14159265358979323846L;
            auto f = [&](long double t) -> long double {
                const double theta = static_cast<double>(t);
                const double rho = *equal_distance_on_normal(p, q, theta, 1e12);
                const double speed = std::hypot(p.a * std::sin(theta), p.b * std::cos(theta));
                const double curvature = p.a * p.b / (speed * speed * speed);
                return rho * speed + curvature * speed * rho * rho / 2;
            };
            const long double fa = f(t0), fm = f((t0 + t1) / 2), fb = f(t1);
            // The tolerance is relative: rho in doubles carries noise of about 1e-14 of it.
            const long double whole = (t1 - t0) / 6 * (fa + 4 * fm + fb);
            independent += adaptive_simpson(f, t0, t1, fa, fm, fb, whole, 1e-11L * std::fabs(whole), 22);
        }
        INFO("site " << c.site << " certified " << a.area.str(20) << " independent " << independent);
        // Doubles and Simpson are not a proof: a margin of 1e-8 relative.
        CHECK(std::fabs(a.area.mid_double() - independent) <= 1e-8 * independent);
        CHECK(relative_width(a.area) <= 1e-9);
        CHECK(a.area.mid_double() > a.site_area.mid_double());
        ++checked;
    }
    CHECK(checked >= 1);
}

TEST_CASE("cell areas: widths at 1e-15 and 1e-30 on small sets", "[cells]") {
    GeneratorOptions o;
    o.count = 6;
    o.seed = 3;
    o.nested_fraction = Rational(1, 8);
    const std::vector<Ellipse> sites = generate_sites(o);
    const std::vector<CellArea> loose = built_areas(sites, 1e-9);
    // At 1e-9 the edges go to the double-interval stage; beyond 44 bits to its
    // pieces with the nodes in Arb, or, when asked, to Arb's integrator.
    std::size_t in_doubles = 0;
    for (const CellArea& a : loose) {
        in_doubles += a.edges_in_doubles;
        CHECK(a.edges_by_arb == 0);
    }
    CHECK(in_doubles >= 3);
    for (const auto& [T, arb_integrator_only] : {std::pair{1e-15, false}, {1e-30, false}, {1e-15, true}}) {
        INFO("T " << T << (arb_integrator_only ? " by Arb's integrator" : ""));
        const std::vector<CellArea> tight = built_areas(sites, T, arb_integrator_only);
        int bounded = 0;
        for (std::size_t i = 0; i < sites.size(); ++i) {
            if (!tight[i].bounded) continue;
            ++bounded;
            CHECK(relative_width(tight[i].area) <= T);
            CHECK(tight[i].precision >= cell_area_precision(T));
            CHECK(tight[i].edges_in_doubles == 0);
            CHECK((arb_integrator_only ? tight[i].edges_by_nodes_in_arb : tight[i].edges_by_arb) == 0);
            CHECK((arb_integrator_only ? tight[i].edges_by_arb : tight[i].edges_by_nodes_in_arb) >= 2);
            // Nested enclosures of one number: the balls must overlap.
            CHECK(arb_overlaps(tight[i].area.get(), loose[i].area.get()));
        }
        CHECK(bounded >= 1);
    }
}

TEST_CASE("cell areas: crossing unequal circles against the polar closed form", "[cells]") {
    // The polar radius of polar_radius() holds for crossing circles too: along
    // a ray from c_i, delta_i grows at rate 1 and delta_j at most so.
    std::mt19937_64 rng(11);
    std::vector<Ellipse> sites;
    int crossing_pairs = 0;
    while (sites.size() < 9) {
        const Ellipse c = Ellipse::circle(test::random_fraction(rng, -600, 600, 32), test::random_fraction(rng, -600, 600, 32),
                                          test::random_fraction(rng, 64, 160, 32));
        int crossings = 0;
        bool allowed = true;
        for (const Ellipse& e : sites) {
            const RelativePosition rp = *relative_position(c, e);
            allowed = allowed && (rp == RelativePosition::separated || rp == RelativePosition::intersecting);
            crossings += rp == RelativePosition::intersecting;
        }
        if (!allowed) continue;
        sites.push_back(c);
        crossing_pairs += crossings;
    }
    REQUIRE(crossing_pairs >= 3);
    const std::vector<CellArea> areas = built_areas(sites, 1e-9);
    int checked = 0;
    for (std::size_t i = 0; i < sites.size(); ++i) {
        if (!areas[i].bounded) continue;
        const double independent = polar_cell_area(sites, i, 1e-12L);
        INFO("site " << i << " certified " << areas[i].area.str(20) << " polar " << independent);
        CHECK(std::fabs(areas[i].area.mid_double() - independent) <= 1e-9 * std::fabs(independent));
        ++checked;
    }
    CHECK(checked >= 1);
}

TEST_CASE("cell areas: a circle nearly inside the circle it crosses, in doubles, against the polar closed form",
          "[cells]") {
    // Circle 0 (radius 1/5) crosses circle 1 (radius 3/5) with its centre
    // inside it, (g / 2) r0 from their edge: the edge is a hairpin around
    // c0, within g / 2 of circle 0's medial axis (its centre), seen from
    // either site. The certified pieces shrink with g; at g = 1/100 the double
    // stage needs about 190 of them on the hairpin edge (900 with the Taylor
    // models' certificate on boxes, 9000 before Taylor models; it once gave
    // up at 4096 and left the edge to Arb's integrator, minutes a cell),
    // integrated once for both cells. Eight circles around make both cells
    // bounded.
    const Rational g(1, 100), r0(1, 5), r1(3, 5);
    std::vector<Ellipse> sites = {Ellipse::circle(Rational(0), Rational(0), r0),
                                  Ellipse::circle(r1 - r0 + g * r0, Rational(0), r1)};
    for (int k = 0; k < 8; ++k) {
        const double angle = k * 0.785398163397448;
        sites.push_back(Ellipse::circle(Rational(static_cast<long>(std::lround(4000 * std::cos(angle))), 1000),
                                        Rational(static_cast<long>(std::lround(4000 * std::sin(angle))), 1000),
                                        Rational(1, 2)));
    }
    REQUIRE(*relative_position(sites[0], sites[1]) == RelativePosition::intersecting);
    const std::vector<CellArea> areas = built_areas(sites, 1e-9);
    for (std::size_t i : {0, 1}) {
        REQUIRE(areas[i].bounded);
        const double independent = polar_cell_area(sites, i, 1e-12L);
        INFO("site " << i << " certified " << areas[i].area.str(20) << " polar " << independent);
        CHECK(std::fabs(areas[i].area.mid_double() - independent) <= 1e-9 * std::fabs(independent));
        CHECK(relative_width(areas[i].area) <= 1e-9);
        CHECK(areas[i].edges_by_arb == 0);
    }
    CHECK(areas[0].quadrature.pieces + areas[1].quadrature.pieces > 100);
    CHECK(areas[0].edges_from_neighbors + areas[1].edges_from_neighbors >= 1);
}

TEST_CASE("cell areas: a crossing through a medial axis is refused; bad tolerances are input errors", "[cells]") {
    // A needle (aspect 9.5) whose tip lies deep in a fatter ellipse: their
    // edge runs through the needle's axis, which the normal lines cannot follow.
    const std::vector<Ellipse> sites = {
        Ellipse(Rational(993, 245), Rational(32, 75), Rational(9, 103), Rational(3609, 52), Rational(68)),
        Ellipse(Rational(55, 41), Rational(349, 142), Rational(59, 101), Rational(15621, 212), Rational(15052, 217)),
        Ellipse::circle(60, 60, 1), Ellipse::circle(80, 60, 1), Ellipse::circle(70, 80, 1)};
    REQUIRE(*relative_position(sites[0], sites[1]) == RelativePosition::intersecting);
    DelaunayGraph graph = test::ellipse_graph(sites);
    graph.insert_all();
    CHECK_THROWS_WITH(cell_areas(graph, sites), Catch::Contains("sites 0 and 1 cross so deeply"));
    const std::vector<Ellipse> apart = {Ellipse::circle(0, 0, 1), Ellipse::circle(3, 0, 1), Ellipse::circle(0, 9, 1)};
    DelaunayGraph g2 = test::ellipse_graph(apart);
    g2.insert_all();
    for (double T : {0.0, -1.0, 2.0, std::nan("")}) {
        CellAreaOptions o;
        o.tolerance = T;
        CHECK_THROWS_AS(cell_areas(g2, apart, o), InputError);
    }
}

TEST_CASE("cell areas: threads do not change the result; edges are shared within a chunk", "[cells]") {
    GeneratorOptions g;
    g.count = 120;
    g.seed = 3;
    const std::vector<Ellipse> sites = generate_sites(g);
    DelaunayGraph graph = test::ellipse_graph(sites);
    graph.insert_all();
    const auto areas = [&](unsigned threads, std::size_t chunk, std::vector<std::size_t>* progress = nullptr) {
        CellAreaOptions o;
        o.threads = threads;
        o.chunk = chunk;
        if (progress) o.progress = [progress](std::size_t done, std::size_t) { progress->push_back(done); };
        return cell_areas(graph, sites, o);
    };
    std::vector<std::size_t> progress;
    const std::vector<CellArea> one = areas(1, 16), three = areas(3, 16, &progress), all = areas(0, 16);
    const std::vector<CellArea> whole = areas(2, 1024);
    // Every call once, in order, the last with the total (the calls come one at a time).
    REQUIRE(progress.size() == sites.size());
    for (std::size_t k = 0; k < progress.size(); ++k) CHECK(progress[k] == k + 1);
    const std::vector<VoronoiCell> cells = voronoi_cells(graph, face_numbers(graph));
    std::size_t bounded = 0, shared_in_chunks = 0, shared_whole = 0, between_bounded = 0;
    for (SiteId s = 0; s < sites.size(); ++s) {
        for (const std::vector<CellArea>* other : {&three, &all}) {
            const CellArea& a = one[s];
            const CellArea& b = (*other)[s];
            CHECK(arb_equal(a.area.get(), b.area.get()));
            CHECK(arb_equal(a.perimeter.get(), b.perimeter.get()));
            for (int i = 0; i < 2; ++i) CHECK(arb_equal(a.centroid[i].get(), b.centroid[i].get()));
            for (int k = 0; k < 3; ++k) CHECK(arb_equal(a.second_moments[k].get(), b.second_moments[k].get()));
            CHECK(a.edges_from_neighbors == b.edges_from_neighbors);
        }
        CHECK(arb_overlaps(one[s].area.get(), whole[s].area.get()));
        if (!cells[s].visible || !cells[s].bounded()) continue;
        ++bounded;
        shared_in_chunks += one[s].edges_from_neighbors;
        shared_whole += whole[s].edges_from_neighbors;
        for (const CellEdge& e : cells[s].edges) between_bounded += cells[e.neighbor].visible && cells[e.neighbor].bounded();
    }
    REQUIRE(bounded >= 60);
    // In one chunk each edge between two bounded cells is integrated once (a
    // cell whose first pass failed integrates its edges again); in chunks of
    // 16 the edges across chunks twice.
    INFO("edges between bounded cells " << between_bounded << ", shared " << shared_whole << " in one chunk, "
                                        << shared_in_chunks << " in chunks of 16");
    CHECK(2 * shared_whole <= between_bounded);
    CHECK(2 * shared_whole >= between_bounded * 9 / 10);
    CHECK(shared_in_chunks < shared_whole);
    CHECK(shared_in_chunks > 0);
}
