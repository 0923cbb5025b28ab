// Gauss-Legendre rules on [-1, 1] with nodes and weights as double
// intervals, computed by Arb (arb_hypgeom_legendre_p_ui_root) on first use
// of each size and kept by their owner.
#pragma once

#include "util/interval.hpp"

#include <vector>

namespace ellvor {

struct GaussLegendreRule {
    std::vector<Interval> nodes, weights;
};

class GaussLegendreRules {
public:
    static constexpr int kMaxPoints = 48;
    // The n-point rule, 1 <= n <= kMaxPoints.
    const GaussLegendreRule& rule(int n);

private:
    std::vector<GaussLegendreRule> rules_ = std::vector<GaussLegendreRule>(kMaxPoints + 1);
};

}  // namespace ellvor
