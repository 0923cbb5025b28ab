#include "cells/gauss_legendre_rule.hpp"

#include "util/error.hpp"

#include <arb_hypgeom.h>

namespace ellvor {

const GaussLegendreRule& GaussLegendreRules::rule(int n) {
    if (n < 1 || n > kMaxPoints) throw Error("GaussLegendreRules: no rule of " + std::to_string(n) + " points");
    GaussLegendreRule& r = rules_[n];
    if (r.nodes.empty()) {
        Ball node, weight;
        for (int k = 0; k < n; ++k) {
            arb_hypgeom_legendre_p_ui_root(node.get(), weight.get(), n, k, 128);
            r.nodes.push_back(enclose(node));
            r.weights.push_back(enclose(weight));
        }
    }
    return r;
}

}  // namespace ellvor
