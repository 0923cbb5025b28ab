#include "predicates/voronoi_circle_count.hpp"

#include "predicates/infinite_vertex_conflict.hpp"
#include "predicates/relative_position.hpp"

#include <tuple>

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

Decision<VoronoiCircles> voronoi_circle_count(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3) {
    Decision<VoronoiCircles> count = Decision<VoronoiCircles>::decided(VoronoiCircles::none, Stage::filter);
    for (auto [p, q] : {std::pair{&e1, &e2}, {&e2, &e3}, {&e3, &e1}}) {
        const Decision<RelativePosition> r = relative_position(*p, *q);
        count.depends_on(r);
        if (*r != RelativePosition::separated && *r != RelativePosition::externally_tangent) return count;
    }
    // How many of the three sites conflict with the infinite vertex of the
    // other two, taken in the cyclic order of the triple (digest 2.4): for
    // three points in counter-clockwise order all three do.
    int conflicts = 0;
    for (auto [p, q, r] : {std::tuple{&e1, &e2, &e3}, {&e2, &e3, &e1}, {&e3, &e1, &e2}}) {
        const Decision<Sign> d = infinite_vertex_conflict(*p, *q, *r);
        count.depends_on(d);
        conflicts += *d == Sign::negative;
    }
    constexpr VoronoiCircles by_conflicts[] = {VoronoiCircles::cw_only, VoronoiCircles::none, VoronoiCircles::both,
                                               VoronoiCircles::ccw_only};
    return count.with(by_conflicts[conflicts]);
}

}  // namespace ellvor
