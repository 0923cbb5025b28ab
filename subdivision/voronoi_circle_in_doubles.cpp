#include "subdivision/voronoi_circle_in_doubles.hpp"

#include "subdivision/voronoi_circle_guess.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace ellvor {
namespace {

using Matrix6 = Eigen::Matrix<double, 6, 6>;
using Vector6 = Eigen::Matrix<double, 6, 1>;

// The same formulas in doubles (Newton on the midpoint) and in intervals (the
// certificate): N is double or Interval.
double constant(double c, double) { return c; }
Interval constant(double c, const Interval&) { return Interval(c); }
double root(double x) { return std::sqrt(x); }
Interval root(const Interval& x) { return x.sqrt(); }

// A value and its derivative in the chart parameter (forward differentiation).
template <class N>
struct Jet {
    N value, derivative;
};
template <class N>
Jet<N> operator+(const Jet<N>& f, const Jet<N>& g) { return {f.value + g.value, f.derivative + g.derivative}; }
template <class N>
Jet<N> operator-(const Jet<N>& f, const Jet<N>& g) { return {f.value - g.value, f.derivative - g.derivative}; }
template <class N>
Jet<N> operator*(const Jet<N>& f, const Jet<N>& g) {
    return {f.value * g.value, f.derivative * g.value + f.value * g.derivative};
}
template <class N>
Jet<N> operator*(const N& c, const Jet<N>& f) { return {c * f.value, c * f.derivative}; }
template <class N>
Jet<N> operator/(const Jet<N>& f, const Jet<N>& g) {
    const N q = f.value / g.value;
    return {q, (f.derivative - q * g.derivative) / g.value};
}
template <class N>
Jet<N> sqrt(const Jet<N>& f) {
    const N s = root(f.value);
    return {s, f.derivative / (constant(2, s) * s)};
}

// An ellipse: semi-axes, rotation (cos, sin) and center.
template <class N>
struct Shape {
    N a, b, cos, sin, xc, yc;
};

Shape<Interval> interval_shape(const Ellipse& e) {
    const Ellipse::Enclosure& k = e.enclosure();
    return {k.a, k.b, k.cos, k.sin, k.xc, k.yc};
}

Shape<double> double_shape(const Ellipse& e) {
    const Ellipse::Enclosure& k = e.enclosure();
    return {k.a.mid(), k.b.mid(), k.cos.mid(), k.sin.mid(), k.xc.mid(), k.yc.mid()};
}

// Boundary point P and outward unit normal nu at chart parameter t, with
// their derivatives in t. In the ellipse's frame the boundary is
// (a cos, b sin) with cos = (1 - t^2)/(1 + t^2), sin = 2t/(1 + t^2)
// (sites/ellipse.hpp); the flipped chart u = -1/t gives the opposite point,
// (cos, sin) -> -(cos, sin) at the same formula in u. The outward normal is
// along (b cos, a sin), of length at least min(a, b).
template <class N>
struct BoundaryJet {
    Jet<N> px, py, nx, ny;
};

template <class N>
BoundaryJet<N> boundary_at(const Shape<N>& k, bool flipped, const N& t) {
    const N one = constant(1, t), zero = constant(0, t);
    const Jet<N> T{t, one}, T2 = T * T, den = Jet<N>{one, zero} + T2;
    const N sign = constant(flipped ? -1 : 1, t);
    const Jet<N> c = sign * ((Jet<N>{one, zero} - T2) / den), s = sign * ((constant(2, t) * T) / den);
    const Jet<N> lx = k.a * c, ly = k.b * s, gx = k.b * c, gy = k.a * s;
    const Jet<N> norm = sqrt(gx * gx + gy * gy);
    const Jet<N> mx = gx / norm, my = gy / norm;
    const Jet<N> cx{k.xc, zero}, cy{k.yc, zero};
    return {cx + (k.cos * lx - k.sin * ly), cy + (k.sin * lx + k.cos * ly), k.cos * mx - k.sin * my,
            k.sin * mx + k.cos * my};
}

// F and J of the tritangent system at x = (t_1, t_2, t_3, rho, V_x, V_y).
template <class N>
void tritangent_system(const std::array<Shape<N>, 3>& k, const std::array<bool, 3>& flipped,
                       const std::array<N, 6>& x, std::array<N, 6>& F, std::array<std::array<N, 6>, 6>& J) {
    const N zero = constant(0, x[0]), minus_one = constant(-1, x[0]);
    for (auto& row : J) row.fill(zero);
    const N& rho = x[3];
    for (int i = 0; i < 3; ++i) {
        const BoundaryJet<N> p = boundary_at(k[i], flipped[i], x[i]);
        F[2 * i] = p.px.value + rho * p.nx.value - x[4];
        F[2 * i + 1] = p.py.value + rho * p.ny.value - x[5];
        J[2 * i][i] = p.px.derivative + rho * p.nx.derivative;
        J[2 * i + 1][i] = p.py.derivative + rho * p.ny.derivative;
        J[2 * i][3] = p.nx.value;
        J[2 * i + 1][3] = p.ny.value;
        J[2 * i][4] = minus_one;
        J[2 * i + 1][5] = minus_one;
    }
}

double magnitude(const Interval& x) { return std::fmax(std::fabs(x.lo), std::fabs(x.hi)); }

// Rounded up: |a| + |b| and c * d for nonnegative c, d.
double add_up(double a, double b) { return Interval::up(a + b); }
double mul_up(double c, double d) { return Interval::up(c * d); }

struct Certificate {
    std::array<Interval, 6> box;  // K(X): holds the unique solution
};

// The Krawczyk test with epsilon-inflation: boxes m +- r, r from the size of
// the Newton correction, grown a few times when K(X) is not inside X.
std::optional<Certificate> krawczyk(const std::array<Shape<Interval>, 3>& k, const std::array<bool, 3>& flipped,
                                    const Vector6& m, const Matrix6& Y, double length_scale) {
    std::array<Interval, 6> point, F;
    std::array<std::array<Interval, 6>, 6> J;
    for (int j = 0; j < 6; ++j) point[j] = Interval(m[j]);
    tritangent_system(k, flipped, point, F, J);
    std::array<Interval, 6> correction;  // Y F(m)
    std::array<double, 6> r;
    for (int i = 0; i < 6; ++i) {
        Interval sum(0.0);
        for (int j = 0; j < 6; ++j) sum = sum + Y(i, j) * F[j];
        if (!sum.finite()) return std::nullopt;
        correction[i] = sum;
        const double unit = i < 3 ? 1.0 : length_scale;
        r[i] = 2 * magnitude(sum) + 1e-15 * (std::fabs(m[i]) + unit);
    }
    for (int attempt = 0; attempt < 3; ++attempt) {
        std::array<Interval, 6> X, K;
        for (int j = 0; j < 6; ++j) X[j] = Interval(Interval::down(m[j] - r[j]), Interval::up(m[j] + r[j]));
        tritangent_system(k, flipped, X, F, J);
        bool inside = true;
        std::array<double, 6> reach{};
        for (int i = 0; i < 6; ++i) {
            // Row i of I - Y J(X), using where J is zero (column t_c: rows
            // 2c, 2c + 1; V_x and V_y: -1 in the even and odd rows), times
            // X - m = [-r, r]: its magnitude times r.
            std::array<Interval, 6> row;
            for (int c = 0; c < 3; ++c) row[c] = Y(i, 2 * c) * J[2 * c][c] + Y(i, 2 * c + 1) * J[2 * c + 1][c];
            row[3] = Interval(0.0);
            for (int j = 0; j < 6; ++j) row[3] = row[3] + Y(i, j) * J[j][3];
            row[4] = -(Interval(Y(i, 0)) + Interval(Y(i, 2)) + Interval(Y(i, 4)));
            row[5] = -(Interval(Y(i, 1)) + Interval(Y(i, 3)) + Interval(Y(i, 5)));
            double spread = 0;
            for (int c = 0; c < 6; ++c) {
                const Interval entry = Interval(i == c ? 1.0 : 0.0) - row[c];
                spread = add_up(spread, mul_up(magnitude(entry), r[c]));
            }
            K[i] = Interval(m[i]) - correction[i] + Interval(-spread, spread);
            if (!K[i].finite()) return std::nullopt;
            if (!(K[i].lo > X[i].lo && K[i].hi < X[i].hi)) inside = false;
            reach[i] = std::fmax(std::fabs(K[i].lo - m[i]), std::fabs(K[i].hi - m[i]));
        }
        if (inside) return Certificate{K};
        for (int i = 0; i < 6; ++i) r[i] = 2 * std::fmax(r[i], reach[i]);
    }
    return std::nullopt;
}

// The tangency points are counter-clockwise on the circle iff the normals
// are: P_i = V - rho nu_i, and a translation followed by the scaling by
// -rho multiplies the orientation of three points by rho^2 > 0.
bool counterclockwise(const std::array<Shape<Interval>, 3>& k, const std::array<bool, 3>& flipped,
                      const std::array<Interval, 6>& box) {
    std::array<Interval, 3> nx, ny;
    for (int i = 0; i < 3; ++i) {
        const BoundaryJet<Interval> p = boundary_at(k[i], flipped[i], box[i]);
        nx[i] = p.nx.value, ny[i] = p.ny.value;
    }
    const Interval orientation = (nx[1] - nx[0]) * (ny[2] - ny[0]) - (ny[1] - ny[0]) * (nx[2] - nx[0]);
    return orientation.positive();
}

}  // namespace

