#include "predicates/voronoi_circle_count.hpp"

#include "predicates/infinite_vertex_conflict.hpp"
#include "predicates/relative_position.hpp"

#include <algorithm>
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

VoronoiCircleCount voronoi_circle_count_decided(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3) {
    Stage stage = Stage::filter;
    for (auto [p, q] : {std::pair{&e1, &e2}, {&e2, &e3}, {&e3, &e1}}) {
        const RelativePositionResult r = relative_position_decided(*p, *q);
        stage = std::max(stage, r.stage);
        if (r.position != RelativePosition::separated && r.position != RelativePosition::externally_tangent)
            return {VoronoiCircles::none, stage};
    }
    // How many of the three sites conflict with the infinite vertex of the
    // other two, taken in the cyclic order of the triple (digest 2.4): for
    // three points in counter-clockwise order all three do.
    int conflicts = 0;
    for (auto [p, q, r] : {std::tuple{&e1, &e2, &e3}, {&e2, &e3, &e1}, {&e3, &e1, &e2}}) {
        const SignDecision d = infinite_vertex_conflict(*p, *q, *r);
        stage = std::max(stage, d.stage);
        conflicts += d.sign < 0;
    }
    switch (conflicts) {
        case 3: return {VoronoiCircles::ccw_only, stage};
        case 2: return {VoronoiCircles::both, stage};
        case 1: return {VoronoiCircles::none, stage};
        default: return {VoronoiCircles::cw_only, stage};
    }
}

}  // namespace ellvor
