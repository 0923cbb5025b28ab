// A cell's measures from its edges' Green integrals (cells/edge_integrals.hpp)
// on random polygons: each side a straight edge, integrated exactly about an
// origin of its own, forward or (as a neighbour's edge) backward; the sums
// about a random point against the polygon's closed forms (shoelace sums).
#include "cells/edge_integrals.hpp"
#include "util/interval.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

using namespace ellvor;

namespace {

constexpr long kPrec = 128;

// A double as an exact ball.
Ball ball(double x) { return ball_of(Interval(x), kPrec); }

// The measures of EdgeMeasure over the segment from a to b about `origin`:
// polynomials of degree <= 4 in the segment's parameter, which 3-point
// Gauss-Legendre integrates exactly (nodes 1/2 +- sqrt(3/5)/2, weights 5/18,
// 8/18, 5/18 on [0, 1]).
EdgeIntegrals segment(const double (&a)[2], const double (&b)[2], const double (&origin)[2]) {
    EdgeIntegrals e;
    e.origin[0] = origin[0], e.origin[1] = origin[1];
    e.start = {ball(a[0]), ball(a[1])};
    e.end = {ball(b[0]), ball(b[1])};
    Ball root, nodes[3], weights[3];
    arb_set_ui(root.get(), 15);
    arb_sqrt(root.get(), root.get(), kPrec);
    arb_div_ui(root.get(), root.get(), 10, kPrec);  // sqrt(3/5) / 2
    arb_set_d(nodes[1].get(), 0.5);
    arb_sub(nodes[0].get(), nodes[1].get(), root.get(), kPrec);
    arb_add(nodes[2].get(), nodes[1].get(), root.get(), kPrec);
    for (int i = 0; i < 3; ++i) {
        arb_set_ui(weights[i].get(), i == 1 ? 8 : 5);
        arb_div_ui(weights[i].get(), weights[i].get(), 18, kPrec);
    }
    const Ball dx = ball(b[0] - a[0]), dy = ball(b[1] - a[1]);  // exact for these small dyadic points
    for (int i = 0; i < 3; ++i) {
        Ball X, Y, t;
        arb_mul(X.get(), nodes[i].get(), dx.get(), kPrec);
        arb_add(X.get(), X.get(), ball(a[0] - origin[0]).get(), kPrec);
        arb_mul(Y.get(), nodes[i].get(), dy.get(), kPrec);
        arb_add(Y.get(), Y.get(), ball(a[1] - origin[1]).get(), kPrec);
        const auto add = [&](int j, std::initializer_list<const Ball*> factors) {
            Ball v;
            arb_set(v.get(), weights[i].get());
            for (const Ball* f : factors) arb_mul(v.get(), v.get(), f->get(), kPrec);
            arb_add(e.m[j].get(), e.m[j].get(), v.get(), kPrec);
        };
        using M = EdgeMeasure;
        add(M::x_dy, {&X, &dy});
        add(M::y_dx, {&Y, &dx});
        add(M::x2_dy, {&X, &X, &dy});
        add(M::y2_dx, {&Y, &Y, &dx});
        add(M::xy_dy, {&X, &Y, &dy});
        add(M::x3_dy, {&X, &X, &X, &dy});
        add(M::y3_dx, {&Y, &Y, &Y, &dx});
        add(M::x2y_dy, {&X, &X, &Y, &dy});
        arb_hypot(t.get(), dx.get(), dy.get(), kPrec);
        add(M::length, {&t});
    }
    return e;
}

// A random dyadic value in [lo, hi) with 10 fractional bits.
double dyadic(std::mt19937_64& rng, double lo, double hi) {
    return std::ldexp(std::floor(std::ldexp(std::uniform_real_distribution<double>(lo, hi)(rng), 10)), -10);
}

}  // namespace

