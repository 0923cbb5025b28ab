#include "sites/separating_slab.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace ellvor {

SlabSite SlabSite::of(const Interval& a, const Interval& b, const Interval& cos, const Interval& sin,
                      const Interval& xc, const Interval& yc) {
    return {a, b, cos, sin, xc, yc, a.mid(), b.mid(), cos.mid(), sin.mid(), xc.mid(), yc.mid()};
}

SlabSite SlabSite::of(const Ellipse& e) {
    const Ellipse::Enclosure& q = e.enclosure();
    return of(q.a, q.b, q.cos, q.sin, q.xc, q.yc);
}

Interval support_enclosure(const SlabSite& f, double nx, double ny) {
    const Interval nu = nx * f.cos + ny * f.sin, nv = ny * f.cos - nx * f.sin;
    return ((f.a * nu).square() + (f.b * nv).square()).sqrt();
}

namespace {

// Support function of the centered ellipse in the direction (nx, ny), doubles.
double support(const SlabSite& f, double nx, double ny) {
    const double nu = nx * f.cd + ny * f.sd, nv = ny * f.cd - nx * f.sd;
    return std::sqrt(f.ad * f.ad * nu * nu + f.bd * f.bd * nv * nv);
}
// The direction rotated from d = (dx, dy) by the angle 2 atan(t), unnormalized.
std::pair<double, double> direction(double dx, double dy, double t) {
    const double c = 1 - t * t, s = 2 * t;
    return {c * dx - s * dy, s * dx + c * dy};
}

// The largest scale of p (about its center) that keeps a slab of width >= gap
// normal to n between p and q, in doubles (the search) ...
double slab_scale(const SlabSite& p, const SlabSite& q, double gap, double nx, double ny) {
    const double dx = q.xd - p.xd, dy = q.yd - p.yd;
    return (nx * dx + ny * dy - support(q, nx, ny) - gap * std::sqrt(nx * nx + ny * ny)) / support(p, nx, ny);
}
// ... and a certified lower bound of it (0 when none is proven).
double slab_scale_lower(const SlabSite& p, const SlabSite& q, double gap_upper, double nx, double ny) {
    const Interval along = nx * (q.xc - p.xc) + ny * (q.yc - p.yc);
    const Interval norm = (Interval(nx).square() + Interval(ny).square()).sqrt();
    const Interval room = along - support_enclosure(q, nx, ny) - gap_upper * norm;
    const Interval hp = support_enclosure(p, nx, ny);
    if (!room.positive() || !hp.positive()) return 0;
    return (room / hp).lo;
}

// The direction (as the parameter t of `direction` from the line of the
// centers) that maximizes `value`: every separating direction of two
// disjoint convex sets lies within a right angle of the line of the centers,
// and those with a slab scale (or width) >= s form an arc (quasi-concave), so
// a coarse scan and a golden-section search find it (the result is only a
// candidate, certified by the caller).
// `good_enough(t, v)` may end the search early at a candidate t of value v
// (the caller certifies it; the packing generator maximizes, so it never does).
template <class Value, class Stop>
double best_direction(Value value, Stop good_enough) {
    constexpr int kScan = 16;
    int best = kScan / 2;
    double best_value = value(0);
    for (int i = 0; i <= kScan; ++i) {
        const double v = value(-1 + 2.0 * i / kScan);
        if (v > best_value) best_value = v, best = i;
    }
    double lo = -1 + 2.0 * std::max(best - 1, 0) / kScan, hi = -1 + 2.0 * std::min(best + 1, kScan) / kScan;
    const double r = 0.6180339887498949;
    double t1 = hi - r * (hi - lo), t2 = lo + r * (hi - lo);
    double v1 = value(t1), v2 = value(t2);
    for (int it = 0; it < 48; ++it) {
        if (v1 < v2 ? good_enough(t2, v2) : good_enough(t1, v1)) break;
        if (v1 < v2) {
            lo = t1, t1 = t2, v1 = v2, t2 = lo + r * (hi - lo), v2 = value(t2);
        } else {
            hi = t2, t2 = t1, v2 = v1, t1 = hi - r * (hi - lo), v1 = value(t1);
        }
    }
    return v1 < v2 ? t2 : t1;
}

}  // namespace

// A certified lower bound of the largest scale of p keeping it gap away from
// q (0 when none is proven); `enough`: stop as soon as this much is proven.
double certified_separating_scale(const SlabSite& p, const SlabSite& q, double gap, double gap_upper, double enough) {
    const double dx = q.xd - p.xd, dy = q.yd - p.yd;
    const double along_centers = slab_scale_lower(p, q, gap_upper, dx, dy);
    if (along_centers >= enough) return along_centers;
    const auto n = direction(dx, dy, best_direction(
                                         [&](double t) {
                                             const auto m = direction(dx, dy, t);
                                             return slab_scale(p, q, gap, m.first, m.second);
                                         },
                                         [](double, double) { return false; }));
    return std::max(along_centers, slab_scale_lower(p, q, gap_upper, n.first, n.second));
}

double certified_separation(const SlabSite& p, const SlabSite& q, double enough) {
    // The width (n.(c2 - c1) - h_p(n) - h_q(n)) / |n|, along the line of the
    // centers, then along the widest direction found.
    const double dx = q.xd - p.xd, dy = q.yd - p.yd;
    auto width = [&](double nx, double ny) {
        const Interval along = nx * (q.xc - p.xc) + ny * (q.yc - p.yc);
        const Interval norm = (Interval(nx).square() + Interval(ny).square()).sqrt();
        const Interval w = (along - support_enclosure(q, nx, ny) - support_enclosure(p, nx, ny)) / norm;
        return w.finite() ? w.lo : -1.0;
    };
    const double along_centers = width(dx, dy);
    if (along_centers >= enough) return along_centers;
    // The search stops at the first direction whose slab, widened by the
    // rounding its certificate may lose, is proven at least `enough` wide
    // (separating two sites needs any positive width, not the widest).
    double proven = along_centers;
    const double margin = 0x1p-40 * (std::fabs(dx) + std::fabs(dy) + p.ad + p.bd + q.ad + q.bd);
    const auto n = direction(dx, dy, best_direction(
                                         [&](double t) {
                                             const auto m = direction(dx, dy, t);
                                             return (m.first * dx + m.second * dy - support(p, m.first, m.second) -
                                                     support(q, m.first, m.second)) /
                                                    std::sqrt(m.first * m.first + m.second * m.second);
                                         },
                                         [&](double t, double v) {
                                             if (!(v > enough + margin)) return false;
                                             const auto m = direction(dx, dy, t);
                                             proven = std::max(proven, width(m.first, m.second));
                                             return proven >= enough;
                                         }));
    return std::max(proven, width(n.first, n.second));
}

}  // namespace ellvor
