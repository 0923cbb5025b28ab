#include "graph/site_grid.hpp"

#include "util/error.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace ellvor {

namespace {

// Cells along a side of length `cells` cells: ceil, at least 1, at most `limit`.
long cell_count(double cells, long limit) {
    if (!(cells >= 0)) return 1;
    if (cells >= static_cast<double>(limit - 1)) return limit;
    return static_cast<long>(cells) + 1;
}

}  // namespace

SiteGrid::SiteGrid(std::vector<LocationHint> points) : points_(std::move(points)), added_(points_.size(), false) {
    if (points_.size() >= 0xffffffffu) throw Error("SiteGrid: 2^32 - 1 points or more");
    cell_first_.assign(2, 0);
    if (points_.empty()) return;
    double xmin = HUGE_VAL, xmax = -HUGE_VAL, ymin = HUGE_VAL, ymax = -HUGE_VAL;
    for (const LocationHint& p : points_) {
        xmin = std::min(xmin, p.x), xmax = std::max(xmax, p.x);
        ymin = std::min(ymin, p.y), ymax = std::max(ymax, p.y);
    }
    const double width = std::max(xmax - xmin, 0.0), height = std::max(ymax - ymin, 0.0);
    const double n = static_cast<double>(points_.size());
    // About one site per cell; a box of zero height or width (collinear
    // centers) gets cells along its length.
    double cell = width * height > 0 ? std::sqrt(width * height / n) : std::max(width, height) / n;
    if (!(cell > 0) || !std::isfinite(cell)) cell = std::max({width, height, 1.0});
    // At most about 4 n cells, however thin the box.
    const long limit = 4 * static_cast<long>(points_.size());
    columns_ = cell_count(width / cell, limit);
    rows_ = cell_count(height / cell, limit / columns_ + 1);
    cell = std::max({cell, width / static_cast<double>(columns_), height / static_cast<double>(rows_)}) * (1 + 1e-9);
    for (LocationHint& p : points_) p = {(p.x - xmin) / cell, (p.y - ymin) / cell};
    // Counting sort of the sites by cell (by id within a cell).
    const std::size_t cells = static_cast<std::size_t>(columns_ * rows_);
    cell_first_.assign(cells + 1, 0);
    for (const LocationHint& p : points_) ++cell_first_[static_cast<std::size_t>(cell_of(p)) + 1];
    for (std::size_t c = 0; c < cells; ++c) cell_first_[c + 1] += cell_first_[c];
    cell_sites_.resize(points_.size());
    std::vector<std::uint32_t> next(cell_first_.begin(), cell_first_.end() - 1);
    for (std::size_t i = 0; i < points_.size(); ++i)
        cell_sites_[next[static_cast<std::size_t>(cell_of(points_[i]))]++] = static_cast<std::uint32_t>(i);
}

}  // namespace ellvor