TEST_CASE("add_edge: a polygon's area and moments from its sides, forward and backward, about any point",
          "[cells][edge_integrals]") {
    std::mt19937_64 rng(2026);
    for (int trial = 0; trial < 200; ++trial) {
        // A polygon: sorted angles about a random centre.
        const int n = 3 + trial % 6;
        std::vector<double> angles(n);
        for (double& t : angles) t = std::uniform_real_distribution<double>(0, 6.283185307179586)(rng);
        std::sort(angles.begin(), angles.end());
        const double cx = dyadic(rng, -50, 50), cy = dyadic(rng, -50, 50);
        std::vector<std::array<double, 2>> corners;
        for (double t : angles) {
            const double r = dyadic(rng, 1, 8);
            corners.push_back({dyadic(rng, cx + r * std::cos(t), cx + r * std::cos(t) + 0.01),
                               dyadic(rng, cy + r * std::sin(t), cy + r * std::sin(t) + 0.01)});
        }
        // The moments' point c: near the polygon, not at its centre.
        const BallPoint c{ball(dyadic(rng, cx - 5, cx + 5)), ball(dyadic(rng, cy - 5, cy + 5))};
        CellIntegrals sums;
        Ball area, first[2], second[3], perimeter;
        for (int i = 0; i < n; ++i) {
            const double a[2] = {corners[i][0], corners[i][1]};
            const double b[2] = {corners[(i + 1) % n][0], corners[(i + 1) % n][1]};
            const double origin[2] = {dyadic(rng, cx - 10, cx + 10), dyadic(rng, cy - 10, cy + 10)};
            // Half the sides as a neighbour's edges: integrated from b to a.
            if (rng() % 2)
                add_edge(segment(a, b, origin), true, c, kPrec, sums);
            else
                add_edge(segment(b, a, origin), false, c, kPrec, sums);
            // The closed forms about c: with cross = x_i y_{i+1} - x_{i+1} y_i,
            // area sum cross / 2, x: (x_i + x_{i+1}) cross / 6, x^2: (x_i^2 +
            // x_i x_{i+1} + x_{i+1}^2) cross / 12, x y: (x_i y_{i+1} + 2 x_i
            // y_i + 2 x_{i+1} y_{i+1} + x_{i+1} y_i) cross / 24.
            Ball x0, y0, x1, y1, cross, t, u;
            arb_sub(x0.get(), ball(a[0]).get(), c.x.get(), kPrec);
            arb_sub(y0.get(), ball(a[1]).get(), c.y.get(), kPrec);
            arb_sub(x1.get(), ball(b[0]).get(), c.x.get(), kPrec);
            arb_sub(y1.get(), ball(b[1]).get(), c.y.get(), kPrec);
            arb_mul(cross.get(), x0.get(), y1.get(), kPrec);
            arb_submul(cross.get(), x1.get(), y0.get(), kPrec);
            arb_addmul(area.get(), cross.get(), ball(0.5).get(), kPrec);
            for (int k = 0; k < 2; ++k) {
                const Ball &p = k ? y0 : x0, &q = k ? y1 : x1;
                arb_add(t.get(), p.get(), q.get(), kPrec);
                arb_mul(t.get(), t.get(), cross.get(), kPrec);
                arb_div_ui(t.get(), t.get(), 6, kPrec);
                arb_add(first[k].get(), first[k].get(), t.get(), kPrec);
                arb_sqr(t.get(), p.get(), kPrec);
                arb_addmul(t.get(), p.get(), q.get(), kPrec);
                arb_addmul(t.get(), q.get(), q.get(), kPrec);
                arb_mul(t.get(), t.get(), cross.get(), kPrec);
                arb_div_ui(t.get(), t.get(), 12, kPrec);
                arb_add(second[2 * k].get(), second[2 * k].get(), t.get(), kPrec);
            }
            arb_mul(t.get(), x0.get(), y1.get(), kPrec);
            arb_addmul(t.get(), x1.get(), y0.get(), kPrec);
            arb_mul(u.get(), x0.get(), y0.get(), kPrec);
            arb_addmul(u.get(), x1.get(), y1.get(), kPrec);
            arb_mul_2exp_si(u.get(), u.get(), 1);
            arb_add(t.get(), t.get(), u.get(), kPrec);
            arb_mul(t.get(), t.get(), cross.get(), kPrec);
            arb_div_ui(t.get(), t.get(), 24, kPrec);
            arb_add(second[1].get(), second[1].get(), t.get(), kPrec);
            arb_sub(t.get(), x1.get(), x0.get(), kPrec);
            arb_sub(u.get(), y1.get(), y0.get(), kPrec);
            arb_hypot(t.get(), t.get(), u.get(), kPrec);
            arb_add(perimeter.get(), perimeter.get(), t.get(), kPrec);
        }
        INFO("trial " << trial << " area " << sums.area.str(30) << " shoelace " << area.str(30));
        // (Signed: a polygon whose angles span less than a half turn may run clockwise.)
        CHECK(arb_overlaps(sums.area.get(), area.get()));
        CHECK(arb_overlaps(sums.perimeter.get(), perimeter.get()));
        for (int k = 0; k < 2; ++k) CHECK(arb_overlaps(sums.first[k].get(), first[k].get()));
        for (int k = 0; k < 3; ++k) CHECK(arb_overlaps(sums.second[k].get(), second[k].get()));
        // Tight: the balls are proofs, not bounds at infinity.
        CHECK(arb_rel_accuracy_bits(sums.area.get()) > 90);
        CHECK(mag_cmp_2exp_si(arb_radref(sums.second[1].get()), -60) < 0);
    }
}
