#include "predicates/voronoi_circle_count.hpp"

#include "predicates/circle_predicates.hpp"
#include "predicates/circle_semi_static.hpp"
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

Decision<bool> none_inside_another(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3) {
    Decision<bool> separated = Decision<bool>::decided(true, Stage::filter);
    for (auto [p, q] : {std::pair{&e1, &e2}, {&e2, &e3}, {&e3, &e1}}) {
        const Decision<RelativePosition> r = relative_position(*p, *q);
        separated.depends_on(r);
        const bool crossing_circles = *r == RelativePosition::intersecting && p->is_circle() && q->is_circle();
        if (*r != RelativePosition::separated && *r != RelativePosition::externally_tangent && !crossing_circles)
            return separated.with(false);
    }
    return separated;
}

Decision<VoronoiCircles> voronoi_circle_count(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3) {
    // Three circles in doubles first: a count it proves also proves that no
    // site contains another.
    const Decision<VoronoiCircles> fast = circle_voronoi_circle_count_semi_static(e1, e2, e3);
    if (fast.is_decided()) return fast;
    const Decision<bool> separated = none_inside_another(e1, e2, e3);
    if (!*separated) return separated.with(VoronoiCircles::none);
    if (e1.is_circle() && e2.is_circle() && e3.is_circle())
        return Decision<VoronoiCircles>::decided(circle_voronoi_circle_count(e1, e2, e3), Stage::exact);
    // How many of the three sites conflict with the infinite vertex of the
    // other two, taken in the cyclic order of the triple: for three points in
    // counter-clockwise order all three do.
    Decision<VoronoiCircles> count = separated.with(VoronoiCircles::none);
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
