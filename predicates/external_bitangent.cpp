#include "predicates/external_bitangent.hpp"

#include "sites/ellipse_polynomials.hpp"
#include "util/error.hpp"

#include <arb_fmpz_poly.h>

#include <algorithm>
#include <vector>

namespace ellvor {

namespace {
// The bitangent quartic and tangent-side quadratic have these formal degrees;
// a lower actual degree means a root at the i-point.
constexpr long kBitangentFormalDegree = 4;
constexpr long kTangentSideFormalDegree = 2;
constexpr long kIntersectionFormalDegree = 4;
}  // namespace

int sign_at(const IntPolynomial& p, long formal_degree, BoundaryParameter& t) {
    if (t.at_infinity()) return p.degree() == formal_degree ? p.coeff(formal_degree).sign() : 0;
    return ellvor::sign_at(p, *t.value);
}

int compare(BoundaryParameter& a, BoundaryParameter& b) {
    if (a.at_infinity() || b.at_infinity()) return a.at_infinity() - b.at_infinity();
    return ellvor::compare(*a.value, *b.value);
}

int position_in_arc(BoundaryParameter& from, BoundaryParameter& to, BoundaryParameter& x) {
    // from == to is an arc of length zero (a degenerate edge), not the circle.
    if (compare(from, to) == 0) return compare(x, from) == 0 ? 0 : -1;
    const int after_from = compare(x, from), before_to = compare(to, x);
    if (after_from == 0 || before_to == 0) return 0;
    const bool inside = compare(from, to) < 0 ? (after_from > 0 && before_to > 0)   // from < x < to
                                              : (after_from > 0 || before_to > 0);  // wraps through infinity
    return inside ? 1 : -1;
}

BallPoint boundary_point(const Ellipse& e, BoundaryParameter& t, long prec) {
    if (t.at_infinity()) {
        const Point ip = e.i_point();
        return {Ball(ip.x, prec), Ball(ip.y, prec)};
    }
    return e.point_at(t.value->to_ball(prec), prec);
}

BoundaryParameter external_bitangent_on(const Ellipse& e, const Ellipse& other, HullSide side) {
    // Each real root of the bitangent quartic is a common tangent line; it is
    // external when the other ellipse (so its center) is on E's side of it.
    const IntPolynomial quartic = bitangent_quartic(e, other);
    const IntPolynomial center_side = tangent_side_quadratic(e, other.center());
    struct Root {
        BoundaryParameter t;
        bool external;
    };
    std::vector<Root> roots;  // counter-clockwise: ascending, then infinity
    for (auto& r : real_roots(quartic)) {
        BoundaryParameter t{r};
        roots.push_back({t, sign_at(center_side, kTangentSideFormalDegree, t) < 0});
    }
    if (quartic.degree() < kBitangentFormalDegree) {
        BoundaryParameter t;
        roots.push_back({t, sign_at(center_side, kTangentSideFormalDegree, t) < 0});
    }
    // Counter-clockwise on E: [departure, internal..., arrival] with the
    // internal tangency points on the arc facing the other ellipse.
    int externals = 0;
    for (const auto& r : roots) externals += r.external;
    if (roots.size() == 2 && externals == 2) {
        // Crossing sites have no internal tangent; their crossing points lie
        // on the arc of E inside the other, which is part of the facing arc,
        // and mark it instead (DESIGN.md §9).
        const IntPolynomial crossings = intersection_quartic(e, other);
        for (auto& r : real_roots(crossings)) roots.push_back({BoundaryParameter{r}, false});
        if (crossings.degree() < kIntersectionFormalDegree) roots.push_back({BoundaryParameter{}, false});
        std::sort(roots.begin(), roots.end(), [](Root& a, Root& b) { return compare(a.t, b.t) < 0; });
    }
    const size_t n = roots.size();
    if (n < 3 || externals != 2)
        throw Error("external bitangent: one ellipse lies inside the other (" + std::to_string(n) +
                    " common tangents)");
    for (size_t i = 0; i < n; ++i) {
        const Root& neighbour = roots[side == HullSide::arrival ? (i + n - 1) % n : (i + 1) % n];
        if (roots[i].external && !neighbour.external) return roots[i].t;
    }
    throw Error("external bitangent: inconsistent tangent classification");
}

}  // namespace ellvor
