#include "cells/voronoi_edge_cover.hpp"

#include "cells/normal_ray_in_doubles.hpp"
#include "util/error.hpp"
#include "util/interval_trig.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

namespace ellvor {
namespace {

// An upper bound of |b - c| (b a ball, c a double), rounded up.
double gap_bound(const Ball& b, double c, long prec) {
    Ball d;
    Arf a;
    arf_set_d(a.get(), c);
    arb_sub_arf(d.get(), b.get(), a.get(), prec);
    Arf u;
    arb_get_abs_ubound_arf(u.get(), d.get(), prec);
    return arf_get_d(u.get(), ARF_RND_UP);
}

double hypot_up(double x, double y) {
    // sqrt and the products round to nearest: a relative nudge of 2^-50 covers them.
    return std::nextafter(std::sqrt(x * x + y * y) * (1 + std::ldexp(1.0, -50)), INFINITY);
}

// V(theta) = P(theta) + s n~(theta) over a complex ball of theta, S enclosing s there.
void ray_points(const SiteBalls& p, const ComplexBall& theta, const ComplexBall& s, long prec, ComplexBall& x,
                ComplexBall& y) {
    ComplexBall c, sn, lx, ly, t;
    acb_sin_cos(sn.get(), c.get(), theta.get(), prec);
    // the frame coordinates of P + s n~: (c (a + s b), sn (b + s a))
    acb_mul_arb(t.get(), s.get(), p.b.get(), prec);
    acb_add_arb(t.get(), t.get(), p.a.get(), prec);
    acb_mul(lx.get(), c.get(), t.get(), prec);
    acb_mul_arb(t.get(), s.get(), p.a.get(), prec);
    acb_add_arb(t.get(), t.get(), p.b.get(), prec);
    acb_mul(ly.get(), sn.get(), t.get(), prec);
    // rotate and translate
    acb_mul_arb(x.get(), lx.get(), p.cos.get(), prec);
    acb_mul_arb(t.get(), ly.get(), p.sin.get(), prec);
    acb_sub(x.get(), x.get(), t.get(), prec);
    acb_add_arb(x.get(), x.get(), p.xc.get(), prec);
    acb_mul_arb(y.get(), lx.get(), p.sin.get(), prec);
    acb_mul_arb(t.get(), ly.get(), p.cos.get(), prec);
    acb_add(y.get(), y.get(), t.get(), prec);
    acb_add_arb(y.get(), y.get(), p.yc.get(), prec);
}

// V over a real ball of theta, in real balls (V is real there).
bool real_ray_points(NormalRayBisector& bisector, const SiteBalls& p, const Ball& theta, long prec, Ball& x, Ball& y) {
    ComplexBall s, vx, vy;
    if (!bisector.solve(ComplexBall(theta), prec, s)) return false;
    arb_zero(s.imag());  // s is real for real theta (cells/normal_ray_bisector.hpp)
    ray_points(p, ComplexBall(theta), s, prec, vx, vy);
    arb_set(x.get(), vx.real());
    arb_set(y.get(), vy.real());
    return true;
}

double magnitude_up(const acb_t z) {
    Mag m;
    acb_get_mag(m.get(), z);
    return mag_get_d(m.get());
}

// Points a second-order piece may ask for before it is halved instead.
constexpr double kMaxPointsAPiece = 4096;

// Bounds on a piece J = [l, h] from the root's model on a region Z about J
// (in doubles the disk of radius half + margin about J's middle, its
// quadratic model; Arb's, the box of real radius half + margin, imaginary
// radius margin, its linear one): with s_m = s0 + s1 d + s2 d^2 (d = theta -
// mid; s2 = 0 for Arb's) and W = P + s_m n~ = C + R (c A, sn B), A = a + b
// s_m, B = b + a s_m (c, sn the cosine and sine of theta, R the rotation),
// V = W + e n~ where |e n~| <= M = remainder sup_Z |n~| on Z, so on J
// (Cauchy, margin the distance from J to Z's boundary)
//     |V'| <= |W'| + M / margin,   |V''| <= |W''| + 2 M / margin^2,
// W' and W'' in closed form over J (s_m' = s1 + 2 s2 d, s_m'' = 2 s2):
//     u' = -sn A + c b s_m',               v' = c B + sn a s_m',
//     u'' = -c A - 2 sn b s_m' + c b s_m'', v'' = -sn B + 2 c a s_m' + sn a s_m''.
// (The quadratic model's remainder is of the third order in the disk's
// radius where the linear one's is of the second: its Cauchy term no longer
// sets the rings' point spacing on nearly straight edges.)
struct PieceBounds {
    double speed, curvature;  // the bounds of |V'| and |V''| on J
    Ball x, y;                // V(J)
};

std::optional<PieceBounds> piece_bounds(NormalRayBisector& bisector, NormalRayInDoubles& doubles, const SiteBalls& p,
                                        const Ellipse::Enclosure& site, double l, double h, double margin, long prec,
                                        bool& doubles_held, bool arb_may_try) {
    const double half = 0.5 * (h - l), m = 0.5 * (l + h);
    // The model: in double intervals, else by Arb when the caller allows it
    // (a rule of cost: a piece is never accepted without a certificate).
    Interval mid, s0, s1, s2;
    double remainder, M;  // |e| and |e n~| on Z
    const std::optional<NormalRayInDoubles::RootModel> fast = doubles.root_model(m, half + margin);
    if (!fast && !arb_may_try) return std::nullopt;
    if (fast) {
        doubles_held = true;
        mid = Interval(fast->mid), s0 = Interval(fast->s0), s1 = Interval(fast->s1), s2 = Interval(fast->s2);
        remainder = fast->quadratic_remainder;
        M = remainder * fast->normal * (1 + 1e-15);
    } else {
        ComplexBall z;
        arf_set_d(arb_midref(z.real()), m);
        mag_set_d(arb_radref(z.real()), half + margin);
        mag_set_d(arb_radref(z.imag()), margin);
        NormalRayBisector::LinearModel model;
        if (!bisector.solve(z, prec, model)) return std::nullopt;
        const auto real_part = [](const ComplexBall& z) {
            Ball r;
            arb_set(r.get(), z.real());
            return enclose(r);
        };
        mid = real_part(model.mid), s0 = real_part(model.s0), s1 = real_part(model.s1);
        // sup_Z |n~| = sup |(b c, a sn)|
        ComplexBall c, sn, t;
        acb_sin_cos(sn.get(), c.get(), z.get(), prec);
        acb_mul_arb(t.get(), c.get(), p.b.get(), prec);
        const double bc = magnitude_up(t.get());
        acb_mul_arb(t.get(), sn.get(), p.a.get(), prec);
        remainder = mag_get_d(model.remainder.get());
        M = remainder * hypot_up(bc, magnitude_up(t.get())) * (1 + 1e-15);
    }

    // Over J, in double intervals (Arb's balls were a twelfth of a JSON run).
    const Interval J(l, h), &a = site.a, &b = site.b;
    Interval sj, cj;
    sin_cos(J, sj, cj);
    const Interval d = J - mid;
    const Interval s_m = (s2 * d + s1) * d + s0;
    const Interval dds = 2.0 * s2, ds = dds * d + s1;  // s_m'' = 2 s2, s_m' = s1 + 2 s2 d
    const Interval A = a + b * s_m, B = b + a * s_m;
    const Interval u1 = -(sj * A) + cj * b * ds, v1 = cj * B + sj * a * ds;
    const Interval u2 = -(cj * A) - 2.0 * (sj * b * ds) + cj * b * dds;
    const Interval v2 = -(sj * B) + 2.0 * (cj * a * ds) + sj * a * dds;
    const auto up = [](const Interval& x) { return Interval::max(std::fabs(x.lo), std::fabs(x.hi)); };
    PieceBounds out;
    out.speed = hypot_up(up(u1), up(v1)) + M / margin * (1 + 1e-12);
    out.curvature = hypot_up(up(u2), up(v2)) + 2 * M / (margin * margin) * (1 + 1e-12);
    // V(J) within W(J) and M: s(J) within s_m(J) +- remainder; V = C + R (c (a + s b), sn (b + s a)).
    const Interval sJ = s_m + Interval(-remainder, remainder);
    const Interval lx = cj * (a + sJ * b), ly = sj * (b + sJ * a);
    out.x = ball_of(site.xc + lx * site.cos - ly * site.sin, prec);
    out.y = ball_of(site.yc + lx * site.sin + ly * site.cos, prec);
    if (!std::isfinite(out.speed) || !std::isfinite(out.curvature)) return std::nullopt;
    return out;
}

// Whether V(l) and V(h) are certainly more than `distance` apart (false when
// either is not certified in double intervals).
bool apart(NormalRayInDoubles& points, double l, double h, double distance) {
    const std::optional<std::array<Interval, 2>> a = points.point(Interval(l)), b = points.point(Interval(h));
    if (!a || !b) return false;
    double gap2 = 0;  // a lower bound of |V(l) - V(h)|^2
    for (int i = 0; i < 2; ++i) {
        const double g = std::max({0.0, (*a)[i].lo - (*b)[i].hi, (*b)[i].lo - (*a)[i].hi});
        gap2 += g * g;
    }
    return gap2 * (1 - std::ldexp(1.0, -50)) > distance * distance;
}

}  // namespace

std::vector<EdgeCoverBox> voronoi_edge_cover(NormalRayBisector& bisector, const Ball& from, const Ball& to,
                                             const EdgeCoverOptions& options) {
    const long prec = options.prec;
    const SiteBalls p(bisector.first(), prec);
    NormalRayInDoubles points(bisector.first(), bisector.second(), bisector.signed_tie());
    const Ellipse::Enclosure site = bisector.first().enclosure();
    Arf lo_arf, hi_arf, from_hi, to_lo;
    arb_get_lbound_arf(lo_arf.get(), from.get(), prec);
    arb_get_ubound_arf(hi_arf.get(), to.get(), prec);
    arb_get_ubound_arf(from_hi.get(), from.get(), prec);
    arb_get_lbound_arf(to_lo.get(), to.get(), prec);
    // Doubles rounded outward: the range still holds both vertex balls.
    const double lo = arf_get_d(lo_arf.get(), ARF_RND_DOWN), hi = arf_get_d(hi_arf.get(), ARF_RND_UP);
    const double first_end = arf_get_d(from_hi.get(), ARF_RND_UP), last_start = arf_get_d(to_lo.get(), ARF_RND_DOWN);
    if (!(lo <= hi) || !std::isfinite(lo) || !std::isfinite(hi))
        throw Error("voronoi_edge_cover: the vertex angles are not in order");
    const double smallest = std::ldexp(std::max(hi - lo, 1e-300), -40);

    std::vector<EdgeCoverBox> out;
    double first_piece_end = lo, last_piece_start = hi;
    // The overshoot past the true vertices: V at most the vertex balls' width beyond them.
    const double overshoot = std::max(first_end - lo, hi - last_start);
    // The model holds on pieces of about the same width: a piece over twice
    // as wide as the last one it held on is halved untried.
    // Nor is one tried wider than its poles allow (edge_quadrature.cpp's
    // rule, with this disk of radius the piece's width; at least a 64th of
    // the edge): the edge tried whole failed most often (4% of a JSON run).
    double certified_width = 0.5 * std::max(points.pole_limited_width(lo, 1.0, 0.15), (hi - lo) / 64);
    bool doubles_held = false;
    std::vector<std::pair<double, double>> stack{{lo, hi}};
    while (!stack.empty()) {
        const auto [l, h] = stack.back();
        stack.pop_back();
        EdgeCoverBox box;
        bool ok = false;
        const double m = 0.5 * (l + h);
        // Second order: points along J, as many as its bounds ask. Arb's
        // model is tried only where the doubles' never held on the edge, and
        // on pieces of at most a sixteenth of it: a wider piece is most often
        // only too wide for either (Arb's tries on the first pieces of the
        // edges were an eighth of a JSON run), and halving it is cheaper.
        const bool arb_may_try = !doubles_held && h - l <= (hi - lo) / 16;
        const std::optional<PieceBounds> bounds =
            h - l > 2 * certified_width
                ? std::nullopt
                : piece_bounds(bisector, points, p, site, l, h, 0.5 * (h - l), prec, doubles_held, arb_may_try);
        if (bounds) {
            certified_width = h - l;
            // Seven tenths of the radius for the chords and the overshoot, a
            // tenth at most for the points' own enclosures (double intervals:
            // ~1e-13), the rest for simplified_polyline.
            const double chords = 0.7 * options.radius - bounds->speed * overshoot;
            const double pieces = chords > 0 ? std::ceil((h - l) / std::sqrt(8 * chords / bounds->curvature)) : INFINITY;
            if (pieces <= kMaxPointsAPiece) {
                const int k = static_cast<int>(std::max(1.0, pieces));
                double gap = 0;
                for (int i = 0; i <= k && gap <= 0.1 * options.radius; ++i) {
                    const double theta = i == k ? h : l + (h - l) * i / k;
                    std::optional<std::array<Interval, 2>> v = points.point(Interval(theta));
                    Ball vx, vy;
                    if (!v) {  // Arb then
                        if (!real_ray_points(bisector, p, ball_of(Interval(theta), prec), prec, vx, vy)) {
                            gap = INFINITY;
                            break;
                        }
                        v = std::array<Interval, 2>{enclose(vx), enclose(vy)};
                    }
                    const std::array<double, 2> c{(*v)[0].mid(), (*v)[1].mid()};
                    gap = std::max(gap, hypot_up(std::max(c[0] - (*v)[0].lo, (*v)[0].hi - c[0]),
                                                 std::max(c[1] - (*v)[1].lo, (*v)[1].hi - c[1])));
                    box.points.push_back(c);
                }
                const double step = (h - l) / k * (1 + 1e-12);
                const double err = step * step / 8 * bounds->curvature + bounds->speed * overshoot + gap;
                ok = err <= options.radius;
                box.error = err;
                if (ok) {
                    arb_set(box.x.get(), bounds->x.get());
                    arb_set(box.y.get(), bounds->y.get());
                } else {
                    box.points.clear();
                }
            }
        }
        // First order, unless V(l) and V(h), both in V(J), are over twice the
        // radius apart (certified in double intervals): then no point is
        // within the radius of all of V(J).
        if (!ok && !apart(points, l, h, 2 * options.radius) &&
            real_ray_points(bisector, p, ball_of(Interval(l, h), prec), prec, box.x, box.y)) {
            const std::array<double, 2> c{box.x.mid_double(), box.y.mid_double()};
            box.error = hypot_up(gap_bound(box.x, c[0], prec), gap_bound(box.y, c[1], prec));
            ok = box.error <= options.radius;
            box.points = {c};
        }
        if (ok) {
            if (out.empty()) first_piece_end = h;
            last_piece_start = l;
            out.push_back(std::move(box));
            if (static_cast<long>(out.size()) > options.max_boxes)
                throw Error("voronoi_edge_cover: more than " + std::to_string(options.max_boxes) + " boxes");
            continue;
        }
        if (!(h - l > smallest) || !(l < m && m < h))
            throw Error("voronoi_edge_cover: the edge cannot be certified near angle " + std::to_string(l));
        stack.push_back({m, h});  // the left half is next: boxes come in increasing theta
        stack.push_back({l, m});
    }
    // The end pieces must hold the whole vertex balls (then the first and the
    // last box hold the true vertices); pieces that small mean a failure anyway.
    if (out.empty() || !(first_piece_end >= first_end) || !(last_piece_start <= last_start))
        throw Error("voronoi_edge_cover: an end piece is narrower than its vertex ball");
    return out;
}

std::vector<std::array<double, 2>> simplified_polyline(const std::vector<EdgeCoverBox>& boxes, double radius) {
    using Point = std::array<double, 2>;
    std::vector<Point> points;
    double error = 0, extent = 0;
    for (const EdgeCoverBox& box : boxes) {
        error = std::max(error, box.error);
        for (const Point& q : box.points) {
            if (points.empty() || q != points.back()) points.push_back(q);  // boxes share their ends
            extent = std::max({extent, std::fabs(q[0]), std::fabs(q[1])});
        }
    }
    // The distances below, in doubles, err by a few units of extent's last
    // place: 2^-40 extent covers them.
    const double tolerance = radius - error - std::ldexp(extent, -40);
    if (points.size() <= 2 || !(tolerance > 0)) return points;
    const auto distance_to_segment = [](const Point& q, const Point& a, const Point& b) {
        const double dx = b[0] - a[0], dy = b[1] - a[1], length2 = dx * dx + dy * dy;
        double t = length2 > 0 ? ((q[0] - a[0]) * dx + (q[1] - a[1]) * dy) / length2 : 0;
        t = std::min(1.0, std::max(0.0, t));
        return std::hypot(q[0] - (a[0] + t * dx), q[1] - (a[1] + t * dy));
    };
    std::vector<char> keep(points.size(), 0);
    keep.front() = keep.back() = 1;
    std::vector<std::pair<std::size_t, std::size_t>> stack{{0, points.size() - 1}};
    while (!stack.empty()) {
        const auto [from, to] = stack.back();
        stack.pop_back();
        double farthest = -1;
        std::size_t at = from;
        for (std::size_t i = from + 1; i < to; ++i) {
            const double d = distance_to_segment(points[i], points[from], points[to]);
            if (!(d <= farthest)) farthest = d, at = i;  // a NaN distance is kept
        }
        if (at == from || farthest <= tolerance) continue;
        keep[at] = 1;
        stack.push_back({from, at});
        stack.push_back({at, to});
    }
    std::vector<Point> out;
    for (std::size_t i = 0; i < points.size(); ++i)
        if (keep[i]) out.push_back(points[i]);
    return out;
}

double distance_bound(const EdgeCoverBox& box, const Rational& cx, const Rational& cy, long prec) {
    Ball dx, dy, c;
    arb_sub(dx.get(), box.x.get(), Ball(cx, prec).get(), prec);
    arb_sub(dy.get(), box.y.get(), Ball(cy, prec).get(), prec);
    arb_sqr(dx.get(), dx.get(), prec);
    arb_sqr(dy.get(), dy.get(), prec);
    arb_add(c.get(), dx.get(), dy.get(), prec);
    arb_sqrt(c.get(), c.get(), prec);
    Arf u;
    arb_get_ubound_arf(u.get(), c.get(), prec);
    return arf_get_d(u.get(), ARF_RND_UP);
}

}  // namespace ellvor
