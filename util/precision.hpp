// The precision policy of the numerical stages, in one place: where the Arb
// stages start, how far they may go, and the guard bits they keep, each with
// the reason for its value. Every precision loop in ellvor is bounded by one
// of these limits and ends with a clear Error, never with a guess.
#pragma once

#include <algorithm>

namespace ellvor::precision {

// First Arb precision of every stage: one 64-bit limb, the cheapest Arb
// precision; random inputs are decided here (experiments/results/incircle.md).
constexpr long kStart = 64;

// Default cap of the subdivision stage: beyond it the exact stage decides
// whether the compared values are equal. Refining a Voronoi circle to 4096
// bits costs about a millisecond, a tenth of a degree-184 resultant, and
// nearly degenerate inputs that need more are rare.
constexpr long kDefaultCap = 4096;
// Largest cap a user may ask for (the CLI's --max-precision): Arb works at
// any precision, and 2^24 bits (16 Mbit numbers) still fit in memory.
constexpr long kMaxCap = 1L << 24;

// After the exact stage proved that two values differ, the Arb stage resumes
// above the cap until it separates them. Distinct algebraic numbers of the
// degrees involved separate long before this; reaching it is an internal
// error. It grows with the cap so that every cap the CLI accepts leaves room
// to resume.
constexpr long kResumeLimit = 1L << 17;
inline long resume_limit(long cap) { return std::max(kResumeLimit, 4 * cap); }

// The exact stage isolates a resultant root inside a certified enclosure by
// refining the enclosure; a simple root of a degree-184 polynomial with
// 10^4-bit coefficients is isolated at a few thousand bits.
constexpr long kExactIsolationLimit = 1L << 16;

// kappa1 compares two distances that are algebraic of degree 4; its exact
// stage is cheap (milliseconds), so its Arb stage hands over early.
constexpr long kSideOfBisectorCap = 512;

// A certified enclosure used to decide a sign at precision p is refined to
// p - kEnclosureGuard correct bits: the few bits lost by the arithmetic that
// follows (a distance, an angle) must not eat into what the comparison needs.
constexpr long kEnclosureGuard = 16;

// The Voronoi circle solver (subdivision/voronoi_circle_enclosure.cpp) keeps
// this many bits between its working precision and what it trusts: Y and the
// J(X) term of the Krawczyk operator are computed at half the precision plus
// these bits, Newton counts as stalled this far below the precision, and a
// refinement aims this far (twice) above the bits asked for. Rounding in the
// 6 x 6 system costs a few bits per operation chain; 32 leaves room for them.
constexpr long kSolverGuardBits = 32;

// The exhaustive search (subdivision/voronoi_circle_search.cpp) evaluates a
// box at kSearchGuardBits + magnitude bits + the box's resolution: rounding
// stays this far below the variation the box itself produces, so interval
// widths come from the box, not from rounding, and every split is meaningful.
constexpr long kSearchGuardBits = 24;

// Circles beyond 2^kHugeCircleBits times their sites' size get starts from a
// tangent line (subdivision/huge_circle_start.hpp) when the model circles'
// starts do not certify: below it, double guesses converge (a circle 2^10
// sizes away is conditioned like 2^20, well within doubles).
constexpr long kHugeCircleBits = 10;
// The double certificate (subdivision/voronoi_circle_in_doubles.hpp) offers
// them from 2^kHugeCircleBitsInDoubles sizes on: the circle models of sites in
// a row (along a packing's walls) may have no Apollonius circle at all, and
// their hull circles, 10 to 500 sizes away, then had no start in doubles and
// cost the Arb solver's guesses 10-30 ms each.
constexpr long kHugeCircleBitsInDoubles = 3;

// The tangent-line starts of huge circles separate the gap g of the third site
// from 0 at doubling precisions from kHugeCircleFirst to kHugeCircleLast: a g
// that no 4096-bit pass separates belongs to a circle beyond 2^1300 sizes, or
// to an exactly tangent line (no circle: the search proves that).
constexpr long kHugeCircleFirst = 128;
constexpr long kHugeCircleLast = 4096;

}  // namespace ellvor::precision
