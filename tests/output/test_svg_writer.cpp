// The SVG drawing of the diagram: structure of the document (balanced tags,
// one root, one <ellipse> per site, one <path> per Voronoi edge, one shaded
// lens per crossing pair, legend counts), and the geometry of the traced
// bisector arcs, checked against a brute-force nearest point (dense samples on
// each ellipse, then a local golden-section refinement): every point is
// equidistant in signed distance from its two sites within the stated
// tolerance and no third site is closer by more than it. Crossing circles:
// the same, and the edge of a crossing pair runs through the crossing points
// that no other site covers.
#include "cells/cell_tessellation.hpp"
#include "graph/delaunay_graph.hpp"
#include "output/bisector_trace.hpp"
#include "output/svg_writer.hpp"
#include "traits/ellipse_delaunay_traits.hpp"
#include "sites/site_generators.hpp"
#include "sites/site_io.hpp"
#include "tests/support/command_runner.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using namespace ellvor;

namespace {

constexpr double kPi = 3.14159265358979323846;

// Checks that the tags are balanced and that there is exactly one root
// element, <svg>; returns "" or a description of the problem.
std::string check_xml(const std::string& s) {
    std::vector<std::string> stack;
    int roots = 0;
    std::string root;
    std::size_t i = 0;
    while ((i = s.find('<', i)) != std::string::npos) {
        if (s.compare(i, 4, "<!--") == 0) {
            const std::size_t e = s.find("-->", i);
            if (e == std::string::npos) return "unterminated comment";
            i = e + 3;
            continue;
        }
        if (s.compare(i, 2, "<?") == 0) {
            if (!stack.empty() || roots) return "processing instruction inside the document";
            const std::size_t e = s.find("?>", i);
            if (e == std::string::npos) return "unterminated <?";
            i = e + 2;
            continue;
        }
        const std::size_t e = s.find('>', i);
        if (e == std::string::npos) return "unterminated tag";
        std::string tag = s.substr(i + 1, e - i - 1);
        i = e + 1;
        if (tag.find('<') != std::string::npos) return "'<' inside a tag: " + tag;
        if (!tag.empty() && tag[0] == '/') {
            const std::string name = tag.substr(1);
            if (stack.empty() || stack.back() != name) return "unbalanced </" + name + ">";
            stack.pop_back();
            continue;
        }
        const bool self_closing = !tag.empty() && tag.back() == '/';
        const std::string name = tag.substr(0, tag.find_first_of(" \t\n/"));
        if (name.empty()) return "empty tag";
        if (stack.empty()) {
            ++roots;
            root = name;
        }
        if (!self_closing) stack.push_back(name);
    }
    if (!stack.empty()) return "unclosed <" + stack.back() + ">";
    if (roots != 1 || root != "svg") return "expected one <svg> root, found " + std::to_string(roots) + " roots";
    // Nothing but white space outside the root (after the comments and the declaration).
    return "";
}

std::size_t count(const std::string& s, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t i = s.find(what); i != std::string::npos; i = s.find(what, i + 1)) ++n;
    return n;
}

long attribute(const std::string& s, const std::string& name) {
    std::smatch m;
    if (!std::regex_search(s, m, std::regex(name + "=\"([0-9]+)\""))) return -1;
    return std::stol(m[1]);
}

// Brute-force distance from (x, y) to an ellipse: the best of dense samples,
// refined by golden-section search between its neighbours (the squared
// distance is unimodal there once the samples are dense enough). Negative
// inside.
struct BruteForce {
    EllipseShape e;
    std::vector<double> xs, ys;
    static constexpr int kSamples = 1024;

