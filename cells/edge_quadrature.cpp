#include "cells/edge_quadrature.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace ellvor {
namespace {

constexpr int kMeasures = MeasureIntervals::count;
// The Bernstein parameter: larger needs fewer nodes but a wider disk, on
// which the certificate fails sooner. With the certificate on the disk that
// holds the ellipse and the Gauss error from the models' remainders, 2.5 did
// best on 150 random and 150 packed cells in a box (callgrind against 2.25:
// -1.4% and -1.0%; 2.75 -1.2% and -0.6%; 2 and 3 worse).
constexpr double kRho = 2.5;
// The narrowest piece (2^-kMaxDepth of the edge), and pieces tried in all,
// before the caller takes over. An edge that passes near a site's medial axis (a circle nearly inside
// the one it crosses: a hairpin about its centre) certifies only on pieces
// about as wide as that distance: some 1000 tries at 1/200 of the radius
// (test_cell_area.cpp). Arb's integrator needs pieces as small at ten times
// the cost a node, so the budget is generous.
constexpr int kMaxDepth = 40;
constexpr int kMaxPieces = 1 << 18;
// The width tried after a certified piece: scaled so that the Krawczyk
// test's contraction (DiskBounds::contraction, whose share above 1/2 grows
// about as the square of the width) would come to 3/4, by a factor between
// 0.7 and 1.5 (callgrind, 150 random and 150 packed cells in a box: 5% and
// 6% fewer instructions than a constant 1.2, which was 5-6% better than
// bisecting the edge; targets 0.7 and 0.8 did worse).
constexpr double kTargetContraction = 0.75, kMinGrowth = 0.7, kMaxGrowth = 1.5;
// n Gauss-Legendre points integrate polynomials of degree 2n - 1 exactly.
constexpr int kMinPoints = (NormalRayInDoubles::kDiskDegree + 2) / 2;
// A piece's disk radius over its width: the Bernstein ellipse's major semi-axis
// (rho + 1/rho) / 2 over 2.
constexpr double kDiskOverWidth = (kRho + 1 / kRho) / 4;
// The share of its middle's distance to the nearest pole angle
// (NormalRayInDoubles::pole_angles) that an edge's first piece's disk is given
// at most: the disk certificate holds to about a quarter of the distance to
// a pole (two circles 10 apart: 0.25-0.27), and the whole edge, tried first,
// failed 2.5 times an edge. 0.15, 0.18, 0.2, 0.25 measured (callgrind; 0.15
// before the residual's models of degree 4).
constexpr double kPoleShare = 0.2;

// The bounds of NormalRayInDoubles::bounds_on_disk over a disk holding the
// Bernstein ellipse of [a, b] (the center distances over [a, b]): about the
// middle, of radius its semi-major axis h (rho + 1/rho) / 2, rounded up, plus
// the uncertainty of the middle. Nothing when the certificate fails there.
std::optional<NormalRayInDoubles::DiskBounds> bounds_on_ellipse(NormalRayInDoubles& bisector, const Interval& mid,
                                                               const Interval& half) {
    const Interval rho(kRho), inverse = Interval(1.0) / rho;
    const double uncertainty = mid.hi - mid.lo;
    const double R = Interval::up(((rho + inverse) * half).hi * 0.5 + uncertainty);
    return bisector.bounds_on_disk(mid.mid(), R, Interval::up(half.hi + uncertainty));
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

// The certified pieces of the edge [a, b] (enclosures of its ends; the pieces
// split it at doubles between them): on each, the least rule size n that
// meets the piece's share of every tolerance by the bounds on the complex
// disk (in doubles), then integrate_piece(A, B, n, error), which sums the rule
// on [A, B] and returns false when a node cannot be certified. A piece whose
// disk or nodes fail is halved. False when that goes too narrow or too long.
// `reach` is raised to the pieces' bounds of |V - p's center| and |V - q's
// center| (over the pieces, which cover [a.lo, b.hi]).
template <class IntegratePiece>
bool integrate_pieces(NormalRayInDoubles& bisector, const Interval& a, const Interval& b,
                      const double (&tolerance)[kMeasures], QuadratureCounts& count, std::array<double, 2>& reach,
                      IntegratePiece&& integrate_piece) {
    const double first = a.mid(), last = b.mid();
    const auto end = [&](double x) { return x == first ? a : x == last ? b : Interval(x); };
    const double length = last - first, smallest = std::ldexp(length, -kMaxDepth);
    static const std::array<double, GaussLegendreRules::kMaxPoints + 1> factor = error_factors();
    // Along the edge from its first end, as a step control: a piece whose disk
    // or nodes fail is halved, the one after a certified piece is sized by
    // its contraction (the certificate holds on pieces of about the same
    // width). The first is as wide as the edge, or as its poles allow (but
    // at least a 64th of it: an edge may pass an angle that is no pole,
    // between close sites); capping every piece so made some edges crawl
    // (150 random cells: 29 times the instructions).
    const double first_width = std::max(bisector.pole_limited_width(first, kDiskOverWidth, kPoleShare), length / 64);
    double start = first, width = std::min(length, first_width);
    int done = 0;
    while (start < last) {
        if (++done > kMaxPieces) return false;
        // The rest of the edge when a step would leave less than a quarter of itself.
        const double stop = start + width < last - 0.25 * width ? start + width : last;
        const auto shrink = [&] {
            width = 0.5 * (stop - start);
            return width >= smallest;
        };
        const Interval A = end(start), B = end(stop);
        const Interval half = (B - A) * Interval(0.5), mid = (A + B) * Interval(0.5);
        const std::optional<NormalRayInDoubles::DiskBounds> bounds = bounds_on_ellipse(bisector, mid, half);
        if (!bounds) {
            ++count.failed_disks;
            if (!shrink()) return false;
            continue;
        }
        // M bounds |f - p| on the disk, p the density's polynomial of degree
        // kDiskDegree, or |f|: the rule of n >= kMinPoints points
        // integrates p exactly, so its error on f is its error on f - p.
        std::array<double, kMeasures> M;
        for (int j = 0; j < kMeasures; ++j) M[j] = std::min(bounds->density[j], bounds->beyond_polynomial[j]);
        // The least n that meets every measure's share of its tolerance.
        const double share = (stop - start) / length;
        int n = kMinPoints;
        for (int j = 0; j < kMeasures; ++j)
            while (n <= GaussLegendreRules::kMaxPoints &&
                   !(gauss_error(half, M[j], factor[n]) <= tolerance[j] * share))
                ++n;
        if (n > GaussLegendreRules::kMaxPoints) {
            if (!shrink()) return false;
            continue;
        }
        std::array<double, kMeasures> error;
        for (int j = 0; j < kMeasures; ++j) error[j] = gauss_error(half, M[j], factor[n]);
        count.nodes += n;
        if (!integrate_piece(A, B, n, error)) {
            if (!shrink()) return false;
            continue;
        }
        ++count.pieces;
        for (int i = 0; i < 2; ++i) reach[i] = std::max(reach[i], bounds->center_distance[i]);
        // The contraction's share (above 1/2) grows about as the square of
        // the width: aim at kTargetContraction.
        const double share_used = std::max(bounds->contraction - 0.5, 1e-3);
        width = std::clamp(std::sqrt((kTargetContraction - 0.5) / share_used), kMinGrowth, kMaxGrowth) * (stop - start);
        start = stop;
    }
    return true;
}

}  // namespace

std::optional<MeasureIntervals> integrate_edge(NormalRayInDoubles& bisector, GaussLegendreRules& rules, double a,
                                               double b, const double (&tolerance)[kMeasures],
                                               QuadratureCounts* counts, std::array<double, 2>* reach) {
    // Two ends in reverse order: the integral from b to a, negated (the ends
    // of an edge between two equal vertices, four cocircular sites, come from
    // two certified circles and may cross by a rounding).
    if (b < a) {
        if (counts) ++counts->reversed_edges;
        std::optional<MeasureIntervals> reversed = integrate_edge(bisector, rules, b, a, tolerance, counts, reach);
        if (reversed)
            for (Interval& x : reversed->m) x = -x;
        return reversed;
    }
    QuadratureCounts local;
    std::array<double, 2> local_reach = {0, 0};
    MeasureIntervals total;
    for (Interval& x : total.m) x = Interval(0.0);
    // An edge between two equal vertices (four cocircular sites) adds nothing.
    if (!(a < b)) return a == b ? std::optional<MeasureIntervals>(total) : std::nullopt;
    const auto integrate_piece = [&](const Interval& A, const Interval& B, int n,
                                     const std::array<double, kMeasures>& error) {
        const Interval half = (B - A) * Interval(0.5), mid = (A + B) * Interval(0.5);
        const GaussLegendreRule& rule = rules.rule(n);
        MeasureIntervals sum;
        for (Interval& x : sum.m) x = Interval(0.0);
        for (int k = 0; k < n; ++k) {
            const std::optional<MeasureIntervals> f = bisector.densities(mid + half * rule.nodes[k]);
            if (!f) return false;
            for (int j = 0; j < kMeasures; ++j) sum.m[j] = sum.m[j] + rule.weights[k] * f->m[j];
        }
        for (int j = 0; j < kMeasures; ++j) total.m[j] = total.m[j] + half * sum.m[j] + Interval(-error[j], error[j]);
        return true;
    };
    if (!integrate_pieces(bisector, Interval(a), Interval(b), tolerance, counts ? *counts : local,
                          reach ? *reach : local_reach, integrate_piece))
        return std::nullopt;
    return total;
}

std::optional<NormalRayBisector::Densities> integrate_edge_in_arb(NormalRayInDoubles& bounds,
                                                                  NormalRayBisector& bisector,
                                                                  GaussLegendreRules& rules, const Ball (&ends)[2],
                                                                  const double (&tolerance)[kMeasures], long prec,
                                                                  QuadratureCounts* counts, std::array<double, 2>* reach) {
    // Two ends in reverse order: the integral from the second to the first, negated.
    if (arb_gt(ends[0].get(), ends[1].get())) {
        if (counts) ++counts->reversed_edges;
        const Ball reversed_ends[2] = {ends[1], ends[0]};
        std::optional<NormalRayBisector::Densities> reversed =
            integrate_edge_in_arb(bounds, bisector, rules, reversed_ends, tolerance, prec, counts, reach);
        if (reversed)
            for (ComplexBall& x : reversed->m) acb_neg(x.get(), x.get());
        return reversed;
    }
    QuadratureCounts local;
    std::array<double, 2> local_reach = {0, 0};
    NormalRayBisector::Densities total;
    // An edge between two equal vertices (four cocircular sites) adds nothing.
    if (arb_equal(ends[0].get(), ends[1].get())) return total;
    const Interval a = enclose(ends[0]), b = enclose(ends[1]);
    if (!(a.hi < b.lo)) return std::nullopt;
    // The pieces' ends: the edge's own at its two ends, doubles between.
    const auto end = [&](const Interval& x) {
        if (x.lo == a.lo && x.hi == a.hi) return ends[0];
        if (x.lo == b.lo && x.hi == b.hi) return ends[1];
        Ball point;
        arb_set_d(point.get(), x.lo);
        return point;
    };
    const auto integrate_piece = [&](const Interval& A, const Interval& B, int n,
                                     const std::array<double, kMeasures>& error) {
        const Ball lo = end(A), hi = end(B);
        Ball half, mid;
        arb_sub(half.get(), hi.get(), lo.get(), prec);
        arb_mul_2exp_si(half.get(), half.get(), -1);
        arb_add(mid.get(), lo.get(), hi.get(), prec);
        arb_mul_2exp_si(mid.get(), mid.get(), -1);
        const GaussLegendreBallRule& rule = rules.rule_in_arb(n, prec);
        NormalRayBisector::Densities sum, f;
        QuadratureCounts& count = counts ? *counts : local;
        for (int k = 0; k < n; ++k) {
            Ball theta;
            arb_mul(theta.get(), half.get(), rule.nodes[k].get(), prec);
            arb_add(theta.get(), theta.get(), mid.get(), prec);
            // From the piece's disk certificate, else certified by itself.
            if (bounds.densities_in_balls(theta, prec, f))
                ++count.ball_nodes_from_disks;
            else if (!bisector.densities(ComplexBall(theta), prec, f))
                return false;
            for (int j = 0; j < kMeasures; ++j)
                acb_addmul_arb(sum.m[j].get(), f.m[j].get(), rule.weights[k].get(), prec);
        }
        for (int j = 0; j < kMeasures; ++j) {
            acb_addmul_arb(total.m[j].get(), sum.m[j].get(), half.get(), prec);
            Mag bound;
            mag_set_d(bound.get(), error[j]);
            arb_add_error_mag(acb_realref(total.m[j].get()), bound.get());
        }
        return true;
    };
    if (!integrate_pieces(bounds, a, b, tolerance, counts ? *counts : local, reach ? *reach : local_reach,
                          integrate_piece))
        return std::nullopt;
    return total;
}

}  // namespace ellvor
