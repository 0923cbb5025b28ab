#include "subdivision/voronoi_circle_guess.hpp"

#include "subdivision/nearest_point.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <vector>

namespace ellvor {

namespace {

using Vector6 = Eigen::Matrix<double, 6, 1>;
using Matrix6 = Eigen::Matrix<double, 6, 6>;

// An ellipse in doubles: semi-axes, rotation (cos, sin), center.
struct Shape {
    double a, b, c, s, x, y;
};

Shape shape_of(const Ellipse& e) {
    const auto& k = e.enclosure();
    return {k.a.mid(), k.b.mid(), k.cos.mid(), k.sin.mid(), k.xc.mid(), k.yc.mid()};
}

// Residual F(X) and Jacobian J(X) of P_i + rho nu_i - V = 0, X = (theta1..3, rho, x, y).
void evaluate(const std::array<Shape, 3>& e, const Vector6& X, Vector6& F, Matrix6& J) {
    J.setZero();
    const double rho = X[3];
    for (int i = 0; i < 3; ++i) {
        const Shape& k = e[i];
        const double ct = std::cos(X[i]), st = std::sin(X[i]);
        const double px = k.x + k.a * ct * k.c - k.b * st * k.s, py = k.y + k.a * ct * k.s + k.b * st * k.c;
        const double dpx = -k.a * st * k.c - k.b * ct * k.s, dpy = -k.a * st * k.s + k.b * ct * k.c;
        const double gx = k.b * ct * k.c - k.a * st * k.s, gy = k.b * ct * k.s + k.a * st * k.c;
        const double dgx = -k.b * st * k.c - k.a * ct * k.s, dgy = -k.b * st * k.s + k.a * ct * k.c;
        const double norm = std::hypot(gx, gy), dot = (gx * dgx + gy * dgy) / (norm * norm);
        const double nx = gx / norm, ny = gy / norm;
        const double dnx = (dgx - gx * dot) / norm, dny = (dgy - gy * dot) / norm;
        F[2 * i] = px + rho * nx - X[4];
        F[2 * i + 1] = py + rho * ny - X[5];
        J(2 * i, i) = dpx + rho * dnx;
        J(2 * i + 1, i) = dpy + rho * dny;
        J(2 * i, 3) = nx;
        J(2 * i + 1, 3) = ny;
        J(2 * i, 4) = -1;
        J(2 * i + 1, 5) = -1;
    }
}

double scale_of(const std::array<Shape, 3>& e) {
    double s = 1;
    for (const Shape& k : e) s = std::max({s, std::fabs(k.x), std::fabs(k.y), k.a, k.b});
    return s;
}

// Damped Newton; true when |F| is at rounding level.
bool newton(const std::array<Shape, 3>& e, Vector6& X) {
    const double tolerance = 1e-13 * scale_of(e);
    Vector6 F;
    Matrix6 J;
    evaluate(e, X, F, J);
    for (int it = 0; it < 60; ++it) {
        if (F.norm() < tolerance) return true;
        const Vector6 step = J.partialPivLu().solve(F);
        if (!step.allFinite()) return false;
        double damping = 1;
        Vector6 next, Fn;
        Matrix6 Jn;
        for (; damping > 1e-4; damping *= 0.5) {
            next = X - damping * step;
            evaluate(e, next, Fn, Jn);
            if (Fn.norm() < F.norm()) break;
        }
        X = next, F = Fn, J = Jn;
    }
    return F.norm() < tolerance;
}

// The tangency points appear counter-clockwise on the circle iff the
// triangle P1 P2 P3 is positively oriented; and the radius must be positive.
bool is_counterclockwise_solution(const std::array<Shape, 3>& e, const Vector6& X) {
    if (!(X[3] > 0)) return false;
    double p[3][2];
    for (int i = 0; i < 3; ++i) {
        const Shape& k = e[i];
        const double ct = std::cos(X[i]), st = std::sin(X[i]);
        p[i][0] = k.x + k.a * ct * k.c - k.b * st * k.s;
        p[i][1] = k.y + k.a * ct * k.s + k.b * st * k.c;
    }
    const double orient = (p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[1][1] - p[0][1]) * (p[2][0] - p[0][0]);
    return orient > 0;
}

// Circles externally tangent to three circles (Apollonius): |V - C_i| = rho + r_i.
// Subtracting the first equation leaves V linear in rho; the first is then
// quadratic in rho.
std::vector<std::array<double, 3>> apollonius_circles(const std::array<Shape, 3>& e, const std::array<double, 3>& r) {
    std::vector<std::array<double, 3>> out;
    Eigen::Matrix2d A;
    Eigen::Vector2d b, c;
    for (int i = 1; i < 3; ++i) {
        A(i - 1, 0) = 2 * (e[i].x - e[0].x);
        A(i - 1, 1) = 2 * (e[i].y - e[0].y);
        b[i - 1] = e[i].x * e[i].x + e[i].y * e[i].y - e[0].x * e[0].x - e[0].y * e[0].y - r[i] * r[i] + r[0] * r[0];
        c[i - 1] = -2 * (r[i] - r[0]);
    }
    if (std::fabs(A.determinant()) < 1e-12 * A.cwiseAbs().maxCoeff() * A.cwiseAbs().maxCoeff()) return out;
    const Eigen::Matrix2d inverse = A.inverse();
    const Eigen::Vector2d v0 = inverse * b, v1 = inverse * c;
    const Eigen::Vector2d d = v0 - Eigen::Vector2d(e[0].x, e[0].y);
    const double qa = v1.squaredNorm() - 1, qb = 2 * (d.dot(v1) - r[0]), qc = d.squaredNorm() - r[0] * r[0];
    std::vector<double> rhos;
    if (std::fabs(qa) < 1e-14) {
        if (qb != 0) rhos.push_back(-qc / qb);
    } else {
        const double disc = qb * qb - 4 * qa * qc;
        if (disc >= 0) {
            rhos.push_back((-qb + std::sqrt(disc)) / (2 * qa));
            rhos.push_back((-qb - std::sqrt(disc)) / (2 * qa));
        }
    }
    for (double rho : rhos)
        if (rho > 0) {
            const Eigen::Vector2d v = v0 + rho * v1;
            out.push_back({rho, v[0], v[1]});
        }
    return out;
}

// Start point for circle (x, y, rho): each tangency at the nearest point of E_i.
Vector6 start_from(const std::array<Shape, 3>& e, const std::array<double, 3>& circle) {
    Vector6 X;
    X[3] = circle[0], X[4] = circle[1], X[5] = circle[2];
    for (int i = 0; i < 3; ++i) {
        const Shape& k = e[i];
        const double dx = circle[1] - k.x, dy = circle[2] - k.y;
        X[i] = approximate_nearest_angle(k.a, k.b, k.c * dx + k.s * dy, k.c * dy - k.s * dx);
    }
    return X;
}

std::array<Shape, 3> blend(const std::array<Shape, 3>& e, double lambda) {
    std::array<Shape, 3> m = e;
    for (Shape& k : m) {
        const double r = std::min(k.a, k.b);
        k.a = r + lambda * (k.a - r);
        k.b = r + lambda * (k.b - r);
    }
    return m;
}

}  // namespace

std::optional<VoronoiCircleGuess> guess_voronoi_circle(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3) {
    const std::array<Shape, 3> e = {shape_of(e1), shape_of(e2), shape_of(e3)};
    const std::array<Shape, 3> inscribed = blend(e, 0);
    const auto circles = apollonius_circles(inscribed, {inscribed[0].a, inscribed[1].a, inscribed[2].a});
    auto accept = [&](const Vector6& X) {
        VoronoiCircleGuess g;
        for (int i = 0; i < 3; ++i) g.theta[i] = std::remainder(X[i], 2 * M_PI);
        g.radius = X[3], g.x = X[4], g.y = X[5];
        return g;
    };
    // Direct Newton on the ellipses from each Apollonius circle.
    for (const auto& circle : circles) {
        Vector6 X = start_from(e, circle);
        if (newton(e, X) && is_counterclockwise_solution(e, X)) return accept(X);
    }
    // Continuation from the inscribed circles to the ellipses.
    for (const auto& circle : circles) {
        Vector6 X = start_from(inscribed, circle);
        if (!newton(inscribed, X) || !is_counterclockwise_solution(inscribed, X)) continue;
        double lambda = 0, step = 0.25;
        while (lambda < 1 && step > 1e-4) {
            const double next = std::min(1.0, lambda + step);
            Vector6 Y = X;
            const auto shapes = blend(e, next);
            if (newton(shapes, Y) && is_counterclockwise_solution(shapes, Y)) {
                X = Y, lambda = next, step *= 1.5;
            } else {
                step *= 0.5;
            }
        }
        if (lambda == 1) return accept(X);
    }
    return std::nullopt;
}

}  // namespace ellvor