    explicit BruteForce(const Ellipse& site) : e(EllipseShape::of(site)) {
        for (int k = 0; k < kSamples; ++k) {
            double x, y;
            e.point(2 * kPi * k / kSamples, x, y);
            xs.push_back(x);
            ys.push_back(y);
        }
    }
    double distance(double x, double y) const {
        int best = 0;
        double best_d = INFINITY;
        for (int k = 0; k < kSamples; ++k) {
            const double d = (xs[k] - x) * (xs[k] - x) + (ys[k] - y) * (ys[k] - y);
            if (d < best_d) best_d = d, best = k;
        }
        auto d2 = [&](double t) {
            double px, py;
            e.point(t, px, py);
            return (px - x) * (px - x) + (py - y) * (py - y);
        };
        double lo = 2 * kPi * (best - 1) / kSamples, hi = 2 * kPi * (best + 1) / kSamples;
        const double r = 0.5 * (std::sqrt(5.0) - 1);
        double m1 = hi - r * (hi - lo), m2 = lo + r * (hi - lo), f1 = d2(m1), f2 = d2(m2);
        for (int it = 0; it < 60; ++it) {
            if (f1 < f2) hi = m2, m2 = m1, f2 = f1, m1 = hi - r * (hi - lo), f1 = d2(m1);
            else lo = m1, m1 = m2, f1 = f2, m2 = lo + r * (hi - lo), f2 = d2(m2);
        }
        const double d = std::sqrt(std::min({best_d, f1, f2}));
        return e.inside(x, y) ? -d : d;
    }
};

struct Built {
    std::vector<Ellipse> sites;
    DelaunayGraph graph;
    TracedDiagram diagram;
    std::string svg;
    explicit Built(std::vector<Ellipse> s, bool ids = true)
        : sites(s), graph(std::make_unique<EllipseDelaunayTraits>(std::move(s))) {
        graph.insert_all();
        SvgOptions o;
        o.show_ids = ids;
        std::ostringstream out;
        diagram = write_svg(out, graph, sites, o);
        svg = out.str();
    }
};

void check_document(const Built& b) {
    const std::string& svg = b.svg;
    INFO(svg.substr(0, 2000));
    CHECK(check_xml(svg) == "");
    const auto edges = b.graph.edges();
    const auto faces = b.graph.faces();
    const auto hidden = b.graph.hidden();
    // One ellipse element per site, the hidden ones dashed.
    CHECK(count(svg, "<ellipse data-site=") == b.sites.size());
    std::size_t dashed = 0;
    for (std::size_t i = svg.find("<ellipse data-site="); i != std::string::npos; i = svg.find("<ellipse data-site=", i + 1))
        if (svg.substr(i, svg.find('>', i) - i).find("stroke-dasharray") != std::string::npos) ++dashed;
    CHECK(dashed == hidden.size());
    // One path per Voronoi edge drawn; every Voronoi edge is drawn (one per
    // Delaunay edge of the graph, counted with multiplicity).
    CHECK(count(svg, "<path ") == b.diagram.arcs.size());
    CHECK(b.diagram.failed_edges == 0);
    CHECK(b.diagram.misordered_edges == 0);
    CHECK(b.diagram.arcs.size() == edges.size());
    CHECK(b.diagram.vertices.size() == faces.size());
    // The legend's counts.
    const std::string legend = svg.substr(svg.find("<g id=\"legend\""));
    CHECK(attribute(legend, "data-sites") == long(b.sites.size()));
    CHECK(attribute(legend, "data-hidden") == long(hidden.size()));
    CHECK(attribute(legend, "data-delaunay-edges") == long(edges.size()));
    CHECK(attribute(legend, "data-voronoi-vertices") == long(faces.size()));
    CHECK(legend.find(">sites: " + std::to_string(b.sites.size()) + "<") != std::string::npos);
    CHECK(legend.find(">hidden: " + std::to_string(hidden.size()) + "<") != std::string::npos);
    CHECK(legend.find(">Delaunay edges: " + std::to_string(edges.size()) + "<") != std::string::npos);
    CHECK(legend.find(">Voronoi vertices: " + std::to_string(faces.size()) + "<") != std::string::npos);
    // One shaded lens per crossing pair (the ellipses of the overlap group),
    // and a legend row only when there are any.
    const long overlaps = attribute(legend, "data-overlaps");
    CHECK(long(count(svg, "<ellipse data-sites=")) == overlaps);
    CHECK((svg.find("<g id=\"overlaps\"") != std::string::npos) == (overlaps > 0));
    CHECK((legend.find(">overlapping pairs: " + std::to_string(overlaps) + "<") != std::string::npos) == (overlaps > 0));
    // A title, and the tolerance stated in a comment.
    CHECK(count(svg, "<title>") == 1);
    CHECK(svg.find("tolerance") < svg.find("<svg"));
    CHECK(svg.find("(0.5% of the drawing box") != std::string::npos);
}

