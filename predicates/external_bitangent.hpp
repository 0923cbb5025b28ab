// The external bitangents of two separated ellipses, located exactly on the
// boundary of one of them (docs/DESIGN.md §2). Parameters live on the
// projective line: a real algebraic number of degree <= 4, or infinity (the
// i-point), and counter-clockwise order on the ellipse is increasing t
// followed by infinity.
#pragma once

#include "exact/algebraic_real.hpp"
#include "sites/ellipse.hpp"

#include <optional>

namespace ellvor {

// A boundary parameter: nullopt value = t at infinity (the i-point).
struct BoundaryParameter {
    std::optional<AlgebraicReal> value;
    bool at_infinity() const { return !value.has_value(); }
};

// Exact order of two parameters on the projective line cut at infinity
// (ascending t, then infinity): -1, 0, +1.
int compare(BoundaryParameter& a, BoundaryParameter& b);
// Whether x lies strictly inside (+1), at an end (0) or outside (-1) the
// counter-clockwise arc from `from` to `to` (a single point when from == to).
int position_in_arc(BoundaryParameter& from, BoundaryParameter& to, BoundaryParameter& x);

// Sign of p at a boundary parameter; p has formal degree `formal_degree`
// (its value at infinity is the sign of that coefficient, 0 if it vanishes).
int sign_at(const IntPolynomial& p, long formal_degree, BoundaryParameter& t);

// Enclosure of the boundary point at t.
BallPoint boundary_point(const Ellipse& e, BoundaryParameter& t, long prec);

// Going counter-clockwise around the convex hull of E and `other`, the hull
// arrives on E along one external bitangent and departs from E along the
// other. Returns the tangency parameter on E of that bitangent.
// Throws Error when one lies inside the other (no external bitangent);
// crossing sites have them (their crossing points mark the facing arc).
enum class HullSide { arrival, departure };
BoundaryParameter external_bitangent_on(const Ellipse& e, const Ellipse& other, HullSide side);

}  // namespace ellvor
