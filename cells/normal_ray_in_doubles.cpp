#include "cells/normal_ray_in_doubles.hpp"

#include "util/complex_interval.hpp"
#include "util/complex_taylor_model.hpp"
#include "util/fixed_precision_ball.hpp"
#include "util/interval_trig.hpp"
#include "util/upward_interval.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace ellvor {
namespace {

using Site = NormalRayInDoubles::Site;

double magnitude(const Interval& x) { return std::max(std::fabs(x.lo), std::fabs(x.hi)); }
double magnitude(const UpwardInterval& x) { return std::max(std::fabs(x.lo), std::fabs(x.hi)); }

// A site's enclosures for the node's certificate (the same bounds).
struct UpwardSite {
    UpwardInterval a, b, c, s, xc, yc;
    explicit UpwardSite(const Site& e)
        : a(e.a), b(e.b), c(e.c), s(e.s), xc(e.xc), yc(e.yc) {}
};

Interval sym(double r) { return {-r, r}; }

template <class T>
T dot(const T& ax, const T& ay, const T& bx, const T& by) {
    return ax * bx + ay * by;
}

// The Green densities of MeasureIntervals but the length, from V - O = (X, Y)
// and V' = (dX, dY).
template <class T>
void green_densities(const T& X, const T& Y, const T& dX, const T& dY, T (&out)[MeasureIntervals::count]) {
    using M = MeasureIntervals;
    const T X2 = X * X, Y2 = Y * Y;
    out[M::x_dy] = X * dY;
    out[M::y_dx] = Y * dX;
    out[M::x2_dy] = X2 * dY;
    out[M::y2_dx] = Y2 * dX;
    out[M::xy_dy] = X * Y * dY;
    out[M::x3_dy] = X2 * X * dY;
    out[M::y3_dx] = Y2 * Y * dX;
    out[M::x2y_dy] = X2 * Y * dY;
}

UpwardInterval square(const UpwardInterval& x) { return x.square(); }
double square(double x) { return x * x; }

// Principal square roots where the real part is positive (the squared normal
// lengths N^2 near the reals); elsewhere an unbounded enclosure, which fails
// every later check.
double root_of(double x) { return std::sqrt(x); }
UpwardInterval root_of(const UpwardInterval& x) { return x.lo > 0 ? x.sqrt() : UpwardInterval(-INFINITY, INFINITY); }
template <int N, class Coefficient>
TaylorModel<N, Coefficient> root_of(const TaylorModel<N, Coefficient>& a) {
    return principal_root(a);
}

// A site's boundary at an angle with the given sine and cosine: the point,
// the unnormalized outward normal n~, their derivatives in the angle, and
// N^2 = |n~|^2 (as Boundary in normal_ray_bisector.cpp). T: UpwardInterval
// for a node's certificate, the site an UpwardSite; double for Newton, the
// site its EllipseShape; Taylor models for the disk's, the site a Site (the
// same member names).
template <class T>
struct Frame {
    // What a frame holds: always the point and n~; q's frames the tangent
    // too (F and J need it); p's frames everything (F_theta, the densities).
    enum Parts { point_normal = 0, tangent = 1, all = 3 };
    T x{}, y{}, nx{}, ny{}, dx{}, dy{}, dnx{}, dny{}, n2{};

    Frame() = default;
    template <class S>
    Frame(const S& e, const T& sin, const T& cos, int parts = all) {
        const auto rotate = [&e](const T& lx, const T& ly, T& X, T& Y) {
            X = lx * e.c - ly * e.s;
            Y = lx * e.s + ly * e.c;
        };
        const T ac = e.a * cos, bs = e.b * sin, bc = e.b * cos, as = e.a * sin;
        rotate(ac, bs, x, y);
        x = x + e.xc;
        y = y + e.yc;
        rotate(bc, as, nx, ny);
        if (parts & tangent) rotate(-as, bc, dx, dy);
        if (parts != all) return;
        n2 = square(as) + square(bc);
        rotate(-bs, ac, dnx, dny);
    }
};

// A frame of models as one of lower degree (truncated(): the dropped terms
// in the remainders).
template <int M, int N>
Frame<RealTaylorModel<M>> truncated(const Frame<RealTaylorModel<N>>& f) {
    Frame<RealTaylorModel<M>> t;
    t.x = truncated<M>(f.x), t.y = truncated<M>(f.y), t.nx = truncated<M>(f.nx), t.ny = truncated<M>(f.ny);
    t.dx = truncated<M>(f.dx), t.dy = truncated<M>(f.dy), t.dnx = truncated<M>(f.dnx), t.dny = truncated<M>(f.dny);
    t.n2 = truncated<M>(f.n2);
    return t;
}

// V - Q, P - Q and (P - Q) . n~ at s (V = P + s n~), and F from them.
template <class T>
struct Differences {
    T dx, dy, ex, ey, e_n;
    Differences(const Frame<T>& bp, const Frame<T>& bq, const T& s)
        : dx(bp.x + s * bp.nx - bq.x), dy(bp.y + s * bp.ny - bq.y), ex(bp.x - bq.x), ey(bp.y - bq.y),
          e_n(dot(ex, ey, bp.nx, bp.ny)) {}
    // With the signed tie F1 is (V - Q) . n~q - s N Nq
    // (normal_ray_bisector.hpp): the frames must then hold N^2 (Parts all).
    void residual(const Frame<T>& bp, const Frame<T>& bq, const T& s, bool is_signed, T (&F)[2]) const {
        F[0] = dot(dx, dy, bq.dx, bq.dy);
        F[1] = is_signed ? dot(dx, dy, bq.nx, bq.ny) - s * (root_of(bp.n2) * root_of(bq.n2))
                    : dot(ex, ey, ex, ey) + 2.0 * (s * e_n);
    }
};

// The tie's (F's second row's) derivatives in s and in theta, g_s and
// g_theta (System's J[1][0] and F_theta[1]; g_theta left empty unless asked
// for): s' = -g_theta / g_s, all that a node's densities need of the system.
// Also W = P' + s n~' (with g_theta) and, with the signed tie, N and Nq.
template <class T>
struct TieDerivatives {
    T g_s, g_theta, wx, wy, np, nq;

    TieDerivatives(const Frame<T>& bp, const Frame<T>& bq, const T& s, const Differences<T>& d, bool is_signed,
                   bool with_theta = true) {
        if (with_theta) wx = bp.dx + s * bp.dnx, wy = bp.dy + s * bp.dny;
        if (!is_signed) {
            g_s = 2.0 * d.e_n;
            if (with_theta) g_theta = 2.0 * dot(d.ex, d.ey, wx, wy);
            return;
        }
        np = root_of(bp.n2), nq = root_of(bq.n2);
        g_s = dot(bp.nx, bp.ny, bq.nx, bq.ny) - np * nq;
        if (with_theta) g_theta = dot(wx, wy, bq.nx, bq.ny) - s * nq * dot(bp.nx, bp.ny, bp.dnx, bp.dny) / np;
    }
};

// The bisector system of normal_ray_bisector.cpp (BisectorSystem) at s, p's
// boundary bp and q's boundary bq: F, its Jacobian in (s, phi), and (unless
// asked not to: left empty) the theta-derivatives of its rows; the signed
// tie's row when it is the signed one (both frames whole).
template <class T>
struct System {
    T F[2], J[2][2], F_theta[2];

