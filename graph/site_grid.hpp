// A uniform grid of the sites' location hints (a point per site, in doubles)
// that proposes a start for the nearest-neighbour walk: a site already in the
// graph whose hint is close to the new site's. Only the walk's length depends
// on it -- the walk itself is decided by kappa1 -- so rounding here is harmless.
//
// The cells hold every site from the start, in one array ordered by cell
// (counting sort; 8 bytes a site where a vector per cell cost about 60), and a
// bit per site says whether it was added: the grid lives through a whole
// build, so its bytes count in the build's peak memory. Points are kept in
// cell units from the box's corner: squared distances neither overflow nor
// need hypot, whatever the coordinates.
#pragma once

#include "decision/delaunay_traits.hpp"

#include <cmath>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace ellvor {

class SiteGrid {
public:
    // About one cell per site over the bounding box of all the points; site
    // i is at points[i]. Error for 2^32 - 1 points or more.
    explicit SiteGrid(std::vector<LocationHint> points);
    void add(SiteId s) {
        added_[s] = true;
        ++added_count_;
    }
    // A nearest point to s's among the added sites that `usable` accepts (the
    // smaller id at equal distances), or nullopt. The rings of cells around
    // s's are searched until no farther ring can hold an added point nearer
    // than the nearest added one, usable or not: with every added site
    // usable the answer is a nearest added point; a usable site beyond the
    // nearest unusable ones may be missed (only a walk's start).
    template <class Usable>
    std::optional<SiteId> nearest(SiteId s, Usable&& usable) const;

private:
    long cell_of(const LocationHint& p) const { return index_in(p.y, rows_) * columns_ + index_in(p.x, columns_); }
    // floor(v) clamped to [0, count - 1], without converting an out-of-range
    // double to long (undefined behaviour).
    static long index_in(double v, long count) {
        if (!(v >= 0)) return 0;
        if (v >= static_cast<double>(count - 1)) return count - 1;
        return static_cast<long>(v);
    }
    // Visits the sites of cell (r, c).
    template <class Visit>
    void for_each_in(long r, long c, Visit&& visit) const {
        const std::size_t cell = static_cast<std::size_t>(r * columns_ + c);
        for (std::uint32_t k = cell_first_[cell]; k < cell_first_[cell + 1]; ++k) visit(cell_sites_[k]);
    }

    std::vector<LocationHint> points_;  // in cell units from the box's lower left corner
    long columns_ = 1, rows_ = 1;
    std::vector<std::uint32_t> cell_first_;  // cell c holds cell_sites_[cell_first_[c], cell_first_[c + 1])
    std::vector<std::uint32_t> cell_sites_;  // every site, by cell, then by id
    std::vector<bool> added_;
    std::size_t added_count_ = 0;
};

template <class Usable>
std::optional<SiteId> SiteGrid::nearest(SiteId s, Usable&& usable) const {
    if (added_count_ == 0) return std::nullopt;
    const double x = points_[s].x, y = points_[s].y;
    const long home = cell_of(points_[s]), c0 = home % columns_, r0 = home / columns_;
    double best = HUGE_VAL;                          // squared, over every added site
    std::pair<double, SiteId> found{HUGE_VAL, 0};    // the nearest usable one
    bool any = false;
    auto visit = [&](std::uint32_t t) {
        if (!added_[t]) return;
        const double dx = points_[t].x - x, dy = points_[t].y - y, d = dx * dx + dy * dy;
        best = std::min(best, d);
        const std::pair<double, SiteId> candidate{d, t};
        if ((!any || candidate < found) && usable(SiteId{t})) found = candidate, any = true;
    };
    // A point in ring k is at least (k - 1) cells away from any point of the
    // home cell: once that exceeds the best distance found, no ring can beat
    // it. Only the ring's cells are visited (its two rows, then its two
    // columns without their ends), so a walk over k rings costs O(k^2).
    for (long ring = 0; ring <= std::max(columns_, rows_) && (ring < 1 || double(ring - 1) * double(ring - 1) <= best);
         ++ring) {
        const long c_lo = std::max(c0 - ring, 0L), c_hi = std::min(c0 + ring, columns_ - 1);
        for (const long r : {r0 - ring, r0 + ring}) {
            if (r >= 0 && r < rows_)
                for (long c = c_lo; c <= c_hi; ++c) for_each_in(r, c, visit);
            if (ring == 0) break;  // one row
        }
        const long r_lo = std::max(r0 - ring + 1, 0L), r_hi = std::min(r0 + ring - 1, rows_ - 1);
        for (const long c : {c0 - ring, c0 + ring})
            if (ring > 0 && c >= 0 && c < columns_)
                for (long r = r_lo; r <= r_hi; ++r) for_each_in(r, c, visit);
    }
    if (!any) return std::nullopt;
    return found.second;
}

}  // namespace ellvor
