#include "sites/meeting_pair_candidates.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>

namespace ellvor {
namespace {

// The bounding box of a site's circumscribed disk, outward-rounded.
struct Box {
    double x0, y0, x1, y1;
    bool meets(const Box& o) const { return x0 <= o.x1 && o.x0 <= x1 && y0 <= o.y1 && o.y0 <= y1; }
};

Box disk_box(const Ellipse& e) {
    const Ellipse::Enclosure& k = e.enclosure();
    const Interval r(Interval::max(k.a.hi, k.b.hi));
    return {(Interval(k.xc.lo) - r).lo, (Interval(k.yc.lo) - r).lo, (Interval(k.xc.hi) + r).hi,
            (Interval(k.yc.hi) + r).hi};
}

// A grid level: cells of side 2^level. A site goes to the level whose side
// exceeds its box's width and height, in the cell of its box's lower-left
// corner. Two boxes that meet, the larger of level k, have corners less than
// 2^k apart, so at level k their cells are neighbours (scaling by 2^-k is
// exact; the clamp, never reached by the input limits, only merges cells).
struct Cell {
    int level;
    std::int64_t row, column;
    bool operator<(const Cell& o) const {
        return level != o.level ? level < o.level : row != o.row ? row < o.row : column < o.column;
    }
};

std::int64_t cell_coordinate(double x, int level) {
    const double c = std::floor(std::ldexp(x, -level)), limit = std::ldexp(1.0, 60);
    return static_cast<std::int64_t>(std::clamp(c, -limit, limit));
}

Cell cell_at(const Box& b, int level) { return {level, cell_coordinate(b.y0, level), cell_coordinate(b.x0, level)}; }

// The smallest level whose side exceeds the box's width and height.
int level_of(const Box& b) {
    const double size = std::max((Interval(b.x1) - Interval(b.x0)).hi, (Interval(b.y1) - Interval(b.y0)).hi);
    int exponent = 0;
    std::frexp(size, &exponent);  // size < 2^exponent
    return exponent;
}

}  // namespace

std::vector<std::pair<std::size_t, std::size_t>> pairs_that_may_meet(const std::vector<Ellipse>& sites) {
    const std::size_t n = sites.size();
    std::vector<Box> boxes;
    boxes.reserve(n);
    for (const Ellipse& e : sites) boxes.push_back(disk_box(e));
    std::vector<std::pair<std::size_t, std::size_t>> pairs;
    // Sites too large or far for doubles (beyond the input limits) meet every site.
    std::vector<std::size_t> unbounded;
    std::vector<std::pair<Cell, std::size_t>> entries;  // (cell, site), sorted
    std::vector<int> site_level(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
        const Box& b = boxes[i];
        if (!std::isfinite(b.x0) || !std::isfinite(b.y0) || !std::isfinite(b.x1) || !std::isfinite(b.y1)) {
            unbounded.push_back(i);
            continue;
        }
        site_level[i] = level_of(b);
        entries.push_back({cell_at(b, site_level[i]), i});
    }
    std::sort(entries.begin(), entries.end(),
              [](const auto& x, const auto& y) { return x.first < y.first || (!(y.first < x.first) && x.second < y.second); });
    std::vector<int> levels;
    for (const auto& entry : entries)
        if (levels.empty() || levels.back() != entry.first.level) levels.push_back(entry.first.level);

    for (const auto& [own, p] : entries) {
        const Box& b = boxes[p];
        for (auto level = std::lower_bound(levels.begin(), levels.end(), own.level); level != levels.end(); ++level) {
            const Cell c = cell_at(b, *level);
            for (std::int64_t row = c.row - 1; row <= c.row + 1; ++row) {
                auto it = std::lower_bound(entries.begin(), entries.end(), Cell{*level, row, c.column - 1},
                                           [](const auto& entry, const Cell& key) { return entry.first < key; });
                for (; it != entries.end() && !(Cell{*level, row, c.column + 1} < it->first); ++it) {
                    const std::size_t q = it->second;
                    // Sites of one level find each other: keep the pair once.
                    if (q == p || (*level == own.level && q < p) || !b.meets(boxes[q])) continue;
                    pairs.push_back({std::min(p, q), std::max(p, q)});
                }
            }
        }
    }
    for (std::size_t u : unbounded)
        for (std::size_t q = 0; q < n; ++q)
            if (q != u && !(std::binary_search(unbounded.begin(), unbounded.end(), q) && q < u))
                pairs.push_back({std::min(u, q), std::max(u, q)});
    std::sort(pairs.begin(), pairs.end(),
              [](const auto& x, const auto& y) { return x.second != y.second ? x.second < y.second : x.first < y.first; });
    return pairs;
}

}  // namespace ellvor
