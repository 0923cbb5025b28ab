#include "sites/mirror_symmetry.hpp"

namespace ellvor {

Ellipse mirror_across(const Ellipse& e, const AxisLine& line) {
    const Rational two_c = Rational(2) * line.c;
    return Ellipse(e.a(), e.b(), -e.w(), line.vertical ? two_c - e.xc() : e.xc(),
                   line.vertical ? e.yc() : two_c - e.yc());
}

bool strictly_beside(const Ellipse& e, const AxisLine& line) {
    const Rational gap = (line.vertical ? e.xc() : e.yc()) - line.c;
    const Rational a2 = e.a() * e.a(), b2 = e.b() * e.b();
    const Rational c2 = e.cos_rotation() * e.cos_rotation(), s2 = e.sin_rotation() * e.sin_rotation();
    const Rational half_extent_squared = line.vertical ? a2 * c2 + b2 * s2 : a2 * s2 + b2 * c2;
    return gap * gap > half_extent_squared;
}

namespace {

// The axis-parallel line across which f is e's mirror image, wherever e lies.
std::optional<AxisLine> reflecting_line(const Ellipse& e, const Ellipse& f) {
    const Ellipse::PointSetKey k = e.point_set_key(), m = f.point_set_key();
    // Reflection keeps the diagonal of the normalized quadratic form and negates its xy entry.
    if (k[2] != m[2] || k[3] != -m[3] || k[4] != m[4]) return std::nullopt;
    if (k[1] == m[1] && k[0] != m[0]) return AxisLine{true, (k[0] + m[0]) * Rational(1, 2)};
    if (k[0] == m[0] && k[1] != m[1]) return AxisLine{false, (k[1] + m[1]) * Rational(1, 2)};
    return std::nullopt;
}

}  // namespace

std::optional<AxisLine> mirror_line(const Ellipse& e, const Ellipse& f) {
    const std::optional<AxisLine> line = reflecting_line(e, f);
    if (line && !strictly_beside(e, *line)) return std::nullopt;
    return line;
}

std::optional<AxisLine> bisector_line(const Ellipse& e, const Ellipse& f) {
    const std::optional<AxisLine> line = reflecting_line(e, f);
    if (line && !(e.is_circle() && f.is_circle()) && !strictly_beside(e, *line)) return std::nullopt;
    return line;
}

SelfMirror self_mirror(const Ellipse& e, const AxisLine& line) {
    if (e.is_circle() || mirror_across(e, line).point_set_key() != e.point_set_key()) return SelfMirror::none;
    // Symmetric and not a circle: an axis of e lies along the line. Across a
    // vertical line u = (cos, sin) is kept iff cos = 0, across a horizontal one iff sin = 0.
    const bool a_axis_along = (line.vertical ? e.cos_rotation() : e.sin_rotation()).is_zero();
    return a_axis_along ? SelfMirror::negates_parameter : SelfMirror::inverts_parameter;
}

}  // namespace ellvor