// Every point of every arc: equidistant from its two sites, no third site
// closer (both within the tolerance); consecutive points inside the box closer
// than the tolerance; finite ends at their Voronoi vertices.
void check_geometry(const Built& b) {
    const double tol = b.diagram.tolerance;
    REQUIRE(tol > 0);
    std::vector<BruteForce> brute;
    for (const Ellipse& e : b.sites) brute.emplace_back(e);
    std::size_t points = 0;
    double worst_equidistance = 0, worst_side = 0;
    for (const VoronoiEdgeArc& arc : b.diagram.arcs) {
        REQUIRE(arc.points.size() >= 2);
        for (std::size_t k = 0; k < arc.points.size(); ++k) {
            const BisectorPoint& pt = arc.points[k];
            const double dp = brute[arc.p].distance(pt.x, pt.y), dq = brute[arc.q].distance(pt.x, pt.y);
            worst_equidistance = std::max(worst_equidistance, std::fabs(dp - dq));
            INFO("arc " << arc.p << " " << arc.q << " point " << k << " (" << pt.x << ", " << pt.y << ")");
            CHECK(std::fabs(dp - dq) <= tol);
            CHECK(std::fabs(dp - pt.rho) <= tol);
            for (SiteId s = 0; s < b.sites.size(); ++s) {
                if (s == arc.p || s == arc.q) continue;
                const double ds = brute[s].distance(pt.x, pt.y);
                worst_side = std::max(worst_side, dp - ds);
                CHECK(ds >= dp - tol);
            }
            if (k > 0) {
                const BisectorPoint& prev = arc.points[k - 1];
                if (b.diagram.box.contains(pt.x, pt.y) && b.diagram.box.contains(prev.x, prev.y))
                    CHECK(std::hypot(pt.x - prev.x, pt.y - prev.y) <= tol);
            }
            ++points;
        }
        // Finite ends are at a certified Voronoi vertex.
        auto at_vertex = [&](const BisectorPoint& pt) {
            for (const VoronoiVertexPoint& v : b.diagram.vertices)
                if (v.certified && std::hypot(v.x - pt.x, v.y - pt.y) <= tol) return true;
            return false;
        };
        if (!arc.from_infinity) CHECK(at_vertex(arc.points.front()));
        if (!arc.to_infinity) CHECK(at_vertex(arc.points.back()));
        // Unbounded ends leave the drawing box.
        if (arc.from_infinity) CHECK(!b.diagram.box.contains(arc.points.front().x, arc.points.front().y));
        if (arc.to_infinity) CHECK(!b.diagram.box.contains(arc.points.back().x, arc.points.back().y));
    }
    CHECK(points > 0);
    // Far below the tolerance in practice (the root solve is ~1e-12 relative).
    CHECK(worst_equidistance <= 1e-3 * tol);
    CHECK(worst_side <= 1e-3 * tol);
}

// Circle sites in doubles (exact for the integer data of these tests).
struct Disk {
    double x, y, r;
};

Disk disk(const Ellipse& e) {
    REQUIRE(e.is_circle());
    return {e.xc().to_double(), e.yc().to_double(), e.a().to_double()};
}

double signed_distance(const Disk& c, double x, double y) { return std::hypot(x - c.x, y - c.y) - c.r; }

bool cross(const Disk& c, const Disk& d) {
    const double d2 = (c.x - d.x) * (c.x - d.x) + (c.y - d.y) * (c.y - d.y);
    return d2 < (c.r + d.r) * (c.r + d.r) && d2 > (c.r - d.r) * (c.r - d.r);
}