std::optional<DoubleVoronoiCircle> certify_voronoi_circle_in_doubles(const std::array<const Ellipse*, 3>& sites,
                                                                      const std::array<double, 3>& theta,
                                                                      double radius, double center_x,
                                                                      double center_y) {
    std::array<Shape<double>, 3> shape;
    std::array<Shape<Interval>, 3> enclosed;
    std::array<bool, 3> flipped;
    Vector6 m;
    double length_scale = std::fabs(radius);
    for (int i = 0; i < 3; ++i) {
        shape[i] = double_shape(*sites[i]);
        enclosed[i] = interval_shape(*sites[i]);
        length_scale = std::max({length_scale, shape[i].a, shape[i].b});
        // The chart in which the parameter is at most 1 in magnitude.
        flipped[i] = std::cos(theta[i]) < 0;
        const double t = std::tan(theta[i] / 2);
        m[i] = flipped[i] ? -1 / t : t;
    }
    m[3] = radius, m[4] = center_x, m[5] = center_y;
    // One Newton step in doubles in the charts (the guess solved the system
    // in angles), then Y = J(m)^-1.
    Matrix6 Y;
    for (int step = 0; step < 2; ++step) {
        std::array<double, 6> x, F;
        std::array<std::array<double, 6>, 6> J;
        for (int j = 0; j < 6; ++j) x[j] = m[j];
        tritangent_system(shape, flipped, x, F, J);
        Matrix6 jacobian;
        for (int i = 0; i < 6; ++i)
            for (int j = 0; j < 6; ++j) jacobian(i, j) = J[i][j];
        Y = Eigen::PartialPivLU<Matrix6>(jacobian).inverse();
        if (!Y.allFinite()) return std::nullopt;
        if (step == 0) m -= Y * Eigen::Map<const Vector6>(F.data());
    }
    if (!m.allFinite()) return std::nullopt;
    const std::optional<Certificate> certificate = krawczyk(enclosed, flipped, m, Y, length_scale);
    if (!certificate) return std::nullopt;
    const std::array<Interval, 6>& box = certificate->box;
    if (!box[3].positive() || !counterclockwise(enclosed, flipped, box)) return std::nullopt;
    DoubleVoronoiCircle circle;
    for (int i = 0; i < 3; ++i) circle.parameter[i] = box[i];
    circle.flipped = flipped;
    circle.radius = box[3], circle.center_x = box[4], circle.center_y = box[5];
    return circle;
}

std::optional<DoubleVoronoiCircle> certify_voronoi_circle_in_doubles(const Ellipse& e1, const Ellipse& e2,
                                                                      const Ellipse& e3) {
    std::optional<DoubleVoronoiCircle> certified;
    const double origin_x = e1.enclosure().xc.mid(), origin_y = e1.enclosure().yc.mid();
    for_each_voronoi_circle_guess(
        e1, e2, e3,
        [&](const VoronoiCircleGuess& g) {
            certified = certify_voronoi_circle_in_doubles({&e1, &e2, &e3}, g.theta, g.radius, origin_x + g.x,
                                                          origin_y + g.y);
            return certified.has_value();
        },
        GuessEffort::quick);
    return certified;
}

}  // namespace ellvor
