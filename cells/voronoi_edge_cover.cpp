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

// V(J) = P(J) + S n~(J) over the real theta-interval J, S enclosing s(J).
void ray_points(const SiteBalls& p, const Ball& theta, const Ball& s, long prec, Ball& x, Ball& y) {
    Ball c, sn, lx, ly, t;
    arb_sin_cos(sn.get(), c.get(), theta.get(), prec);
    // the frame coordinates of P + s n~: (a c + s b c, b sn + s a sn) = (c (a + s b), sn (b + s a))
    arb_mul(t.get(), s.get(), p.b.get(), prec);
    arb_add(t.get(), t.get(), p.a.get(), prec);
    arb_mul(lx.get(), c.get(), t.get(), prec);
    arb_mul(t.get(), s.get(), p.a.get(), prec);
    arb_add(t.get(), t.get(), p.b.get(), prec);
    arb_mul(ly.get(), sn.get(), t.get(), prec);
    // rotate and translate
    arb_mul(x.get(), lx.get(), p.cos.get(), prec);
    arb_submul(x.get(), ly.get(), p.sin.get(), prec);
    arb_add(x.get(), x.get(), p.xc.get(), prec);
    arb_mul(y.get(), lx.get(), p.sin.get(), prec);
    arb_addmul(y.get(), ly.get(), p.cos.get(), prec);
    arb_add(y.get(), y.get(), p.yc.get(), prec);
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
    std::vector<std::pair<double, double>> stack{{lo, hi}};
    while (!stack.empty()) {
        const auto [l, h] = stack.back();
        stack.pop_back();
        Arf al, ah;
        arf_set_d(al.get(), l);
        arf_set_d(ah.get(), h);
        Ball theta;
        arb_set_interval_arf(theta.get(), al.get(), ah.get(), prec);
        ComplexBall s;
        EdgeCoverBox box;
        bool ok = bisector.solve(ComplexBall(theta), prec, s);
        if (ok) {
            // s is real for real theta (cells/normal_ray_bisector.hpp): its real part holds it.
            Ball sr;
            arb_set(sr.get(), s.real());
            ray_points(p, theta, sr, prec, box.x, box.y);
            box.center = {box.x.mid_double(), box.y.mid_double()};
            box.radius = hypot_up(gap_bound(box.x, box.center[0], prec), gap_bound(box.y, box.center[1], prec));
            ok = box.radius <= options.radius;
        }
        if (ok) {
            if (out.empty()) first_piece_end = h;
            last_piece_start = l;
            out.push_back(std::move(box));
            if (static_cast<long>(out.size()) > options.max_boxes)
                throw Error("voronoi_edge_cover: more than " + std::to_string(options.max_boxes) + " boxes");
            continue;
        }
        const double m = 0.5 * (l + h);
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
