// Gauss-Legendre rules on [-1, 1] with nodes and weights as double
// intervals, or as balls at a given precision, computed by Arb
// (arb_hypgeom_legendre_p_ui_root) on first use of each size (and precision)
// and kept by their owner.
#pragma once

#include "util/interval.hpp"

#include <map>
#include <utility>
#include <vector>

namespace ellvor {

struct GaussLegendreRule {
    std::vector<Interval> nodes, weights;
};

struct GaussLegendreBallRule {
    std::vector<Ball> nodes, weights;
};

class GaussLegendreRules {
public:
    // Enough for a tolerance of 10^-30 on pieces whose Bernstein ellipse is
    // certified (cells/edge_quadrature.cpp: rho = 5/2, error ~ 6^-n).
    static constexpr int kMaxPoints = 64;
    // The n-point rule, 1 <= n <= kMaxPoints.
    const GaussLegendreRule& rule(int n);
    const GaussLegendreBallRule& rule_in_arb(int n, long prec);

private:
    std::vector<GaussLegendreRule> rules_ = std::vector<GaussLegendreRule>(kMaxPoints + 1);
    std::map<std::pair<int, long>, GaussLegendreBallRule> ball_rules_;
};

}  // namespace ellvor
