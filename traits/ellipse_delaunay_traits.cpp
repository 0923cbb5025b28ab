#include "traits/ellipse_delaunay_traits.hpp"

#include "circles/circle_semi_static.hpp"
#include "predicates/edge_conflict.hpp"
#include "predicates/incircle.hpp"
#include "predicates/infinite_vertex_conflict.hpp"
#include "predicates/relative_position.hpp"
#include "predicates/side_of_bisector.hpp"
#include "sites/meeting_pair_candidates.hpp"
#include "traits/triple_key.hpp"
#include "util/error.hpp"

#include <algorithm>
#include <initializer_list>
#include <string>
#include <utility>

namespace ellvor {
namespace {

std::string ids(std::initializer_list<SiteId> list) {
    std::string s;
    for (SiteId i : list) s += (s.empty() ? "" : ", ") + std::to_string(i);
    return s;
}

// Counts the call, records the stage that decided and returns the answer
// (every predicate decides under the default options; an undecided one is an
// internal error that value() reports, naming the sites here).
template <class T>
T counted(TraitsStats& stats, Predicate predicate, const Decision<T>& d, std::initializer_list<SiteId> sites) {
    PredicateCount& count = stats[predicate];
    ++count.calls;
    count.stages.record(d.stage);
    if (!d.is_decided())
        throw Error(std::string("undecided predicate: ") + predicate_name(predicate) + " of sites (" + ids(sites) +
                    ") could not be certified (precision " + std::to_string(d.precision) + ", internal error)");
    return *d;
}

// The memo key of an unordered pair.
std::uint64_t unordered_pair_key(SiteId p, SiteId q) {
    return (static_cast<std::uint64_t>(std::min(p, q)) << 32) | static_cast<std::uint64_t>(std::max(p, q));
}

}  // namespace

EllipseDelaunayTraits::EllipseDelaunayTraits(std::vector<Ellipse> sites) : sites_(std::move(sites)) {
    // Copies of an ellipse share its exact parameters: the traits keep their
    // own, so that a graph's memory is all its own (and a compact circle
    // keeps none, whatever its caller asked of it).
    for (Ellipse& e : sites_) e.make_own();
}

Sign EllipseDelaunayTraits::compare_weight(SiteId a, SiteId b) const {
    // The areas a b: their double enclosures (the insertion order sorts by
    // them), then equal sizes (circles of one radius: common), exactly only
    // when the enclosures overlap.
    const Ellipse &ea = site(a), &eb = site(b);
    // Circles of doubles (a build's sort compares n log n pairs): the radius
    // is its double, up(lo) of its enclosure (circles/semi_static.hpp), and
    // a b = r^2 orders as r.
    if (ea.is_dyadic_circle() && eb.is_dyadic_circle()) {
        const double ra = Interval::up(ea.enclosure().a.lo), rb = Interval::up(eb.enclosure().a.lo);
        return ra > rb ? Sign::positive : ra < rb ? Sign::negative : Sign::zero;
    }
    // The enclosures first: they are in the site, its exact parameters one
    // pointer away.
    const Interval area_a = ea.enclosure().a * ea.enclosure().b, area_b = eb.enclosure().a * eb.enclosure().b;
    if (area_b.hi < area_a.lo) return Sign::positive;
    if (area_a.hi < area_b.lo) return Sign::negative;
    if (ea.a() == eb.a() && ea.b() == eb.b()) return Sign::zero;
    const Rational x = ea.a() * ea.b(), y = eb.a() * eb.b();
    return y < x ? Sign::positive : x < y ? Sign::negative : Sign::zero;
}

std::optional<DelaunayTraits::WeightBounds> EllipseDelaunayTraits::weight_bounds(SiteId i) const {
    const Ellipse::Enclosure e = site(i).enclosure();
    const Interval area = e.a * e.b;
    return WeightBounds{area.lo, area.hi};
}

LocationHint EllipseDelaunayTraits::location_hint(SiteId i) const {
    const Ellipse::Enclosure& e = site(i).enclosure();
    return {e.xc.mid(), e.yc.mid()};
}

void EllipseDelaunayTraits::check_sites() {
    if (sites_checked_) return;
    // Circles are valid in any position (two circles meet in two points at
    // most): only pairs with an ellipse are checked.
    sites_checked_ = std::all_of(sites_.begin(), sites_.end(), [](const Ellipse& e) { return e.is_circle(); });
    if (sites_checked_) return;
    for (const auto& [p, q] : pairs_that_may_meet(sites_))
        if (!site(p).is_circle() || !site(q).is_circle()) crosses(p, q);  // throws for a rejected pair
    sites_checked_ = true;
}

bool EllipseDelaunayTraits::is_hidden(SiteId p, SiteId q) {
    if (p == q) return true;
    // Most pairs are far apart, or (circles) q is the larger: decided at
    // once, cheaper than the memo.
    if (circle_not_inside_in_doubles(site(p), site(q)) || bounding_circles_apart_in_doubles(site(p), site(q))) {
        return counted(stats_, Predicate::is_hidden, Decision<bool>::decided(false, Stage::filter), {p, q});
    }
    const std::uint64_t key = (static_cast<std::uint64_t>(p) << 32) | static_cast<std::uint64_t>(q);
    auto found = hidden_memo_.find(key);
    if (found != hidden_memo_.end()) return found->second;
    const RelativePosition r = counted(stats_, Predicate::is_hidden, relative_position(site(p), site(q)), {p, q});
    if (r == RelativePosition::intersecting) {
        const std::string problem = crossing_pair_problem(site(p), site(q));
        if (!problem.empty()) throw IntersectingSites(std::min(p, q), std::max(p, q), problem);
    }
    bool q_in_p = false, p_in_q = false;
    switch (r) {
        case RelativePosition::second_inside:
        case RelativePosition::second_inside_tangent: q_in_p = true; break;
        case RelativePosition::first_inside:
        case RelativePosition::first_inside_tangent: p_in_q = true; break;
        case RelativePosition::identical: q_in_p = p_in_q = true; break;
        default: break;
    }
    hidden_memo_[key] = q_in_p;
    hidden_memo_[(static_cast<std::uint64_t>(q) << 32) | static_cast<std::uint64_t>(p)] = p_in_q;
    crossing_memo_[unordered_pair_key(p, q)] = r == RelativePosition::intersecting;
    return q_in_p;
}

bool EllipseDelaunayTraits::crosses(SiteId p, SiteId q) {
    if (p == q || bounding_circles_apart_in_doubles(site(p), site(q))) return false;
    auto found = crossing_memo_.find(unordered_pair_key(p, q));
    if (found != crossing_memo_.end()) return found->second;
    is_hidden(p, q);  // fills both memos
    return crossing_memo_.at(unordered_pair_key(p, q));
}

Sign EllipseDelaunayTraits::side_of_bisector(SiteId i, SiteId j, SiteId k) {
    return counted(stats_, Predicate::side_of_bisector, side_of_bisector_at_center(site(i), site(j), site(k)),
                   {i, j, k});
}

Sign EllipseDelaunayTraits::infinite_vertex_conflict(SiteId i, SiteId j, SiteId q) {
    const Sign s = counted(stats_, Predicate::infinite_vertex_conflict,
                           ellvor::infinite_vertex_conflict(site(i), site(j), site(q)), {i, j, q});
    if (s == Sign::zero) throw Error("internal error: infinite vertex conflict returned 0 for sites (" + ids({i, j, q}) + ")");
    return s;
}

Decision<InCircle> EllipseDelaunayTraits::incircle_of_face(SiteId i, SiteId j, SiteId k, SiteId q) {
    const Ellipse &ei = site(i), &ej = site(j), &ek = site(k), &eq = site(q);
    // Four circles of doubles: the semi-static sign, straight (a build's
    // usual call); then the closed forms, no solver to cache.
    if (ei.is_dyadic_circle() && ej.is_dyadic_circle() && ek.is_dyadic_circle() && eq.is_dyadic_circle()) {
        const Decision<InCircle> fast = circle_incircle_semi_static(ei, ej, ek, eq);
        if (fast.is_decided()) return fast;
    }
    if (ei.is_circle() && ej.is_circle() && ek.is_circle() && eq.is_circle()) return ellvor::incircle(ei, ej, ek, eq);
    // Before the cache: a question the bounding disks decide costs no
    // lookup and no entry (a random build's faces mostly; a tenth less time
    // at 10^5 sites and a sixth less memory than the entry's own bounds).
    const Decision<InCircle> by_disks = incircle_by_bounding_disks(ei, ej, ek, eq);
    if (by_disks.is_decided()) return by_disks;
    VoronoiCircleCache::Entry& entry = cache_.at(i, site(i), j, site(j), k, site(k));
    // The cached circle is that of the rotated triple: ask in that order.
    const TripleKey ids = triple_key(i, j, k);
    InCircleOptions options;
    options.use_bounding_disks = false;
    const Decision<InCircle> d =
        ellvor::incircle(site(ids[0]), site(ids[1]), site(ids[2]), site(q), options, &entry.circle);
    // Later calls on this face read the enclosures; the charts can go.
    entry.circle.release_charts();
    return d;
}

Sign EllipseDelaunayTraits::incircle(SiteId i, SiteId j, SiteId k, SiteId q) {
    return incircle_sign(counted(stats_, Predicate::incircle, incircle_of_face(i, j, k, q), {i, j, k, q}));
}

bool EllipseDelaunayTraits::finite_edge_interior_conflict(SiteId p1, SiteId p2, SiteId p3, SiteId p4, SiteId q, bool b) {
    return counted(stats_, Predicate::finite_edge_interior_conflict,
                   ellvor::finite_edge_interior_conflict(site(p1), site(p2), site(p3), site(p4), site(q), b), {p1, p2, p3, p4, q});
}

bool EllipseDelaunayTraits::finite_edge_interior_conflict(SiteId p1, SiteId p2, SiteId p3, SiteId q, bool b) {
    return counted(stats_, Predicate::finite_edge_interior_conflict,
                   ellvor::finite_edge_interior_conflict(site(p1), site(p2), site(p3), site(q), b), {p1, p2, p3, q});
}

bool EllipseDelaunayTraits::finite_edge_interior_conflict(SiteId p1, SiteId p2, SiteId q, bool b) {
    return counted(stats_, Predicate::finite_edge_interior_conflict,
                   ellvor::finite_edge_interior_conflict(site(p1), site(p2), site(q), b), {p1, p2, q});
}

bool EllipseDelaunayTraits::infinite_edge_interior_conflict(SiteId p2, SiteId p3, SiteId p4, SiteId q, bool b) {
    return counted(stats_, Predicate::infinite_edge_interior_conflict,
                   ellvor::infinite_edge_interior_conflict(site(p2), site(p3), site(p4), site(q), b), {p2, p3, p4, q});
}

bool EllipseDelaunayTraits::is_degenerate_edge(SiteId p1, SiteId p2, SiteId p3, SiteId p4) {
    // One circle touches p4; so unless p4 is tangent to VC(p1, p2, p3) they
    // differ: kappa3 on the face's cached circle proves most edges regular.
    const Decision<InCircle> touch = incircle_of_face(p1, p2, p3, p4);
    if (touch.is_decided() && *touch != InCircle::tangent)
        return counted(stats_, Predicate::is_degenerate_edge, touch.with(false), {p1, p2, p3, p4});
    return counted(stats_, Predicate::is_degenerate_edge,
                   ellvor::is_degenerate_edge(site(p1), site(p2), site(p3), site(p4)), {p1, p2, p3, p4});
}

}  // namespace ellvor
