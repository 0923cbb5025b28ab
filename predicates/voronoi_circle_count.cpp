#include "predicates/voronoi_circle_count.hpp"

#include "predicates/infinite_vertex_conflict.hpp"
#include "predicates/relative_position.hpp"

namespace ellvor {

const char* voronoi_circles_name(VoronoiCircles v) {
    switch (v) {
        case VoronoiCircles::none: return "none";
        case VoronoiCircles::ccw_only: return "ccw";
        case VoronoiCircles::cw_only: return "cw";
        case VoronoiCircles::both: return "both";
    }
    return "?";
}

VoronoiCircles voronoi_circle_count(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3) {
    for (auto [p, q] : {std::pair{&e1, &e2}, {&e2, &e3}, {&e3, &e1}}) {
        const RelativePosition r = relative_position(*p, *q);
        if (r != RelativePosition::separated && r != RelativePosition::externally_tangent) return VoronoiCircles::none;
    }
    // How many of the three sites conflict with the infinite vertex of the
    // other two, taken in the cyclic order of the triple (digest 2.4): for
    // three points in counter-clockwise order all three do.
    const int conflicts = (infinite_vertex_conflict(e1, e2, e3).sign < 0) +
                          (infinite_vertex_conflict(e2, e3, e1).sign < 0) +
                          (infinite_vertex_conflict(e3, e1, e2).sign < 0);
    switch (conflicts) {
        case 3: return VoronoiCircles::ccw_only;
        case 2: return VoronoiCircles::both;
        case 1: return VoronoiCircles::none;
        default: return VoronoiCircles::cw_only;
    }
}

}  // namespace ellvor
