#include "predicates/distance_filter.hpp"

#include "subdivision/nearest_point.hpp"

#include <cmath>

namespace ellvor {

LocalPoint to_local(const Ellipse& e, Interval x, Interval y) {
    const Ellipse::Enclosure& k = e.enclosure();
    const Interval dx = x - k.xc, dy = y - k.yc;
    return {k.cos * dx + k.sin * dy, k.cos * dy - k.sin * dx, k.a, k.b};
}

Interval signed_distance_disk_bounds(const Ellipse::Enclosure& k, Interval x, Interval y) {
    const Interval to_center = ((x - k.xc).square() + (y - k.yc).square()).sqrt();
    const Interval outer(std::fmax(k.a.hi, k.b.hi)), inner(std::fmin(k.a.lo, k.b.lo));
    return Interval((to_center - outer).lo, (to_center - inner).hi);
}

int filtered_side(const LocalPoint& q) {
    const Interval v = (q.x / q.a).square() + (q.y / q.b).square() - Interval(1.0);
    if (!v.finite()) return 0;
    return v.positive() ? 1 : v.negative() ? -1 : 0;
}

Interval outside_distance_bounds(const LocalPoint& q) {
    double theta = approximate_nearest_angle(q.a.mid(), q.b.mid(), q.x.mid(), q.y.mid());
    // A boundary point through the rational parametrization at an exact double
    // u = tan(theta/2), in the chart where |u| <= 1 (flip by pi otherwise).
    double sign = 1.0;
    if (std::cos(theta) < 0) {
        theta = theta > 0 ? theta - M_PI : theta + M_PI;
        sign = -1.0;
    }
    const Interval u(std::tan(theta / 2));
    const Interval den = Interval(1.0) + u.square();
    const Interval c = (Interval(1.0) - u.square()) / den * Interval(sign);
    const Interval s = (Interval(2.0) * u) / den * Interval(sign);
    const Interval bx = q.a * c, by = q.b * s;
    const Interval dx = q.x - bx, dy = q.y - by;
    const Interval upper = (dx.square() + dy.square()).sqrt();
    const Interval nx = c / q.a, ny = s / q.b;
    const Interval lower = (nx * dx + ny * dy) / (nx.square() + ny.square()).sqrt();
    const Interval d(std::fmax(lower.lo, 0.0), upper.hi);
    return d.finite() ? d : Interval(0.0, INFINITY);
}

}  // namespace ellvor
