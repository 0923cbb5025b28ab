#include "subdivision/voronoi_circle_guess.hpp"

#include "subdivision/nearest_point.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <functional>
#include <cmath>
#include <vector>

namespace ellvor {

namespace {

using Vector6 = Eigen::Matrix<double, 6, 1>;
using Matrix6 = Eigen::Matrix<double, 6, 6>;

// An ellipse in doubles: semi-axes, rotation (cos, sin), center relative to
// the frame's origin.
struct Shape {
    double a, b, c, s, x, y;
};

// The center relative to the origin site's center: in doubles when both
// centers are within 2^26 sizes of (0, 0) (the rounding of each, half an ulp,
// is then below 2^-27 of the sizes: harmless in a starting point), else
// subtracted exactly before rounding, so that the shapes keep the triple's
// relative geometry however far from (0, 0) it lies.
Shape shape_of(const Ellipse& e, const Ellipse& origin) {
    const auto &k = e.enclosure(), &o = origin.enclosure();
    const double size = std::min({k.a.mid(), k.b.mid(), o.a.mid(), o.b.mid()});
    const double reach = std::max({std::fabs(k.xc.mid()), std::fabs(k.yc.mid()), std::fabs(o.xc.mid()),
                                   std::fabs(o.yc.mid())});
    if (reach < 0x1p26 * size)
        return {k.a.mid(), k.b.mid(), k.cos.mid(), k.sin.mid(), k.xc.mid() - o.xc.mid(), k.yc.mid() - o.yc.mid()};
    return {k.a.mid(), k.b.mid(), k.cos.mid(), k.sin.mid(), (e.xc() - origin.xc()).to_double(),
            (e.yc() - origin.yc()).to_double()};
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

// Damped Newton; true when |F| is at the rounding level of the sites and of
// the circle (a huge circle of nearly collinear sites has a large center),
// or, when Newton stalls above that, within kStalledTolerance of it: an
// ill-conditioned system (a needle-like site touched near its tip) cannot do
// better in doubles, and the Arb stage, which certifies or refuses every
// guess, carries on from there.
bool newton(const std::array<Shape, 3>& e, Vector6& X) {
    constexpr double kTolerance = 1e-13, kStalledTolerance = 1e-6;
    const double site_scale = scale_of(e);
    auto tolerance_at = [&](const Vector6& Y, double relative) {
        return relative * std::max({site_scale, std::fabs(Y[3]), std::fabs(Y[4]), std::fabs(Y[5])});
    };
    Vector6 F;
    Matrix6 J;
    evaluate(e, X, F, J);
    for (int it = 0; it < 60; ++it) {
        if (F.norm() < tolerance_at(X, kTolerance)) return true;
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
    return F.norm() < tolerance_at(X, kStalledTolerance);
}

// The tangency points appear counter-clockwise on the circle iff their unit
// normals do (P_i = V - rho nu_i: the same orientation for every rho != 0,
// and the only one defined at rho = 0); and the radius can be a signed
// distance: positive, or (overlapping sites) above minus every site's
// smallest semi-axis, the depth of its deepest point (whether the foot points
// are the nearest ones is the certificate's question, DESIGN.md §4.1).
bool is_counterclockwise_solution(const std::array<Shape, 3>& e, const Vector6& X) {
    double n[3][2];
    for (int i = 0; i < 3; ++i) {
        const Shape& k = e[i];
        if (!(X[3] > -std::min(k.a, k.b))) return false;
        // The outward normal at angle theta: (b cos, a sin) in the ellipse's frame.
        const double lx = k.b * std::cos(X[i]), ly = k.a * std::sin(X[i]), length = std::hypot(lx, ly);
        n[i][0] = (lx * k.c - ly * k.s) / length;
        n[i][1] = (lx * k.s + ly * k.c) / length;
    }
    const double orient = (n[1][0] - n[0][0]) * (n[2][1] - n[0][1]) - (n[1][1] - n[0][1]) * (n[2][0] - n[0][0]);
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
    double rhos[2];  // no heap for two numbers (this runs before every certificate in doubles)
    int count = 0;
    if (std::fabs(qa) < 1e-14) {
        if (qb != 0) rhos[count++] = -qc / qb;
    } else {
        const double disc = qb * qb - 4 * qa * qc;
        if (disc >= 0) {
            rhos[count++] = (-qb + std::sqrt(disc)) / (2 * qa);
            rhos[count++] = (-qb - std::sqrt(disc)) / (2 * qa);
        }
    }
    // Signed radii: |V - C_i| = rho + r_i needs rho + r_i > 0 for each circle
    // (rho < 0 is an internal circle of overlapping sites).
    const double smallest = std::min({r[0], r[1], r[2]});
    out.reserve(count);
    for (int k = 0; k < count; ++k)
        if (const double rho = rhos[k]; rho + smallest > 0) {
            const Eigen::Vector2d v = v0 + rho * v1;
            out.push_back({rho, v[0], v[1]});
        }
    return out;
}

// Apollonius circles when the three centers are (nearly) collinear: in a
// frame with the line as x-axis the subtracted equations are linear in
// (X, rho), and Y^2 = (rho + r1)^2 - (X - x1)^2 gives the two circles.
std::vector<std::array<double, 3>> collinear_apollonius_circles(const std::array<Shape, 3>& c) {
    std::vector<std::array<double, 3>> out;
    const double dx = c[2].x - c[0].x, dy = c[2].y - c[0].y, length = std::hypot(dx, dy);
    if (!(length > 0)) return out;
    const double ex = dx / length, ey = dy / length;
    double x[3], r[3];
    for (int i = 0; i < 3; ++i) x[i] = (c[i].x - c[0].x) * ex + (c[i].y - c[0].y) * ey, r[i] = c[i].a;
    // 2 X (x1 - xi) - 2 rho (ri - r1) = ri^2 - r1^2 - xi^2 + x1^2, i = 2, 3
    Eigen::Matrix2d A;
    Eigen::Vector2d b;
    for (int i = 1; i < 3; ++i) {
        A(i - 1, 0) = 2 * (x[0] - x[i]);
        A(i - 1, 1) = -2 * (r[i] - r[0]);
        b[i - 1] = r[i] * r[i] - r[0] * r[0] - x[i] * x[i] + x[0] * x[0];
    }
    if (!(std::fabs(A.determinant()) > 1e-12 * A.cwiseAbs().maxCoeff() * A.cwiseAbs().maxCoeff())) return out;
    const Eigen::Vector2d sol = A.inverse() * b;
    const double X = sol[0], rho = sol[1], y2 = (rho + r[0]) * (rho + r[0]) - (X - x[0]) * (X - x[0]);
    if (!(rho + std::min({r[0], r[1], r[2]}) > 0) || !(y2 >= 0)) return out;
    for (double side : {1.0, -1.0}) {
        const double Y = side * std::sqrt(y2);
        out.push_back({rho, c[0].x + X * ex - Y * ey, c[0].y + X * ey + Y * ex});
    }
    return out;
}

// The Apollonius circles of a circle model, the collinear case included.
std::vector<std::array<double, 3>> model_circles(const std::array<Shape, 3>& circles) {
    auto found = apollonius_circles(circles, {circles[0].a, circles[1].a, circles[2].a});
    if (!found.empty()) return found;  // moved (the conditional operator copied it)
    return collinear_apollonius_circles(circles);
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

double model_radius(const Shape& k, CircleModel m) {
    switch (m) {
        case CircleModel::inscribed: return std::min(k.a, k.b);
        case CircleModel::mean: return 0.5 * (k.a + k.b);
        case CircleModel::circumscribed: return std::max(k.a, k.b);
    }
    return k.a;
}

// Shapes morphed from the circle model (lambda = 0) to the ellipses (1).
std::array<Shape, 3> blend(const std::array<Shape, 3>& e, CircleModel m, double lambda) {
    std::array<Shape, 3> out = e;
    for (Shape& k : out) {
        const double r = model_radius(k, m);
        k.a = r + lambda * (k.a - r);
        k.b = r + lambda * (k.b - r);
    }
    return out;
}

// Fallback: Newton in the plane on V for d1(V) = d2(V) = d3(V) (distances to
// the ellipses, gradients the unit vectors from the nearest points), started
// from a grid over and around the sites' bounding box.
bool equidistant_point_search(const std::array<Shape, 3>& e, const std::function<bool(const Vector6&)>& offer) {
    double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
    for (const Shape& k : e) {
        const double r = std::max(k.a, k.b);
        x0 = std::min(x0, k.x - r), x1 = std::max(x1, k.x + r);
        y0 = std::min(y0, k.y - r), y1 = std::max(y1, k.y + r);
    }
    const double w = x1 - x0, h = y1 - y0;
    constexpr int kGrid = 9;
    for (int gi = 0; gi < kGrid; ++gi)
        for (int gj = 0; gj < kGrid; ++gj) {
            double vx = x0 - w + 3 * w * gi / (kGrid - 1), vy = y0 - h + 3 * h * gj / (kGrid - 1);
            Vector6 X;
            bool converged = false;
            for (int it = 0; it < 40 && !converged; ++it) {
                double d[3], ux[3], uy[3];
                bool outside = true;
                for (int i = 0; i < 3; ++i) {
                    const Shape& k = e[i];
                    const double dx = vx - k.x, dy = vy - k.y;
                    const double lx = k.c * dx + k.s * dy, ly = k.c * dy - k.s * dx;
                    outside = outside && (lx * lx / (k.a * k.a) + ly * ly / (k.b * k.b) > 1);
                    const double th = approximate_nearest_angle(k.a, k.b, lx, ly);
                    X[i] = th;
                    const double px = k.x + k.a * std::cos(th) * k.c - k.b * std::sin(th) * k.s;
                    const double py = k.y + k.a * std::cos(th) * k.s + k.b * std::sin(th) * k.c;
                    d[i] = std::hypot(vx - px, vy - py);
                    ux[i] = (vx - px) / d[i], uy[i] = (vy - py) / d[i];
                }
                if (!outside) break;
                const double g1 = d[0] - d[1], g2 = d[0] - d[2];
                if (std::fabs(g1) + std::fabs(g2) < 1e-10 * (1 + d[0])) {
                    X[3] = d[0], X[4] = vx, X[5] = vy;
                    converged = true;
                    break;
                }
                const double a11 = ux[0] - ux[1], a12 = uy[0] - uy[1], a21 = ux[0] - ux[2], a22 = uy[0] - uy[2];
                const double det = a11 * a22 - a12 * a21;
                if (!(std::fabs(det) > 1e-300)) break;
                vx -= (a22 * g1 - a12 * g2) / det;
                vy -= (a11 * g2 - a21 * g1) / det;
            }
            if (converged && newton(e, X) && is_counterclockwise_solution(e, X) && offer(X)) return true;
        }
    return false;
}

}  // namespace

bool for_each_voronoi_circle_guess(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3,
                                   const std::function<bool(const VoronoiCircleGuess&)>& try_guess) {
    const std::array<Shape, 3> e = {shape_of(e1, e1), shape_of(e2, e1), shape_of(e3, e1)};
    std::vector<Vector6> tried;
    // Offers a solution unless an equal one was offered already.
    auto offer = [&](const Vector6& X) {
        for (const Vector6& Y : tried)
            if ((X.tail<3>() - Y.tail<3>()).norm() <= 1e-9 * (1 + X.tail<3>().norm())) return false;
        tried.push_back(X);
        VoronoiCircleGuess g;
        for (int i = 0; i < 3; ++i) g.theta[i] = std::remainder(X[i], 2 * M_PI);
        g.radius = X[3], g.x = X[4], g.y = X[5];
        return try_guess(g);
    };
    // Direct Newton on the ellipses from each Apollonius circle of each model.
    for (CircleModel m : kCircleModels) {
        const auto circles = blend(e, m, 0);
        for (const auto& circle : model_circles(circles)) {
            Vector6 X = start_from(e, circle);
            if (newton(e, X) && is_counterclockwise_solution(e, X) && offer(X)) return true;
        }
    }
    // Continuation from each model's counter-clockwise circle to the ellipses.
    for (CircleModel m : kCircleModels) {
        const auto circles = blend(e, m, 0);
        for (const auto& circle : model_circles(circles)) {
            Vector6 X = start_from(circles, circle);
            if (!newton(circles, X) || !is_counterclockwise_solution(circles, X)) continue;
            double lambda = 0, step = 0.25;
            while (lambda < 1 && step > 1e-4) {
                const double next = std::min(1.0, lambda + step);
                Vector6 Y = X;
                const auto shapes = blend(e, m, next);
                if (newton(shapes, Y) && is_counterclockwise_solution(shapes, Y)) {
                    X = Y, lambda = next, step *= 1.5;
                } else {
                    step *= 0.5;
                }
            }
            if (lambda == 1 && offer(X)) return true;
        }
    }
    return equidistant_point_search(e, offer);
}

std::vector<std::array<double, 3>> model_apollonius_circles(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3,
                                                            CircleModel model) {
    return model_circles(blend({shape_of(e1, e1), shape_of(e2, e1), shape_of(e3, e1)}, model, 0));
}

}  // namespace ellvor