// The two points where the boundaries of crossing circles meet: on the line
// of the centers at distance l from c's, and h to either side.
std::array<std::array<double, 2>, 2> crossing_points(const Disk& c, const Disk& d) {
    const double dx = d.x - c.x, dy = d.y - c.y, len = std::hypot(dx, dy);
    const double l = (len * len + c.r * c.r - d.r * d.r) / (2 * len), h = std::sqrt(c.r * c.r - l * l);
    const double mx = c.x + l * dx / len, my = c.y + l * dy / len;
    return {{{mx - h * dy / len, my + h * dx / len}, {mx + h * dy / len, my - h * dx / len}}};
}

double segment_distance(const BisectorPoint& a, const BisectorPoint& b, double x, double y) {
    const double ux = b.x - a.x, uy = b.y - a.y, len2 = ux * ux + uy * uy;
    const double t = len2 > 0 ? std::clamp(((x - a.x) * ux + (y - a.y) * uy) / len2, 0.0, 1.0) : 0;
    return std::hypot(a.x + t * ux - x, a.y + t * uy - y);
}

// Distance from (x, y) to the polyline.
double polyline_distance(const std::vector<BisectorPoint>& pts, double x, double y) {
    double best = INFINITY;
    for (std::size_t k = 1; k < pts.size(); ++k) best = std::min(best, segment_distance(pts[k - 1], pts[k], x, y));
    return best;
}

// For a drawing of circles: the overlap count is the number of crossing pairs
// of visible sites; every crossing point of such a pair that no other visible
// site covers (nor comes within the tolerance of) is on the Voronoi edge of
// the pair, so a traced arc of the pair passes through it. Returns the number
// of crossing points so checked.
std::size_t check_crossings(const Built& b) {
    const double tol = b.diagram.tolerance;
    std::set<SiteId> hidden;
    for (const auto& h : b.graph.hidden()) hidden.insert(h.first);
    std::vector<Disk> disks;
    for (const Ellipse& e : b.sites) disks.push_back(disk(e));
    long pairs = 0;
    std::size_t checked = 0;
    for (SiteId p = 0; p < disks.size(); ++p)
        for (SiteId q = p + 1; q < disks.size(); ++q) {
            if (hidden.count(p) || hidden.count(q) || !cross(disks[p], disks[q])) continue;
            ++pairs;
            for (const auto& [x, y] : crossing_points(disks[p], disks[q])) {
                bool covered = false;
                for (SiteId s = 0; s < disks.size(); ++s)
                    if (s != p && s != q && !hidden.count(s) && signed_distance(disks[s], x, y) <= tol) covered = true;
                if (covered) continue;
                double nearest = INFINITY;
                for (const VoronoiEdgeArc& arc : b.diagram.arcs)
                    if (std::set<SiteId>{arc.p, arc.q} == std::set<SiteId>{p, q})
                        nearest = std::min(nearest, polyline_distance(arc.points, x, y));
                INFO("sites " << p << " " << q << " crossing point (" << x << ", " << y << ")");
                CHECK(nearest <= 1e-2 * tol);
                ++checked;
            }
        }
    CHECK(attribute(b.svg.substr(b.svg.find("<g id=\"legend\"")), "data-overlaps") == pairs);
    return checked;
}

// Overlapping circles with integer data: centers in [0, 60]^2, radii 3 to 12
// (crossing, nested and disjoint pairs; no two identical).
std::vector<Ellipse> overlapping_circles(std::uint64_t seed, int n) {
    std::mt19937_64 rng(seed);
    std::uniform_int_distribution<long> coordinate(0, 60), radius(3, 12);
    std::vector<Ellipse> sites;
    std::set<std::array<long, 3>> seen;
    while (int(sites.size()) < n) {
        const std::array<long, 3> c = {coordinate(rng), coordinate(rng), radius(rng)};
        if (seen.insert(c).second) sites.push_back(Ellipse::circle(Rational(c[0]), Rational(c[1]), Rational(c[2])));
    }
    return sites;
}

}  // namespace

