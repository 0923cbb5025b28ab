// A needle of a triple: a site far longer than wide (semi-axes 10^8 : 1,
// fuzz F7, F8, F10; docs/DESIGN.md §4.2, item 4). Neither the floating-point
// guesses nor the search's boxes resolve where a circle touches it, while
// the circle itself is well conditioned; a chain of sites from a stout copy
// of the needle to the needle carries a circle the search finds cheaply to
// the needle's, each link a start that the certificate
// (voronoi_circle_enclosure.hpp) alone judges. Two chains:
//
//  * thicker: the minor semi-axis raised to major / 2^k. With eps = minor /
//    major and the contact's normal angle phi fixed, tan(theta) = eps
//    tan(phi) (theta the parameter's angle from the long axis): in phi the
//    system is regular as eps -> 0 (the circle through the tip with that
//    normal), and away from the tips it is regular in theta (the needle
//    tends to a segment). So the circle with the needle at eps' predicts the
//    needle's to O(eps') with the contact mapped to the same normal near a tip,
//    the same angle on a side (a circle past a needle's tip, F7, F8).
//  * shorter: the major semi-axis lowered to minor 2^k. Near the middle of a
//    long side the boundary tends to a line as the major axis M grows, and
//    the system is regular in the position along the axis, M cos(theta): the
//    contact mapped to the same position (other sites beside a needle 10^6
//    times longer than they are, F10).
#pragma once

#include "sites/ellipse.hpp"
#include "util/flint_types.hpp"

#include <optional>

namespace ellvor {

// log2(major / minor), rounded down.
long aspect_bits(const Ellipse& e);

// The site of the triple with the largest aspect, if it is at least
// 2^kNeedleBits (a needle).
std::optional<int> thinnest_needle(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3);

enum class NeedleChain { thicker, shorter };

// A link of the chain: e at aspect 2^bits, its minor semi-axis raised to
// major / 2^bits (thicker) or its major semi-axis lowered to minor 2^bits
// (shorter), exactly; e itself at its own aspect or beyond.
Ellipse needle_link(const Ellipse& e, NeedleChain chain, long bits);

// How a contact on a link is carried to the next one (`to`, which differs
// from `from` in one semi-axis): the point with the same angle, the same
// normal, or the same position along the major axis (on the same side).
enum class ContactMap { same_angle, same_normal, same_position };

// Updates the chart and chart parameter of the contact, at precision prec.
void carry_contact(const Ellipse& from, const Ellipse& to, ContactMap map, bool& flipped, Ball& parameter, long prec);

// The maps to try for a contact at that chart parameter on `from`, best
// first: for the thicker chain the same normal first within sqrt(minor /
// major) of a tip (in the angle from the long axis), else the same angle
// first; for the shorter chain the same position.
std::array<ContactMap, 2> contact_maps(const Ellipse& from, NeedleChain chain, bool flipped, const Ball& parameter,
                                       long prec);

// Needles are sites of aspect 2^kNeedleBits or more; a chain starts at aspect
// 2^kStoutNeedleBits (the search certifies such triples in a few hundred
// boxes) and multiplies the aspect's bits by 3/2 a link.
constexpr long kNeedleBits = 12;
constexpr long kStoutNeedleBits = 4;

}  // namespace ellvor
