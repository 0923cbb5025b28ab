#include "cells/voronoi_edge_cover.hpp"

#include "util/error.hpp"

#include <cmath>
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

Ball real_ball(double l, double h, long prec) {
    Arf al, ah;
    arf_set_d(al.get(), l);
    arf_set_d(ah.get(), h);
    Ball theta;
    arb_set_interval_arf(theta.get(), al.get(), ah.get(), prec);
    return theta;
}

double magnitude_up(const acb_t z) {
    Mag m;
    acb_get_mag(m.get(), z);
    return mag_get_d(m.get());
}

}  // namespace

std::vector<EdgeCoverBox> voronoi_edge_cover(NormalRayBisector& bisector, const Ball& from, const Ball& to,
                                             const EdgeCoverOptions& options) {
    const long prec = options.prec;
    const SiteBalls p(bisector.first(), prec);
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
    double reach = 0.25;  // the complex half-side the second order tries first; halves when it fails
    Ball end_x, end_y;    // V at end_angle, the last second-order piece's end
    double end_angle = 0;
    bool have_end = false;
    std::vector<std::pair<double, double>> stack{{lo, hi}};
    while (!stack.empty()) {
        const auto [l, h] = stack.back();
        stack.pop_back();
        EdgeCoverBox box;
        bool ok = false;
        const double half = 0.5 * (h - l), m = 0.5 * (l + h);
        // Second order.
        for (double R = std::max(reach, 4 * half); !ok && R >= 4 * half; R *= 0.5) {
            ComplexBall z, s, vx, vy;
            arf_set_d(arb_midref(z.real()), m);
            mag_set_d(arb_radref(z.real()), R);
            mag_set_d(arb_radref(z.imag()), R);
            if (!bisector.solve(z, prec, s)) {
                reach = R * 0.5;
                continue;
            }
            ray_points(p, z, s, prec, vx, vy);
            // Cauchy's estimates hold for V - c, any constant c: the middle of the enclosure.
            arb_set(box.x.get(), vx.real());
            arb_set(box.y.get(), vy.real());
            ComplexBall cx, cy;
            arb_get_mid_arb(cx.real(), vx.real());
            arb_get_mid_arb(cy.real(), vy.real());
            acb_sub(vx.get(), vx.get(), cx.get(), prec);
            acb_sub(vy.get(), vy.get(), cy.get(), prec);
            const double M = hypot_up(magnitude_up(vx.get()), magnitude_up(vy.get()));
            const double rho = R - half;
            const double err = half * half * M / (rho * rho) * (1 + 1e-12) + M / rho * overshoot;
            if (!(err <= options.radius)) break;  // too long: bisect
            // The ends: V at l is the previous piece's end when they meet.
            if (!(have_end && end_angle == l)) {
                have_end = real_ray_points(bisector, p, real_ball(l, l, prec), prec, end_x, end_y);
                end_angle = l;
                if (!have_end) break;
            }
            Ball hx, hy;
            if (!real_ray_points(bisector, p, real_ball(h, h, prec), prec, hx, hy)) break;
            const std::array<double, 2> a{end_x.mid_double(), end_y.mid_double()}, b{hx.mid_double(), hy.mid_double()};
            const double ends = std::max(hypot_up(gap_bound(end_x, a[0], prec), gap_bound(end_y, a[1], prec)),
                                         hypot_up(gap_bound(hx, b[0], prec), gap_bound(hy, b[1], prec)));
            if (!(err + ends <= options.radius)) break;
            end_x = hx;
            end_y = hy;
            end_angle = h;
            have_end = true;
            box.points = {a, b};
            ok = true;
        }
        // First order.
        if (!ok && real_ray_points(bisector, p, real_ball(l, h, prec), prec, box.x, box.y)) {
            const std::array<double, 2> c{box.x.mid_double(), box.y.mid_double()};
            ok = hypot_up(gap_bound(box.x, c[0], prec), gap_bound(box.y, c[1], prec)) <= options.radius;
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