    template <class S>
    System(const S& q, const Frame<T>& bp, const Frame<T>& bq, const T& s, bool is_signed, bool with_theta = true) {
        const Differences<T> d(bp, bq, s);
        d.residual(bp, bq, s, is_signed, F);
        J[0][0] = dot(bp.nx, bp.ny, bq.dx, bq.dy);
        J[0][1] = -dot(bq.dx, bq.dy, bq.dx, bq.dy) - dot(d.dx, d.dy, bq.x - q.xc, bq.y - q.yc);
        const TieDerivatives<T> tie(bp, bq, s, d, is_signed, with_theta);
        J[1][0] = tie.g_s;
        J[1][1] = is_signed ? dot(d.dx, d.dy, bq.dnx, bq.dny) - s * tie.np * dot(bq.nx, bq.ny, bq.dnx, bq.dny) / tie.nq
                            : -2.0 * F[0];
        if (!with_theta) return;
        F_theta[0] = dot(tie.wx, tie.wy, bq.dx, bq.dy);
        F_theta[1] = tie.g_theta;
    }
};

// (V - Q) . n~q: positive when V lies outside q along its normal at Q.
template <class T>
T side(const Frame<T>& bp, const Frame<T>& bq, const T& s) {
    return dot(bp.x + s * bp.nx - bq.x, bp.y + s * bp.ny - bq.y, bq.nx, bq.ny);
}

template <class T>
bool strictly_inside(const T& x, double r) { return x.lo > -r && x.hi < r; }

// The Krawczyk image about the point, K = -C F + (I - C J(X)) Y, and whether
// it lies in the interior of Y (each component within +- r_i).
template <class T>
bool krawczyk_inside(const double (&C)[2][2], const T (&CF)[2], const T (&J)[2][2], const T (&Y)[2],
                     const double (&r)[2], T (&K)[2]) {
    bool inside = true;
    for (int i = 0; i < 2; ++i) {
        K[i] = -CF[i];
        for (int j = 0; j < 2; ++j) {
            T m = -(C[i][0] * J[0][j] + C[i][1] * J[1][j]);
            if (i == j) m = m + T(1.0);
            K[i] = K[i] + m * Y[j];
        }
        inside = inside && strictly_inside(K[i], r[i]);
    }
    return inside;
}

// C = J^-1 in doubles; false when singular.
bool inverse(const double (&J)[2][2], double (&C)[2][2]) {
    const double a = J[0][0], b = J[0][1], c = J[1][0], d = J[1][1];
    const double det = a * d - b * c;
    if (!(std::fabs(det) > 0) || !std::isfinite(det)) return false;
    C[0][0] = d / det, C[0][1] = -b / det, C[1][0] = -c / det, C[1][1] = a / det;
    return true;
}

Site site_of(const Ellipse& e) {
    const Ellipse::Enclosure k = e.enclosure();  // enclose() of each parameter, kept by the ellipse
    return {k.a, k.b, k.cos, k.sin, k.xc, k.yc, EllipseShape::of(e)};
}

// min(a, b) / max(a, b): the depth of the medial axis in units of n~.
Interval medial_depth(const Site& e) {
    const Interval smaller(std::min(e.a.lo, e.b.lo), std::min(e.a.hi, e.b.hi));
    const Interval larger(std::max(e.a.lo, e.b.lo), std::max(e.a.hi, e.b.hi));
    return smaller / larger;
}

// The frame's parts that q's frames need: the signed tie also asks N^2 and n~'.
template <class T>
int q_parts(bool is_signed) {
    return is_signed ? Frame<T>::all : Frame<T>::tangent;
}

}  // namespace

NormalRayInDoubles::NormalRayInDoubles(const Ellipse& p, const Ellipse& q)
    : NormalRayInDoubles(p, q, NormalRayBisector::uses_signed_tie(p, q)) {}

NormalRayInDoubles::NormalRayInDoubles(const Ellipse& p, const Ellipse& q, bool signed_tie)
    : p_(site_of(p)),
      q_(site_of(q)),
      p_ellipse_(&p),
      q_ellipse_(&q),
      signed_(signed_tie),
      medial_p_(medial_depth(p_)),
      medial_q_(medial_depth(q_)) {
    const EllipseShape &ps = p_.shape, &qs = q_.shape;
    origin_[0] = ps.xc, origin_[1] = ps.yc;
    size_ = std::max({ps.a, ps.b, qs.a, qs.b, std::hypot(ps.xc - qs.xc, ps.yc - qs.yc)});
    const double a = magnitude(q_.a), b = magnitude(q_.b), c = magnitude(q_.c), s = magnitude(q_.s);
    q_slack_[0] = Interval::up(Interval::up(a * c) + Interval::up(b * s));
    q_slack_[1] = Interval::up(Interval::up(a * s) + Interval::up(b * c));
}

bool NormalRayInDoubles::newton(double theta, const double (&start)[2], double (&x)[2], double (&C)[2][2]) const {
    if (!std::isfinite(start[0])) return false;
    x[0] = start[0], x[1] = start[1];
    // F and J alone: of p's frame what they need, no theta-derivatives.
    const Frame<double> bp(p_.shape, std::sin(theta), std::cos(theta),
                           signed_ ? Frame<double>::all : Frame<double>::point_normal);
    // Until a step is below 1e-8 (relative: quadratic convergence leaves
    // the point after it within about 1e-16 of the root times the system's
    // curvature; 1e-10 and 1e-15 each cost a step more, 1% and 2% of a cell,
    // for the same widths).
    for (int step = 0; step < 8; ++step) {
        const System<double> at(q_.shape, bp, Frame<double>(q_.shape, std::sin(x[1]), std::cos(x[1]), q_parts<double>(signed_)),
                                x[0], signed_, false);
        if (!inverse(at.J, C)) return false;
        const double f0 = at.F[0], f1 = at.F[1];
        const double d0 = C[0][0] * f0 + C[0][1] * f1, d1 = C[1][0] * f0 + C[1][1] * f1;
        x[0] -= d0, x[1] -= d1;
        if (!std::isfinite(x[0]) || !std::isfinite(x[1])) return false;
        const double size = std::max(std::fabs(d0) / (1 + std::fabs(x[0])), std::fabs(d1) / (1 + std::fabs(x[1])));
        if (size <= 1e-8) return x[0] > (signed_ ? -medial_p_.hi : 0.0);
    }
    return false;
}

std::optional<MeasureIntervals> NormalRayInDoubles::densities(const Interval& theta) {
    std::optional<Node> n = node(theta, true);
    return n ? n->densities : std::nullopt;
}

void NormalRayInDoubles::start_near(double theta, double x, double y) {
    const EllipseShape& ps = p_.shape;
    double px, py, nx, ny;  // (nx, ny) the unit normal: s = rho / N as in ray_start
    ps.point(theta, px, py);
    ps.normal(theta, nx, ny);
    last_[0] = ((x - px) * nx + (y - py) * ny) / std::hypot(ps.b * std::cos(theta), ps.a * std::sin(theta));
    last_[1] = q_.shape.nearest_angle(x, y);
}

std::array<double, 2> NormalRayInDoubles::pole_angles() const {
    const EllipseShape &ps = p_.shape, &qs = q_.shape;
    const double dx = qs.xc - ps.xc, dy = qs.yc - ps.yc;
    const double lx = ps.c * dx + ps.s * dy, ly = -ps.s * dx + ps.c * dy;  // in p's frame
    // n~ . (lx, ly) = b cos lx + a sin ly = 0.
    const double t = std::atan2(-ps.b * lx, ps.a * ly);
    return {t, t > 0 ? t - M_PI : t + M_PI};
}

