#include "predicates/voronoi_circle_count.hpp"

#include "circles/circle_predicates.hpp"
#include "circles/circle_semi_static.hpp"
#include "predicates/covered_site.hpp"
#include "predicates/distance_filter.hpp"
#include "predicates/infinite_vertex_conflict.hpp"
#include "predicates/relative_position.hpp"
#include "subdivision/voronoi_circle_enclosure.hpp"
#include "exact/medial_axis_tangency.hpp"

#include <array>
#include <optional>
#include <tuple>
#include <vector>

namespace ellvor {

Decision<bool> none_inside_another(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3) {
    Decision<bool> separated = Decision<bool>::decided(true, Stage::filter);
    for (auto [p, q] : {std::pair{&e1, &e2}, {&e2, &e3}, {&e3, &e1}}) {
        // Apart, or each center outside the other site (close sites side by
        // side, as in dense packings): neither inside the other, without
        // relative_position's separating slab.
        if (bounding_circles_apart_in_doubles(*p, *q) || centers_outside_each_other_in_doubles(*p, *q)) continue;
        const Decision<RelativePosition> r = relative_position(*p, *q);
        separated.depends_on(r);
        if (*r != RelativePosition::separated && *r != RelativePosition::externally_tangent &&
            *r != RelativePosition::intersecting)
            return separated.with(false);
    }
    return separated;
}

namespace {

// A point of x certainly outside y and z: then y and z do not cover x.
// The points tried are x's center and eight points on or just inside its
// boundary (unit-disk points (c, s) with c^2 + s^2 <= 1 mapped by x's axes),
// in double intervals.
bool has_point_outside_both(const Ellipse& x, const Ellipse& y, const Ellipse& z) {
    const Ellipse::Enclosure& k = x.enclosure();
    constexpr double d = 0.7;  // 2 d^2 < 1
    constexpr double unit_disk[9][2] = {{0, 0}, {1, 0}, {-1, 0}, {0, 1}, {0, -1}, {d, d}, {d, -d}, {-d, d}, {-d, -d}};
    for (const auto& [c, s] : unit_disk) {
        const Interval along = c * k.a, across = s * k.b;
        const Interval px = k.xc + along * k.cos - across * k.sin, py = k.yc + along * k.sin + across * k.cos;
        if (filtered_side(to_local(y, px, py)) > 0 && filtered_side(to_local(z, px, py)) > 0) return true;
    }
    return false;
}

// The sites that may lie in the union of the other two with an empty cell,
// as (x, y, z) with x the site. Such a site crosses both (a site disjoint
// from it has no say on its points, one containing it would hide it alone)
// and lies in their union (each of its points is deeper in one of them than
// in x). Circles never qualify: a disk owns its center unless another disk
// contains it.
std::vector<std::array<const Ellipse*, 3>> sites_maybe_covered(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3) {
    std::vector<std::array<const Ellipse*, 3>> covered;
    if (e1.is_circle() && e2.is_circle() && e3.is_circle()) return covered;
    // Cheapest first: sites apart (the bounding circles), then a point
    // outside the other two (clears close sites side by side, dense
    // packings), then the relative positions, each pair's asked once.
    std::optional<bool> crossing[3];  // of (e1, e2), (e2, e3), (e3, e1)
    auto crosses = [&](int pair, const Ellipse& a, const Ellipse& b) {
        if (!crossing[pair]) crossing[pair] = *relative_position(a, b) == RelativePosition::intersecting;
        return *crossing[pair];
    };
    const bool near[3] = {!bounding_circles_apart_in_doubles(e1, e2), !bounding_circles_apart_in_doubles(e2, e3),
                          !bounding_circles_apart_in_doubles(e3, e1)};
    auto maybe_covered = [&](const Ellipse& x, const Ellipse& y, const Ellipse& z, int xy, int zx) {
        return near[xy] && near[zx] && !has_point_outside_both(x, y, z) && crosses(xy, x, y) && crosses(zx, z, x);
    };
    if (maybe_covered(e1, e2, e3, 0, 2)) covered.push_back({&e1, &e2, &e3});
    if (maybe_covered(e2, e3, e1, 1, 0)) covered.push_back({&e2, &e3, &e1});
    if (maybe_covered(e3, e1, e2, 2, 1)) covered.push_back({&e3, &e1, &e2});
    return covered;
}

}  // namespace

namespace {

// voronoi_circle_count; with `whether_both`, only whether the count is
// `both` (exactly two of the three kappa2 signs conflicts) is asked: two signs
// without a conflict settle that (at most one conflict), and nullopt says
// "not both" then, with the provenance in `early`.
std::optional<Decision<VoronoiCircles>> count_circles(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3,
                                                      bool whether_both, Decision<bool>* early) {
    // Three circles in doubles first: a count it proves also proves that no
    // site contains another.
    const Decision<VoronoiCircles> fast = circle_voronoi_circle_count_semi_static(e1, e2, e3);
    if (fast.is_decided()) return fast;
    // Sites apart with one orientation: their kappa2 signs agree, 0 or 3 conflicts.
    if (whether_both && bounding_disks_uniformly_oriented(e1, e2, e3)) {
        *early = Decision<bool>::decided(false, Stage::filter);
        return std::nullopt;
    }
    const Decision<bool> separated = none_inside_another(e1, e2, e3);
    if (!*separated) return separated.with(VoronoiCircles::none);
    if (e1.is_circle() && e2.is_circle() && e3.is_circle())
        return Decision<VoronoiCircles>::decided(circle_voronoi_circle_count(e1, e2, e3), Stage::exact);
    // How many of the three sites conflict with the infinite vertex of the
    // other two, taken in the cyclic order of the triple: for three points in
    // counter-clockwise order all three do.
    Decision<VoronoiCircles> count = separated.with(VoronoiCircles::none);
    int conflicts = 0, asked = 0;
    for (auto [p, q, r] : {std::tuple{&e1, &e2, &e3}, {&e2, &e3, &e1}, {&e3, &e1, &e2}}) {
        if (whether_both && asked == 2 && conflicts == 0) {
            *early = count.with(false);
            return std::nullopt;
        }
        const Decision<Sign> d = infinite_vertex_conflict(*p, *q, *r);
        count.depends_on(d);
        conflicts += *d == Sign::negative;
        ++asked;
    }
    constexpr VoronoiCircles by_conflicts[] = {VoronoiCircles::cw_only, VoronoiCircles::none, VoronoiCircles::both,
                                               VoronoiCircles::ccw_only};
    const auto covered = conflicts == 2 ? sites_maybe_covered(e1, e2, e3) : std::vector<std::array<const Ellipse*, 3>>{};
    if (!covered.empty()) {
        // Two conflicts also describe a triple where one site lies in the
        // union of the other two with an empty cell: no circle at all
        // (DESIGN.md §9). A proof that a site is covered so says "none";
        // else the complete solver tells the two apart.
        count.depends_on(Decision<bool>::decided(true, Stage::subdivision));
        for (const auto& [x, y, z] : covered)
            if (covered_without_circle(*x, *y, *z)) return count.with(VoronoiCircles::none);
        VoronoiCircleSolver solver(e1, e2, e3, common_medial_axis_tangency);
        return count.with(solver.certify() ? VoronoiCircles::both : VoronoiCircles::none);
    }
    return count.with(by_conflicts[conflicts]);
}

}  // namespace

Decision<VoronoiCircles> voronoi_circle_count(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3) {
    return *count_circles(e1, e2, e3, false, nullptr);
}

Decision<bool> has_both_voronoi_circles(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3) {
    Decision<bool> early = Decision<bool>::decided(false, Stage::filter);
    const std::optional<Decision<VoronoiCircles>> count = count_circles(e1, e2, e3, true, &early);
    if (!count) return early;
    return count->with(**count == VoronoiCircles::both);
}

}  // namespace ellvor
