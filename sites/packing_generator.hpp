// Dense packings of ellipses (`ellvor generate packing`): N random ellipses in
// the square box [0, L]^2, L = ceil(sqrt(N)) (so a site's mean area is about
// the packing fraction F), at packing fraction pi * sum(a b) / L^2 >= F, every
// site inside the box and every pair at distance >= G (the gap).
//
// Method: random sequential addition (RSA) in decreasing order of size, up
// to a start fraction (0.55, or F when lower): site n gets the area A0 s_n^2
// with s_n = 1 / (1 + 5 n / (N - 1)) (sizes from 1 down to 1/6: a
// polydisperse set, as the small sites fill the holes between the large
// ones; equal sizes jam near 0.43 under growth), its aspect ratio and
// rotation drawn at random, its center drawn until it fits. Then growth: in
// passes over the sites in file order, each site is scaled about its center
// by the largest factor (at most 1 + 1/128 per pass, at most 3 in all) that
// keeps it G away from the others and inside the box, until the fraction
// reaches F; so pairs come within about G of each other as in a grown
// packing. A site that cannot grow stays as it is (its neighbours only grow);
// when no site can grow, the fraction is not reachable and an Error says the
// fraction reached (about 0.63 at aspect 1..4).
//
// Certified: a pair is accepted only with a separating slab of width >= G, a
// direction n with n.(c2 - c1) - h1(n) - h2(n) >= G |n| (h the support
// functions of the centered ellipses, sqrt(a^2 (n.u)^2 + b^2 (n.v)^2)),
// evaluated in outward-rounded double intervals on the exact parameters
// (sites/separating_slab.hpp, which also searches the direction). Every parameter is a dyadic rational that is an exact
// double: b = m / 2^24, a = k b / 2^12 (the aspect ratio k / 2^12 in
// [LO, HI] exactly), w = j / 2^20, the center on the grid 2^-40.
//
// Machine-independent: the draws are integers from std::mt19937_64 (as
// sites/site_generators.hpp), and every floating-point value that decides
// something (a direction searched for, an interval bound) comes from IEEE 754
// basic operations (+ - * / sqrt, round to nearest; the intervals step one ulp
// outward by bit patterns), which IEEE 754 defines bit for bit; no library
// function (sin, exp, ...) is used. So the same seed gives the same file on
// every IEEE machine (without x87 excess precision or fused multiply-adds,
// which the C++17 build on x86-64 does not use).
#pragma once

#include "sites/ellipse.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace ellvor {

// Fewer sites do not fit a box of side ceil(sqrt(N)) at these sizes.
constexpr long kMinPackingCount = 30;

struct PackingOptions {
    long count = 100;
    Rational fraction = Rational(1, 2);   // packing fraction F, in (0, kMaxPackingFraction]
    Rational gap = Rational(1, 1000);     // G in [0, 1/10]; 0: disjoint (a positive gap, however small)
    Rational aspect_lo = Rational(1);     // a/b in [aspect_lo, aspect_hi], 1 <= lo <= hi <= 16
    Rational aspect_hi = Rational(4);
    std::uint64_t seed = 1;
};

// Above this the method cannot go (and no random packing of ellipses is known
// to: the densest random packings of disks are near 0.84-0.86).
inline Rational max_packing_fraction() { return Rational(17, 20); }

struct Packing {
    std::vector<Ellipse> sites;
    long box_side = 0;            // L: the box is [0, L]^2
    Rational fraction_lower;      // certified bounds of the packing fraction reached (pi bracketed by rationals)
    Rational fraction_upper;
};

// Throws Error for bad options (a message saying which), and when the fraction
// cannot be reached (the message says the fraction reached, rounded down).
Packing generate_packing(const PackingOptions& options);

// The certified bounds of the fraction reached, as decimals rounded outward:
// "[0.58001234, 0.58001235]".
std::string fraction_bounds_text(const Packing& packing);

// The options as a command line, for file headers.
std::string describe(const PackingOptions& options);

// A certified sufficient test (the slab above, with a searched direction):
// true only if the two sites are at distance >= gap (> 0 when gap is 0).
bool packing_pair_certified(const Ellipse& e1, const Ellipse& e2, const Rational& gap);

}  // namespace ellvor