double NormalRayInDoubles::pole_limited_width(double start, double disk_over_width, double share) const {
    // A pole a ahead needs disk_over_width w <= share (a - start - w/2), one
    // behind disk_over_width w <= share (start - a + w/2).
    double width = INFINITY;
    for (double pole : pole_angles())
        for (int turn = -2; turn <= 2; ++turn) {
            const double a = pole + 2 * M_PI * turn;
            width = std::min(width, a >= start ? share * (a - start) / (disk_over_width + share / 2)
                                               : share * (start - a) / (disk_over_width - share / 2));
        }
    return width;
}

std::optional<double> NormalRayInDoubles::area_density_estimate(double theta) {
    double x[2], start[2], C[2][2];
    if (!newton(theta, last_, x, C) && !(ray_start(theta, start) && newton(theta, start, x, C))) return std::nullopt;
    last_[0] = x[0], last_[1] = x[1];
    const double s = x[0];
    const Frame<double> bp(p_.shape, std::sin(theta), std::cos(theta));
    const System<double> at(q_.shape, bp, Frame<double>(q_.shape, std::sin(x[1]), std::cos(x[1]), q_parts<double>(signed_)),
                            s, signed_);
    const double ds = -at.F_theta[1] / at.J[1][0];  // s' = -g_theta / g_s
    const double X = bp.x + s * bp.nx - origin_[0], Y = bp.y + s * bp.ny - origin_[1];
    const double dX = bp.dx + ds * bp.nx + s * bp.dnx, dY = bp.dy + ds * bp.ny + s * bp.dny;
    const double density = 0.5 * (X * dY - Y * dX);
    return std::isfinite(density) ? std::optional<double>(density) : std::nullopt;
}

std::optional<std::array<Interval, 2>> NormalRayInDoubles::point(const Interval& theta) {
    std::optional<Node> n = node(theta, false);
    return n ? n->point : std::nullopt;
}

std::optional<NormalRayInDoubles::Node> NormalRayInDoubles::node(const Interval& theta, bool with_densities) {
    const double theta0 = theta.mid();
    if (!std::isfinite(theta0)) return std::nullopt;
    // Newton in doubles from the last node's root, which Gauss nodes, close
    // to each other, make a good start; else from the bisector point on the
    // ray (it may lead to another root of the system, which the certificate
    // rejects).
    double x0[2], C[2][2], start[2] = {last_[0], last_[1]};
    // Or from the last disk's polynomial at theta0, on its real diameter.
    disk_start(theta0, start);
    if (newton(theta0, start, x0, C))
        if (std::optional<Node> n = certified(theta, x0, C, with_densities)) return n;
    if (!ray_start(theta0, start) || !newton(theta0, start, x0, C)) return std::nullopt;
    return certified(theta, x0, C, with_densities);
}

bool NormalRayInDoubles::disk_start(double theta, double (&start)[2]) const {
    if (!disk_ || !(std::fabs(theta - disk_->mid) <= disk_->R)) return false;
    const double d = theta - disk_->mid;
    for (int i = 0; i < 2; ++i) {
        start[i] = disk_->x[i][kDiskDegree];
        for (int k = kDiskDegree - 1; k >= 0; --k) start[i] = start[i] * d + disk_->x[i][k];
    }
    return true;
}

bool NormalRayInDoubles::ray_start(double theta0, double (&start)[2]) const {
    const EllipseShape &ps = p_.shape, &qs = q_.shape;
    const std::optional<double> rho = equal_distance_on_normal(ps, qs, theta0, 1e12 * size_);
    if (!rho || !(signed_ || *rho > 0)) return false;
    double px, py, nx, ny;
    ps.point(theta0, px, py);
    ps.normal(theta0, nx, ny);
    start[0] = *rho / std::hypot(ps.b * std::cos(theta0), ps.a * std::sin(theta0));
    start[1] = qs.nearest_angle(px + *rho * nx, py + *rho * ny);
    return true;
}

