// Two sites of a triple that nearly coincide: an ellipse and a copy moved by
// 10^-20 of its size (docs/DESIGN.md §4.2, item 3). Their tritangent system
// is nearly singular: with E' = E the circles tangent to E and a third site
// form a one-parameter family, and what picks the Voronoi circle out of it is
// the difference of E' from E, of relative size h. Written with
// t' = t + h tau (a linear change of unknowns, under which Newton's method is
// invariant), the system is regular as h -> 0 and its solution analytic in h.
// So the circle of the triple with E' replaced by E + mu (E' - E), for a
// moderate mu h (here 2^-kMovedBits), predicts the blown-up unknowns of the
// real circle to O(2^-kMovedBits): a start that Newton converges from at a
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

// The pair is moved apart to 2^-kMovedBits of its size for the start; near
// duplicates are pairs closer than 2^-kNearDuplicateBits (closer pairs defeat
// the floating-point guesses; 10^-10 is still certified from them).
constexpr long kMovedBits = 20;
constexpr long kNearDuplicateBits = 30;

}  // namespace ellvor
