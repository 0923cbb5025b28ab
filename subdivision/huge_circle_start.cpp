#include "subdivision/huge_circle_start.hpp"
#include "subdivision/shape_in_doubles.hpp"
#include "subdivision/near_duplicate_pair.hpp"
#include "util/precision.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <optional>
#include <vector>

namespace ellvor {

namespace {

// Precision of the first pass, and the largest one tried (util/precision.hpp).
constexpr long kFirstPrecision = precision::kHugeCircleFirst;
constexpr long kLastPrecision = precision::kHugeCircleLast;
// Bits of g needed before the first-order circle is trusted, and the
// precision a start needs per bit of R / size (the tritangent system's
// condition grows like (R / size)^2) plus a margin.
constexpr long kGapBits = 24;
constexpr long kMarginBits = 64;

// ---------------------------------------------------------------- doubles

// Support value h(n) = n.C + |(a n.u, b n.v)| in the unit direction n and
// its derivative along the unit circle, h'(phi) = S(n) . n'(phi) with S the
// support point, each split into the center's part and the shape's part: two
// sites nearly equal in shape cancel in the shape's parts, so the two parts
// of a difference must be subtracted apart (a copy moved by 10^-20: its
// translation is exact in the center's part and lost if added to the
// shape's first). (sx, sy) = S - C.
struct SupportValue {
    double center, shape, center_slope, shape_slope, sx, sy;
    double value() const { return center + shape; }
};
SupportValue support_value(const ShapeInDoubles& k, double nx, double ny) {
    const double m1 = k.c * nx + k.s * ny, m2 = k.c * ny - k.s * nx;
    const double norm = std::hypot(k.a * m1, k.b * m2);
    const double lx = k.a * k.a * m1 / norm, ly = k.b * k.b * m2 / norm;
    const double sx = k.c * lx - k.s * ly, sy = k.s * lx + k.c * ly;
    return {nx * k.x + ny * k.y, norm, -k.x * ny + k.y * nx, -sx * ny + sy * nx, sx, sy};
}

// h(n) and the support point S itself.
double support_point(const ShapeInDoubles& k, double nx, double ny, double& sx, double& sy) {
    const SupportValue h = support_value(k, nx, ny);
    sx = k.x + h.sx, sy = k.y + h.sy;
    return h.value();
}

// h_i - h_j at the direction phi, and its derivative in phi.
using SupportDifference = std::function<double(double phi, double* slope)>;

SupportDifference support_difference_in_doubles(const ShapeInDoubles& p, const ShapeInDoubles& q) {
    return [p, q](double phi, double* slope) {
        const double nx = std::cos(phi), ny = std::sin(phi);
        const SupportValue hp = support_value(p, nx, ny), hq = support_value(q, nx, ny);
        *slope = (hp.shape_slope - hq.shape_slope) + (hp.center_slope - hq.center_slope);
        return (hp.shape - hq.shape) + (hp.center - hq.center);
    };
}

// Directions phi of the external bitangents of two shapes (roots of
// h_i - h_j = f), in doubles: sampling, then Newton safeguarded by bisection.
std::vector<double> bitangent_directions(const ShapeInDoubles& p, const ShapeInDoubles& q, const SupportDifference& f) {
    // Samples half a step off the axes, all around the circle (the last
    // interval wraps past pi: bitangents along the axes of a triple lie there),
    // and at the four axis directions of both shapes: a needle's support value
    // has a valley there only ~(minor / major) radians wide, which may hold a
    // pair of roots between two uniform samples.
    constexpr int kSamples = 64;
    const double step = 2 * M_PI / kSamples, first = -M_PI + step / 2;
    std::vector<double> samples;
    for (int i = 0; i <= kSamples; ++i) samples.push_back(first + i * step);
    for (const ShapeInDoubles* k : {&p, &q})
        for (int quarter = 0; quarter < 4; ++quarter) {
            double axis = std::atan2(k->s, k->c) + quarter * M_PI / 2;
            while (axis < first) axis += 2 * M_PI;
            while (axis >= first + 2 * M_PI) axis -= 2 * M_PI;
            samples.push_back(axis);
        }
    std::sort(samples.begin(), samples.end());
    std::vector<double> roots;
    double slope, lo = samples.front(), f_lo = f(lo, &slope);
    for (std::size_t i = 1; i < samples.size(); ++i) {
        const double hi = samples[i];
        double f_hi = f(hi, &slope);
        if ((f_lo < 0) != (f_hi < 0)) {
            double a = lo, b = hi, fa = f_lo, x = 0.5 * (lo + hi);
            for (int it = 0; it < 60; ++it) {
                const double fx = f(x, &slope);
                if ((fx < 0) == (fa < 0)) a = x, fa = fx;
                else b = x;
                double next = x - fx / slope;
                if (!(next > a && next < b) && !(next > b && next < a)) next = 0.5 * (a + b);
                if (std::fabs(next - x) < 1e-16) break;
                x = next;
            }
            roots.push_back(x);
        }
        lo = hi, f_lo = f_hi;
    }
    return roots;
}

// The first-order circle of the bitangent direction (nx, ny) of shapes i, j
// with the third shape k, as first_order_circle below does in balls (the
// formulas are in the header); false when there is none of positive radius.
// The start's tangency points, as start_of below.
bool double_circle_start(const std::array<ShapeInDoubles, 3>& k, int i, int j, int m, double nx, double ny,
                         DoubleCircleStart& start) {
    double six, siy, sjx, sjy, skx, sky;
    const double h = support_point(k[i], nx, ny, six, siy);
    support_point(k[j], nx, ny, sjx, sjy);
    const auto along_line = [&](double x, double y) { return y * nx - x * ny; };
    const double c = 0.5 * (along_line(six, siy) + along_line(sjx, sjy));
    const double half_spacing = along_line(six, siy) - c;
    double ux = nx, uy = ny, radius = 0, vx = 0, vy = 0;
    for (int round = 0; round < 3; ++round) {
        support_point(k[m], ux, uy, skx, sky);
        const double w_line = along_line(skx, sky) - c, w_normal = skx * nx + sky * ny - h;
        radius = (w_line * w_line - half_spacing * half_spacing + w_normal * w_normal) / (2 * w_normal);
        if (!(radius > 0) || !std::isfinite(radius)) return false;
        const double height = h + radius - half_spacing * half_spacing / (2 * radius);
        vx = height * nx - c * ny, vy = height * ny + c * nx;
        const double dx = vx - skx, dy = vy - sky, length = std::hypot(dx, dy);
        ux = dx / length, uy = dy / length;
    }
    for (int site = 0; site < 3; ++site) {
        double tx = k[site].x, ty = k[site].y, px = 0, py = 0;
        for (int round = 0; round < 2; ++round) {
            const double dx = vx - tx, dy = vy - ty, length = std::hypot(dx, dy);
            px = dx / length, py = dy / length;
            support_point(k[site], px, py, tx, ty);
        }
        // (cos theta, sin theta) ~ (a m1, b m2); t = tan(theta / 2), or u = -1/t
        const ShapeInDoubles& e = k[site];
        const double p = e.a * (e.c * px + e.s * py), q = e.b * (e.c * py - e.s * px), norm = std::hypot(p, q);
        start.flipped[site] = p < 0;
        start.x[site] = p < 0 ? -q / (norm - p) : q / (norm + p);
    }
    start.x[3] = radius, start.x[4] = vx, start.x[5] = vy;
    return std::all_of(start.x.begin(), start.x.end(), [](double v) { return std::isfinite(v); });
}

// ---------------------------------------------------------------- balls

struct BallVector {
    Ball x, y;
};

class ArbSite {
public:
    ArbSite(const Ellipse& e, long prec)
        : a_(e.a(), prec), b_(e.b(), prec), c_(e.cos_rotation(), prec), s_(e.sin_rotation(), prec),
          x_(e.xc(), prec), y_(e.yc(), prec) {}