TEST_CASE("svg: the bundled example is drawn completely", "[graph][svg]") {
    Built b(read_sites(std::string(ELLVOR_SOURCE_DIR) + "/data/example.ell"));
    check_document(b);
    CHECK(count(b.svg, "<text") >= b.sites.size());  // the ids
    check_geometry(b);
}

TEST_CASE("svg: traced arcs of random ellipses lie on their bisectors, on the right side", "[graph][svg]") {
    for (std::uint64_t seed : {3u, 11u}) {
        GeneratorOptions g;
        g.count = 12;
        g.seed = seed;
        g.nested_fraction = Rational(1, 6);
        Built b(generate_sites(g), false);
        INFO("seed " << seed);
        check_document(b);
        check_geometry(b);
    }
    GeneratorOptions g;
    g.kind = SiteKind::circles;
    g.count = 10;
    g.seed = 5;
    Built b(generate_sites(g), false);
    check_document(b);
    check_geometry(b);
}

TEST_CASE("svg: two visible sites give one bisector unbounded both ways", "[graph][svg]") {
    // Two ellipses and one hidden in the first.
    std::vector<Ellipse> sites = {Ellipse(Rational(4), Rational(1), Rational(1, 3), Rational(0), Rational(0)),
                                  Ellipse(Rational(2), Rational(3, 2), Rational(0), Rational(9), Rational(2)),
                                  Ellipse::circle(Rational(1, 2), Rational(0), Rational(1, 2))};
    Built b(sites);
    check_document(b);
    REQUIRE(b.diagram.arcs.size() == 1);
    CHECK(b.diagram.arcs[0].from_infinity);
    CHECK(b.diagram.arcs[0].to_infinity);
    check_geometry(b);
}

TEST_CASE("svg: a single site and no site draw no Voronoi edge", "[graph][svg]") {
    Built one({Ellipse::circle(Rational(0), Rational(0), Rational(1))});
    check_document(one);
    CHECK(one.diagram.arcs.empty());
    Built none(std::vector<Ellipse>{});
    CHECK(check_xml(none.svg) == "");
    CHECK(count(none.svg, "<ellipse ") == 0);
}

TEST_CASE("svg: the tracer's parametrization runs along the arc of tangency angles", "[graph][svg]") {
    // Two unit circles at (0, 0) and (4, 0): the bisector is the line x = 2,
    // and the tangency angle on the first decreases from top to bottom.
    const EllipseShape p = EllipseShape::of(Ellipse::circle(Rational(0), Rational(0), Rational(1)));
    const EllipseShape q = EllipseShape::of(Ellipse::circle(Rational(4), Rational(0), Rational(1)));
    TraceOptions o;
    o.box = {-2, -4, 6, 4};
    o.tolerance = 0.04;
    const auto pts = trace_bisector(p, q, std::nullopt, std::nullopt, o);
    REQUIRE(pts.size() > 10);
    CHECK(pts.front().y > 4);
    CHECK(pts.back().y < -4);
    for (const BisectorPoint& pt : pts) CHECK(pt.x == Approx(2).margin(1e-9));
    for (std::size_t k = 1; k < pts.size(); ++k) CHECK(pts[k].y < pts[k - 1].y);
    // Between two given angles (+45 and -45 degrees on p): from (2, 2) down to (2, -2).
    const auto part = trace_bisector(p, q, kPi / 4, -kPi / 4, o);
    REQUIRE(part.size() >= 2);
    CHECK(part.front().y == Approx(2).margin(1e-9));
    CHECK(part.back().y == Approx(-2).margin(1e-9));
}

TEST_CASE("svg: ellvor build --svg writes the drawing; --svg-ids needs --svg", "[graph][svg][cli]") {
    ellvor::test::ScratchDirectory dir;
    const std::string example = std::string(ELLVOR_SOURCE_DIR) + "/data/example.ell";
    const auto r = dir.ellvor("build '" + example + "' --svg '" + dir.path() + "/d.svg' --svg-ids");
    INFO(r.out << r.err);
    REQUIRE(r.status == 0);
    const std::string svg = ellvor::test::read_file(dir.path() + "/d.svg");
    CHECK(check_xml(svg) == "");
    CHECK(count(svg, "<ellipse ") == 20);
    CHECK(attribute(svg, "data-hidden") == 4);
    const auto bad = dir.ellvor("build '" + example + "' --svg-ids");
    CHECK(bad.status == 2);
    const auto help = dir.ellvor("build --help");
    CHECK(ellvor::test::contains(help.out, "0.5% of the drawing box"));
}