namespace {

// What certify_node reads: the pair, Newton's point x0 and inverse C, theta, and the
// sines and cosines at theta (an interval) and at x0's phi.
struct NodeInput {
    const Site &p, &q;
    bool is_signed;
    const Interval &medial_p, &medial_q;  // r_p, r_q
    const double (&q_slack)[2];           // NormalRayInDoubles::q_slack_
    Interval theta, sin_theta, cos_theta, sin_phi, cos_phi;
    const double (&x0)[2];
    const double (&C)[2][2];
    const double (&origin)[2];
    bool with_densities;
};

// q's frame over phi0 +- r from the frame at phi0 (sines and cosines there):
// sine and cosine move by at most r (their derivatives are at most 1), and
// q's frame, linear in them, by r times q_slack (the whole frame of the
// signed tie from the widened sine and cosine: sin(phi0 + t) = sin phi0 cos t
// + cos phi0 sin t, cos t in [1 - r^2/2, 1], |sin t| <= min(r, 1)). Under the
// upward rounding mode.
Frame<UpwardInterval> widened_q_frame(const NodeInput& in, const UpwardSite& q, const Frame<UpwardInterval>& bq0,
                                      double r) {
    using U = UpwardInterval;
    if (in.is_signed) {
        const double h = std::min(r, 1.0);
        const U sin_phi(in.sin_phi), cos_phi(in.cos_phi), sin_t(-h, h), cos_t(-((r * r) * 0.5 - 1.0), 1.0);
        return Frame<U>(q, sin_phi * cos_t + cos_phi * sin_t, cos_phi * cos_t - sin_phi * sin_t);
    }
    Frame<U> bq = bq0;
    const double mx = r * in.q_slack[0], my = r * in.q_slack[1];  // rounded up
    const U move[2] = {U(-mx, mx), U(-my, my)};
    bq.x = bq.x + move[0], bq.dx = bq.dx + move[0], bq.ny = bq.ny + move[0];
    bq.y = bq.y + move[1], bq.dy = bq.dy + move[1], bq.nx = bq.nx + move[1];
    return bq;
}

// The point V = P + s n~ once s(theta) is enclosed in `root` (left empty
// when its finiteness is not proved). Under the upward rounding mode.
void point_of(const Frame<UpwardInterval>& bp, const UpwardInterval& root, std::array<UpwardInterval, 2>& v,
              std::optional<std::array<Interval, 2>>& point) {
    v = {bp.x + root * bp.nx, bp.y + root * bp.ny};
    if (v[0].finite() && v[1].finite()) point = std::array<Interval, 2>{v[0].interval(), v[1].interval()};
}

// What a node gives once s(theta) is enclosed in `root`: the point V and
// (with_densities) the densities, with s' = -g_theta / g_s from the tie's
// derivatives over a box holding the root (System's J[1][0], F_theta[1]).
// The densities are left empty when |V'|^2 > 0 or finiteness is not proved.
// Under the upward rounding mode.
void node_values(const NodeInput& in, const Frame<UpwardInterval>& bp, const UpwardInterval& root,
                 const TieDerivatives<UpwardInterval>& on_box, std::optional<MeasureIntervals>& densities,
                 std::optional<std::array<Interval, 2>>& point) {
    using U = UpwardInterval;
    const U ds = -(on_box.g_theta / on_box.g_s);
    std::array<U, 2> v;
    point_of(bp, root, v, point);
    if (!in.with_densities) return;
    // The densities of NormalRayBisector::densities.
    const U vx = bp.dx + ds * bp.nx + root * bp.dnx, vy = bp.dy + ds * bp.ny + root * bp.dny;
    U out[MeasureIntervals::count];
    green_densities(v[0] - U(in.origin[0]), v[1] - U(in.origin[1]), vx, vy, out);
    const U v2 = dot(vx, vy, vx, vy);
    if (!v2.positive()) return;
    out[MeasureIntervals::length] = v2.sqrt();
    MeasureIntervals d;
    for (int j = 0; j < MeasureIntervals::count; ++j) {
        if (!out[j].finite()) return;
        d.m[j] = out[j].interval();
    }
    densities = d;
}

// The Krawczyk test about x0 with epsilon-inflation, F(x0) over the whole
// interval of theta (C may be any matrix to the proof), and at the root it
// proves the node's values (node_values). All of it under the upward rounding
// mode (util/upward_interval.hpp: one rounding an operation, no widening
// step; these operations in Interval were about half of a cell's time). The
// sines and cosines come from the caller (util/interval_trig.hpp needs
// round-to-nearest). False when the root is not certified.
ELLVOR_UPWARD_ROUNDING_FUNCTION bool certify_node(const NodeInput& in, std::optional<MeasureIntervals>& densities,
                                                  std::optional<std::array<Interval, 2>>& point) {
    using U = UpwardInterval;
    const UpwardRoundingScope upward;
    const UpwardSite p(in.p), q(in.q);
    const bool is_signed = in.is_signed;
    const double(&x0)[2] = in.x0;
    const double(&C)[2][2] = in.C;
    const Frame<U> bp(p, U(in.sin_theta), U(in.cos_theta));
    const Frame<U> bq0(q, U(in.sin_phi), U(in.cos_phi), q_parts<U>(is_signed));
    const U s0(x0[0]);
    U F[2];
    Differences<U>(bp, bq0, s0).residual(bp, bq0, s0, is_signed, F);
    // K = -C F(x0) + (I - C J(X)) (X - x0) inside the interior of X - x0?
    U CF[2];
    for (int i = 0; i < 2; ++i) CF[i] = C[i][0] * F[0] + C[i][1] * F[1];
    double r[2];
    for (int i = 0; i < 2; ++i) r[i] = 2 * magnitude(CF[i]) + std::ldexp(1 + std::fabs(x0[i]), -44);
    const U medial_p(in.medial_p), medial_q(in.medial_q);
    for (int attempt = 0; attempt < 3; ++attempt) {
        if (!std::isfinite(r[0]) || !std::isfinite(r[1]) || r[1] > 1) return false;
        const U s = s0 + U(-r[0], r[0]);
        // s > 0, or s > -r_p with the signed tie (normal_ray_bisector.hpp).
        if (!(is_signed ? s + medial_p : s).positive()) return false;
        const Frame<U> bq = widened_q_frame(in, q, bq0, r[1]);
        const System<U> on_box(q, bp, bq, s, is_signed);
        const U Y[2] = {U(-r[0], r[0]), U(-r[1], r[1])};
        U K[2];
        if (!krawczyk_inside(C, CF, on_box.J, Y, r, K)) {
            for (int i = 0; i < 2; ++i) r[i] = std::max(2 * r[i], 2 * magnitude(K[i]));
            continue;
        }
        // V outside q along its normal, or above q's medial axis with the signed tie.
        if (!(is_signed ? side(bp, bq, s) + medial_q * bq.n2 : side(bp, bq, s)).positive()) return false;
        // The root: s in x0 + K; the tie derivatives over X contain their values there.
        const TieDerivatives<U> tie(bp, bq, s, Differences<U>(bp, bq, s), is_signed);
        if (tie.g_s.contains_zero()) return false;
        node_values(in, bp, s0 + K[0], tie, densities, point);
        return true;
    }
    return false;
}

// The node from the last disk certificate, whose theta lies on the disk's
// real diameter: there the system has one root x* in X(theta) = x_model(theta)
// + D(0, reach), the bisector point; with C(theta) = sum C_k d^k and A the
// mean-value Jacobian between x0 and x* (both in X(theta), and so the segment
// between), x0 - x* = C(theta) F(x0) + (I - C(theta) A)(x0 - x*), whose
// entries the disk bounds: |I - C(theta) A|_ij <= a_ij (`coupling`). So e =
// |x0 - x*| satisfies (I - a) e <= c, c = |C(theta) F(x0)|, and as sum_j a_ij
// reach_j < reach_i (the disk's test), I - a has a nonnegative inverse: e <=
// (I - a)^-1 c = delta. No Krawczyk test, no side check (the disk's hold for
// its root). (A common scale t reach_i for both unknowns, t = max_i c_i /
// (reach_i - sum_j a_ij reach_j), was as wide as s's reach allowed when phi's
// row of the test had little margin: a thousand times the root's error.)
// p's frame at theta and q's at phi0 given; false when x0 is not in
// X(theta). Under the upward rounding mode. Then certify_node_in_disk gives
// the node's values from the root in x0 +- delta.
bool disk_offsets(const NodeInput& in, const NormalRayInDoubles::DiskProof& disk, const Frame<UpwardInterval>& bp,
                  const Frame<UpwardInterval>& bq0, double (&delta)[2]) {
    using U = UpwardInterval;
    constexpr int kDegree = NormalRayInDoubles::kDiskDegree;
    const double(&x0)[2] = in.x0;
    const U d = U(in.theta) - U(disk.mid);
    // x0 in X(theta)?
    for (int i = 0; i < 2; ++i) {
        U model(disk.x[i][kDegree]);
        for (int k = kDegree - 1; k >= 0; --k) model = model * d + U(disk.x[i][k]);
        if (!(magnitude(U(x0[i]) - model) < disk.reach[i])) return false;
    }
    const U s0(x0[0]);
    U F[2];
    Differences<U>(bp, bq0, s0).residual(bp, bq0, s0, in.is_signed, F);
    U c[2];
    for (int i = 0; i < 2; ++i) {
        U CF = U(disk.C[kDegree][i][0]) * F[0] + U(disk.C[kDegree][i][1]) * F[1];
        for (int k = kDegree - 1; k >= 0; --k) CF = CF * d + (U(disk.C[k][i][0]) * F[0] + U(disk.C[k][i][1]) * F[1]);
        c[i] = U(magnitude(CF));
    }
    const double(&a)[2][2] = disk.coupling;
    const U diagonal[2] = {U(1.0) - U(a[0][0]), U(1.0) - U(a[1][1])};
    const U det = diagonal[0] * diagonal[1] - U(a[0][1]) * U(a[1][0]);
    if (!det.positive() || !diagonal[0].positive() || !diagonal[1].positive()) return false;
    delta[0] = ((diagonal[1] * c[0] + U(a[0][1]) * c[1]) / det).hi;
    delta[1] = ((U(a[1][0]) * c[0] + diagonal[0] * c[1]) / det).hi;
    return std::isfinite(delta[0]) && delta[1] <= 1;
}

ELLVOR_UPWARD_ROUNDING_FUNCTION bool certify_node_in_disk(const NodeInput& in, const NormalRayInDoubles::DiskProof& disk,
                                                          std::optional<MeasureIntervals>& densities,
                                                          std::optional<std::array<Interval, 2>>& point) {
    using U = UpwardInterval;
    const UpwardRoundingScope upward;
    const UpwardSite p(in.p), q(in.q);
    // A point alone (a ring's) needs of p's frame what F does, and no s'.
    const Frame<U> bp(p, U(in.sin_theta), U(in.cos_theta),
                      in.with_densities || in.is_signed ? Frame<U>::all : Frame<U>::point_normal);
    const Frame<U> bq0(q, U(in.sin_phi), U(in.cos_phi), q_parts<U>(in.is_signed));
    double delta[2];
    if (!disk_offsets(in, disk, bp, bq0, delta)) return false;
    const U s = U(in.x0[0]) + U(-delta[0], delta[0]);
    if (!in.with_densities) {
        std::array<U, 2> v;
        point_of(bp, s, v, point);
        return true;
    }
    const Frame<U> bq = widened_q_frame(in, q, bq0, delta[1]);
    const TieDerivatives<U> tie(bp, bq, s, Differences<U>(bp, bq, s), in.is_signed);
    if (tie.g_s.contains_zero()) return false;
    node_values(in, bp, s, tie, densities, point);
    return true;
}

// disk_offsets alone (NormalRayInDoubles::root_from_disk).
ELLVOR_UPWARD_ROUNDING_FUNCTION bool root_offsets_in_disk(const NodeInput& in, const NormalRayInDoubles::DiskProof& disk,
                                                          double (&delta)[2]) {
    using U = UpwardInterval;
    const UpwardRoundingScope upward;
    const UpwardSite p(in.p), q(in.q);
    const Frame<U> bp(p, U(in.sin_theta), U(in.cos_theta));
    const Frame<U> bq0(q, U(in.sin_phi), U(in.cos_phi), q_parts<U>(in.is_signed));
    return disk_offsets(in, disk, bp, bq0, delta);
}

}  // namespace

