// The "refine -> exact -> resume" skeleton shared by the predicates that
// compare two certified quantities which may be exactly equal (InCircle: the
// distance from the Voronoi circle's center to Q against its radius; the
// order of two Voronoi vertices along a bisector):
//  1. subdivision: the sign at doubling precision from precision::kStart up
//     to the cap; a decided sign ends the predicate;
//  2. exact: past the cap, whether the two quantities are equal (proven with
//     resultants); equal ends the predicate with Sign::zero;
//  3. subdivision again, above the cap, until the sign separates -- which it
//     must, since the exact stage proved the quantities distinct. The resume
//     limit turns an internal error into an Error, never into a loop.
#pragma once

#include "decision/stage.hpp"
#include "util/error.hpp"
#include "util/precision.hpp"

#include <string>

namespace ellvor {

struct RefinementOptions {
    long cap = precision::kDefaultCap;  // the subdivision stage hands over to the exact stage beyond this
    bool exact_stage = true;            // false: stop at the cap, undecided (experiments, tests)
};

// sign_at(prec) -> int: the sign at Arb precision prec, 0 when undecided.
// equal_exactly(prec) -> bool: the exact stage, given the precision the
// subdivision reached (its enclosures are that good).
template <class SignAt, class EqualExactly>
Decision<Sign> refine_then_exact(const char* what, const RefinementOptions& options, SignAt&& sign_at,
                                 EqualExactly&& equal_exactly) {
    long prec = precision::kStart;
    for (; prec <= options.cap; prec *= 2)
        if (const int s = sign_at(prec)) return Decision<Sign>::decided(sign_of(s), Stage::subdivision, prec);
    const long reached = prec / 2;
    if (!options.exact_stage) return Decision<Sign>::undecided(Stage::subdivision, reached);
    if (equal_exactly(reached)) return Decision<Sign>::decided(Sign::zero, Stage::exact, reached);
    const long limit = precision::resume_limit(options.cap);
    for (; prec <= limit; prec *= 2)
        if (const int s = sign_at(prec)) return Decision<Sign>::decided(sign_of(s), Stage::exact, prec);
    throw Error(std::string(what) + ": values proven distinct by the exact stage were not separated within " +
                std::to_string(limit) + " bits (internal error)");
}

}  // namespace ellvor