    // Support value in the unit direction n and the support point.
    Ball support(const BallVector& n, BallVector* point, long prec) const {
        Ball m1, m2, t, norm, lx, ly;
        local(n, m1, m2, prec);
        arb_mul(t.get(), a_.get(), m1.get(), prec);
        arb_mul(norm.get(), b_.get(), m2.get(), prec);
        arb_hypot(norm.get(), t.get(), norm.get(), prec);
        arb_mul(lx.get(), a_.get(), t.get(), prec);  // a^2 m1 / norm
        arb_div(lx.get(), lx.get(), norm.get(), prec);
        arb_mul(ly.get(), b_.get(), b_.get(), prec);
        arb_mul(ly.get(), ly.get(), m2.get(), prec);
        arb_div(ly.get(), ly.get(), norm.get(), prec);
        to_global(lx, ly, *point, prec);
        Ball h;
        arb_mul(h.get(), n.x.get(), x_.get(), prec);
        arb_addmul(h.get(), n.y.get(), y_.get(), prec);
        arb_add(h.get(), h.get(), norm.get(), prec);
        return h;
    }

    // The chart and chart parameter of the boundary point whose outward
    // normal is n: (cos theta, sin theta) ~ (a m1, b m2), t = tan(theta / 2).
    bool chart_parameter(const BallVector& n, Ball& parameter, long prec) const {
        Ball m1, m2, p, q, norm, denominator;
        local(n, m1, m2, prec);
        arb_mul(p.get(), a_.get(), m1.get(), prec);
        arb_mul(q.get(), b_.get(), m2.get(), prec);
        arb_hypot(norm.get(), p.get(), q.get(), prec);
        const bool flipped = arf_sgn(arb_midref(p.get())) < 0;
        if (flipped) {  // u = -1/t = -q / (|(p, q)| - p)
            arb_sub(denominator.get(), norm.get(), p.get(), prec);
            arb_div(parameter.get(), q.get(), denominator.get(), prec);
            arb_neg(parameter.get(), parameter.get());
        } else {  // t = q / (|(p, q)| + p)
            arb_add(denominator.get(), norm.get(), p.get(), prec);
            arb_div(parameter.get(), q.get(), denominator.get(), prec);
        }
        return flipped;
    }