bool NormalRayInDoubles::on_disk(const Interval& theta) const {
    if (!disk_) return false;
    const Interval d = theta - Interval(disk_->mid);
    return std::max(-d.lo, d.hi) <= disk_->R;
}

std::optional<std::array<Interval, 2>> NormalRayInDoubles::root_from_disk(const Interval& theta, const double (&x)[2]) {
    if (!on_disk(theta)) return std::nullopt;
    Interval sin, cos, sin_phi, cos_phi;
    sin_cos(theta, sin, cos);
    sin_cos(Interval(x[1]), sin_phi, cos_phi);
    const double C[2][2] = {{0, 0}, {0, 0}};  // the disk's are used
    const NodeInput in{p_, q_, signed_, medial_p_, medial_q_, q_slack_, theta, sin, cos, sin_phi, cos_phi,
                       x, C,  origin_, false};
    double delta[2];
    if (!root_offsets_in_disk(in, *disk_, delta)) return std::nullopt;
    return std::array<Interval, 2>{Interval(x[0]) + Interval(-delta[0], delta[0]),
                                   Interval(x[1]) + Interval(-delta[1], delta[1])};
}

std::optional<NormalRayInDoubles::Node> NormalRayInDoubles::certified(const Interval& theta, const double (&x0)[2],
                                                                      const double (&C)[2][2], bool with_densities) {
    Interval sin, cos, sin_phi, cos_phi;
    sin_cos(theta, sin, cos);
    sin_cos(Interval(x0[1]), sin_phi, cos_phi);
    const NodeInput in{p_, q_, signed_, medial_p_, medial_q_, q_slack_, theta, sin, cos, sin_phi, cos_phi,
                       x0, C,  origin_, with_densities};
    Node out;
    // From the last disk's proof when theta is on its real diameter (a
    // node of its piece), else by a Krawczyk test of its own.
    if (on_disk(theta) && certify_node_in_disk(in, *disk_, out.densities, out.point))
        ++disk_nodes_;
    else if (!certify_node(in, out.densities, out.point))
        return std::nullopt;
    last_[0] = x0[0], last_[1] = x0[1];
    return out;
}

namespace {

// A site's exact parameters as balls, under Frame's member names.
struct BallSite {
    FixedPrecisionBall a, b, c, s, xc, yc;
    BallSite(const SiteBalls& e, long prec)
        : a(e.a, prec), b(e.b, prec), c(e.cos, prec), s(e.sin, prec), xc(e.xc, prec), yc(e.yc, prec) {}
};

void sin_cos(const FixedPrecisionBall& angle, FixedPrecisionBall& sin, FixedPrecisionBall& cos) {
    Ball s, c;
    arb_sin_cos(s.get(), c.get(), angle.ball().get(), angle.precision());
    sin = FixedPrecisionBall(s, angle.precision()), cos = FixedPrecisionBall(c, angle.precision());
}

// An upper bound of |x| (infinite for a ball that is not finite).
double magnitude(const FixedPrecisionBall& x) {
    Mag bound;
    arb_get_mag(bound.get(), x.ball().get());
    return mag_get_d(bound.get());  // rounded up
}

// x widened by r (rounded up: the error is a Mag).
void add_error(FixedPrecisionBall& x, double r) {
    Ball widened = x.ball();
    Mag error;
    mag_set_d(error.get(), r);
    arb_add_error_mag(widened.get(), error.get());
    x = FixedPrecisionBall(widened, x.precision());
}

FixedPrecisionBall midpoint(const FixedPrecisionBall& x) {
    Ball m;
    arb_get_mid_arb(m.get(), x.ball().get());
    return FixedPrecisionBall(m, x.precision());
}

// sum_k coefficient(k) d^k, k = 0 .. kDiskDegree, by Horner.
template <class Coefficient>
FixedPrecisionBall horner(const FixedPrecisionBall& d, Coefficient&& coefficient) {
    FixedPrecisionBall sum = coefficient(NormalRayInDoubles::kDiskDegree);
    for (int k = NormalRayInDoubles::kDiskDegree - 1; k >= 0; --k) sum = sum * d + coefficient(k);
    return sum;
}

}  // namespace

