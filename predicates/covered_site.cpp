#include "predicates/covered_site.hpp"

#include "exact/real_roots.hpp"
#include "predicates/distance_filter.hpp"
#include "sites/ellipse_polynomials.hpp"
#include "subdivision/ellipse_shape.hpp"
#include "subdivision/inscribed_disk.hpp"

#include <algorithm>
#include <vector>

namespace ellvor {
namespace {

// The intersection quartic's formal degree: a lower degree is a root at t = infinity.
constexpr long kQuarticDegree = 4;
// Pieces of S examined at most for (B).
constexpr int kMaxPieces = 256;
// Points of S where (B) is first guessed in doubles.
constexpr int kGuessSamples = 64;
// Precision of the inscribed-disk test in (B): the depths compared are far from equal.
constexpr long kDepthPrecision = 64;

// (A): for every real t and t = infinity, qy(t) < 0 or qz(t) < 0, the
// quartics' signs being the side of y and z at x's boundary point P(t).
bool boundary_inside_union(const IntPolynomial& qy, const IntPolynomial& qz) {
    if (qy.is_zero() || qz.is_zero()) return false;
    // At t = infinity: the coefficient of t^4 (zero there is the root).
    auto at_infinity = [](const IntPolynomial& q) { return q.degree() < kQuarticDegree ? 0 : q.coeff(kQuarticDegree).sign(); };
    if (at_infinity(qy) >= 0 && at_infinity(qz) >= 0) return false;
    IntPolynomial product;
    fmpz_poly_mul(product.get(), qy.get(), qz.get());
    const std::vector<IsolatingInterval> roots = isolate_real_roots(product);
    // A sample point in every gap between the roots and beyond them: no root of either quartic.
    std::vector<Rational> samples;
    if (roots.empty()) {
        samples.push_back(Rational(0));
    } else {
        samples.push_back(roots.front().lo - Rational(1));
        for (std::size_t i = 1; i < roots.size(); ++i) samples.push_back((roots[i - 1].hi + roots[i].lo) * Rational(1, 2));
        samples.push_back(roots.back().hi + Rational(1));
    }
    for (const Rational& s : samples)
        if (qy.sign_at(s) >= 0 && qz.sign_at(s) >= 0) return false;
    // At each root, the quartic that does not vanish there must be negative; it keeps
    // its sign between the samples beside the root. A common root is a point on both.
    for (std::size_t i = 0; i < roots.size(); ++i) {
        const Rational &left = samples[i], &right = samples[i + 1];
        const bool on_y = count_real_roots(qy, left, right) > 0, on_z = count_real_roots(qz, left, right) > 0;
        if (on_y == on_z) return false;
        if ((on_y ? qz : qy).sign_at(left) >= 0) return false;
    }
    return true;
}

// delta(q, e) lies outside [-2 r, r] for every q of the box: beyond r outside
// e, or deeper than 2 r inside (the closed disk of radius 2 r about q in e).
bool clear_of_band(const Ellipse& e, Interval qx, Interval qy, const Rational& r) {
    const double r_hi = Interval::up(r.to_double()), r_lo = Interval::down(r.to_double());
    const Interval bounds = signed_distance_disk_bounds(e.enclosure(), qx, qy);
    if (bounds.lo > r_hi || bounds.hi < -2 * r_hi) return true;
    const LocalPoint local = to_local(e, qx, qy);
    const int side = filtered_side(local);
    if (side > 0) return outside_distance_bounds(local).lo > r_hi;
    if (side < 0 && r_lo > 0) {
        // The closed disk of radius 2 r about any q of the box lies in the one
        // of radius 2 r + w about its midpoint m (w = the box's width plus its
        // height, above its half-diagonal): that one is tested, about an exact
        // point. The box itself as the center would blur the distance quartic
        // by its width times the site's size (a piece 0.01 long beside an
        // ellipse of size 20 left a depth of 0.3 against 0.08 unproven, fuzz F10).
        const Interval widths = (Interval(qx.hi) - Interval(qx.lo)) + (Interval(qy.hi) - Interval(qy.lo));
        Ball radius(Rational(2) * r, kDepthPrecision), margin, mx, my;
        arb_set_d(margin.get(), widths.hi);
        arb_add(radius.get(), radius.get(), margin.get(), kDepthPrecision);
        arb_set_d(mx.get(), qx.mid());
        arb_set_d(my.get(), qy.mid());
        return inside_distance_minus(e, radius, mx, my, kDepthPrecision) > 0;
    }
    return false;
}

// (B) on S = C + s L d, s in [-1, 1] (L the larger semi-axis, d its unit direction).
bool axis_clear_of_both_bands(const Ellipse& x, const Ellipse& y, const Ellipse& z) {
    const Ellipse::Enclosure& k = x.enclosure();
    const bool a_long = !(x.a() < x.b());
    const Interval length = a_long ? k.a : k.b;
    const Interval dx = a_long ? k.cos : -k.sin, dy = a_long ? k.sin : k.cos;
    const Rational r = a_long ? x.b() : x.a();
    // A guess first, in plain doubles (it only saves time: "not proven" is always allowed): a
    // point of S well inside both bands, where an internal circle may well be, ends it.
    const EllipseShape sx = EllipseShape::of(x), sy = EllipseShape::of(y), sz = EllipseShape::of(z);
    const double band = r.to_double(), long_axis = length.mid(), ux = dx.mid(), uy = dy.mid();
    for (int i = 0; i <= kGuessSamples; ++i) {
        const double t = -1 + 2.0 * i / kGuessSamples, px = sx.xc + t * long_axis * ux, py = sx.yc + t * long_axis * uy;
        auto in_band = [&](const EllipseShape& e) {
            const double d = e.signed_distance(px, py);
            return d > -1.75 * band && d < 0.75 * band;
        };
        if (in_band(sy) && in_band(sz)) return false;
    }
    const double min_piece = band / 8;
    std::vector<Interval> stack{Interval(-1, 1)};
    int pieces = 0;
    while (!stack.empty()) {
        if (++pieces > kMaxPieces) return false;
        const Interval s = stack.back();
        stack.pop_back();
        const Interval qx = k.xc + s * length * dx, qy = k.yc + s * length * dy;
        if (clear_of_band(y, qx, qy, r) || clear_of_band(z, qx, qy, r)) continue;
        // A piece much shorter than the band's width 3 r that is not clear is in both bands, or
        // so near both that (B) cannot be shown here.
        if (((s.hi - s.lo) * length).hi < min_piece) return false;
        const double m = s.mid();
        stack.push_back(Interval(s.lo, m));
        stack.push_back(Interval(m, s.hi));
    }
    return true;
}

}  // namespace

bool covered_without_circle(const Ellipse& x, const Ellipse& y, const Ellipse& z) {
    return boundary_inside_union(intersection_quartic(x, y), intersection_quartic(x, z)) &&
           axis_clear_of_both_bands(x, y, z);
}

}  // namespace ellvor
