#include "output/bisector_trace.hpp"

#include "subdivision/nearest_point.hpp"
#include "subdivision/voronoi_circle_enclosure.hpp"
#include "exact/medial_axis_tangency.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace ellvor {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kTwoPi = 2 * kPi;

double wrap(double x) {  // into [0, 2 pi)
    x = std::fmod(x, kTwoPi);
    if (x < 0) x += kTwoPi;
    if (x >= kTwoPi) x = 0;
    return x;
}

}  // namespace

double DrawingBox::diagonal() const { return std::hypot(width(), height()); }

// ---------------------------------------------------------------- one bisector

namespace {

class Tracer {
public:
    Tracer(const EllipseShape& p, const EllipseShape& q, const TraceOptions& o) : p_(p), q_(q), o_(o) {
        cx_ = 0.5 * (o.box.xmin + o.box.xmax);
        cy_ = 0.5 * (o.box.ymin + o.box.ymax);
        far_ = o.far_distance > 0 ? o.far_distance : 2 * o.box.diagonal();
        cap_ = 1e4 * (far_ + o.box.diagonal());
    }

    // g > 0 exactly on the arc A of tangency angles that have a bisector point.
    double g(double theta) const {
        double nx, ny;
        p_.normal(theta, nx, ny);
        return q_.support(nx, ny) - p_.support(nx, ny);
    }

    // Finds the ends of A; false if A looks empty (q inside p).
    bool find_arc() {
        const int n = 720;
        double best = -std::numeric_limits<double>::infinity(), best_t = 0;
        for (int k = 0; k < n; ++k) {
            const double t = kTwoPi * k / n, v = g(t);
            if (v > best) best = v, best_t = t;
        }
        if (!(best > 0)) return false;
        inner_ = best_t;
        auto end = [&](double dir) {
            const double step = dir * kTwoPi / n;
            double in = inner_, out = inner_ + step;
            for (int k = 0; k < n && g(out) > 0; ++k) in = out, out += step;
            for (int k = 0; k < 80; ++k) {
                const double m = 0.5 * (in + out);
                (g(m) > 0 ? in : out) = m;
            }
            return in;  // the last angle known inside A
        };
        alpha_ccw_ = end(+1);
        alpha_cw_ = end(-1);
        length_ = wrap(alpha_ccw_ - alpha_cw_);
        if (length_ == 0) length_ = kTwoPi;
        return true;
    }

    double u_of(double theta) const { return std::min(std::max(wrap(theta - alpha_cw_), 0.0), length_); }
    double length() const { return length_; }
    double inner_u() const { return u_of(inner_); }

    // The bisector point at u (angle alpha_cw + u on p); empty if rho > cap,
    // or if the point would lie beyond p's medial axis (crossing ellipses only).
    std::optional<BisectorPoint> at(double u) const {
        const double theta = alpha_cw_ + u;
        double px, py, nx, ny;
        p_.point(theta, px, py);
        p_.normal(theta, nx, ny);
        const std::optional<double> rho = equal_distance_on_normal(p_, q_, theta, cap_);
        if (!rho) return std::nullopt;
        return BisectorPoint{px + *rho * nx, py + *rho * ny, theta, *rho};
    }

    // An angle between u_inner and u_end (an end of A, at infinity) whose
    // point is far outside the box, with its point.
    std::pair<double, BisectorPoint> far_end(double u_inner, const BisectorPoint& inner, double u_end) const {
        const double R = std::max(far_, 2 * dist_center(inner));
        auto is_far = [&](const std::optional<BisectorPoint>& b) { return !b || dist_center(*b) >= R; };
        double near_u = u_inner;
        BisectorPoint near_pt = inner;
        for (int k = 1; k <= 200; ++k) {
            const double u = u_end - (u_end - u_inner) * std::ldexp(1.0, -k);
            const auto b = at(u);
            if (is_far(b)) {
                double lo = near_u, hi = u;
                std::optional<BisectorPoint> hi_pt = b;
                for (int it = 0; it < 60; ++it) {
                    const double m = 0.5 * (lo + hi);
                    const auto bm = at(m);
                    if (is_far(bm)) {
                        hi = m, hi_pt = bm;
                    } else {
                        lo = m, near_pt = *bm;
                    }
                }
                if (hi_pt) return {hi, *hi_pt};
                return {lo, near_pt};
            }
            near_u = u;
            near_pt = *b;
        }
        return {near_u, near_pt};
    }

