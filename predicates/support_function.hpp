// The support function of an ellipse, h(n) = n.C + sqrt(a^2 (n.u)^2 + b^2 (n.v)^2)
// for a direction n (u, v: the ellipse's axes; n need not be a unit vector),
// in plain doubles and in outward-rounded intervals; and with it the external
// common tangents of two separated ellipses: the directions where their
// support functions agree. There are exactly two, and h1 - h2 changes sign at
// each, so a proven sign change over a tiny interval of directions isolates
// one of them. The filters ahead of the exact bitangent computations (kappa2,
// kappa4 on infinite edges) are built on it.
//
// A tangent line is identified by its outward normal n, and counter-clockwise
// order of normals is counter-clockwise order of the contact points on a
// site: comparing normals compares positions on the site's boundary.
#pragma once

#include "sites/ellipse.hpp"
#include "util/interval.hpp"

#include <optional>
#include <vector>

namespace ellvor {

// h(n) and the support point, enclosed, for an enclosed direction n.
struct SupportEnclosure {
    Interval value, x, y;
};
SupportEnclosure support_enclosure(const Ellipse::Enclosure& k, Interval nx, Interval ny);
// h(n) alone: the same interval as support_enclosure(k, nx, ny).value, at
// about half the cost (the filters compare values only).
Interval support_value(const Ellipse::Enclosure& k, Interval nx, Interval ny);

// The directions n = sign (1 - tau^2, 2 tau), tau in [tau_lo, tau_hi]: a chart
// of the half circle cos(phi) >= 0 (sign +1) or <= 0 (sign -1), phi =
// 2 atan(tau) (+ pi), increasing with tau. |tau| <= 1 up to rounding.
struct NormalInterval {
    double sign = 1, tau_lo = 0, tau_hi = 0;
    Interval tau() const { return Interval(tau_lo, tau_hi); }
    Interval nx() const { return (Interval(1.0) - tau().square()) * Interval(sign); }
    Interval ny() const { return Interval(2.0) * tau() * Interval(sign); }
};

// One of the two external common tangents of separated sites E1, E2, proven
// inside `normal`; `arrival` when the counter-clockwise hull of E1 and E2
// arrives on E1 along it (h1 - h2 rises through 0 there), else it departs.
struct BitangentNormal {
    NormalInterval normal;
    bool arrival = false;
};

// Both external common tangents of E1, E2 that could be proven (from the
// mean-radius circles' tangents in closed form, refined by Newton; else by
// sampling h1 - h2 around the circle). Possibly fewer than two: the exact
// stage decides then.
std::vector<BitangentNormal> certified_bitangent_normals(const Ellipse::Enclosure& k1, const Ellipse::Enclosure& k2);

// A box (nx, ny) holding the unit normal of the tangent where the hull of
// E1, E2 arrives on E1, without locating it: when the sites' circumscribed
// disks are proven apart (|C2 - C1| = d > R1 + R2, R = max(a, b)), that
// normal n has n.(C2 - C1) = rho1(n) - rho2(n) in [r1 - R2, R1 - r2] (rho the
// support function about the center, between r = min(a, b) and R), so
// n = s e + sqrt(1 - s^2) e' with e = (C2 - C1)/d, e' = e turned by +90
// degrees, s in [(r1 - R2)/d, (R1 - r2)/d]: h1 - h2 is negative at e and
// positive at -e, has exactly two zeros (the external tangents) and so
// rises through 0 once on the half circle through e', at the arrival one.
// Then contracted on request: s = (rho1(n) - rho2(n))/d with the rho_i
// enclosed over the box (its width times ~(R - r)/d each time). Wider than
// the tiny interval of certified_bitangent_normal, but ~20 interval
// operations (and ~40 a contraction) against its Newton search and sign
// checks.
class ArrivalNormalBox {
public:
    // nullopt when the disks are not proven apart. The box refers to k1 and
    // k2 (copying them was a tenth of its cost): they must outlive it.
    static std::optional<ArrivalNormalBox> of(const Ellipse::Enclosure& k1, const Ellipse::Enclosure& k2);
    // An enclosure of the unit normal (its vectors need not be unit).
    Interval nx() const { return nx_; }
    Interval ny() const { return ny_; }
    // One contraction step; false (the box unchanged) when the enclosures
    // contradict each other, which a sound enclosure never does.
    bool contract();

private:
    ArrivalNormalBox(const Ellipse::Enclosure& k1, const Ellipse::Enclosure& k2) : k1_(&k1), k2_(&k2) {}
    void set_box();
    const Ellipse::Enclosure *k1_, *k2_;
    Interval d_, ex_, ey_, s_, nx_, ny_;
};

// The tangent where the hull arrives on E1 (arrival) or departs from it, if proven.
std::optional<NormalInterval> certified_bitangent_normal(const Ellipse& e1, const Ellipse& e2, bool arrival);

// Counter-clockwise order of two normals on the circle cut at phi = -pi/2:
// -1, +1, or nullopt when the intervals overlap or both touch one seam of
// the charts.
std::optional<int> compare_normals(const NormalInterval& a, const NormalInterval& b);

// external_bitangent.hpp's position_in_arc for normals: +1 strictly inside the
// counter-clockwise arc from `from` to `to`, -1 outside; nullopt when an
// order is not proven (a coincidence among them is the exact stage's).
std::optional<int> normal_in_arc(const NormalInterval& from, const NormalInterval& to, const NormalInterval& x);

}  // namespace ellvor
