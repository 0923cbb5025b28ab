// The answers of the predicates whose result is more than a sign, with their
// names as the CLI and the JSON print them. They live in the decision core so
// that every cascade -- the ellipse predicates and the circle closed forms --
// returns the same types.
#pragma once

#include "decision/stage.hpp"

namespace ellvor {

// kappa3 (incircle, docs/DESIGN.md §2).
enum class InCircle {
    conflict,     // NEGATIVE: Q meets the open Voronoi disk
    no_conflict,  // POSITIVE
    tangent,      // ZERO: Q externally tangent to the circle (proven by the exact stage)
    no_circle,    // NEGATIVE by CGAL's rule: the triple has no counter-clockwise Voronoi circle
};

inline const char* incircle_name(InCircle r) {
    switch (r) {
        case InCircle::conflict: return "conflict";
        case InCircle::no_conflict: return "no-conflict";
        case InCircle::tangent: return "tangent";
        case InCircle::no_circle: return "no-circle";
    }
    return "?";
}

// CGAL's sign: NEGATIVE for conflict and no_circle, POSITIVE no_conflict, ZERO tangent.
inline Sign incircle_sign(InCircle r) {
    switch (r) {
        case InCircle::conflict:
        case InCircle::no_circle: return Sign::negative;
        case InCircle::no_conflict: return Sign::positive;
        case InCircle::tangent: break;
    }
    return Sign::zero;
}

// Which Voronoi circles a triple (E1, E2, E3) has (docs/DESIGN.md §2).
enum class VoronoiCircles {
    none,      // neither orientation
    ccw_only,  // only the circle of (E1, E2, E3)
    cw_only,   // only the circle of (E1, E3, E2)
    both,
};

inline const char* voronoi_circles_name(VoronoiCircles v) {
    switch (v) {
        case VoronoiCircles::none: return "none";
        case VoronoiCircles::ccw_only: return "ccw";
        case VoronoiCircles::cw_only: return "cw";
        case VoronoiCircles::both: return "both";
    }
    return "?";
}

}  // namespace ellvor
