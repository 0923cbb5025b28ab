#include "subdivision/voronoi_circle_by_bounding_disks.hpp"

#include "util/upward_ball.hpp"

#include <algorithm>
#include <cmath>

namespace ellvor {

// The orientation x1 x x2 + x2 x x3 + x3 x x1 at x_i = c_i + u_i, |u_i| <=
// R_i, is its value at the centers plus u1 x (c2 - c3) + u2 x (c3 - c1) + u3 x
// (c1 - c2) + u1 x u2 + u2 x u3 + u3 x u1: within R1 |c2 - c3| + R2 |c3 - c1| +
// R3 |c1 - c2| + R1 R2 + R2 R3 + R3 R1 of it (a bound symmetric in the three).
// In doubles, about the centers' midpoints (their enclosures' widths added
// to the radii): the orientation's rounding is Shewchuk's orient2d bound,
// and the bound's, a sum of positive products and square roots, is below
// 1e-14 of it.
int bounding_disks_orientation(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3) {
    const Ellipse* sites[3] = {&e1, &e2, &e3};
    double x[3], y[3], R[3];
    for (int i = 0; i < 3; ++i) {
        const Ellipse::Enclosure k = sites[i]->enclosure();  // the fields read here only
        x[i] = k.xc.mid(), y[i] = k.yc.mid();
        R[i] = std::max(k.a.hi, k.b.hi) + (k.xc.hi - k.xc.lo) + (k.yc.hi - k.yc.lo);
    }
    const double left = (x[1] - x[0]) * (y[2] - y[0]), right = (y[1] - y[0]) * (x[2] - x[0]);
    const double orientation = std::fabs(left - right) - 3.3306690738754716e-16 * (std::fabs(left) + std::fabs(right));
    double spread = R[0] * R[1] + R[1] * R[2] + R[2] * R[0];
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3, l = (i + 2) % 3;
        spread += R[i] * std::sqrt((x[j] - x[l]) * (x[j] - x[l]) + (y[j] - y[l]) * (y[j] - y[l]));
    }
    if (!(orientation > spread * (1 + 1e-14))) return 0;  // also for NaN or infinity
    return left > right ? 1 : -1;
}

namespace {

// The enclosure itself, in midpoint-radius balls under the upward rounding
// mode (util/upward_ball.hpp: straight-line operations, where intervals
// branch on signs; written first in util/interval.hpp's intervals, the
// function took 149 M instructions of a 10^4-site build, in balls 85 M).
ELLVOR_UPWARD_ROUNDING_FUNCTION std::optional<CircleBounds> apollonius_bounds(const Ellipse& e1, const Ellipse& e2,
                                                                              const Ellipse& e3) {
    const UpwardRoundingScope upward;
    using B = UpwardBall;
    const Ellipse::Enclosure k[3] = {e1.enclosure(), e2.enclosure(), e3.enclosure()};
    const auto ball = [](const Interval& x) { return B::around(UpwardInterval(x)); };
    // The weights w_i in [min(a, b), max(a, b)]; coordinates about c_1.
    B w[3];
    for (int i = 0; i < 3; ++i)
        w[i] = B::around(UpwardInterval(Interval::min(k[i].a.lo, k[i].b.lo), Interval::max(k[i].a.hi, k[i].b.hi)));
    // |V - c_i|^2 - |V - c_1|^2 = (rho + w_i)^2 - (rho + w_1)^2 with d_i =
    // c_i - c_1 and V about c_1: 2 d_i . V = |d_i|^2 - w_i^2 + w_1^2 -
    // 2 (w_i - w_1) rho, i = 2, 3.
    const B x1 = ball(k[0].xc), y1 = ball(k[0].yc);
    B m[2][2], b[2], g[2];
    for (int i = 1; i < 3; ++i) {
        const B dx = ball(k[i].xc) - x1, dy = ball(k[i].yc) - y1;
        m[i - 1][0] = dx.twice(), m[i - 1][1] = dy.twice();
        b[i - 1] = dx.square() + dy.square() - w[i].square() + w[0].square();
        g[i - 1] = -(w[i] - w[0]).twice();
    }
    // 1/det is NaN when the ball reaches zero: every test below fails then.
    const B inverse = (m[0][0] * m[1][1] - m[0][1] * m[1][0]).reciprocal();
    // V = V0 + rho V1, and |V|^2 = (rho + w_1)^2.
    const B v0x = (m[1][1] * b[0] - m[0][1] * b[1]) * inverse, v0y = (m[0][0] * b[1] - m[1][0] * b[0]) * inverse;
    const B v1x = (m[1][1] * g[0] - m[0][1] * g[1]) * inverse, v1y = (m[0][0] * g[1] - m[1][0] * g[0]) * inverse;
    const B qa = v1x.square() + v1y.square() - B(1.0);
    const B qb = (v0x * v1x + v0y * v1y - w[0]).twice();
    const B qc = v0x.square() + v0y.square() - w[0].square();
    const B root = (qb.square() - 4.0 * (qa * qc)).sqrt();  // NaN unless the discriminant is positive
    const B half_over_qa = qa.twice().reciprocal();        // NaN when qa reaches zero
    // The circle's root: the one whose rho + w_i may be >= 0 at every site
    // (the other has some rho + w_i < 0: a root of the squared system alone).
    int kept = 0;
    B rho;
    for (const B& r : {(root - qb) * half_over_qa, -(root + qb) * half_over_qa}) {
        if (!r.finite()) return std::nullopt;
        bool excluded = false;
        for (const B& weight : w) excluded = excluded || (r + weight).upper() < 0;
        if (!excluded) ++kept, rho = r;
    }
    if (kept != 1) return std::nullopt;
    const B vx = x1 + (v0x + rho * v1x), vy = y1 + (v0y + rho * v1y);
    if (!vx.finite() || !vy.finite()) return std::nullopt;
    return CircleBounds{Interval(vx.lower(), vx.upper()), Interval(vy.lower(), vy.upper()),
                        Interval(rho.lower(), rho.upper())};
}

}  // namespace

std::optional<CircleBounds> voronoi_circle_by_bounding_disks(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3) {
    // In round-to-nearest (its rounding bound says so), before the scope.
    if (bounding_disks_orientation(e1, e2, e3) <= 0) return std::nullopt;
    return apollonius_bounds(e1, e2, e3);
}

}  // namespace ellvor
