#include "sites/medial_axis.hpp"

namespace ellvor {

std::optional<MedialAxis> medial_axis(const Ellipse& e) {
    if (e.a() == e.b()) return std::nullopt;
    MedialAxis axis;
    axis.along_a = e.b() < e.a();
    axis.cx = e.xc();
    axis.cy = e.yc();
    // u = (cos, sin) along the a-axis, v = (-sin, cos) along the b-axis (§2).
    axis.dx = axis.along_a ? e.cos_rotation() : -e.sin_rotation();
    axis.dy = axis.along_a ? e.sin_rotation() : e.cos_rotation();
    const Rational a2 = e.a() * e.a(), b2 = e.b() * e.b();
    axis.major2 = axis.along_a ? a2 : b2;
    axis.minor2 = axis.along_a ? b2 : a2;
    axis.focal2 = axis.major2 - axis.minor2;
    return axis;
}

}  // namespace ellvor
