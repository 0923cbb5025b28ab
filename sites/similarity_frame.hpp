// Exact similarities x -> (x - origin) / 2^exponent: a translation by a
// dyadic point and a scaling by a power of two. Every predicate is invariant
// under them (its signs and orders, and the boundary parameters t, which a
// similarity does not change), so the numerical stages may work in a frame
// where the sites have size about 1 and lie near the origin: their precision
// then depends on the configuration, not on where it lies or how large it is
// (a triple 10^30 away from the origin, or scaled by 10^-100, is the same
// problem as the original).
#pragma once

#include "sites/ellipse.hpp"

#include <initializer_list>

namespace ellvor {

class SimilarityFrame {
public:
    // The identity.
    SimilarityFrame() = default;

    // A frame for a group of sites: the identity when they are already near
    // the unit frame (largest semi-axis within 2^+-kNearUnitBits of 1, centers
    // within 2^kNearUnitBits of it from the origin); otherwise the unit is the
    // power of two nearest the largest semi-axis and the origin a dyadic point
    // within 2^-kOriginBits units of the first site's center.
    static SimilarityFrame for_sites(std::initializer_list<const Ellipse*> sites);

    bool is_identity() const { return identity_; }
    long exponent() const { return exponent_; }
    const Point& origin() const { return origin_; }

    // Images, exactly.
    Ellipse apply(const Ellipse& e) const;
    Point apply(const Point& p) const;
    // Back to the original frame: a length times 2^exponent, a coordinate
    // plus the origin's; at precision prec plus the bits by which the
    // origin exceeds the unit, so that nothing of the frame's accuracy is lost.
    Ball length_to_original(const Ball& length, long prec) const;
    Ball x_to_original(const Ball& x, long prec) const;
    Ball y_to_original(const Ball& y, long prec) const;

    // Bits by which the sites' magnitude may exceed their size before a frame
    // pays (a few extra limbs of precision are cheaper than exact arithmetic
    // on transformed sites), and how close to the first center the origin is.
    static constexpr long kNearUnitBits = 20;
    static constexpr long kOriginBits = 30;

private:
    Ball coordinate_to_original(const Ball& c, const Rational& origin, long prec) const;

    bool identity_ = true;
    long exponent_ = 0;
    Point origin_{Rational(0), Rational(0)};
    long origin_bits_ = 0;  // bits of |origin| above the unit
};

}  // namespace ellvor
