// Floating-point tracing of the bisector of two ellipses, for drawing only
// (the SVG output). Nothing here decides anything about the graph: the
// combinatorics come from DelaunayGraph, the Voronoi vertices from the
// certified Voronoi circles; this only joins them by polylines.
//
// The bisector of two sites Ep, Eq (disjoint or crossing) is the
// locus of equal signed distance delta (the distance to the boundary,
// negative inside). It is parametrized by the angle theta of the foot point
// on Ep: V = P(theta) + rho n(theta) (n the outward unit normal) has
// delta(V, Ep) = rho for every rho >= 0, and for rho < 0 down to minus the
// depth of Ep's medial axis below P(theta) (EllipseShape::medial_depth; r for
// a circle), and rho solves delta(V(rho), Eq) = rho. f(rho) = delta(V(rho),
// Eq) - rho is nonincreasing (delta is 1-Lipschitz), so rho is found by a
// safeguarded Newton / bisection: on [0, infinity) when P(theta) is outside
// Eq (f(0) > 0), on [-medial_depth, 0] when it is inside (f(0) < 0: V lies in
// both sites, the equal-depth part of the bisector through the lens). A root
// exists iff h_q(n) > h_p(n) (h the support function), i.e. for theta in an
// open arc A of Ep whose two ends are the directions of the external
// bitangents (the two Voronoi vertices at infinity); the arc of Ep inside Eq
// lies within A, and its ends, the crossing points, have rho = 0, so a traced
// Voronoi edge passes through them continuously. (Crossing ellipses that are
// not circles, which the graph accepts (docs/DESIGN.md §9), can do worse for
// the drawing: h_q(n) > h_p(n) on several arcs, of which the tracer follows
// the one around the largest difference; and where the bisector crosses Ep's
// medial axis inside the lens a piece of it has no foot point on Ep, which the
// tracer bridges by a chord.)
//
// Orientation (checked by the tests): for the Delaunay edge p -> q with the
// face f on its left and g on its right, the dual Voronoi edge runs from the
// vertex of f to the vertex of g, and on Ep the tangency angle DEcreases
// along it; an infinite vertex on the left is the counter-clockwise end of A,
// one on the right the clockwise end.
#pragma once

#include "graph/delaunay_graph.hpp"
#include "sites/ellipse.hpp"
#include "subdivision/ellipse_shape.hpp"

#include <optional>
#include <vector>

namespace ellvor {

struct DrawingBox {
    double xmin = 0, ymin = 0, xmax = 1, ymax = 1;
    double width() const { return xmax - xmin; }
    double height() const { return ymax - ymin; }
    double size() const { return width() > height() ? width() : height(); }
    double diagonal() const;
    bool contains(double x, double y, double slack = 0) const {
        return x >= xmin - slack && x <= xmax + slack && y >= ymin - slack && y <= ymax + slack;
    }
};

struct BisectorPoint {
    double x = 0, y = 0;
    double theta = 0;  // tangency angle on the first site
    double rho = 0;    // signed distance to both sites (negative inside both)
};

struct TraceOptions {
    DrawingBox box;
    // Consecutive points of a traced arc are closer than this, except on
    // pieces far outside the box (both ends farther from the box than from
    // each other), which are left coarse since the drawing clips them.
    double tolerance = 0.01;
    // An unbounded end is traced until its points are at least this far from
    // the box's center (0: twice the box's diagonal).
    double far_distance = 0;
};

// The portion of the bisector of (p, q) between two tangency angles on p, in
// the direction of decreasing angle. `from` empty: start at the
// counter-clockwise end of the arc A (infinity); `to` empty: end at its
// clockwise end. Unbounded ends are traced until they are far outside the
// box. `ok` (optional) is false when the angles did not follow that order in
// A (then the arc between them is traced the other way round).
std::vector<BisectorPoint> trace_bisector(const EllipseShape& p, const EllipseShape& q, std::optional<double> from,
                                          std::optional<double> to, const TraceOptions& options,
                                          bool* ok = nullptr);

// One Voronoi edge of the diagram, traced.
struct VoronoiEdgeArc {
    SiteId p = 0, q = 0;                  // the Delaunay edge p -> q (the left face's vertex first)
    bool from_infinity = false, to_infinity = false;
    // The triangulation's faces on the left and right of p -> q (none when
    // the graph has fewer than three visible sites), to name the ends.
    FaceIndex left_face, right_face;
    std::vector<BisectorPoint> points;    // equidistant from p and q, in order
};

struct VoronoiVertexPoint {
    std::array<SiteId, 3> face{};         // counter-clockwise, as in the triangulation
    bool certified = false;
    double x = 0, y = 0, radius = 0;      // radius < 0: inside its three sites (crossing circles)
};

struct TracedDiagram {
    DrawingBox box;
    double tolerance = 0;
    std::vector<VoronoiVertexPoint> vertices;  // one per finite face
    std::vector<VoronoiEdgeArc> arcs;          // one per Voronoi edge drawn
    std::size_t failed_edges = 0;       // an endpoint's Voronoi circle could not be certified
    std::size_t misordered_edges = 0;   // angles out of the expected order (never expected)
};

// The drawing box: the sites' bounding box plus `margin_fraction` of its larger side.
DrawingBox drawing_box(const std::vector<Ellipse>& sites, double margin_fraction);

// Every Voronoi edge of the graph traced within `tolerance_fraction` of the
// box's larger side (the box from drawing_box(sites, margin_fraction)).
TracedDiagram trace_voronoi_diagram(const DelaunayGraph& graph, const std::vector<Ellipse>& sites,
                                    double tolerance_fraction, double margin_fraction);

}  // namespace ellvor
