#include "predicates/relative_position.hpp"

#include "exact/real_roots.hpp"
#include "predicates/distance_filter.hpp"
#include "sites/ellipse_polynomials.hpp"
#include "sites/meeting_pair_candidates.hpp"
#include "sites/separating_slab.hpp"
#include "util/error.hpp"
#include "util/interval.hpp"


#include <algorithm>
#include <cmath>

namespace ellvor {

const char* relative_position_name(RelativePosition p) {
    switch (p) {
        case RelativePosition::separated: return "separated";
        case RelativePosition::externally_tangent: return "externally-tangent";
        case RelativePosition::intersecting: return "intersecting";
        case RelativePosition::first_inside: return "first-inside";
        case RelativePosition::first_inside_tangent: return "first-inside-tangent";
        case RelativePosition::second_inside: return "second-inside";
        case RelativePosition::second_inside_tangent: return "second-inside-tangent";
        case RelativePosition::identical: return "identical";
    }
    return "?";
}

namespace {

// The intersection quartic of E1 against E2 has formal degree 4 in t; a lower
// actual degree means the i-point of E1 lies on E2, a root at t = infinity.
constexpr long kIntersectionFormalDegree = 4;

// Where P1(t) meets E2: real roots with odd multiplicity are crossings, roots
// with even multiplicity are touchings (the sign of E2's conic along E1
// changes exactly at the former).
struct ContactPoints {
    bool crossing = false;
    bool touching = false;
};

ContactPoints contact_points(const IntPolynomial& quartic) {
    ContactPoints c;
    const long at_infinity = kIntersectionFormalDegree - quartic.degree();
    if (at_infinity > 0) (at_infinity % 2 ? c.crossing : c.touching) = true;
    for (const auto& [factor, exponent] : squarefree_factors(quartic))
        if (factor.degree() >= 1 && !isolate_real_roots(factor).empty())
            (exponent % 2 ? c.crossing : c.touching) = true;
    return c;
}

// Sign of E2's conic at some boundary point of E1 where it does not vanish:
// -1 if that point is inside E2, +1 outside. The quartic has at most four
// real roots, so one of five rational parameters is not a root.
int side_of_boundary(const IntPolynomial& quartic) {
    for (long t = 0; t <= kIntersectionFormalDegree; ++t) {
        int s = quartic.sign_at(Rational(t));
        if (s != 0) return s;
    }
    return 0;  // unreachable for a nonzero quartic
}

// Exact filter: the circumscribed circles (radius max(a, b)) are apart.
bool bounding_circles_apart_exactly(const Ellipse& e1, const Ellipse& e2) {
    const Rational r = std::max(e1.a(), e1.b()) + std::max(e2.a(), e2.b());
    const Rational dx = e1.xc() - e2.xc(), dy = e1.yc() - e2.yc();
    return dx * dx + dy * dy > r * r;
}

// Filter: the sites' extents along the line of their centers are apart,
// in outward-rounded doubles. With n = C2 - C1, E1 lies in n.x <= n.C1 + h1
// and E2 in n.x >= n.C2 - h2, h_i = sqrt(a_i^2 (n.u_i)^2 + b_i^2 (n.v_i)^2)
// (the support function), and n.C2 - n.C1 = |n|^2. Sharper than the bounding
// circles (h_i <= max(a_i, b_i) |n|): it separates flat ellipses stacked
// along their minor axes, as in grids.
bool supports_apart_in_doubles(const Ellipse& e1, const Ellipse& e2) {
    const Ellipse::Enclosure &k1 = e1.enclosure(), &k2 = e2.enclosure();
    const Interval nx = k2.xc - k1.xc, ny = k2.yc - k1.yc;
    auto support = [&](const Ellipse::Enclosure& k) {
        const Interval nu = nx * k.cos + ny * k.sin, nv = ny * k.cos - nx * k.sin;
        return (k.a.square() * nu.square() + k.b.square() * nv.square()).sqrt();
    };
    const Interval gap = nx.square() + ny.square() - support(k1) - support(k2);
    return gap.finite() && gap.positive();
}

// Filter: a slab of positive width between the sites along a searched
// direction (sites/separating_slab.hpp), proven in outward-rounded doubles.
// Close sites that are not tangent -- dense packings -- have one although
// their extents along the line of the centers overlap (elongated sites side
// by side, offset); without it they went to the intersection quartic.
// Circles are left to the exact comparison of the radii, which is cheaper.
bool separated_by_searched_slab(const Ellipse& e1, const Ellipse& e2) {
    if (e1.is_circle() && e2.is_circle()) return false;
    return certified_separation(SlabSite::of(e1), SlabSite::of(e2), 0) > 0;
}

// Two circles, exactly: |C1 - C2|^2 against (r1 + r2)^2 and (r1 - r2)^2.
RelativePosition circle_position(const Ellipse& c1, const Ellipse& c2) {
    const Rational dx = c1.xc() - c2.xc(), dy = c1.yc() - c2.yc(), d2 = dx * dx + dy * dy;
    const Rational sum = c1.a() + c2.a(), difference = c1.a() - c2.a();
    const int outer = fmpq_cmp(d2.get(), (sum * sum).get()), inner = fmpq_cmp(d2.get(), (difference * difference).get());
    if (outer > 0) return RelativePosition::separated;
    if (outer == 0) return RelativePosition::externally_tangent;
    if (inner > 0) return RelativePosition::intersecting;
    if (difference.is_zero()) return RelativePosition::identical;  // d2 = 0 and equal radii
    const bool first_larger = difference.sign() > 0;
    if (inner == 0) return first_larger ? RelativePosition::second_inside_tangent : RelativePosition::first_inside_tangent;
    return first_larger ? RelativePosition::second_inside : RelativePosition::first_inside;
}

}  // namespace

bool bounding_circles_apart_in_doubles(const Ellipse& e1, const Ellipse& e2) {
    const Ellipse::Enclosure &k1 = e1.enclosure(), &k2 = e2.enclosure();
    const Interval dx = k1.xc - k2.xc, dy = k1.yc - k2.yc;
    const Interval r = Interval(std::fmax(k1.a.hi, k1.b.hi)) + Interval(std::fmax(k2.a.hi, k2.b.hi));
    const Interval gap = dx.square() + dy.square() - r.square();
    return gap.finite() && gap.positive();
}

bool circle_not_inside_in_doubles(const Ellipse& p, const Ellipse& q) {
    if (!p.is_circle() || !q.is_circle()) return false;
    const Ellipse::Enclosure &kp = p.enclosure(), &kq = q.enclosure();
    const Interval room = kp.a - kq.a, dx = kp.xc - kq.xc, dy = kp.yc - kq.yc;
    // A lower bound of |dx| (and of |dy|) is one of |C_p - C_q|.
    auto least = [](const Interval& d) { return d.lo > 0 ? d.lo : d.hi < 0 ? -d.hi : 0.0; };
    return std::fmax(least(dx), least(dy)) > room.hi;
}

bool centers_outside_each_other_in_doubles(const Ellipse& p, const Ellipse& q) {
    const Ellipse::Enclosure &kp = p.enclosure(), &kq = q.enclosure();
    return filtered_side(to_local(q, kp.xc, kp.yc)) > 0 && filtered_side(to_local(p, kq.xc, kq.yc)) > 0;
}

Decision<RelativePosition> relative_position(const Ellipse& e1, const Ellipse& e2) {
    auto exactly = [](RelativePosition p) { return Decision<RelativePosition>::decided(p, Stage::exact); };
    // The slab before the exact bounding circles: close ellipses (the pairs
    // that get this far) rarely have their bounding circles apart.
    if (bounding_circles_apart_in_doubles(e1, e2) || supports_apart_in_doubles(e1, e2) ||
        separated_by_searched_slab(e1, e2) || bounding_circles_apart_exactly(e1, e2))
        return Decision<RelativePosition>::decided(RelativePosition::separated, Stage::filter);
    if (e1.is_circle() && e2.is_circle()) return exactly(circle_position(e1, e2));
    const IntPolynomial i12 = intersection_quartic(e1, e2);
    if (i12.is_zero()) return exactly(RelativePosition::identical);
    const ContactPoints contact = contact_points(i12);
    if (contact.crossing) return exactly(RelativePosition::intersecting);
    // No crossing: E1 is inside E2 or not, judged away from the contacts.
    const bool tangent = contact.touching;
    if (side_of_boundary(i12) < 0)
        return exactly(tangent ? RelativePosition::first_inside_tangent : RelativePosition::first_inside);
    if (side_of_boundary(intersection_quartic(e2, e1)) < 0)
        return exactly(tangent ? RelativePosition::second_inside_tangent : RelativePosition::second_inside);
    return exactly(tangent ? RelativePosition::externally_tangent : RelativePosition::separated);
}

int boundary_meeting_points(const Ellipse& e1, const Ellipse& e2) {
    const IntPolynomial quartic = intersection_quartic(e1, e2);
    if (quartic.is_zero()) throw Error("boundary_meeting_points: the two sites are the same point set");
    int points = quartic.degree() < kIntersectionFormalDegree ? 1 : 0;
    for (const auto& [factor, exponent] : squarefree_factors(quartic))
        if (factor.degree() >= 1) points += static_cast<int>(isolate_real_roots(factor).size());
    return points;
}

std::string crossing_pair_problem(const Ellipse& e1, const Ellipse& e2) {
    if (e1.is_circle() && e2.is_circle()) return "";  // two circles meet in two points at most
    const int points = boundary_meeting_points(e1, e2);
    if (points > 2)
        return "their boundaries meet in " + std::to_string(points) + " points (sites may cross in at most two)";
    return "";
}

void require_acceptable_crossings(const std::vector<Ellipse>& sites) {
    for (const auto& [i, j] : pairs_that_may_meet(sites))
        if (*relative_position(sites[i], sites[j]) == RelativePosition::intersecting) {
            const std::string problem = crossing_pair_problem(sites[i], sites[j]);
            if (!problem.empty()) throw IntersectingSites(i, j, problem);
        }
}

bool is_hidden(const Ellipse& p, const Ellipse& q) {
    switch (*relative_position(p, q)) {
        case RelativePosition::second_inside:
        case RelativePosition::second_inside_tangent:
        case RelativePosition::identical: return true;
        default: return false;
    }
}

}  // namespace ellvor
