#include "output/packing_fraction.hpp"

#include <algorithm>

namespace ellvor {

std::optional<Ball> packing_fraction(const Cell& cell) {
    if (!cell.visible) return std::nullopt;
    Ball ratio;
    if (!cell.bounded) return ratio;  // zero
    arb_div(ratio.get(), cell.site_area.get(), cell.area.get(), std::max(64L, cell.precision));
    return ratio;
}

}  // namespace ellvor
