// The exact stage for comparisons of Voronoi vertices (docs/DESIGN.md §4.5; the paper, section 3.1,
// Lemma 3.1): when two certified Voronoi circles share a site E and their
// enclosures cannot be separated, decide exactly whether they touch E at the
// same point. Each contact parameter on E is a root of the InCircle resultant
// of its triple (degree 184 for three ellipses); the enclosure isolates that
// root, and the two are equal iff the gcd of the two resultants has a root in
// both enclosures.
//
// Contacts at or near E's i-point (t = infinity) are handled by computing the
// resultants for E's quarter-turned twin (b, a, w'') -- the same point set,
// parametrized from a point a quarter turn away -- in which the contact has a
// finite parameter.
//
// Before the resultants, a cheaper certificate: when a short rational point in
// the enclosures is proven the center of both circles (rational_voronoi_center.hpp),
// they are one circle, so they touch E at the same point. Symmetric inputs
// (grids) are decided so; when it fails the resultants decide.
#pragma once

#include "sites/ellipse.hpp"
#include "subdivision/voronoi_circle_enclosure.hpp"

#include <array>
#include <optional>

namespace ellvor {

// A certified Voronoi circle of an ordered triple, and where the shared site
// is in that triple.
struct CertifiedVoronoiCircle {
    std::array<const Ellipse*, 3> triple;
    VoronoiCircleSolver* solver;  // certified
    int index;                    // the shared site is triple[index]
};

class ContactComparison {
public:
    // use_rational_center = false skips the rational-center certificate (tests
    // reach the resultants with it).
    ContactComparison(const CertifiedVoronoiCircle& a, const CertifiedVoronoiCircle& b, bool use_rational_center = true)
        : a_(a), b_(b), try_rational_center_(use_rational_center) {}
    // Whether the two circles touch the shared site at the same point, proven
    // exactly. Refines both solvers, doubling the precision, until the
    // enclosures are apart, or the rational center (tried once, when they
    // first overlap) proves one circle, or each enclosure isolates a single
    // root of its resultant (the resultants are computed on first need and
    // kept). Throws Error past
    // max(precision::kExactIsolationLimit, 4 reached_precision) bits, where
    // reached_precision is what the subdivision stage already spent: simple
    // roots are isolated long before (an internal error).
    bool same_contact_point(long reached_precision);

    // How the last same_contact_point proved its answer.
    enum class Proof { none, enclosures, rational_center, resultants };  // enclosures: disjoint balls
    Proof proof() const { return proof_; }

private:
    // The same at the solvers' current precision; nullopt when an enclosure
    // does not yet isolate a single root.
    std::optional<bool> same_contact_point_at_current_precision();
    // The rational-center certificate: true when proven one circle.
    bool common_rational_center() const;
    enum class Chart { t, twin_minus, twin_plus };  // parameter of E, or of its twin turned by -+ pi/2
    Ball contact(const CertifiedVoronoiCircle& c) const;
    IntPolynomial polynomial(const CertifiedVoronoiCircle& c) const;

    CertifiedVoronoiCircle a_, b_;
    std::optional<Chart> chart_;
    std::optional<IntPolynomial> pa_, pb_;
    bool try_rational_center_;  // until tried once
    Proof proof_ = Proof::none;
};

}  // namespace ellvor