    // Appends the points strictly after `a` up to and including `b`.
    void subdivide(double ua, const BisectorPoint& a, double ub, const BisectorPoint& b, int depth,
                   std::vector<BisectorPoint>& out) const {
        const double chord = std::hypot(a.x - b.x, a.y - b.y);
        // Pieces far outside the box (both ends farther from it than they are
        // from each other) are not refined: they are clipped away.
        const bool outside = box_distance(a) > chord && box_distance(b) > chord;
        if (depth < 60 && chord > o_.tolerance && !outside) {
            const double um = 0.5 * (ua + ub);
            if (const auto m = at(um)) {
                subdivide(ua, a, um, *m, depth + 1, out);
                subdivide(um, *m, ub, b, depth + 1, out);
                return;
            }
        }
        out.push_back(b);
    }

    void trace(double ua, const BisectorPoint& a, double ub, const BisectorPoint& b, std::vector<BisectorPoint>& out) const {
        out.push_back(a);
        // A few uniform pieces first, so that a bulge between two close
        // endpoints is not missed.
        const int pieces = 8;
        double u0 = ua;
        BisectorPoint p0 = a;
        for (int k = 1; k <= pieces; ++k) {
            const double u1 = k == pieces ? ub : ua + (ub - ua) * k / pieces;
            std::optional<BisectorPoint> p1 = k == pieces ? std::optional<BisectorPoint>(b) : at(u1);
            if (!p1) continue;
            subdivide(u0, p0, u1, *p1, 0, out);
            u0 = u1;
            p0 = *p1;
        }
    }

private:
    double dist_center(const BisectorPoint& b) const { return std::hypot(b.x - cx_, b.y - cy_); }
    double box_distance(const BisectorPoint& b) const {
        const double dx = std::max({0.0, o_.box.xmin - b.x, b.x - o_.box.xmax});
        const double dy = std::max({0.0, o_.box.ymin - b.y, b.y - o_.box.ymax});
        return std::hypot(dx, dy);
    }

    const EllipseShape &p_, &q_;
    const TraceOptions& o_;
    double cx_ = 0, cy_ = 0, far_ = 0, cap_ = 0;
    double inner_ = 0, alpha_ccw_ = 0, alpha_cw_ = 0, length_ = 0;
};

}  // namespace

std::vector<BisectorPoint> trace_bisector(const EllipseShape& p, const EllipseShape& q, std::optional<double> from,
                                          std::optional<double> to, const TraceOptions& options, bool* ok) {
    if (ok) *ok = true;
    std::vector<BisectorPoint> out;
    Tracer t(p, q, options);
    if (!t.find_arc()) {
        if (ok) *ok = false;
        return out;
    }
    double u_from = from ? t.u_of(*from) : t.length();
    double u_to = to ? t.u_of(*to) : 0.0;
    if (from && to && u_from < u_to) {
        // Out of order: trace between them anyway (never expected on a valid graph).
        if (ok) *ok = false;
    }
    // The finite ends (and an inner point when both ends are infinite).
    std::optional<BisectorPoint> a = from ? t.at(u_from) : std::nullopt;
    std::optional<BisectorPoint> b = to ? t.at(u_to) : std::nullopt;
    if ((from && !a) || (to && !b)) {
        if (ok) *ok = false;
        return out;
    }
    if (!from && !to) {
        const double um = t.inner_u();
        const auto m = t.at(um);
        if (!m) {
            if (ok) *ok = false;
            return out;
        }
        const auto [ua, pa] = t.far_end(um, *m, t.length());
        const auto [ub, pb] = t.far_end(um, *m, 0.0);
        t.trace(ua, pa, um, *m, out);
        std::vector<BisectorPoint> rest;
        t.trace(um, *m, ub, pb, rest);
        out.insert(out.end(), rest.begin() + 1, rest.end());
        return out;
    }
    if (!from) {
        const auto [ua, pa] = t.far_end(u_to, *b, t.length());
        u_from = ua;
        a = pa;
    }
    if (!to) {
        const auto [ub, pb] = t.far_end(u_from, *a, 0.0);
        u_to = ub;
        b = pb;
    }
    t.trace(u_from, *a, u_to, *b, out);
    return out;
}

// ---------------------------------------------------------------- the diagram

