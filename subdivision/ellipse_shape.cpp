#include "subdivision/ellipse_shape.hpp"

#include "subdivision/nearest_point.hpp"

#include <algorithm>
#include <cmath>

namespace ellvor {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The angle in [0, pi/2] of the point (a cos t, b sin t) nearest to (X, Y),
// a point inside with X, Y >= 0 and a >= b. At the nearest point P the
// normal passes through (X, Y): (X, Y) - P = lambda (P_x / a^2, P_y / b^2),
// so with s = lambda + b^2, cos t = a X / (s + a^2 - b^2) and sin t = b Y / s,
// and s is the root of F(s) = cos^2 t + sin^2 t - 1. F decreases on s > 0,
// where its one root is the nearest point (Eberly, "Distance from a point to
// an ellipse"); F(b Y) >= 0 and, the point being inside, F(b^2) < 0. F is
// convex, so Newton from the left stays in the bracket; bisection guards it.
double inner_nearest_angle(double a, double b, double X, double Y) {
    const double e = (a - b) * (a + b), ax = a * X, by = b * Y;
    if (Y == 0) {
        // On the major axis: the vertex, or off the medial axis's segment
        // |x| < e / a the point above it whose normal passes through (X, 0).
        return ax >= e ? 0 : std::acos(ax / e);
    }
    auto F = [&](double s, double* slope) {
        const double cx = ax / (s + e), sy = by / s;
        if (slope) *slope = -2 * (cx * cx / (s + e) + sy * sy / s);
        return cx * cx + sy * sy - 1;
    };
    double lo = by, hi = b * b, s = lo;
    for (int it = 0; it < 200; ++it) {
        double slope;
        const double v = F(s, &slope);
        if (v == 0) break;
        (v > 0 ? lo : hi) = s;
        double next = slope < 0 ? s - v / slope : 0.5 * (lo + hi);
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        const bool done = std::fabs(next - s) <= 1e-15 * s || hi - lo <= 1e-15 * hi;
        s = next;
        if (done) break;
    }
    return std::atan2(by / s, ax / (s + e));
}

}  // namespace

// ---------------------------------------------------------------- EllipseShape

EllipseShape EllipseShape::of(const Ellipse& e) {
    // The nearest doubles of the parameters, as to_double gives them: up(lo)
    // of the ellipse's kept enclosures (util/interval.hpp, enclose), + 0.0
    // making -0 +0 (the rationals' conversions cost Arb divisions).
    const Ellipse::Enclosure k = e.enclosure();
    const auto nearest = [](const Interval& x) { return Interval::up(x.lo) + 0.0; };
    EllipseShape s;
    s.a = nearest(k.a);
    s.b = nearest(k.b);
    s.c = nearest(k.cos);
    s.s = nearest(k.sin);
    s.xc = nearest(k.xc);
    s.yc = nearest(k.yc);
    return s;
}

void EllipseShape::point(double theta, double& x, double& y) const {
    const double lx = a * std::cos(theta), ly = b * std::sin(theta);
    x = xc + lx * c - ly * s;
    y = yc + lx * s + ly * c;
}

void EllipseShape::normal(double theta, double& nx, double& ny) const {
    const double lx = b * std::cos(theta), ly = a * std::sin(theta);
    const double len = std::hypot(lx, ly);
    nx = (lx * c - ly * s) / len;
    ny = (lx * s + ly * c) / len;
}

bool EllipseShape::inside(double x, double y) const {
    const double dx = x - xc, dy = y - yc;
    const double lx = dx * c + dy * s, ly = -dx * s + dy * c;
    return (lx / a) * (lx / a) + (ly / b) * (ly / b) < 1;
}