    BallVector center() const { return {x_, y_}; }

private:
    void local(const BallVector& n, Ball& m1, Ball& m2, long prec) const {
        arb_mul(m1.get(), c_.get(), n.x.get(), prec);
        arb_addmul(m1.get(), s_.get(), n.y.get(), prec);
        arb_mul(m2.get(), c_.get(), n.y.get(), prec);
        arb_submul(m2.get(), s_.get(), n.x.get(), prec);
    }
    void to_global(const Ball& lx, const Ball& ly, BallVector& out, long prec) const {
        arb_mul(out.x.get(), c_.get(), lx.get(), prec);
        arb_submul(out.x.get(), s_.get(), ly.get(), prec);
        arb_add(out.x.get(), out.x.get(), x_.get(), prec);
        arb_mul(out.y.get(), s_.get(), lx.get(), prec);
        arb_addmul(out.y.get(), c_.get(), ly.get(), prec);
        arb_add(out.y.get(), out.y.get(), y_.get(), prec);
    }

    Ball a_, b_, c_, s_, x_, y_;
};

BallVector direction(const Ball& phi, long prec) {
    BallVector n;
    arb_sin_cos(n.y.get(), n.x.get(), phi.get(), prec);
    return n;
}

// h_i - h_j in balls at precision prec, rounded to doubles: for a nearly
// coincident pair, whose difference in shape (a copy turned by 10^-30)
// vanishes in doubles.
SupportDifference support_difference_in_balls(const ArbSite& p, const ArbSite& q, long prec) {
    return [&p, &q, prec](double phi0, double* slope) {
        Ball phi, f, s, dx, dy;
        arb_set_d(phi.get(), phi0);
        const BallVector n = direction(phi, prec);
        BallVector sp, sq;
        arb_sub(f.get(), p.support(n, &sp, prec).get(), q.support(n, &sq, prec).get(), prec);
        // slope = (S_p - S_q) . (-sin, cos)
        arb_sub(dx.get(), sp.x.get(), sq.x.get(), prec);
        arb_sub(dy.get(), sp.y.get(), sq.y.get(), prec);
        arb_mul(s.get(), dy.get(), n.x.get(), prec);
        arb_submul(s.get(), dx.get(), n.y.get(), prec);
        *slope = s.mid_double();
        return f.mid_double();
    };
}

// Newton on h_i(phi) - h_j(phi) = 0 in midpoint arithmetic, from a
// double-precision root: quadratic convergence, a few steps.
Ball refine_direction(const ArbSite& p, const ArbSite& q, double phi0, long prec) {
    Ball phi;
    arb_set_d(phi.get(), phi0);
    for (long bits = 50; bits < 2 * prec; bits *= 2) {
        const BallVector n = direction(phi, prec);
        BallVector sp, sq;
        Ball f, slope, tangent_x;
        arb_sub(f.get(), p.support(n, &sp, prec).get(), q.support(n, &sq, prec).get(), prec);
        // slope = (S_p - S_q) . (-sin, cos)
        Ball dx, dy;
        arb_sub(dx.get(), sp.x.get(), sq.x.get(), prec);
        arb_sub(dy.get(), sp.y.get(), sq.y.get(), prec);
        arb_mul(slope.get(), dy.get(), n.x.get(), prec);
        arb_submul(slope.get(), dx.get(), n.y.get(), prec);
        arb_div(f.get(), f.get(), slope.get(), prec);
        arb_sub(phi.get(), phi.get(), f.get(), prec);
        arb_get_mid_arb(phi.get(), phi.get());
    }
    return phi;
}

// Bits of |x| above 2^0 (x a ball away from 0), roughly.
long magnitude(const Ball& x) { return arf_abs_bound_lt_2exp_si(arb_midref(x.get())); }

struct FirstOrderCircle {
    BallVector center;
    Ball radius;
    long ratio_bits;  // log2(R / size), roughly
};

// The unit vector from `from` toward `to`.
BallVector unit_direction(const BallVector& from, const BallVector& to, long prec) {
    BallVector u;
    Ball length;
    arb_sub(u.x.get(), to.x.get(), from.x.get(), prec);
    arb_sub(u.y.get(), to.y.get(), from.y.get(), prec);
    arb_hypot(length.get(), u.x.get(), u.y.get(), prec);
    arb_div(u.x.get(), u.x.get(), length.get(), prec);
    arb_div(u.y.get(), u.y.get(), length.get(), prec);
    return u;
}

// Dot product of a point with (n_x, n_y) or with d = n turned by +90 degrees.
Ball along_normal(const BallVector& p, const BallVector& n, long prec) {
    Ball v;
    arb_mul(v.get(), p.x.get(), n.x.get(), prec);
    arb_addmul(v.get(), p.y.get(), n.y.get(), prec);
    return v;
}
Ball along_line(const BallVector& p, const BallVector& n, long prec) {
    Ball v;
    arb_mul(v.get(), p.y.get(), n.x.get(), prec);
    arb_submul(v.get(), p.x.get(), n.y.get(), prec);
    return v;
}

// The circle of the bitangent direction phi of sites (i, j), with the third
// site k, at precision prec; false when the gap g = h_k(n) - h_i(n) does not
// have kGapBits correct bits at this precision, or there is no circle of
// positive radius on the line's far side.
bool first_order_circle(const std::array<ArbSite, 3>& s, int i, int j, int k, const Ball& phi, long size_bits,
                        long prec, FirstOrderCircle& out, bool& resolved) {
    const BallVector n = direction(phi, prec);
    BallVector support_i, support_j, support_k;
    const Ball h = s[i].support(n, &support_i, prec);
    s[j].support(n, &support_j, prec);
    Ball c, half_spacing_squared;
    arb_add(c.get(), along_line(support_i, n, prec).get(), along_line(support_j, n, prec).get(), prec);
    arb_mul_2exp_si(c.get(), c.get(), -1);
    arb_sub(half_spacing_squared.get(), along_line(support_i, n, prec).get(), c.get(), prec);
    arb_sqr(half_spacing_squared.get(), half_spacing_squared.get(), prec);
    // Site k touches the circle at its boundary point with outward normal u,
    // u = n first (k near the line), then u toward the circle's center (k far
    // off, the circle between it and the pair).
    BallVector u = n;
    for (int round = 0; round < 3; ++round) {
        s[k].support(u, &support_k, prec);
        Ball w_line, w_normal, radius, numerator, t;
        arb_sub(w_line.get(), along_line(support_k, n, prec).get(), c.get(), prec);
        arb_sub(w_normal.get(), along_normal(support_k, n, prec).get(), h.get(), prec);
        if (round == 0) {
            resolved = !arb_contains_zero(w_normal.get()) && arb_rel_accuracy_bits(w_normal.get()) >= kGapBits;
            if (!resolved) return false;
        }
        arb_sqr(numerator.get(), w_line.get(), prec);
        arb_sub(numerator.get(), numerator.get(), half_spacing_squared.get(), prec);
        arb_addmul(numerator.get(), w_normal.get(), w_normal.get(), prec);
        arb_div(radius.get(), numerator.get(), w_normal.get(), prec);
        arb_mul_2exp_si(radius.get(), radius.get(), -1);
        if (!arb_is_positive(radius.get())) return false;
        // n.V = h_i + R - (x_i - c)^2 / (2 R); V = c d + (n.V) n, d = (-n_y, n_x)
        Ball height;
        arb_div(t.get(), half_spacing_squared.get(), radius.get(), prec);
        arb_mul_2exp_si(t.get(), t.get(), -1);
        arb_add(height.get(), h.get(), radius.get(), prec);
        arb_sub(height.get(), height.get(), t.get(), prec);
        arb_mul(out.center.x.get(), height.get(), n.x.get(), prec);
        arb_submul(out.center.x.get(), c.get(), n.y.get(), prec);
        arb_mul(out.center.y.get(), height.get(), n.y.get(), prec);
        arb_addmul(out.center.y.get(), c.get(), n.x.get(), prec);
        out.radius = radius;
        u = unit_direction(support_k, out.center, prec);
        // A start needs no rigour: midpoints keep the error of V out of u.
        arb_get_mid_arb(u.x.get(), u.x.get());
        arb_get_mid_arb(u.y.get(), u.y.get());
    }
    out.ratio_bits = std::max(0L, magnitude(out.radius) - size_bits);
    return true;
}

// The start of a first-order circle: each tangency at the boundary point
// whose outward normal points at V (two rounds: aimed from the site's center,
// then from the point found; V is ~R away, so the second is within
// (size / R)^2 radians).
VoronoiCircleStart start_of(const std::array<ArbSite, 3>& s, const FirstOrderCircle& circle, long prec) {
    VoronoiCircleStart start;
    start.precision = prec;
    for (int m = 0; m < 3; ++m) {
        BallVector toward = s[m].center();
        for (int round = 0; round < 2; ++round) {
            const BallVector n = unit_direction(toward, circle.center, prec);
            s[m].support(n, &toward, prec);
            if (round == 1) {
                start.flipped[m] = s[m].chart_parameter(n, start.parameter[m], prec);
                arb_get_mid_arb(start.parameter[m].get(), start.parameter[m].get());
            }
        }
    }
    arb_get_mid_arb(start.radius.get(), circle.radius.get());
    arb_get_mid_arb(start.center_x.get(), circle.center.x.get());
    arb_get_mid_arb(start.center_y.get(), circle.center.y.get());
    return start;
}

}  // namespace

bool for_each_huge_circle_start(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3, long min_ratio_bits,
                                const std::function<bool(const VoronoiCircleStart&)>& try_start) {
    const std::array<const Ellipse*, 3> sites = {&e1, &e2, &e3};
    Rational smallest;
    for (const Ellipse* e : sites)
        for (const Rational* axis : {&e->a(), &e->b()})
            if (smallest.is_zero() || *axis < smallest) smallest = *axis;
    const long size_bits = magnitude(Ball(smallest, 64));
    // A nearly coincident pair (a copy moved by 10^-20, fuzz F9) has h_i - h_j
    // of the order of its difference h, so its bitangent's direction needs
    // log2(1 / h) bits more than a pair apart to be resolved at all, and as
    // many again to be within h / R of the true one, which the pair's
    // nearly singular system needs of a start.
    const std::optional<NearDuplicatePair> close_pair = closest_near_duplicate_pair(e1, e2, e3, kNearDuplicateBits);
    constexpr int kPairs[3][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}};
    for (const auto& pair : kPairs) {
        const int i = pair[0], j = pair[1], k = pair[2];
        const Ellipse &ei = *sites[i], &ej = *sites[j];
        const bool nearly_coincident =
            close_pair && std::min(i, j) == close_pair->first && std::max(i, j) == close_pair->second;
        const long first_precision = kFirstPrecision + (nearly_coincident ? 2 * close_pair->bits : 0);
        // The pair's difference in balls when it is below the doubles' rounding (a copy turned by 10^-30).
        const ShapeInDoubles pi = shape_relative_to(ei, ei), pj = shape_relative_to(ej, ei);
        std::optional<ArbSite> ai, aj;
        if (nearly_coincident) ai.emplace(ei, first_precision), aj.emplace(ej, first_precision);
        const std::vector<double> directions =
            bitangent_directions(pi, pj,
                                 nearly_coincident ? support_difference_in_balls(*ai, *aj, first_precision)
                                                   : support_difference_in_doubles(pi, pj));
        for (double phi0 : directions) {
            // Raise the precision until g is resolved, then to what the
            // circle's size needs.
            for (long prec = first_precision; prec <= kLastPrecision; prec *= 2) {
                const std::array<ArbSite, 3> s = {ArbSite(e1, prec), ArbSite(e2, prec), ArbSite(e3, prec)};
                const Ball phi = refine_direction(s[i], s[j], phi0, prec);
                FirstOrderCircle circle;
                bool resolved = false;
                if (!first_order_circle(s, i, j, k, phi, size_bits, prec, circle, resolved)) {
                    if (resolved) break;  // no circle on this line's far side
                    continue;
                }
                if (circle.ratio_bits < min_ratio_bits) break;
                const long needed = kMarginBits + 3 * circle.ratio_bits;
                if (prec < needed && 2 * prec <= kLastPrecision) continue;
                if (try_start(start_of(s, circle, prec))) return true;
                break;
            }
        }
    }
    return false;
}

