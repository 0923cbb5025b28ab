// A site in doubles with its center relative to another site's: the starts
// of huge_circle_start.hpp and bisector_walk_start.hpp see a triple from one
// of its own sites, so that a close pair far from the origin (or beside a
// site 10^29 sizes away) keeps its relative position's digits. Only for
// starts: nothing here is certified.
#pragma once

#include "sites/ellipse.hpp"

namespace ellvor {

struct ShapeInDoubles {
    double a, b, c, s, x, y;  // semi-axes, rotation (cos, sin), center minus the origin site's
};

inline ShapeInDoubles shape_relative_to(const Ellipse& e, const Ellipse& origin) {
    const Ellipse::Enclosure& k = e.enclosure();
    return {k.a.mid(),
            k.b.mid(),
            k.cos.mid(),
            k.sin.mid(),
            (e.xc() - origin.xc()).to_double(),
            (e.yc() - origin.yc()).to_double()};
}

}  // namespace ellvor
