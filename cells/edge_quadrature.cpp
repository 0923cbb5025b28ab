#include "cells/edge_quadrature.hpp"

#include <array>
#include <cmath>
#include <vector>

namespace ellvor {
namespace {

constexpr int kMeasures = MeasureIntervals::count;
// The Bernstein parameter: larger needs fewer nodes but a wider box, on which
// the certificate fails sooner. With the second-order box enclosure 2 did
// best on random and packed cells (callgrind, 30 sites each: 2.25 and 2.5
// within 1.5%, 3 7% worse, 4 20%).
constexpr double kRho = 2;
// Halvings of the edge, and pieces tried in all, before the caller takes
// over. An edge that passes near a site's medial axis (a circle nearly inside
// the one it crosses: a hairpin about its centre) certifies only on pieces
// about as wide as that distance: some 9000 tries at 1/200 of the radius
// (test_cell_area.cpp). Arb's integrator needs pieces as small at ten times
// the cost a node, so the budget is generous.
constexpr int kMaxDepth = 40;
constexpr int kMaxPieces = 1 << 18;

// Upper bounds of |density j| over the complex box of the Bernstein ellipse
// of [a, b]; nothing when the certificate fails there.
std::optional<std::array<double, kMeasures>> bounds_on_ellipse(NormalRayInDoubles& bisector, const Interval& mid,
                                                               const Interval& half) {
    // Semi-axes h (rho + 1/rho) / 2 and h (rho - 1/rho) / 2, rounded up, plus
    // the uncertainty of the middle.
    const Interval rho(kRho), inverse = Interval(1.0) / rho;
    const double along = Interval::up(((rho + inverse) * half).hi * 0.5 + (mid.hi - mid.lo));
    const double across = Interval::up(((rho - inverse) * half).hi * 0.5);
    return bisector.bounds_on_box(mid.mid(), along, across);
}

// (64/15) rho^(2 - 2n) / (rho^2 - 1) for n = 0 .. kMaxPoints, rounded up.
std::array<double, GaussLegendreRules::kMaxPoints + 1> error_factors() {
    std::array<double, GaussLegendreRules::kMaxPoints + 1> factors;
    const Interval rho2 = Interval(kRho).square();
    Interval f = Interval(64.0) / Interval(15.0) * rho2 / (rho2 - Interval(1.0));
    for (double& x : factors) {
        x = f.hi;
        f = f / rho2;
    }
    return factors;
}

// The n-point rule's error bound on a piece of half-length h: h M factor[n].
double gauss_error(const Interval& half, double M, double factor) { return (half * Interval(M) * Interval(factor)).hi; }

}  // namespace

std::optional<MeasureIntervals> integrate_edge(NormalRayInDoubles& bisector, GaussLegendreRules& rules, double a,
                                               double b, const double (&tolerance)[kMeasures],
                                               QuadratureCounts* counts) {
    QuadratureCounts local;
    QuadratureCounts& count = counts ? *counts : local;
    MeasureIntervals total;
    for (Interval& x : total.m) x = Interval(0.0);
    struct Piece {
        double a, b;
        int depth;
    };
    // An edge between two equal vertices (four cocircular sites) adds nothing.
    if (!(a < b)) return a == b ? std::optional<MeasureIntervals>(total) : std::nullopt;
    std::vector<Piece> pieces{{a, b, 0}};
    const double length = b - a;
    const std::array<double, GaussLegendreRules::kMaxPoints + 1> factor = error_factors();
    // The certificate holds on pieces of about the same width along an edge:
    // a piece over twice as wide as the last certified one is halved untried.
    double certified_width = INFINITY;
    int done = 0;
    while (!pieces.empty()) {
        const Piece piece = pieces.back();
        pieces.pop_back();
        const auto halve = [&pieces, &piece] {
            if (piece.depth >= kMaxDepth) return false;
            const double m = 0.5 * (piece.a + piece.b);
            pieces.push_back({m, piece.b, piece.depth + 1});
            pieces.push_back({piece.a, m, piece.depth + 1});
            return true;
        };
        if (++done > kMaxPieces) return std::nullopt;
        if (piece.b - piece.a > 2 * certified_width && halve()) continue;
        const Interval A(piece.a), B(piece.b);
        const Interval half = (B - A) * Interval(0.5), mid = (A + B) * Interval(0.5);
        const std::optional<std::array<double, kMeasures>> M = bounds_on_ellipse(bisector, mid, half);
        if (!M) {
            ++count.failed_boxes;
            if (!halve()) return std::nullopt;
            continue;
        }
        certified_width = piece.b - piece.a;
        // The least n that meets every measure's share of its tolerance.
        const double share = (piece.b - piece.a) / length;
        int n = 1;
        for (int j = 0; j < kMeasures; ++j)
            while (n <= GaussLegendreRules::kMaxPoints &&
                   !(gauss_error(half, (*M)[j], factor[n]) <= tolerance[j] * share))
                ++n;
        if (n > GaussLegendreRules::kMaxPoints) {
            if (!halve()) return std::nullopt;
            continue;
        }
        const GaussLegendreRule& rule = rules.rule(n);
        MeasureIntervals sum;
        for (Interval& x : sum.m) x = Interval(0.0);
        bool certified = true;
        count.nodes += n;
        for (int k = 0; k < n && certified; ++k) {
            const std::optional<MeasureIntervals> f = bisector.densities(mid + half * rule.nodes[k]);
            certified = f.has_value();
            for (int j = 0; j < kMeasures && certified; ++j) sum.m[j] = sum.m[j] + rule.weights[k] * f->m[j];
        }
        if (!certified) {
            if (!halve()) return std::nullopt;
            continue;
        }
        ++count.pieces;
        for (int j = 0; j < kMeasures; ++j) {
            const double error = gauss_error(half, (*M)[j], factor[n]);
            total.m[j] = total.m[j] + half * sum.m[j] + Interval(-error, error);
        }
    }
    return total;
}

}  // namespace ellvor
