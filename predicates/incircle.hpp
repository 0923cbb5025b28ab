// kappa3, InCircle (CGAL Vertex_conflict_2 with four sites; DESIGN.md): the
// position of a query site Q relative to the Voronoi circle of the ordered
// triple (E1, E2, E3) -- externally tangent to the three, tangency points
// counter-clockwise E1 -> E2 -> E3.
#pragma once

#include "predicates/stage.hpp"
#include "sites/ellipse.hpp"
#include "subdivision/voronoi_circle_enclosure.hpp"

namespace ellvor {

enum class InCircle {
    conflict,     // NEGATIVE: Q meets the open Voronoi disk
    no_conflict,  // POSITIVE
    tangent,      // ZERO: Q externally tangent to the circle (proven by the exact stage)
    no_circle,    // NEGATIVE by CGAL's rule: the triple has no counter-clockwise Voronoi circle
    undecided,    // only with exact_stage = false: the subdivision stage reached its
                  // precision cap (the certification of the circle itself is complete)
};

const char* incircle_name(InCircle r);
// CGAL's sign: -1 for conflict and no_circle, +1 no_conflict, 0 tangent.
// Throws Error for undecided.
int incircle_sign(InCircle r);

struct InCircleOptions {
    long max_precision = 4096;  // the subdivision stage hands over to the exact stage beyond this
    bool exact_stage = true;    // false: stop at the cap with "undecided" (experiments, tests)
    bool use_filter = true;     // false: skip the closed-form filter for four circles
};

struct InCircleDecision {
    InCircle result = InCircle::undecided;
    Stage stage = Stage::subdivision;  // of the last stage that ran
    long precision = 0;                // Arb precision that decided (or the cap)
    long newton_steps = 0;             // Arb Newton steps spent on the Voronoi circle
};

// The cascade: for four circles, a closed-form filter in double intervals
// (circle_incircle_filter.hpp); then the existence of the counter-clockwise
// circle from three kappa2 signs; then the certified enclosure of the circle (center V, radius rho) and
// the distance d(V, Q) -- double intervals first, then Arb -- compared with
// rho at doubling precision; past the cap, the exact stage decides whether Q
// is tangent (resultants, voronoi_vertex_equality.hpp) and, if it is not,
// the subdivision resumes until it separates.
// `solver`, when given, is the cached solver of (E1, E2, E3) and is refined in
// place (see VoronoiCircleCache).
InCircleDecision incircle(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3, const Ellipse& q,
                          const InCircleOptions& options = {}, VoronoiCircleSolver* solver = nullptr);

}  // namespace ellvor