TEST_CASE("svg: nearest points and signed distances inside an ellipse", "[svg]") {
    // Inside points, many inside the evolute (where the normals of three
    // boundary points or more pass through them), on the axes and at the
    // center; both a > b and a < b; against the brute force.
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> unit(-1, 1);
    const std::vector<Ellipse> shapes = {Ellipse(Rational(5), Rational(1), Rational(1, 3), Rational(2), Rational(-1)),
                                         Ellipse(Rational(1), Rational(3), Rational(0), Rational(0), Rational(0)),
                                         Ellipse(Rational(2), Rational(2), Rational(0), Rational(1), Rational(1)),
                                         Ellipse(Rational(7, 2), Rational(3), Rational(-2), Rational(0), Rational(4))};
    for (const Ellipse& site : shapes) {
        const BruteForce brute(site);
        const EllipseShape& e = brute.e;
        std::vector<std::array<double, 2>> local = {{0, 0}, {0.5 * e.a, 0}, {0.99 * e.a, 0}, {0, 0.5 * e.b}, {0, 0.99 * e.b},
                                                    {0.3 * e.a, 1e-9 * e.b}, {1e-9 * e.a, 0.3 * e.b}};
        while (local.size() < 300) {
            const double u = unit(rng), v = unit(rng);
            if (u * u + v * v < 1) local.push_back({u * e.a, v * e.b});
        }
        for (const auto& [u, v] : local) {
            const double x = e.xc + u * e.c - v * e.s, y = e.yc + u * e.s + v * e.c;
            INFO(site.str() << " at (" << x << ", " << y << ")");
            const double d = e.signed_distance(x, y);
            CHECK(d < 0);
            CHECK(d == Approx(brute.distance(x, y)).margin(1e-9 * e.a));
        }
        // A foot point stays the nearest point down the inward normal up to
        // the medial axis, not beyond it (unless the site is a circle: there
        // the axis is the center).
        for (double theta : {0.0, 0.3, 1.2, 2.0, 4.5}) {
            double px, py, nx, ny;
            e.point(theta, px, py);
            e.normal(theta, nx, ny);
            const double m = e.medial_depth(theta);
            INFO(site.str() << " theta " << theta);
            CHECK(e.signed_distance(px - 0.999 * m * nx, py - 0.999 * m * ny) == Approx(-0.999 * m).margin(1e-9 * e.a));
            if (!site.is_circle())
                CHECK(e.signed_distance(px - 1.01 * m * nx, py - 1.01 * m * ny) > -1.01 * m + 1e-6 * e.a);
        }
    }
}

