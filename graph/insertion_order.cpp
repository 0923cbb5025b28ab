#include "graph/insertion_order.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

namespace ellvor {

namespace {
constexpr std::size_t kFirstRound = 1024;
constexpr int kHilbertOrder = 16;  // a 65536 x 65536 grid
}  // namespace

std::vector<std::size_t> bulk_insertion_rounds(std::size_t n) {
    std::vector<std::size_t> rounds;
    std::size_t done = 0, next = kFirstRound;
    while (done < n) {
        const std::size_t size = std::min(next, n - done);
        rounds.push_back(size);
        done += size;
        if (done > kFirstRound) next *= 2;  // 1024, 1024, 2048, 4096, ...
    }
    return rounds;
}

std::uint32_t hilbert_index(double x, double y, double x0, double y0, double side) {
    constexpr std::uint32_t cells = 1u << kHilbertOrder;
    auto cell = [&](double v, double origin) {
        const double scaled = side > 0 ? (v - origin) / side * cells : 0;
        if (!(scaled > 0)) return std::uint32_t{0};  // NaN too
        return scaled >= cells - 1 ? cells - 1 : static_cast<std::uint32_t>(scaled);
    };
    std::uint32_t cx = cell(x, x0), cy = cell(y, y0), index = 0;
    // Quadrant by quadrant from the largest: the quadrant's rank along the
    // curve, then the point mapped into the quadrant's own frame (rotated or
    // reflected so that the curve inside it runs the standard way).
    for (std::uint32_t s = cells / 2; s > 0; s /= 2) {
        const std::uint32_t rx = (cx & s) ? 1 : 0, ry = (cy & s) ? 1 : 0;
        index += s * s * ((3 * rx) ^ ry);
        if (ry == 0) {
            if (rx == 1) {
                cx = s - 1 - (cx & (s - 1));
                cy = s - 1 - (cy & (s - 1));
            }
            std::swap(cx, cy);
        }
        cx &= s - 1;
        cy &= s - 1;
    }
    return index;
}

namespace {

void sort_by_decreasing_weight(const DelaunayTraits& traits, std::vector<SiteId>& sites) {
    // The weights' bounds, read once a site: a comparison of two whose
    // bounds are apart reads two entries of this vector, where the traits
    // read two sites' data scattered in memory (at 10^6 ellipses, n log n
    // such reads were a few % of the build). The same answers: the bounds
    // are certified, and the traits decide every other pair.
    std::vector<DelaunayTraits::WeightBounds> bounds(traits.size());
    bool bounded = true;
    for (SiteId i : sites) {
        const std::optional<DelaunayTraits::WeightBounds> b = traits.weight_bounds(i);
        if (!b) {
            bounded = false;
            break;
        }
        bounds[i] = *b;
    }
    if (!bounded) {
        std::stable_sort(sites.begin(), sites.end(),
                         [&](SiteId x, SiteId y) { return traits.compare_weight(x, y) == Sign::positive; });
        return;
    }
    std::stable_sort(sites.begin(), sites.end(), [&](SiteId x, SiteId y) {
        if (bounds[y].hi < bounds[x].lo) return true;
        if (bounds[x].hi < bounds[y].lo) return false;
        return traits.compare_weight(x, y) == Sign::positive;
    });
}

}  // namespace

std::vector<SiteId> bulk_insertion_order(const DelaunayTraits& traits) {
    std::vector<SiteId> order(traits.size());
    std::iota(order.begin(), order.end(), 0);
    sort_by_decreasing_weight(traits, order);
    if (order.size() <= kFirstRound) return order;
    std::vector<LocationHint> hints(traits.size());
    double xmin = HUGE_VAL, xmax = -HUGE_VAL, ymin = HUGE_VAL, ymax = -HUGE_VAL;
    for (SiteId i = 0; i < traits.size(); ++i) {
        hints[i] = traits.location_hint(i);
        if (!std::isfinite(hints[i].x) || !std::isfinite(hints[i].y)) continue;
        xmin = std::min(xmin, hints[i].x), xmax = std::max(xmax, hints[i].x);
        ymin = std::min(ymin, hints[i].y), ymax = std::max(ymax, hints[i].y);
    }
    const double side = std::max(xmax - xmin, ymax - ymin);
    if (!(side > 0 && std::isfinite(side))) return order;  // one point, or no finite hint: the weight order
    std::vector<std::uint32_t> key(traits.size());
    for (SiteId i = 0; i < traits.size(); ++i) key[i] = hilbert_index(hints[i].x, hints[i].y, xmin, ymin, side);
    // The first round keeps the weight order: a graph that small is in cache
    // anyway, and its largest sites come first exactly.
    const std::vector<std::size_t> rounds = bulk_insertion_rounds(order.size());
    auto begin = order.begin() + rounds[0];
    for (std::size_t r = 1; r < rounds.size(); ++r) {
        std::stable_sort(begin, begin + rounds[r], [&](SiteId a, SiteId b) { return key[a] < key[b]; });
        begin += rounds[r];
    }
    return order;
}

}  // namespace ellvor