// A node as certify_node_in_disk's, in balls: the root's offsets from the
// proof, e <= (I - a)^-1 |C(theta) F(x)|, at the point x refined by steps
// x <- x - C F(x) with the inverse C of Newton's last Jacobian in doubles
// (each gains about what |I - C J| loses, 45 bits: one step from the root in
// doubles to 114 bits, the precision at a tolerance of 1e-15).
bool NormalRayInDoubles::densities_in_balls(const Ball& theta_ball, long prec, NormalRayBisector::Densities& out) {
    using B = FixedPrecisionBall;
    if (!disk_) return false;
    const DiskProof& disk = *disk_;
    const B theta(theta_ball, prec), d = theta - B(disk.mid);
    if (!(magnitude(d) <= disk.R)) return false;
    const double theta0 = theta_ball.mid_double();
    double start[2], x0[2], C[2][2];
    if (!disk_start(theta0, start) || !newton(theta0, start, x0, C)) return false;
    if (balls_prec_ != prec) {
        p_balls_ = SiteBalls(*p_ellipse_, prec), q_balls_ = SiteBalls(*q_ellipse_, prec);
        balls_prec_ = prec;
    }
    const BallSite p(p_balls_, prec), q(q_balls_, prec);
    B sin_theta, cos_theta;
    sin_cos(theta, sin_theta, cos_theta);
    const Frame<B> bp(p, sin_theta, cos_theta);
    B sin_phi, cos_phi;  // at the last point
    Frame<B> bq;
    const auto residual = [&](const B& s, const B& phi, B (&F)[2]) {
        sin_cos(phi, sin_phi, cos_phi);
        bq = Frame<B>(q, sin_phi, cos_phi, q_parts<B>(signed_));
        Differences<B>(bp, bq, s).residual(bp, bq, s, signed_, F);
    };
    // Steps x <- x - C F(x) until the next one is below 2^(24 - prec) |x|
    // (F's rounding at prec keeps them from shrinking much further); its
    // F(x) then gives the offsets, about that step.
    B x[2] = {B(x0[0], prec), B(x0[1], prec)}, F[2];
    for (int step = 0;; ++step) {
        residual(x[0], x[1], F);
        B correction[2];
        bool converged = true;
        for (int i = 0; i < 2; ++i) {
            correction[i] = midpoint(B(C[i][0]) * F[0] + B(C[i][1]) * F[1]);
            converged = converged && magnitude(correction[i]) <= std::ldexp(1 + std::fabs(x0[i]), 24 - prec);
        }
        if (converged) break;
        if (step == 6) return false;
        for (int i = 0; i < 2; ++i) x[i] = midpoint(x[i] - correction[i]);
    }
    // x in X(theta) for every theta in the ball, where the proof holds.
    for (int i = 0; i < 2; ++i)
        if (!(magnitude(x[i] - horner(d, [&](int k) { return B(disk.x[i][k]); })) < disk.reach[i])) return false;
    B c[2];
    for (int i = 0; i < 2; ++i)
        c[i] = B(magnitude(horner(d, [&](int k) { return B(disk.C[k][i][0]) * F[0] + B(disk.C[k][i][1]) * F[1]; })));
    const double(&a)[2][2] = disk.coupling;
    const B diagonal[2] = {B(1.0) - B(a[0][0]), B(1.0) - B(a[1][1])};
    const B det = diagonal[0] * diagonal[1] - B(a[0][1]) * B(a[1][0]);
    if (!arb_is_positive(det.ball().get()) || !arb_is_positive(diagonal[0].ball().get()) ||
        !arb_is_positive(diagonal[1].ball().get()))
        return false;
    const double delta[2] = {magnitude((diagonal[1] * c[0] + B(a[0][1]) * c[1]) / det),
                             magnitude((B(a[1][0]) * c[0] + diagonal[0] * c[1]) / det)};
    if (!std::isfinite(delta[0]) || !(delta[1] <= 1)) return false;
    // q's frame over phi +- delta_1 from the one at phi, as widened_q_frame's
    // (sine and cosine move by at most delta_1).
    if (signed_) {
        add_error(sin_phi, delta[1]), add_error(cos_phi, delta[1]);
        bq = Frame<B>(q, sin_phi, cos_phi);
    } else {
        for (B* part : {&bq.x, &bq.dx, &bq.ny}) add_error(*part, Interval::up(delta[1] * q_slack_[0]));
        for (B* part : {&bq.y, &bq.dy, &bq.nx}) add_error(*part, Interval::up(delta[1] * q_slack_[1]));
    }
    // The densities from the root's ball, as node_values's.
    B s = x[0];
    add_error(s, delta[0]);
    const TieDerivatives<B> tie(bp, bq, s, Differences<B>(bp, bq, s), signed_);
    if (arb_contains_zero(tie.g_s.ball().get())) return false;
    const B ds = -(tie.g_theta / tie.g_s);
    const B vx = bp.dx + ds * bp.nx + s * bp.dnx, vy = bp.dy + ds * bp.ny + s * bp.dny;
    B densities[MeasureIntervals::count];
    green_densities(bp.x + s * bp.nx - B(origin_[0]), bp.y + s * bp.ny - B(origin_[1]), vx, vy, densities);
    densities[MeasureIntervals::length] = root_of(dot(vx, vy, vx, vy));
    for (int j = 0; j < MeasureIntervals::count; ++j) {
        if (!arb_is_finite(densities[j].ball().get())) return false;
        acb_set_arb(out.m[j].get(), densities[j].ball().get());
    }
    return true;
}

namespace {

// The Taylor models of the disk certificate: degree 2 (the root's model
// below is its Taylor polynomial of that degree).
constexpr int kModelDegree = NormalRayInDoubles::kDiskDegree;
using Model = RealTaylorModel<kModelDegree>;

// The residual H(theta) = F(x_model(theta), theta) and the preconditioned
// C(theta) H(theta) are models of a higher degree: x_model cancels H to
// order kModelDegree, and its next terms are large and cancel between F's
// terms (two circles 10 apart: the tie's d^4 coefficient 17 where C H is
// 0.03 on the disk), which a model of degree 2 bounds term by term, by
// their 1-norms: 6.5 times C H's true size there, a certified disk a third
// narrower.
constexpr int kResidualDegree = 4;
using ResidualModel = RealTaylorModel<kResidualDegree>;

// sum x_k d^k, exact coefficients, on the disk of radius R.
template <int M = kModelDegree>
RealTaylorModel<M> polynomial(const std::array<double, kModelDegree + 1>& x, double R) {
    RealTaylorModel<M> m(ComplexInterval(Interval(x[0])), R);
    for (int k = 1; k <= kModelDegree; ++k) m.c[k] = x[k];
    return m;
}

}  // namespace

// The certificate on a disk of theta: the root there as Taylor models, and
// what the densities and the linear model need.
struct NormalRayInDoubles::DiskRoot {
    Frame<Model> bp;                     // p's boundary on the disk
    Model s, ds;                         // s and s' on the disk
    double s0, slope, curvature;         // s = s0 + slope d + e(theta) = ... + curvature d^2 + e2(theta),
    double remainder, remainder2;        // |e| <= remainder, |e2| <= remainder2
    double contraction;                  // DiskBounds::contraction
};

