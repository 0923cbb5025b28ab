#include "circles/circle_incircle_filter.hpp"

#include "circles/circle_semi_static.hpp"
#include "util/interval.hpp"

#include <algorithm>
#include <array>

namespace ellvor {

namespace {

int sign_of(const Interval& v) { return v.positive() ? 1 : v.negative() ? -1 : 0; }

struct Disk {
    Interval x, y, r;
};

Disk disk(const Ellipse& e) {
    const auto& k = e.enclosure();
    return {k.xc, k.yc, k.a};
}

}  // namespace

Decision<InCircle> circle_incircle_filter(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3, const Ellipse& q) {
    const Decision<InCircle> fast = circle_incircle_semi_static(e1, e2, e3, q);
    if (fast.is_decided()) return fast;
    return circle_incircle_interval_filter(e1, e2, e3, q);
}

Decision<InCircle> circle_incircle_interval_filter(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3,
                                                   const Ellipse& q) {
    const Decision<InCircle> undecided = Decision<InCircle>::undecided(Stage::filter, 0);
    auto decided = [](InCircle r) { return Decision<InCircle>::decided(r, Stage::filter); };
    if (!e1.is_circle() || !e2.is_circle() || !e3.is_circle() || !q.is_circle()) return undecided;
    const std::array<Disk, 3> c = {disk(e1), disk(e2), disk(e3)};
    const Disk dq = disk(q);
    // 2 (C_i - C_1) . V = |C_i|^2 - |C_1|^2 - r_i^2 + r_1^2 - 2 (r_i - r_1) rho, i = 2, 3.
    const Interval two(2.0);
    Interval a[2][2], b[2], g[2];
    for (int i = 1; i < 3; ++i) {
        a[i - 1][0] = two * (c[i].x - c[0].x);
        a[i - 1][1] = two * (c[i].y - c[0].y);
        b[i - 1] = c[i].x.square() + c[i].y.square() - c[0].x.square() - c[0].y.square() - c[i].r.square() +
                   c[0].r.square();
        g[i - 1] = Interval(-2.0) * (c[i].r - c[0].r);
    }
    const Interval det = a[0][0] * a[1][1] - a[0][1] * a[1][0];
    if (det.contains_zero() || !det.finite()) return undecided;
    // V = V0 + rho V1
    const Interval v0x = (a[1][1] * b[0] - a[0][1] * b[1]) / det, v0y = (a[0][0] * b[1] - a[1][0] * b[0]) / det;
    const Interval v1x = (a[1][1] * g[0] - a[0][1] * g[1]) / det, v1y = (a[0][0] * g[1] - a[1][0] * g[0]) / det;
    // |V0 + rho V1 - C_1|^2 = (rho + r_1)^2
    const Interval dx = v0x - c[0].x, dy = v0y - c[0].y;
    const Interval qa = v1x.square() + v1y.square() - Interval(1.0);
    const Interval qb = two * (dx * v1x + dy * v1y - c[0].r);
    const Interval qc = dx.square() + dy.square() - c[0].r.square();
    if (qa.contains_zero()) return undecided;
    const Interval disc = qb.square() - Interval(4.0) * qa * qc;
    if (disc.negative()) return decided(InCircle::no_circle);
    if (disc.contains_zero()) return undecided;
    const Interval root = disc.sqrt();
    int counterclockwise = 0;
    Interval best_rho, best_x, best_y;
    for (const Interval& rho : {(-qb + root) / (two * qa), (-qb - root) / (two * qa)}) {
        // A circle of signed distances: rho + r_i > 0 for every site (rho < 0
        // is an internal circle of overlapping sites).
        int s = 1;
        for (const Disk& site : c) s = std::min(s, sign_of(rho + site.r));
        if (s < 0) continue;
        if (s == 0) return undecided;
        const Interval vx = v0x + rho * v1x, vy = v0y + rho * v1y;
        // Tangency points P_i = C_i + r_i (V - C_i)/|V - C_i| = C_i + r_i (V - C_i)/(rho + r_i).
        Interval px[3], py[3];
        for (int i = 0; i < 3; ++i) {
            const Interval f = c[i].r / (rho + c[i].r);
            px[i] = c[i].x + f * (vx - c[i].x);
            py[i] = c[i].y + f * (vy - c[i].y);
        }
        const int o = sign_of((px[1] - px[0]) * (py[2] - py[0]) - (py[1] - py[0]) * (px[2] - px[0]));
        if (o == 0) return undecided;
        if (o > 0) ++counterclockwise, best_rho = rho, best_x = vx, best_y = vy;
    }
    if (counterclockwise == 0) return decided(InCircle::no_circle);
    if (counterclockwise > 1) return undecided;  // at most one exists: the intervals are too wide
    // Q's signed distance at V against rho (never squared: it may be negative).
    const Interval gap = ((best_x - dq.x).square() + (best_y - dq.y).square()).sqrt() - best_rho - dq.r;
    const int s = sign_of(gap);
    if (s == 0 || !gap.finite()) return undecided;
    return decided(s < 0 ? InCircle::conflict : InCircle::no_conflict);
}

}  // namespace ellvor