double EllipseShape::nearest_angle(double x, double y) const {
    const double dx = x - xc, dy = y - yc;
    const double lx = dx * c + dy * s, ly = -dx * s + dy * c;
    // Fold into the first quadrant, which holds a nearest point.
    const double X = std::fabs(lx), Y = std::fabs(ly);
    double t;
    if (inside(x, y)) {
        // g below can have three zeros there (inside the evolute); the
        // formulation of inner_nearest_angle has one.
        t = a >= b ? inner_nearest_angle(a, b, X, Y) : kPi / 2 - inner_nearest_angle(b, a, Y, X);
    } else {
        // The nearest point of a point outside is the unique zero of g (the
        // derivative of half the squared distance, up to sign): g(0) = -b Y <= 0,
        // g(pi/2) = a X >= 0.
        auto g = [&](double t) { return a * X * std::sin(t) - b * Y * std::cos(t) - (a * a - b * b) * std::sin(t) * std::cos(t); };
        double lo = 0, hi = kPi / 2;
        t = approximate_nearest_angle(a, b, X, Y);  // the library's guess, kept when it is in the quadrant
        if (!(t > lo && t < hi)) t = std::atan2(a * Y, b * X);
        for (int it = 0; it < 100; ++it) {
            const double gt = g(t);
            if (gt == 0) break;
            if (gt < 0) lo = t; else hi = t;
            const double dg = a * X * std::cos(t) + b * Y * std::sin(t) - (a * a - b * b) * (std::cos(t) * std::cos(t) - std::sin(t) * std::sin(t));
            double next = dg > 0 ? t - gt / dg : 0.5 * (lo + hi);
            if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
            if (std::fabs(next - t) < 1e-15 || hi - lo < 1e-15) {
                t = next;
                break;
            }
            t = next;
        }
    }
    // Unfold.
    return std::atan2(ly < 0 ? -std::sin(t) : std::sin(t), lx < 0 ? -std::cos(t) : std::cos(t));
}

double EllipseShape::signed_distance(double x, double y) const {
    double px, py;
    point(nearest_angle(x, y), px, py);
    const double d = std::hypot(x - px, y - py);
    return inside(x, y) ? -d : d;
}

double EllipseShape::medial_depth(double theta) const {
    return std::min(a, b) / std::max(a, b) * std::hypot(b * std::cos(theta), a * std::sin(theta));
}

double EllipseShape::support(double nx, double ny) const {
    const double nu = nx * c + ny * s, nv = -nx * s + ny * c;
    return nx * xc + ny * yc + std::sqrt(a * a * nu * nu + b * b * nv * nv);
}

double EllipseShape::half_width() const { return std::sqrt(a * a * c * c + b * b * s * s); }
double EllipseShape::half_height() const { return std::sqrt(a * a * s * s + b * b * c * c); }

std::optional<double> equal_distance_on_normal(const EllipseShape& p, const EllipseShape& q, double theta, double cap) {
    double px, py, nx, ny;
    p.point(theta, px, py);
    p.normal(theta, nx, ny);
    // f(rho) = delta(V(rho), q) - rho, nonincreasing.
    auto f = [&](double rho, double* slope) {
        const double vx = px + rho * nx, vy = py + rho * ny;
        double qx, qy;
        q.point(q.nearest_angle(vx, vy), qx, qy);
        const double d = q.inside(vx, vy) ? -std::hypot(vx - qx, vy - qy) : std::hypot(vx - qx, vy - qy);
        // The gradient of delta is q's outward normal at the nearest point, (V - Q) / delta.
        if (slope) *slope = d != 0 ? ((vx - qx) * nx + (vy - qy) * ny) / d - 1 : 0;
        return d - rho;
    };
    const double f0 = f(0, nullptr);
    double lo = 0, hi = 0;
    if (f0 > 0) {  // P(theta) outside q: rho > 0
        hi = f0;
        while (f(hi, nullptr) > 0) {
            lo = hi;
            hi *= 2;
            if (hi > cap) return std::nullopt;
        }
    } else if (f0 < 0) {  // P(theta) inside q: rho < 0, V in both sites
        lo = -p.medial_depth(theta);
        if (f(lo, nullptr) < 0) return std::nullopt;
    } else {
        return 0.0;
    }
    double rho = 0.5 * (lo + hi);
    for (int it = 0; it < 200; ++it) {
        double slope;
        const double v = f(rho, &slope);
        if (v == 0) break;
        (v > 0 ? lo : hi) = rho;
        double next = slope < 0 ? rho - v / slope : 0.5 * (lo + hi);
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        const double scale = 1 + std::max(std::fabs(lo), std::fabs(hi));
        const bool done = std::fabs(next - rho) <= 1e-14 * scale || hi - lo <= 1e-14 * scale;
        rho = next;
        if (done) break;
    }
    return rho;
}

}  // namespace ellvor