DrawingBox drawing_box(const std::vector<Ellipse>& sites, double margin_fraction) {
    DrawingBox box;
    if (sites.empty()) return {-1, -1, 1, 1};
    box.xmin = box.ymin = std::numeric_limits<double>::infinity();
    box.xmax = box.ymax = -std::numeric_limits<double>::infinity();
    for (const Ellipse& e : sites) {
        const EllipseShape s = EllipseShape::of(e);
        box.xmin = std::min(box.xmin, s.xc - s.half_width());
        box.xmax = std::max(box.xmax, s.xc + s.half_width());
        box.ymin = std::min(box.ymin, s.yc - s.half_height());
        box.ymax = std::max(box.ymax, s.yc + s.half_height());
    }
    const double margin = margin_fraction * box.size();
    box.xmin -= margin, box.xmax += margin, box.ymin -= margin, box.ymax += margin;
    return box;
}

TracedDiagram trace_voronoi_diagram(const DelaunayGraph& graph, const std::vector<Ellipse>& sites,
                                    double tolerance_fraction, double margin_fraction) {
    TracedDiagram d;
    d.box = drawing_box(sites, margin_fraction);
    d.tolerance = tolerance_fraction * d.box.size();
    TraceOptions options;
    options.box = d.box;
    options.tolerance = d.tolerance;

    std::vector<EllipseShape> shapes;
    for (const Ellipse& e : sites) shapes.push_back(EllipseShape::of(e));

    const Triangulation& tds = graph.triangulation();
    if (tds.empty()) {
        const std::vector<SiteId> visible = graph.visible_sites();
        if (visible.size() == 2) {
            VoronoiEdgeArc arc;
            arc.p = visible[0], arc.q = visible[1];
            arc.from_infinity = arc.to_infinity = true;
            arc.points = trace_bisector(shapes[arc.p], shapes[arc.q], std::nullopt, std::nullopt, options);
            if (arc.points.empty()) ++d.failed_edges; else d.arcs.push_back(std::move(arc));
        }
        return d;
    }

    // The Voronoi vertex of every finite face (index into d.vertices).
    std::map<FaceIndex, std::size_t> vertex_of_face;
    for (FaceIndex f : tds.faces()) {
        if (tds.is_infinite_face(f)) continue;
        const Triangulation::Face& F = tds.face(f);
        VoronoiVertexPoint v;
        for (int k = 0; k < 3; ++k) v.face[k] = tds.vertex(F.v[k]).site();
        VoronoiCircleSolver solver(sites[v.face[0]], sites[v.face[1]], sites[v.face[2]], common_medial_axis_tangency);
        if (solver.refine(53)) {
            const VoronoiCircleEnclosure& c = solver.enclosure();
            v.certified = true;
            v.x = c.center_x.mid_double();
            v.y = c.center_y.mid_double();
            v.radius = c.radius.mid_double();
        }
        vertex_of_face[f] = d.vertices.size();
        d.vertices.push_back(v);
    }

    for (FaceIndex f : tds.faces()) {
        const Triangulation::Face& F = tds.face(f);
        for (int i = 0; i < 3; ++i) {
            const FaceIndex g = F.n[i];
            if (g < f || tds.is_infinite_edge({f, i})) continue;  // each finite edge once
            VoronoiEdgeArc arc;
            arc.p = tds.vertex(F.v[ccw(i)]).site();
            arc.q = tds.vertex(F.v[cw(i)]).site();
            arc.left_face = f;
            arc.right_face = g;
            const EllipseShape& P = shapes[arc.p];
            // The left face (f) gives the start, the right face (g) the end.
            std::optional<double> from, to;
            bool failed = false;
            auto angle = [&](FaceIndex face, std::optional<double>& out, bool& infinite) {
                const auto it = vertex_of_face.find(face);
                if (it == vertex_of_face.end()) {
                    infinite = true;
                    return;
                }
                const VoronoiVertexPoint& v = d.vertices[it->second];
                if (!v.certified) failed = true;
                else out = P.nearest_angle(v.x, v.y);
            };
            angle(f, from, arc.from_infinity);
            angle(g, to, arc.to_infinity);
            if (failed) {
                ++d.failed_edges;
                continue;
            }
            bool ok = true;
            arc.points = trace_bisector(P, shapes[arc.q], from, to, options, &ok);
            if (!ok) ++d.misordered_edges;
            if (arc.points.empty()) {
                ++d.failed_edges;
                continue;
            }
            d.arcs.push_back(std::move(arc));
        }
    }
    return d;
}

}  // namespace ellvor
