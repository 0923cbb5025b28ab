// The medial axis of an ellipse that is not a circle, exactly (docs/DESIGN.md
// §4.2: an internal Voronoi circle centered on it touches the site at two
// mirror points). With major and minor semi-axes M > m and c^2 = M^2 - m^2, it
// is the open segment {C + h d : |h| < c^2 / M} of the major axis (d its unit
// direction: the rotation's cos and sin are rational). The circle about C + h d
// of radius^2 s(h) = m^2 (1 - h^2 / c^2) lies in the ellipse and touches it
// exactly at the two feet h M^2 / c^2 along the axis, mirror images across it.
#pragma once

#include "sites/ellipse.hpp"

#include <optional>

namespace ellvor {

struct MedialAxis {
    Rational cx, cy;           // the center C
    Rational dx, dy;           // the major axis' unit direction d
    Rational major2, minor2;   // M^2, m^2
    Rational focal2;           // c^2 = M^2 - m^2 > 0
    // The major axis is the a-axis: the reflection across it maps the
    // boundary parameter t to -t; else it is the b-axis and t goes to 1/t
    // (SelfMirror in sites/mirror_symmetry.hpp).
    bool along_a = true;
};

// Nothing for a circle (its medial axis is its center).
std::optional<MedialAxis> medial_axis(const Ellipse& e);

}  // namespace ellvor
