#include "predicates/incircle.hpp"

#include "predicates/distance_filter.hpp"
#include "predicates/voronoi_circle_count.hpp"
#include "subdivision/point_ellipse_distance.hpp"
#include "util/error.hpp"

#include <algorithm>
#include <memory>

namespace ellvor {

const char* incircle_name(InCircle r) {
    switch (r) {
        case InCircle::conflict: return "conflict";
        case InCircle::no_conflict: return "no-conflict";
        case InCircle::tangent: return "tangent";
        case InCircle::no_circle: return "no-circle";
        case InCircle::undecided: return "undecided";
    }
    return "?";
}

int incircle_sign(InCircle r) {
    switch (r) {
        case InCircle::conflict:
        case InCircle::no_circle: return -1;
        case InCircle::no_conflict: return 1;
        case InCircle::tangent: return 0;
        case InCircle::undecided: break;
    }
    throw Error("incircle_sign: the predicate is undecided");
}

namespace {

constexpr long kStartPrecision = 64;
// The enclosure is refined to this many bits below the working precision.
constexpr long kEnclosureGuard = 16;

// d(V, Q) - rho with double intervals (the filter): -1, +1, or 0.
int filtered_distance_minus_radius(const VoronoiCircleEnclosure& c, const Ellipse& q) {
    const LocalPoint v = to_local(q, enclose(c.center_x), enclose(c.center_y));
    const int side = filtered_side(v);
    if (side < 0) return -1;  // the center is inside Q
    if (side == 0) return 0;
    const Interval distance = outside_distance_bounds(v), radius = enclose(c.radius);
    if (distance.lo > radius.hi) return 1;
    if (distance.hi < radius.lo) return -1;
    return 0;
}

// d(V, Q) - rho at precision prec: -1, +1, or 0 when undecided.
int distance_minus_radius(const VoronoiCircleEnclosure& c, const Ellipse& q, long prec) {
    if (int s = filtered_distance_minus_radius(c, q)) return s;
    const int side = certified_side(q, c.center_x, c.center_y, prec);
    if (side < 0) return -1;  // the center is inside Q
    if (side == 0) return 0;
    Ball distance, difference;
    if (!certified_outside_distance(q, c.center_x, c.center_y, prec, distance)) return 0;
    arb_sub(difference.get(), distance.get(), c.radius.get(), prec);
    return difference.certain_sign();
}

}  // namespace

InCircleDecision incircle(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3, const Ellipse& q,
                          const InCircleOptions& options, VoronoiCircleSolver* solver) {
    InCircleDecision d;
    const VoronoiCircleCount count = voronoi_circle_count_decided(e1, e2, e3);
    if (count.circles == VoronoiCircles::none || count.circles == VoronoiCircles::cw_only) {
        d.result = InCircle::no_circle;
        d.stage = count.stage;
        return d;
    }
    std::unique_ptr<VoronoiCircleSolver> own;
    if (!solver) {
        own = std::make_unique<VoronoiCircleSolver>(e1, e2, e3);
        solver = own.get();
    }
    d.stage = Stage::subdivision;
    for (long prec = kStartPrecision; prec <= options.max_precision; prec *= 2) {
        d.precision = prec;
        const bool ok = solver->refine(std::max(prec - kEnclosureGuard, 1L));
        d.newton_steps = solver->enclosure().newton_steps;
        if (!ok) return d;  // no certificate: undecided
        if (int s = distance_minus_radius(solver->enclosure(), q, prec)) {
            d.result = s < 0 ? InCircle::conflict : InCircle::no_conflict;
            return d;
        }
    }
    return d;  // undecided at the precision cap
}

}  // namespace ellvor