TEST_CASE("svg: the bisector of two crossing circles runs through their crossing points", "[svg]") {
    TraceOptions o;
    o.box = {-3, -4, 6, 4};
    o.tolerance = 0.04;
    // Equal radii: the line x = 3/2 through (3/2, +-sqrt(7)/2); inside both
    // circles (|y| < sqrt(7)/2) the signed distance rho is negative.
    {
        const Disk c = {0, 0, 2}, d = {3, 0, 2};
        const EllipseShape p = EllipseShape::of(Ellipse::circle(Rational(0), Rational(0), Rational(2)));
        const EllipseShape q = EllipseShape::of(Ellipse::circle(Rational(3), Rational(0), Rational(2)));
        const auto pts = trace_bisector(p, q, std::nullopt, std::nullopt, o);
        REQUIRE(pts.size() > 10);
        CHECK(pts.front().y > 4);
        CHECK(pts.back().y < -4);
        std::size_t inside = 0;
        for (std::size_t k = 0; k < pts.size(); ++k) {
            const BisectorPoint& pt = pts[k];
            INFO("point " << k << " (" << pt.x << ", " << pt.y << ")");
            CHECK(pt.x == Approx(1.5).margin(1e-9));
            CHECK(pt.rho == Approx(signed_distance(c, pt.x, pt.y)).margin(1e-9));
            CHECK(pt.rho == Approx(signed_distance(d, pt.x, pt.y)).margin(1e-9));
            CHECK((pt.rho < 0) == (std::fabs(pt.y) < std::sqrt(7.0) / 2));
            if (pt.rho < 0) ++inside;
            if (k > 0) CHECK(pts[k].y < pts[k - 1].y);       // the tangency angle on p decreases
            if (k > 0) CHECK(pts[k].theta < pts[k - 1].theta);
        }
        CHECK(inside > 10);
        for (const auto& [x, y] : crossing_points(c, d)) CHECK(polyline_distance(pts, x, y) <= 1e-2 * o.tolerance);
        // Between two given angles, one outside q and one inside: from
        // (3/2, 2) down to the lens's middle (3/2, 0), rho = -1/2.
        const auto part = trace_bisector(p, q, std::atan2(2.0, 1.5), 0.0, o);
        REQUIRE(part.size() >= 2);
        CHECK(part.front().y == Approx(2).margin(1e-9));
        CHECK(part.back().y == Approx(0).margin(1e-9));
        CHECK(part.back().rho == Approx(-0.5).margin(1e-9));
    }
    // Different radii, a deep crossing: a hyperbola branch, |V| - |V - D| = 1.
    {
        const Disk c = {0, 0, 3}, d = {2, 1, 2};
        const EllipseShape p = EllipseShape::of(Ellipse::circle(Rational(0), Rational(0), Rational(3)));
        const EllipseShape q = EllipseShape::of(Ellipse::circle(Rational(2), Rational(1), Rational(2)));
        for (bool swap : {false, true}) {
            const auto pts = swap ? trace_bisector(q, p, std::nullopt, std::nullopt, o)
                                  : trace_bisector(p, q, std::nullopt, std::nullopt, o);
            REQUIRE(pts.size() > 10);
            double lowest = 0;
            for (const BisectorPoint& pt : pts) {
                CHECK(signed_distance(c, pt.x, pt.y) == Approx(signed_distance(d, pt.x, pt.y)).margin(1e-9));
                CHECK(pt.rho == Approx(signed_distance(c, pt.x, pt.y)).margin(1e-9));
                lowest = std::min(lowest, pt.rho);
            }
            CHECK(lowest < -0.5);
            for (const auto& [x, y] : crossing_points(c, d)) CHECK(polyline_distance(pts, x, y) <= 1e-2 * o.tolerance);
        }
    }
}

TEST_CASE("svg: crossing circles: traced edges on their bisectors through the crossing points, overlaps shaded",
          "[graph][svg][overlap]") {
    // Two pairs crossing, a third circle through both lenses: the common part
    // of 0, 1, 2 holds an internal Voronoi vertex (negative radius).
    {
        std::vector<Ellipse> sites = {Ellipse::circle(Rational(0), Rational(0), Rational(2)),
                                      Ellipse::circle(Rational(3), Rational(0), Rational(2)),
                                      Ellipse::circle(Rational(3, 2), Rational(5, 2), Rational(3, 2)),
                                      Ellipse::circle(Rational(7), Rational(1), Rational(1)),
                                      Ellipse::circle(Rational(-4), Rational(3), Rational(1))};
        Built b(sites);
        check_document(b);
        check_geometry(b);
        CHECK(check_crossings(b) == 3);  // of each pair's two crossing points one is in the third circle
        CHECK(attribute(b.svg, "data-overlaps") == 3);
        CHECK(count(b.svg, "<clipPath id=\"site-") == 2);
        bool internal = false;
        for (const VoronoiVertexPoint& v : b.diagram.vertices)
            if (v.radius < 0) {
                internal = true;
                CHECK(v.x == Approx(1.5));
                CHECK(v.y == Approx(1.125));
                CHECK(v.radius == Approx(-0.125));
            }
        CHECK(internal);
    }
    // Two crossing circles alone (and one hidden in the first): one bisector,
    // unbounded both ways, through the lens.
    {
        Built b({Ellipse::circle(Rational(0), Rational(0), Rational(3)), Ellipse::circle(Rational(2), Rational(1), Rational(2)),
                 Ellipse::circle(Rational(-1), Rational(0), Rational(1))});
        check_document(b);
        REQUIRE(b.diagram.arcs.size() == 1);
        CHECK(b.diagram.arcs[0].from_infinity);
        CHECK(b.diagram.arcs[0].to_infinity);
        check_geometry(b);
        CHECK(check_crossings(b) == 2);
    }
    // Random sets.
    std::size_t checked = 0, negative = 0, internal = 0;
    for (std::uint64_t seed : {1u, 2u, 3u, 4u}) {
        Built b(overlapping_circles(seed, 14), false);
        INFO("seed " << seed);
        check_document(b);
        check_geometry(b);
        checked += check_crossings(b);
        for (const VoronoiEdgeArc& arc : b.diagram.arcs)
            for (const BisectorPoint& pt : arc.points) negative += pt.rho < 0;
        for (const VoronoiVertexPoint& v : b.diagram.vertices) internal += v.radius < 0;
    }
    // (68 crossing points, 1552 points inside both sites, 6 internal vertices.)
    CHECK(checked >= 40);
    CHECK(negative >= 500);
    CHECK(internal >= 2);
}