std::optional<NormalRayInDoubles::DiskRoot> NormalRayInDoubles::disk_root(double mid, double R) {
    using CI = ComplexInterval;
    disk_.reset();
    constexpr int N = kModelDegree;
    // Newton's root x0 at the real middle (the certificate below covers it:
    // a wrong root fails its checks), the inverse C of J there and the
    // root's Taylor polynomial x(mid + d) = sum x_k d^k: x_1 = -C F_theta;
    // x_2 by central differences of Newton's roots at mid +- h, h = R / 8
    // (their rounding moves x_2 by about 64 u |x| / R^2, the residual on the
    // disk by 64 u |x|, below the certificate's floor; a model evaluation at
    // radius 0 cost 5% of a cell); each further x_k = -C H_k, H_k the
    // coefficient of d^k of F along the polynomial so far (models on a disk
    // of radius 0: Taylor coefficients). All in doubles: any C and
    // polynomial are sound, these keep Y small.
    if (!(R >= 0) || !std::isfinite(R)) return std::nullopt;
    double x0[2], start[2], C[2][2];
    if (!newton(mid, last_, x0, C) && !(ray_start(mid, start) && newton(mid, start, x0, C))) return std::nullopt;
    const Frame<double> bp_mid(p_.shape, std::sin(mid), std::cos(mid));
    const System<double> at(q_.shape, bp_mid,
                            Frame<double>(q_.shape, std::sin(x0[1]), std::cos(x0[1]), q_parts<double>(signed_)), x0[0], signed_);
    if (!inverse(at.J, C)) return std::nullopt;
    std::array<double, N + 1> x[2];
    for (int i = 0; i < 2; ++i) {
        x[i].fill(0.0);
        x[i][0] = x0[i];
        x[i][1] = -(C[i][0] * at.F_theta[0] + C[i][1] * at.F_theta[1]);
    }
    const double h = R / 8;
    double ahead[2], behind[2], C_unused[2][2];
    const double start_ahead[2] = {x0[0] + h * x[0][1], x0[1] + h * x[1][1]};
    const double start_behind[2] = {x0[0] - h * x[0][1], x0[1] - h * x[1][1]};
    if (h > 0 && newton(mid + h, start_ahead, ahead, C_unused) && newton(mid - h, start_behind, behind, C_unused))
        for (int i = 0; i < 2; ++i) {
            const double x2 = (ahead[i] - 2 * x0[i] + behind[i]) / (2 * h * h);
            x[i][2] = std::isfinite(x2) ? x2 : 0.0;
        }
    Model sin, cos;
    const auto residual = [&](const Frame<Model>& bp, const Model& s, const Model& phi, Model (&F)[2]) {
        sin_cos(phi, sin, cos);
        const Frame<Model> bq(q_, sin, cos, q_parts<Model>(signed_));
        Differences<Model>(bp, bq, s).residual(bp, bq, s, signed_, F);
    };
    if constexpr (N > 2) {
        Model H[2];
        sin_cos(Model::variable(CI(Interval(mid)), 0), sin, cos);
        const Frame<Model> bp_at_mid(p_, sin, cos);
        for (int k = 3; k <= N; ++k) {
            residual(bp_at_mid, polynomial(x[0], 0), polynomial(x[1], 0), H);
            for (int i = 0; i < 2; ++i) {
                x[i][k] = -(C[i][0] * H[0].c[k] + C[i][1] * H[1].c[k]);
                if (!std::isfinite(x[i][k])) return std::nullopt;
            }
        }
    }

    // On the disk mid + d, |d| <= R: x = x_model(theta) + y. The system
    // along x_model (H(theta) = F(x_model(theta), theta), of the order N + 1
    // in R, and J) as models of the residual's degree. (Interval evaluations
    // over a box lose how every quantity follows d: a first-order mean-value
    // form, then second-order jets, overestimated H and I - C J(X) ten to
    // thirty times over and kept the boxes small.)
    using RM = ResidualModel;
    static_assert(kResidualDegree >= N, "the residual's models hold x_model");
    RM sin_along, cos_along;
    sin_cos(RM::variable(CI(Interval(mid)), R), sin_along, cos_along);
    const Frame<RM> bp_along(p_, sin_along, cos_along);
    sin_cos(polynomial<kResidualDegree>(x[1], R), sin_along, cos_along);
    const System<RM> along(q_, bp_along, Frame<RM>(q_, sin_along, cos_along, q_parts<RM>(signed_)),
                           polynomial<kResidualDegree>(x[0], R), signed_, false);
    // The Krawczyk test at each theta with its own preconditioner C(theta)
    // = sum C_k d^k, the Taylor polynomial of J^-1 along the model at mid
    // (C_0 = C, C_k = -C sum_{j=1..k} J_j C_{k-j}, J_j the Taylor
    // coefficients of J(x_model(theta), theta); any matrices are sound at
    // each theta: these cancel I - C(theta) J to order N):
    // |I - C(theta) J(X(theta))| and |C(theta) H(theta)| bounded by their
    // models, pointwise in theta.
    std::array<double, N + 1> Ck[2][2];
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) Ck[i][j][0] = C[i][j];
    for (int k = 1; k <= N; ++k) {
        double JC[2][2] = {{0, 0}, {0, 0}};  // sum_j J_j C_{k-j}
        for (int j = 1; j <= k; ++j)
            for (int a = 0; a < 2; ++a)
                for (int b = 0; b < 2; ++b)
                    for (int l = 0; l < 2; ++l) JC[a][b] += along.J[a][l].c[j] * Ck[l][b][k - j];
        for (int a = 0; a < 2; ++a)
            for (int b = 0; b < 2; ++b) {
                Ck[a][b][k] = -(C[a][0] * JC[0][b] + C[a][1] * JC[1][b]);
                if (!std::isfinite(Ck[a][b][k])) return std::nullopt;
            }
    }
    double CH[2], r[2];
    for (int i = 0; i < 2; ++i)
        CH[i] = (polynomial<kResidualDegree>(Ck[i][0], R) * along.F[0] +
                 polynomial<kResidualDegree>(Ck[i][1], R) * along.F[1]).bound();
    for (int i = 0; i < 2; ++i) r[i] = 2 * CH[i] + std::ldexp(1 + std::fabs(x0[i]), -44);
    const Frame<Model> bp_model = truncated<N>(bp_along);
    const Model s_model = polynomial(x[0], R), phi_model = polynomial(x[1], R);
    Model Ct[2][2];
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) Ct[i][j] = polynomial(Ck[i][j], R);
    // The test on X(theta) = x_model(theta) + Y, Y_i = +- r_i + i (+- r_i)
    // in the disk of radius reach_i = sqrt(2) r_i (1.4142135623730951 >
    // sqrt(2)). Two at most: r = 2 |C H|, then, where that failed, twice
    // K's bound (with |C H| nearly exact, a row whose |C H| is much smaller
    // than the other's fails by the coupling through the other's reach
    // alone); a failure after that halves the piece (the caller).
    double reach[2], k_bound[2], coupling[2][2];
    Model X[2];
    std::optional<Frame<Model>> bq;
    std::optional<System<Model>> on_box;
    for (int test = 0;; ++test) {
        if (!std::isfinite(r[0]) || !std::isfinite(r[1]) || r[1] > 1) return std::nullopt;
        X[0] = s_model, X[1] = phi_model;
        for (int i = 0; i < 2; ++i) {
            reach[i] = Interval::up(r[i] * 1.4142135623730951);
            X[i].remainder = Interval::up(X[i].remainder + reach[i]);
        }
        // Re s > 0, or Re s > -r_p with the signed tie (normal_ray_bisector.hpp).
        const CI s_disk = X[0].enclose_disk();
        if (!(signed_ ? s_disk.re + medial_p_ : s_disk.re).positive()) return std::nullopt;
        sin_cos(X[1], sin, cos);
        bq.emplace(q_, sin, cos, q_parts<Model>(signed_));
        on_box.emplace(q_, bp_model, *bq, X[0], signed_);
        bool inside = true;
        for (int i = 0; i < 2; ++i) {
            k_bound[i] = CH[i];
            for (int j = 0; j < 2; ++j) {
                Model m = -(Ct[i][0] * on_box->J[0][j] + Ct[i][1] * on_box->J[1][j]);
                if (i == j) m = m + Interval(1.0);
                coupling[i][j] = m.bound();
                k_bound[i] = Interval::up(k_bound[i] + Interval::up(coupling[i][j] * reach[j]));
            }
            inside = inside && k_bound[i] < r[i];
        }
        if (inside) break;
        if (test == 1) return std::nullopt;
        for (int i = 0; i < 2; ++i) r[i] = Interval::max(r[i], 2 * k_bound[i]);
    }
    // One root in X, holomorphic in theta; q's nearest point when V - Q
    // points out of q (normal_ray_bisector.hpp), or above q's medial axis
    // with the signed tie.
    const Model side =
        dot(bp_model.x + X[0] * bp_model.nx - bq->x, bp_model.y + X[0] * bp_model.ny - bq->y, bq->nx, bq->ny);
    if (!(signed_ ? side + medial_q_ * bq->n2 : side).enclose_disk().re.positive()) return std::nullopt;
    // The root s(theta) lies within |K_0| <= k_bound[0] of x_model(theta),
    // and s' = -g_theta / g_s (g_s zero-free on the disk, else the
    // reciprocal's remainder is infinite).
    Model s_root = s_model;
    s_root.remainder = Interval::up(s_root.remainder + k_bound[0]);
    const Model ds = -(on_box->F_theta[1] / on_box->J[1][0]);
    if (!std::isfinite(ds.remainder)) return std::nullopt;
    // s - (x_0 + x_1 d) = x_2 d^2 + (higher terms) + K_0, s - (x_0 + x_1 d
    // + x_2 d^2) = (higher terms) + K_0.
    Model higher = s_model.variation();
    higher.c[1] = 0;
    const double remainder = Interval::up(higher.bound() + k_bound[0]);
    higher.c[2] = 0;
    const double remainder2 = Interval::up(higher.bound() + k_bound[0]);
    last_[0] = x0[0], last_[1] = x0[1];  // the next piece's Newton start (when no node is certified in doubles)
    DiskProof proof{mid, R, {}, {}, {reach[0], reach[1]},
                    {{coupling[0][0], coupling[0][1]}, {coupling[1][0], coupling[1][1]}}};
    for (int k = 0; k <= N; ++k)
        for (int i = 0; i < 2; ++i)
            for (int j = 0; j < 2; ++j) proof.C[k][i][j] = Ck[i][j][k];
    for (int i = 0; i < 2; ++i)
        for (int k = 0; k <= N; ++k) proof.x[i][k] = x[i][k];
    disk_ = proof;
    // Of K's bound over r, at least 1/2 (r = 2 |C H| + ...): the rest, the
    // contraction's share, grows with the square of R.
    const double contraction = std::max(k_bound[0] / r[0], k_bound[1] / r[1]);
    static_assert(N >= 2, "DiskRoot's curvature is x_2");
    return DiskRoot{bp_model, s_root, ds, x0[0], x[0][1], x[0][2], remainder, remainder2, contraction};
}