bool for_each_huge_circle_start_in_doubles(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3,
                                           long min_ratio_bits,
                                           const std::function<bool(const DoubleCircleStart&)>& try_start) {
    const std::array<const Ellipse*, 3> sites = {&e1, &e2, &e3};
    double smallest = INFINITY;
    for (const Ellipse* e : sites) smallest = std::fmin(smallest, std::fmin(e->enclosure().a.lo, e->enclosure().b.lo));
    constexpr int kPairs[3][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}};
    for (const auto& pair : kPairs) {
        const int i = pair[0], j = pair[1], m = pair[2];
        // Each pair seen from its site i, as in for_each_huge_circle_start.
        const std::array<ShapeInDoubles, 3> k = {shape_relative_to(e1, *sites[i]), shape_relative_to(e2, *sites[i]),
                                        shape_relative_to(e3, *sites[i])};
        for (double phi : bitangent_directions(k[i], k[j], support_difference_in_doubles(k[i], k[j]))) {
            DoubleCircleStart start;
            if (!double_circle_start(k, i, j, m, std::cos(phi), std::sin(phi), start)) continue;
            const double ratio = start.x[3] / smallest;
            if (!(ratio >= std::ldexp(1.0, min_ratio_bits)) || ratio > std::ldexp(1.0, kMaxRatioBitsInDoubles))
                continue;
            start.x[4] += sites[i]->enclosure().xc.mid();
            start.x[5] += sites[i]->enclosure().yc.mid();
            if (try_start(start)) return true;
        }
    }
    return false;
}

}  // namespace ellvor