TEST_CASE("svg: a drawing without crossing sites has no overlap shading", "[graph][svg][overlap]") {
    GeneratorOptions g;
    g.kind = SiteKind::circles;
    g.count = 10;
    g.seed = 5;
    g.nested_fraction = Rational(1, 5);
    Built b(generate_sites(g), false);
    check_document(b);
    CHECK(attribute(b.svg, "data-overlaps") == 0);
    CHECK(b.svg.find("<g id=\"overlaps\"") == std::string::npos);
    CHECK(count(b.svg, "<clipPath ") == 1);  // the drawing box only
}

TEST_CASE("svg: cells coloured by packing fraction, from rings or on the sites", "[output][svg]") {
    std::istringstream in("1 1/2 0 0 0\n1 1 0 4 0\n1/2 1/2 0 2 3\n2 1 1/3 1 -4\n1 1 0 5 5\n1/4 1/4 0 4 0\n3/2 1 0 -4 1\n");
    const std::vector<Ellipse> sites = read_sites(in, "s");
    DelaunayGraph graph(std::make_unique<EllipseDelaunayTraits>(sites));
    graph.insert_all();
    CellTessellation cells = cell_tessellation(sites, CellDomain{});
    std::vector<SiteId> bounded;
    for (const Cell& c : cells.cells)
        if (c.bounded) bounded.push_back(c.site);
    REQUIRE(bounded.size() == 2);
    for (bool rings : {false, true}) {
        CellTessellation drawn = cells;
        for (Cell& c : drawn.cells) c.ring.clear();
        if (rings)  // rings given: a triangle around each bounded cell's site
            for (SiteId s : bounded) {
                const double x = sites[s].xc().to_double(), y = sites[s].yc().to_double();
                drawn.cells[s].ring = {{x - 2, y - 2}, {x + 2, y - 2}, {x, y + 2}};
            }
        SvgOptions o;
        o.cells = &drawn;
        std::ostringstream out;
        write_svg(out, graph, sites, o);
        const std::string svg = out.str();
        INFO(svg.substr(svg.find("<g id=\"legend\"")));
        CHECK(check_xml(svg) == "");
        CHECK(count(svg, "<polygon data-site=") == (rings ? 2u : 0u));
        CHECK(svg.find(std::string("data-rings=\"") + (rings ? "yes" : "no") + "\"") != std::string::npos);
        CHECK(svg.find("data-colored-cells=\"2\"") != std::string::npos);
        // The two ends of the scale, on the cells or on their sites.
        CHECK(svg.find("fill=\"#fde725\"") != std::string::npos);
        CHECK(svg.find("fill=\"#440154\"") != std::string::npos);
    }
}
