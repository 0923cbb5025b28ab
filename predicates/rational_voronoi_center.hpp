// A certificate of a Voronoi circle with a rational center, for the exact
// stage (docs/DESIGN.md §4.5). Symmetric inputs -- a grid of equal ellipses,
// sites placed by reflections or rotations about a point -- put their
// degenerate Voronoi vertices at rational points (the fixed point of the
// symmetry). There the exact question "is this the circle?" needs no
// resultant: with v a rational point strictly outside E1, E2, E3,
//  - d(v, E1)^2 = d(v, E2)^2 = d(v, E3)^2, compared exactly as roots of the
//    squared-distance quartics (degree 4);
//  - the nearest points P1, P2, P3 of v (unique: v is outside the convex
//    sites) counter-clockwise around v,
// make the circle about v of radius d(v, E1) a Voronoi circle of the triple
// (its open disk misses every site and it touches each at P_i) with its
// tangency points counter-clockwise, i.e. *the* counter-clockwise Voronoi
// circle of (E1, E2, E3): a triple has at most one (§2, §4.1).
#pragma once

#include "sites/ellipse.hpp"

#include <array>
#include <memory>
#include <optional>
#include <vector>

namespace ellvor {

class RationalCenter {
public:
    explicit RationalCenter(Point v);
    ~RationalCenter();
    RationalCenter(const RationalCenter&) = delete;
    RationalCenter& operator=(const RationalCenter&) = delete;

    // True when v is proven to be the center of the counter-clockwise Voronoi
    // circle of the ordered triple; false when not proven (v is not the
    // center, or two tangency points coincide and their order is not told).
    // What it learns about a site (by address) serves the later triples.
    bool is_center_of(const std::array<const Ellipse*, 3>& triple);

private:
    class Site;
    Site& site(const Ellipse& e);

    Point v_;
    std::vector<std::unique_ptr<Site>> sites_;
};

// The rational with the smallest denominator in the ball (the first
// continued-fraction convergent inside it), when its numerator and
// denominator have at most max_bits bits; nullopt otherwise. A certified
// enclosure of an exact rational coordinate with a short representation
// yields that coordinate once the ball is narrow enough.
std::optional<Rational> simplest_rational_in(const Ball& ball, long max_bits);

}  // namespace ellvor
