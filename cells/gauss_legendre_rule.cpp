#include "cells/gauss_legendre_rule.hpp"

#include "util/error.hpp"

#include <arb_hypgeom.h>

namespace ellvor {

namespace {

void require_size(int n) {
    if (n < 1 || n > GaussLegendreRules::kMaxPoints)
        throw Error("GaussLegendreRules: no rule of " + std::to_string(n) + " points");
}

}  // namespace

const GaussLegendreRule& GaussLegendreRules::rule(int n) {
    require_size(n);
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

const GaussLegendreBallRule& GaussLegendreRules::rule_in_arb(int n, long prec) {
    require_size(n);
    GaussLegendreBallRule& r = ball_rules_[{n, prec}];
    if (r.nodes.empty()) {
        r.nodes.resize(n);
        r.weights.resize(n);
        for (int k = 0; k < n; ++k)
            arb_hypgeom_legendre_p_ui_root(r.nodes[k].get(), r.weights[k].get(), n, k, prec);
    }
    return r;
}

}  // namespace ellvor
