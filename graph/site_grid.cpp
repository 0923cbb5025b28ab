#include "graph/site_grid.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace ellvor {

namespace {

// floor(v) clamped to [0, count - 1], without converting an out-of-range
// double to long (undefined behaviour).
long index_in(double v, long count) {
    if (!(v >= 0)) return 0;
    if (v >= static_cast<double>(count - 1)) return count - 1;
    return static_cast<long>(v);
}

// Cells along a side of length `cells` cells: ceil, at least 1, at most `limit`.
long cell_count(double cells, long limit) { return index_in(cells, limit) + 1; }

}  // namespace

SiteGrid::SiteGrid(const std::vector<LocationHint>& points) {
    for (const LocationHint& p : points) x_.push_back(p.x), y_.push_back(p.y);
    if (x_.empty()) return;
    const auto [xmin, xmax] = std::minmax_element(x_.begin(), x_.end());
    const auto [ymin, ymax] = std::minmax_element(y_.begin(), y_.end());
    x0_ = *xmin, y0_ = *ymin;
    const double width = std::max(*xmax - *xmin, 0.0), height = std::max(*ymax - *ymin, 0.0);
    const double n = static_cast<double>(x_.size());
    // About one site per cell; a box of zero height or width (collinear
    // centers) gets cells along its length.
    cell_ = width * height > 0 ? std::sqrt(width * height / n) : std::max(width, height) / n;
    if (!(cell_ > 0) || !std::isfinite(cell_)) cell_ = std::max({width, height, 1.0});
    // At most about 4 n cells, however thin the box.
    columns_ = cell_count(width / cell_, 4 * static_cast<long>(x_.size()));
    rows_ = cell_count(height / cell_, 4 * static_cast<long>(x_.size()) / columns_ + 1);
    cell_ = std::max({cell_, width / static_cast<double>(columns_), height / static_cast<double>(rows_)}) * (1 + 1e-9);
    cells_.resize(static_cast<std::size_t>(columns_ * rows_));
}

long SiteGrid::cell_of(double x, double y) const {
    return index_in((y - y0_) / cell_, rows_) * columns_ + index_in((x - x0_) / cell_, columns_);
}

void SiteGrid::add(SiteId s) {
    cells_[static_cast<std::size_t>(cell_of(x_[s], y_[s]))].push_back(s);
    ++added_;
}

std::vector<SiteId> SiteGrid::near(SiteId s) const {
    std::vector<SiteId> out;
    if (added_ == 0) return out;
    // Each distance once: the sort compares pairs, not recomputed distances.
    std::vector<std::pair<double, SiteId>> found;
    const long home = cell_of(x_[s], y_[s]), c0 = home % columns_, r0 = home / columns_;
    double best = HUGE_VAL;
    auto visit = [&](long r, long c) {
        for (SiteId t : cells_[static_cast<std::size_t>(r * columns_ + c)]) {
            found.push_back({std::hypot(x_[t] - x_[s], y_[t] - y_[s]), t});
            best = std::min(best, found.back().first);
        }
    };
    // A center in ring k is at least (k - 1) cells away from any point of the
    // home cell: once that exceeds the best distance found, no ring can beat
    // it. Only the ring's cells are visited (its two rows, then its two
    // columns without their ends), so a walk over k rings costs O(k^2).
    for (long ring = 0; ring <= std::max(columns_, rows_) && (ring - 1) * cell_ <= best; ++ring) {
        const long c_lo = std::max(c0 - ring, 0L), c_hi = std::min(c0 + ring, columns_ - 1);
        for (const long r : {r0 - ring, r0 + ring}) {
            if (r >= 0 && r < rows_)
                for (long c = c_lo; c <= c_hi; ++c) visit(r, c);
            if (ring == 0) break;  // one row
        }
        const long r_lo = std::max(r0 - ring + 1, 0L), r_hi = std::min(r0 + ring - 1, rows_ - 1);
        for (const long c : {c0 - ring, c0 + ring})
            if (ring > 0 && c >= 0 && c < columns_)
                for (long r = r_lo; r <= r_hi; ++r) visit(r, c);
    }
    std::sort(found.begin(), found.end());
    out.reserve(found.size());
    for (const auto& [distance, t] : found) out.push_back(t);
    return out;
}

}  // namespace ellvor