std::optional<NormalRayInDoubles::DiskBounds> NormalRayInDoubles::bounds_on_disk(double mid, double R, double half) {
    using CI = ComplexInterval;
    if (!(half >= 0 && half <= R)) return std::nullopt;
    const std::optional<DiskRoot> r = disk_root(mid, R);
    if (!r) return std::nullopt;
    const Frame<Model>& bp = r->bp;
    const Model &s = r->s, &ds = r->ds;
    // The densities of NormalRayBisector::densities on the disk, as models.
    const Model x = bp.x + s * bp.nx, y = bp.y + s * bp.ny;  // V
    const Model vx = bp.dx + ds * bp.nx + s * bp.dnx, vy = bp.dy + ds * bp.ny + s * bp.dny;
    // The length density |V'| = sqrt(V' . V') = sqrt(u A) sqrt(conj(u) B) /
    // |u| with A = V'x + i V'y, B = V'x - i V'y (conjugates on the reals) and
    // any u != 0: holomorphic where u A and conj(u) B avoid the principal
    // square root's cut, its modulus sqrt(|A| |B|). With u = conj(A(mid))
    // each factor turns half as fast as V' . V' (whose own principal root
    // failed on most disks near the end of a long edge).
    using ComplexModel = ComplexTaylorModel<kModelDegree>;
    const CI i_unit(Interval(0.0), Interval(1.0));
    const ComplexModel complex_vx(vx), complex_vy(vy);
    const ComplexModel A = complex_vx + i_unit * complex_vy, B = complex_vx - i_unit * complex_vy;
    const CI u(Interval(A.c[0].re), Interval(-A.c[0].im));
    const auto off_the_cut = [](const CI& z) { return z.re.positive() || z.im.positive() || (-z.im).positive(); };
    if (!off_the_cut((u * A).enclose_disk()) || !off_the_cut((CI(u.re, -u.im) * B).enclose_disk()))
        return std::nullopt;
    Model densities[MeasureIntervals::count];
    green_densities(x - Interval(origin_[0]), y - Interval(origin_[1]), vx, vy, densities);
    DiskBounds out;
    out.contraction = r->contraction;
    // The length's model: u A(mid) = |A(mid)|^2 > 0, so each root is the
    // principal one's series (its remainder infinite where that fails: then
    // only the modulus bound serves).
    const Interval modulus_u = (u.re.square() + u.im.square()).sqrt();
    const ComplexModel length =
        (Interval(1.0) / modulus_u) * (principal_root(u * A) * principal_root(CI(u.re, -u.im) * B));
    for (int j = 0; j < MeasureIntervals::count; ++j) {
        if (j == MeasureIntervals::length) {
            out.density[j] = length.bound();
            out.beyond_polynomial[j] = length.remainder;
            for (int k = 0; k <= kDiskDegree; ++k) out.polynomial[j][k] = {length.c[k].re, length.c[k].im};
            continue;
        }
        out.density[j] = densities[j].bound();
        out.beyond_polynomial[j] = densities[j].remainder;
        for (int k = 0; k <= kDiskDegree; ++k) out.polynomial[j][k] = {densities[j].c[k], 0};
    }
    out.density[MeasureIntervals::length] = std::min(
        out.density[MeasureIntervals::length], (Interval(A.bound()).sqrt() * Interval(B.bound()).sqrt()).hi);
    for (double b : out.density)
        if (!std::isfinite(b)) return std::nullopt;
    // |V - C|^2 as a model, on the real angles mid +- half: there the root,
    // hence V, is real (normal_ray_bisector.hpp), so its square lies in the
    // enclosure's real part. (Far tighter than |V - C| over the whole disk:
    // the first order is the radial speed only.)
    for (int i = 0; i < 2; ++i) {
        const Site& e = i == 0 ? p_ : q_;
        const Model dx = x - e.xc, dy = y - e.yc;
        const Interval distance2 = (dx * dx + dy * dy).enclose(CI(sym(half), Interval(0.0))).re;
        if (!(distance2.hi >= 0 && std::isfinite(distance2.hi))) return std::nullopt;
        out.center_distance[i] = Interval(distance2.hi).sqrt().hi;
    }
    return out;
}

std::optional<NormalRayInDoubles::RootModel> NormalRayInDoubles::root_model(double mid, double R) {
    const std::optional<DiskRoot> r = disk_root(mid, R);
    if (!r) return std::nullopt;
    // |n~| <= sqrt(|nx|^2 + |ny|^2).
    const double nx = r->bp.nx.bound(), ny = r->bp.ny.bound();
    RootModel model{mid,          r->s0,         r->slope, r->curvature, r->remainder, r->remainder2,
                    (Interval(nx).square() + Interval(ny).square()).sqrt().hi};
    if (!std::isfinite(model.remainder) || !std::isfinite(model.quadratic_remainder) || !std::isfinite(model.normal))
        return std::nullopt;
    return model;
}

}  // namespace ellvor
