#include "predicates/ellipse_delaunay_traits.hpp"

#include "predicates/edge_conflict.hpp"
#include "predicates/incircle.hpp"
#include "predicates/infinite_vertex_conflict.hpp"
#include "predicates/relative_position.hpp"
#include "predicates/side_of_bisector.hpp"
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

// Records the stage that decided and returns the answer (every predicate
// decides under the default options; an undecided one is an internal error
// that value() reports, naming the sites here).
template <class T>
T counted(PredicateCount& count, const Decision<T>& d, const char* what, std::initializer_list<SiteId> sites) {
    count.stages.record(d.stage);
    if (!d.is_decided())
        throw Error(std::string("undecided predicate: ") + what + " of sites (" + ids(sites) +
                    ") could not be certified (precision " + std::to_string(d.precision) + ", internal error)");
    return *d;
}

// The memo key of an unordered pair.
std::uint64_t unordered_pair_key(SiteId p, SiteId q) {
    return (static_cast<std::uint64_t>(std::min(p, q)) << 32) | static_cast<std::uint64_t>(std::max(p, q));
}

}  // namespace

EllipseDelaunayTraits::EllipseDelaunayTraits(std::vector<Ellipse> sites) : sites_(std::move(sites)) {
    area_.reserve(sites_.size());
    for (const Ellipse& e : sites_) area_.push_back(e.a() * e.b());
}

Sign EllipseDelaunayTraits::compare_weight(SiteId a, SiteId b) const {
    const Rational &x = area_.at(a), &y = area_.at(b);
    return y < x ? Sign::positive : x < y ? Sign::negative : Sign::zero;
}

LocationHint EllipseDelaunayTraits::location_hint(SiteId i) const {
    const Ellipse::Enclosure& e = site(i).enclosure();
    return {e.xc.mid(), e.yc.mid()};
}

bool EllipseDelaunayTraits::is_hidden(SiteId p, SiteId q) {
    if (p == q) return true;
    // Most pairs are far apart: decided at once, cheaper than the memo.
    if (bounding_circles_apart_in_doubles(site(p), site(q))) {
        ++stats_.is_hidden.calls;
        stats_.is_hidden.stages.record(Stage::filter);
        return false;
    }
    const std::uint64_t key = (static_cast<std::uint64_t>(p) << 32) | static_cast<std::uint64_t>(q);
    auto found = hidden_memo_.find(key);
    if (found != hidden_memo_.end()) return found->second;
    ++stats_.is_hidden.calls;
    const RelativePosition r = counted(stats_.is_hidden, relative_position(site(p), site(q)), "relative position", {p, q});
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
    ++stats_.side_of_bisector.calls;
    return counted(stats_.side_of_bisector, side_of_bisector_at_center(site(i), site(j), site(k)),
                   "side of bisector", {i, j, k});
}

Sign EllipseDelaunayTraits::vertex_conflict(SiteId i, SiteId j, SiteId q) {
    ++stats_.vertex_conflict3.calls;
    const Sign s = counted(stats_.vertex_conflict3, infinite_vertex_conflict(site(i), site(j), site(q)),
                           "infinite vertex conflict", {i, j, q});
    if (s == Sign::zero) throw Error("internal error: infinite vertex conflict returned 0 for sites (" + ids({i, j, q}) + ")");
    return s;
}

Decision<InCircle> EllipseDelaunayTraits::incircle_of_face(SiteId i, SiteId j, SiteId k, SiteId q) {
    // Four circles take the closed form: no solver to cache.
    if (site(i).is_circle() && site(j).is_circle() && site(k).is_circle() && site(q).is_circle())
        return incircle(site(i), site(j), site(k), site(q));
    VoronoiCircleCache::Entry& entry = cache_.at(i, site(i), j, site(j), k, site(k));
    // The cached circle is that of the rotated triple entry.ids: ask in that order.
    const Decision<InCircle> d = incircle(site(entry.ids[0]), site(entry.ids[1]), site(entry.ids[2]), site(q), {},
                                          &entry.circle);
    // Later calls on this face read the enclosures; the charts can go.
    entry.circle.release_charts();
    return d;
}

Sign EllipseDelaunayTraits::vertex_conflict(SiteId i, SiteId j, SiteId k, SiteId q) {
    ++stats_.vertex_conflict4.calls;
    return incircle_sign(counted(stats_.vertex_conflict4, incircle_of_face(i, j, k, q), "incircle", {i, j, k, q}));
}

bool EllipseDelaunayTraits::finite_edge_interior(SiteId p1, SiteId p2, SiteId p3, SiteId p4, SiteId q, bool b) {
    ++stats_.finite_edge.calls;
    return counted(stats_.finite_edge, finite_edge_interior_conflict(site(p1), site(p2), site(p3), site(p4), site(q), b),
                   "finite edge interior conflict", {p1, p2, p3, p4, q});
}

bool EllipseDelaunayTraits::finite_edge_interior(SiteId p1, SiteId p2, SiteId p3, SiteId q, bool b) {
    ++stats_.finite_edge.calls;
    return counted(stats_.finite_edge, finite_edge_interior_conflict(site(p1), site(p2), site(p3), site(q), b),
                   "finite edge interior conflict", {p1, p2, p3, q});
}

bool EllipseDelaunayTraits::finite_edge_interior(SiteId p1, SiteId p2, SiteId q, bool b) {
    ++stats_.finite_edge.calls;
    return counted(stats_.finite_edge, finite_edge_interior_conflict(site(p1), site(p2), site(q), b),
                   "finite edge interior conflict", {p1, p2, q});
}

bool EllipseDelaunayTraits::infinite_edge_interior(SiteId p2, SiteId p3, SiteId p4, SiteId q, bool b) {
    ++stats_.infinite_edge.calls;
    return counted(stats_.infinite_edge, infinite_edge_interior_conflict(site(p2), site(p3), site(p4), site(q), b),
                   "infinite edge interior conflict", {p2, p3, p4, q});
}

bool EllipseDelaunayTraits::is_degenerate_edge(SiteId p1, SiteId p2, SiteId p3, SiteId p4) {
    ++stats_.degenerate_edge.calls;
    // One circle touches p4; so unless p4 is tangent to VC(p1, p2, p3) they
    // differ: kappa3 on the face's cached circle proves most edges regular.
    const Decision<InCircle> touch = incircle_of_face(p1, p2, p3, p4);
    if (touch.is_decided() && *touch != InCircle::tangent)
        return counted(stats_.degenerate_edge, touch.with(false), "degenerate edge", {p1, p2, p3, p4});
    return counted(stats_.degenerate_edge, voronoi_edge_is_degenerate(site(p1), site(p2), site(p3), site(p4)),
                   "degenerate edge", {p1, p2, p3, p4});
}

}  // namespace ellvor
