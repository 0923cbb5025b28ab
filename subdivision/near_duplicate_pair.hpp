// Two sites of a triple that nearly coincide: an ellipse and a copy moved by
// 10^-20 of its size (docs/DESIGN.md §4.2, item 3). Their tritangent system
// is nearly singular: with E' = E the circles tangent to E and a third site
// form a one-parameter family, and what picks the Voronoi circle out of it is
// the difference of E' from E, of relative size h. Written with
// t' = t + h tau (a linear change of unknowns, under which Newton's method is
// invariant), the system is regular as h -> 0 and its solution analytic in h.
// So the circle of the triple with E' replaced by E + mu (E' - E), for a
// moderate mu h (2^-moved_apart_bits below), predicts the blown-up unknowns of the
// real circle to O(mu h): a start that Newton converges from at a
// precision of about 2 log2(1/h) bits (the Krawczyk box must be narrower than
// h). The certificate (voronoi_circle_enclosure.hpp) alone decides.
#pragma once

#include "sites/ellipse.hpp"

#include <optional>

namespace ellvor {

struct NearDuplicatePair {
    int first = 0, second = 0;  // indices in the triple, first < second
    long bits = 0;              // log2(size / difference), rounded down: the pair's closeness
};

// The closest pair of the triple whose parameters differ by less than
// 2^-min_bits of the pair's smaller semi-axis (the rotation w counted times
// the larger semi-axis), if any; identical pairs are not near duplicates.
std::optional<NearDuplicatePair> closest_near_duplicate_pair(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3,
                                                             long min_bits);

// from + mu (to - from), parameter by parameter, exactly.
Ellipse ellipse_moved_apart(const Ellipse& from, const Ellipse& to, const Rational& mu);

// Near duplicates are pairs closer than 2^-kNearDuplicateBits of their size.
// Copies moved by 10^-10 are still certified from the floating-point guesses,
// but a pair differing by 2^-19 in one semi-axis (fuzz F5: an ellipse and a
// copy 10^-6 thinner, shifted by 6e-30) defeats them and the search alike;
// the start is tried only after the guesses and the tangent-line starts.
constexpr long kNearDuplicateBits = 16;
// The pair is moved apart to 2^-moved_apart_bits(bits) of its size for the
// start: 2^-kMovedBits, or 2^kMovedGapBits times its difference when that is
// farther (a pair at 2^-19 moved to 2^-9), so that the moved triple is far
// from degenerate while the start stays within Newton's reach.
constexpr long kMovedBits = 20;
constexpr long kMovedGapBits = 10;
constexpr long moved_apart_bits(long bits) {
    return bits - kMovedGapBits < kMovedBits ? bits - kMovedGapBits : kMovedBits;
}

}  // namespace ellvor
