// The certified quadrature stages of the cell integrals
// (cells/edge_quadrature.hpp): its Gauss-Legendre rules against the moments
// of x^k, its nodes and boxes (NormalRayInDoubles) against the Arb solver,
// and its edge integrals (nodes in doubles or in Arb) against Arb's own
// integrator of the same density, two independent proofs that must overlap.
#include "cells/edge_quadrature.hpp"
#include "predicates/relative_position.hpp"
#include "tests/support/random_sites.hpp"
#include "util/error.hpp"

#include <acb_calc.h>
#include <catch2/catch.hpp>

#include <cfenv>
#include <cmath>
#include <complex>
#include <random>

using namespace ellvor;

namespace {

constexpr double kPi = 3.14159265358979323846;

bool overlap(const Interval& x, const ComplexBall& z) {
    Ball real;
    arb_set(real.get(), z.real());
    const Interval r = enclose(real);
    return x.lo <= r.hi && r.lo <= x.hi;
}

// The Arb solver's densities at the point theta.
bool densities_at_200_bits(NormalRayBisector& arb, double theta, NormalRayBisector::Densities& out) {
    ComplexBall ball;
    arb_set_d(ball.real(), theta);
    return arb.densities(ball, 200, out);
}

// Every measure's interval meets Arb's ball of it.
void check_overlaps(const MeasureIntervals& d, const NormalRayBisector::Densities& reference) {
    for (int j = 0; j < MeasureIntervals::count; ++j) {
        INFO("measure " << j << " [" << d.m[j].lo << ", " << d.m[j].hi << "]");
        CHECK(overlap(d.m[j], reference.m[j]));
    }
}

// Absolute tolerances of the measures: `area` for those in area units (X dY,
// Y dX), times scale^(d - 2) for those of degree d in lengths.
struct Tolerances {
    double t[MeasureIntervals::count];
    explicit Tolerances(double area, double scale = 1) {
        const int degree[MeasureIntervals::count] = {2, 2, 1, 3, 3, 3, 4, 4, 4};
        for (int j = 0; j < MeasureIntervals::count; ++j) t[j] = area * std::pow(scale, degree[j] - 2);
    }
};

double relative_width(const Interval& x) { return (x.hi - x.lo) / std::max(std::fabs(x.lo), std::fabs(x.hi)); }

// Two random disjoint ellipses, p near the origin and q at distance 4..12.
std::pair<Ellipse, Ellipse> random_pair(std::mt19937_64& rng) {
    for (;;) {
        const Ellipse p(test::random_fraction(rng, 4, 30, 10), test::random_fraction(rng, 4, 30, 10),
                        test::random_fraction(rng, -9, 9, 10), test::random_fraction(rng, -5, 5, 10),
                        test::random_fraction(rng, -5, 5, 10));
        const Ellipse q(test::random_fraction(rng, 4, 30, 10), test::random_fraction(rng, 4, 30, 10),
                        test::random_fraction(rng, -9, 9, 10), test::random_fraction(rng, -120, 120, 10),
                        test::random_fraction(rng, -120, 120, 10));
        if (test::bounding_circles_apart(p, q)) return {p, q};
    }
}

// The angle on p whose normal points at q's center, in doubles.
double facing_angle(const Ellipse& p, const Ellipse& q) {
    const double dx = q.xc().to_double() - p.xc().to_double(), dy = q.yc().to_double() - p.yc().to_double();
    const double c = p.cos_rotation().to_double(), s = p.sin_rotation().to_double();
    // In p's frame the normal at theta is along (b cos theta, a sin theta).
    const double lx = c * dx + s * dy, ly = -s * dx + c * dy;
    return std::atan2(ly * p.b().to_double(), lx * p.a().to_double());
}

// For each of `trials` random pairs (the signed tie on odd trials) whose
// random disk certifies: body(trial, p, q, fast, arb, mid, R), `fast` a
// NormalRayInDoubles holding the proof of the disk of radius R = 0.02 .. 0.05
// about an angle mid within 0.4 of where p faces q, `arb` the pair's complex
// solver.
template <class Body>
void for_each_certified_disk(std::mt19937_64& rng, int trials, Body&& body) {
    std::uniform_real_distribution<double> unit(-1, 1);
    for (int trial = 0; trial < trials; ++trial) {
        const auto [p, q] = random_pair(rng);
        NormalRayInDoubles fast(p, q, trial % 2);
        NormalRayBisector arb(p, q, trial % 2);
        const double mid = facing_angle(p, q) + 0.4 * unit(rng), R = 0.02 + 0.03 * std::fabs(unit(rng));
        if (fast.bounds_on_disk(mid, R, R)) body(trial, p, q, fast, arb, mid, R);
    }
}

// One measure's density, for Arb's integrator.
struct MeasureIntegrand {
    NormalRayBisector* bisector;
    int measure;
};

int measure_integrand(acb_ptr out, const acb_t in, void* param, slong order, slong prec) {
    if (order > 1) {
        acb_indeterminate(out);
        return 0;
    }
    const auto* integrand = static_cast<MeasureIntegrand*>(param);
    ComplexBall theta;
    NormalRayBisector::Densities d;
    acb_set(theta.get(), in);
    if (integrand->bisector->densities(theta, prec, d))
        acb_set(out, d.m[integrand->measure].get());
    else
        acb_indeterminate(out);
    return 0;
}

// Measure j over [a, b] by Arb's integrator to the absolute tolerance, at prec bits.
ComplexBall integral_by_arb(NormalRayBisector& bisector, int j, const Ball& a, const Ball& b, double tolerance,
                            long prec) {
    MeasureIntegrand param{&bisector, j};
    ComplexBall A(a), B(b), integral;
    Mag tol;
    mag_set_d(tol.get(), tolerance);
    acb_calc_integrate_opt_t options;
    acb_calc_integrate_opt_init(options);
    acb_calc_integrate(integral.get(), measure_integrand, &param, A.get(), B.get(), prec - 40, tol.get(), options,
                       prec);
    return integral;
}

}  // namespace

TEST_CASE("Gauss-Legendre rules integrate x^k exactly up to k = 2n - 1", "[cells][quadrature]") {
    GaussLegendreRules rules;
    for (int n = 1; n <= GaussLegendreRules::kMaxPoints; ++n) {
        const GaussLegendreRule& rule = rules.rule(n);
        REQUIRE(rule.nodes.size() == static_cast<std::size_t>(n));
        for (int k : {0, 1, 2 * n - 2, 2 * n - 1}) {
            if (k < 0) continue;
            Interval sum(0.0);
            for (int i = 0; i < n; ++i) {
                Interval power(1.0);
                for (int j = 0; j < k; ++j) power = power * rule.nodes[i];
                sum = sum + rule.weights[i] * power;
            }
            const double exact = k % 2 ? 0.0 : 2.0 / (k + 1);
            INFO("n " << n << " k " << k << " sum [" << sum.lo << ", " << sum.hi << "]");
            CHECK(sum.lo <= exact);
            CHECK(exact <= sum.hi);
            CHECK(sum.hi - sum.lo < 1e-13);
        }
    }
    CHECK_THROWS_AS(rules.rule(0), Error);
    CHECK_THROWS_AS(rules.rule(GaussLegendreRules::kMaxPoints + 1), Error);
}

TEST_CASE("NormalRayInDoubles: its densities contain the Arb solver's at 200 bits", "[cells][quadrature]") {
    std::mt19937_64 rng(20261127);
    std::uniform_real_distribution<double> spread(-0.6, 0.6);
    int compared = 0, certified = 0;
    for (int trial = 0; trial < 60; ++trial) {
        const auto [p, q] = random_pair(rng);
        NormalRayInDoubles fast(p, q);
        NormalRayBisector arb(p, q);
        const double theta = facing_angle(p, q) + spread(rng);
        NormalRayBisector::Densities reference;
        if (!densities_at_200_bits(arb, theta, reference)) continue;
        ++compared;
        const std::optional<MeasureIntervals> d = fast.densities(Interval(theta));
        // The node computes under the upward rounding mode and restores the caller's.
        CHECK(std::fegetround() == FE_TONEAREST);
        if (!d) continue;
        ++certified;
        INFO("trial " << trial);
        check_overlaps(*d, reference);
        CHECK(relative_width(d->m[MeasureIntervals::length]) < 1e-11);
        const Interval &x_dy = d->m[MeasureIntervals::x_dy], &y_dx = d->m[MeasureIntervals::y_dx];
        CHECK(std::max(x_dy.hi - x_dy.lo, y_dx.hi - y_dx.lo) < 1e-11 * (std::fabs(x_dy.mid()) + std::fabs(y_dx.mid())));
        // The uncertified estimate of the area density (a scale) agrees.
        NormalRayInDoubles estimate(p, q);
        const std::optional<double> area = estimate.area_density_estimate(theta);
        REQUIRE(area);
        CHECK(std::fabs(*area - 0.5 * (x_dy.mid() - y_dx.mid())) <= 1e-9 * (std::fabs(x_dy.mid()) + std::fabs(y_dx.mid())));
    }
    // The stage must be reached: it certifies (nearly) every point Arb does.
    CHECK(compared >= 40);
    CHECK(certified >= compared * 9 / 10);
}

TEST_CASE("NormalRayInDoubles on crossing sites: the signed tie's densities contain Arb's at 200 bits", "[cells][quadrature]") {
    // Fat ellipses (aspect <= 1.5) crossing shallowly, and the angles of p
    // facing q: there the edge runs from outside both sites (s > 0) through
    // a boundary crossing (s = 0) into both (s < 0, negative area densities).
    std::mt19937_64 rng(27);
    std::uniform_real_distribution<double> spread(-1.2, 1.2);
    int compared = 0, certified = 0, inside = 0, outside = 0;
    for (int trial = 0; trial < 80; ++trial) {
        const Rational a = test::random_fraction(rng, 20, 30, 10), b = a * test::random_fraction(rng, 7, 10, 10);
        const Rational c = test::random_fraction(rng, 20, 30, 10), d = c * test::random_fraction(rng, 7, 10, 10);
        const double angle = 2 * kPi * std::uniform_real_distribution<double>(0, 1)(rng);
        const Rational distance = (a + c) * test::random_fraction(rng, 75, 95, 100);
        const Ellipse p(a, b, test::random_fraction(rng, -9, 9, 10), Rational(0), Rational(0));
        const Ellipse q(c, d, test::random_fraction(rng, -9, 9, 10), distance * Rational(std::lround(1000 * std::cos(angle)), 1000),
                        distance * Rational(std::lround(1000 * std::sin(angle)), 1000));
        if (!NormalRayBisector::meet(p, q)) continue;
        NormalRayInDoubles fast(p, q);
        NormalRayBisector arb(p, q);
        REQUIRE(arb.signed_tie());
        const double theta = facing_angle(p, q) + spread(rng);
        NormalRayBisector::Densities reference;
        if (!densities_at_200_bits(arb, theta, reference)) continue;
        ++compared;
        ComplexBall ball, s;
        arb_set_d(ball.real(), theta);
        REQUIRE(arb.solve(ball, 200, s));
        (arb_is_negative(acb_realref(s.get())) ? inside : outside) += 1;
        const std::optional<MeasureIntervals> dens = fast.densities(Interval(theta));
        if (!dens) continue;
        ++certified;
        INFO("trial " << trial);
        check_overlaps(*dens, reference);
    }
    CHECK(compared >= 40);
    CHECK(inside >= 5);
    CHECK(outside >= 5);
    CHECK(certified >= compared * 9 / 10);
}

TEST_CASE("close disjoint sites: the signed tie's densities equal the squared tie's", "[cells][quadrature]") {
    // Sites 10^-2 to 10^-7 of their size apart, whose bounding circles
    // overlap: the cells use the signed tie there (uses_signed_tie). Both
    // systems hold for disjoint sites; the squared one, solved by Arb at 200
    // bits, is the independent reference for the signed one in Arb and in
    // double intervals, near the gap and away from it.
    std::mt19937_64 rng(31);
    std::uniform_real_distribution<double> spread(-1.0, 1.0);
    int compared = 0, certified = 0;
    for (int trial = 0; trial < 60; ++trial) {
        const Rational a = test::random_fraction(rng, 20, 30, 10), b = a * test::random_fraction(rng, 5, 10, 10);
        const Ellipse p(a, b, Rational(0), Rational(0), Rational(0));
        // q's vertex faces p's at distance a (1 + gap) along the x axis.
        const Rational c = test::random_fraction(rng, 20, 30, 10), d = c * test::random_fraction(rng, 5, 10, 10);
        const Rational gap = Rational(1, std::lround(std::pow(10.0, 2 + trial % 6)));
        const Ellipse q(c, d, Rational(0), a * (Rational(1) + gap) + c, Rational(0));
        REQUIRE(*relative_position(p, q) == RelativePosition::separated);
        REQUIRE(NormalRayBisector::uses_signed_tie(p, q));
        NormalRayBisector squared(p, q, false), signed_tie(p, q);
        REQUIRE(signed_tie.signed_tie());
        NormalRayInDoubles fast(p, q);
        const double theta = 0.3 * spread(rng) * (trial % 2 ? 1 : 0.01);
        NormalRayBisector::Densities reference, other;
        if (!densities_at_200_bits(squared, theta, reference)) continue;
        ++compared;
        REQUIRE(densities_at_200_bits(signed_tie, theta, other));
        for (int j = 0; j < MeasureIntervals::count; ++j) CHECK(acb_overlaps(reference.m[j].get(), other.m[j].get()));
        const std::optional<MeasureIntervals> dens = fast.densities(Interval(theta));
        if (!dens) continue;
        ++certified;
        INFO("trial " << trial << " theta " << theta);
        check_overlaps(*dens, reference);
    }
    CHECK(compared >= 40);
    CHECK(certified >= compared * 9 / 10);
}

TEST_CASE("NormalRayInDoubles: its bounds, polynomials and root models on a complex disk hold at Arb's points inside", "[cells][quadrature]") {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> unit(-1, 1);
    // Small disks, and disks where the models' second-order terms decide.
    const double radii[] = {0.024, 0.05};
    int disks = 0, bounded = 0, large_disks = 0, large_bounded = 0, points = 0, checked_points = 0;
    int checked_remainders = 0, useful_remainders = 0, quadratic_tighter = 0;
    for (int trial = 0; trial < 80; ++trial) {
        const auto [p, q] = random_pair(rng);
        NormalRayInDoubles fast(p, q);
        NormalRayBisector arb(p, q);
        const bool large = trial % 2;
        const double mid = facing_angle(p, q) + 0.4 * unit(rng), R = radii[large];
        ++(large ? large_disks : disks);
        const std::optional<NormalRayInDoubles::DiskBounds> bounds = fast.bounds_on_disk(mid, R, R);
        const std::optional<NormalRayInDoubles::RootModel> model = fast.root_model(mid, R);
        // One certificate: the bounds need it and more (|V'|'s factors off the
        // square root's cut on the disk).
        CHECK((!bounds || model));
        if (!bounds || !model) continue;
        const std::array<double, MeasureIntervals::count>& M = bounds->density;
        ++(large ? large_bounded : bounded);
        // The center distance at real angles: V - C = a cos u + b sin v + s n~
        // at 128 bits, u and v p's axes (normal_ray_bisector.hpp).
        const SiteBalls site(p, 128);
        for (int k = 0; k < 4; ++k) {
            ComplexBall theta, s;
            arb_set_d(theta.real(), mid + R * unit(rng));
            REQUIRE(arb.solve(theta, 128, s));
            Ball c, sn, d[2], t;
            arb_cos(c.get(), theta.real(), 128);
            arb_sin(sn.get(), theta.real(), 128);
            // Along u: a cos + s b cos; along v: b sin + s a sin.
            Ball along_u, along_v;
            arb_mul(t.get(), acb_realref(s.get()), site.b.get(), 128);
            arb_add(t.get(), t.get(), site.a.get(), 128);
            arb_mul(along_u.get(), t.get(), c.get(), 128);
            arb_mul(t.get(), acb_realref(s.get()), site.a.get(), 128);
            arb_add(t.get(), t.get(), site.b.get(), 128);
            arb_mul(along_v.get(), t.get(), sn.get(), 128);
            // (x, y) = along_u (cos, sin) + along_v (-sin, cos) of the rotation.
            arb_mul(d[0].get(), along_u.get(), site.cos.get(), 128);
            arb_submul(d[0].get(), along_v.get(), site.sin.get(), 128);
            arb_mul(d[1].get(), along_u.get(), site.sin.get(), 128);
            arb_addmul(d[1].get(), along_v.get(), site.cos.get(), 128);
            // V - C_q = (V - C_p) + (C_p - C_q).
            const SiteBalls other(q, 128);
            Ball e[2];
            arb_add(e[0].get(), d[0].get(), site.xc.get(), 128);
            arb_sub(e[0].get(), e[0].get(), other.xc.get(), 128);
            arb_add(e[1].get(), d[1].get(), site.yc.get(), 128);
            arb_sub(e[1].get(), e[1].get(), other.yc.get(), 128);
            for (int i = 0; i < 2; ++i) {
                Ball& v = i == 0 ? d[0] : e[0];
                const Ball& w = i == 0 ? d[1] : e[1];
                arb_sqr(v.get(), v.get(), 128);
                arb_addmul(v.get(), w.get(), w.get(), 128);
                arb_sqrt(v.get(), v.get(), 128);
                Arf lower;
                arb_get_lbound_arf(lower.get(), v.get(), 128);
                const double bound = bounds->center_distance[i];
                INFO("trial " << trial << " |V - C| of " << (i ? "q " : "p ") << v.str(20) << " bound " << bound);
                CHECK(arf_get_d(lower.get(), ARF_RND_DOWN) <= bound);
                // Within the disk's width of the true value: a bound, not a guess at infinity.
                CHECK(bound <= 2 * arf_get_d(lower.get(), ARF_RND_UP) + 20 * R);
            }
        }
        for (int k = 0; k < 8; ++k) {
            // A point of the disk, its edge included (k = 0).
            const double radius = k == 0 ? R : R * std::sqrt(std::fabs(unit(rng))), angle = 3.14159 * unit(rng);
            ComplexBall z;
            arb_set_d(z.real(), mid + radius * std::cos(angle));
            arb_set_d(z.imag(), radius * std::sin(angle));
            // (Arb's certificate over the segment from mid to z may fail far
            // from the reals: such points are skipped, and counted.)
            NormalRayBisector::Densities d;
            ++points;
            if (!arb.densities(z, 128, d)) continue;
            ++checked_points;
            // The model: |s(z) - s0 - s1 (z - mid)| <= remainder.
            ComplexBall s, dz, error;
            REQUIRE(arb.solve(z, 128, s));
            Ball centre, s0, s1;
            arb_set_d(centre.get(), mid);
            acb_set(dz.get(), z.get());
            arb_sub(dz.real(), dz.real(), centre.get(), 128);
            arb_set_d(s0.get(), model->s0);
            arb_set_d(s1.get(), model->s1);
            acb_mul_arb(error.get(), dz.get(), s1.get(), 128);
            acb_add_arb(error.get(), error.get(), s0.get(), 128);
            acb_sub(error.get(), s.get(), error.get(), 128);
            Mag e;
            acb_get_mag_lower(e.get(), error.get());
            CHECK(mag_get_d(e.get()) <= model->remainder);
            // The quadratic model: |s(z) - s0 - s1 (z - mid) - s2 (z - mid)^2| <= quadratic_remainder.
            ComplexBall d2;
            Ball s2;
            arb_set_d(s2.get(), model->s2);
            acb_sqr(d2.get(), dz.get(), 128);
            acb_mul_arb(d2.get(), d2.get(), s2.get(), 128);
            acb_sub(error.get(), error.get(), d2.get(), 128);
            acb_get_mag_lower(e.get(), error.get());
            CHECK(mag_get_d(e.get()) <= model->quadratic_remainder);
            quadratic_tighter += model->quadratic_remainder < model->remainder;
            for (int j = 0; j < MeasureIntervals::count; ++j) {
                Mag m;
                acb_get_mag_lower(m.get(), d.m[j].get());
                INFO("trial " << trial << " measure " << j << " bound " << M[j]);
                CHECK(mag_get_d(m.get()) <= M[j]);
                // |f - p| <= beyond_polynomial, p the density's polynomial in
                // z - mid; the length's model continues |V'| and Arb's value
                // is the principal root: the same up to sign.
                if (!std::isfinite(bounds->beyond_polynomial[j])) continue;
                ComplexBall polynomial, coefficient, difference;
                for (int k = NormalRayInDoubles::kDiskDegree; k >= 0; --k) {
                    acb_mul(polynomial.get(), polynomial.get(), dz.get(), 128);
                    acb_set_d_d(coefficient.get(), bounds->polynomial[j][k][0], bounds->polynomial[j][k][1]);
                    acb_add(polynomial.get(), polynomial.get(), coefficient.get(), 128);
                }
                acb_sub(difference.get(), d.m[j].get(), polynomial.get(), 128);
                Mag e_minus, e_plus;
                acb_get_mag_lower(e_minus.get(), difference.get());
                acb_add(difference.get(), d.m[j].get(), polynomial.get(), 128);
                acb_get_mag_lower(e_plus.get(), difference.get());
                const double e_density = j == MeasureIntervals::length
                                             ? std::min(mag_get_d(e_minus.get()), mag_get_d(e_plus.get()))
                                             : mag_get_d(e_minus.get());
                INFO("beyond the polynomial " << e_density << ", bound " << bounds->beyond_polynomial[j]);
                CHECK(e_density <= bounds->beyond_polynomial[j]);
                ++checked_remainders;
                // Of the model's order, mostly far below the modulus's.
                useful_remainders += bounds->beyond_polynomial[j] <= M[j] / 10;
            }
        }
    }
    // The stage must be reached on disks this small, and often on the large ones.
    CHECK(bounded >= disks * 3 / 4);
    INFO("large disks certified: " << large_bounded << " of " << large_disks);
    CHECK(large_bounded >= large_disks / 2);
    INFO("points checked: " << checked_points << " of " << points);
    CHECK(checked_points >= points * 9 / 10);
    // Every density's model has a finite remainder on nearly every disk.
    INFO("remainders checked: " << checked_remainders << ", a tenth of the modulus's bound or less: " << useful_remainders);
    CHECK(checked_remainders >= checked_points * MeasureIntervals::count * 9 / 10);
    CHECK(useful_remainders >= checked_remainders * 3 / 4);
    // The quadratic model's remainder below the linear one's nearly always.
    INFO("quadratic remainder the tighter at " << quadratic_tighter << " of " << checked_points);
    CHECK(quadratic_tighter >= checked_points * 9 / 10);
}

TEST_CASE("NormalRayInDoubles: its pole angles are where p's normal is perpendicular to the centers' line", "[cells][quadrature]") {
    std::mt19937_64 rng(5);
    for (int trial = 0; trial < 50; ++trial) {
        const auto [p, q] = random_pair(rng);
        const std::array<double, 2> poles = NormalRayInDoubles(p, q).pole_angles();
        const double a = p.a().to_double(), b = p.b().to_double();
        const double c = p.cos_rotation().to_double(), s = p.sin_rotation().to_double();
        const double dx = q.xc().to_double() - p.xc().to_double(), dy = q.yc().to_double() - p.yc().to_double();
        for (double theta : poles) {
            // n~ in the plane: (b cos, a sin) of p's frame, rotated.
            const double lx = b * std::cos(theta), ly = a * std::sin(theta);
            const double nx = c * lx - s * ly, ny = s * lx + c * ly;
            INFO("trial " << trial << " theta " << theta);
            CHECK(std::fabs(nx * dx + ny * dy) <= 1e-12 * std::hypot(nx, ny) * std::hypot(dx, dy));
            CHECK(std::fabs(theta) <= M_PI);
        }
        CHECK(std::fabs(std::fabs(poles[0] - poles[1]) - M_PI) <= 1e-12);
    }
}

// Two unit circles 10 apart: the edge is the line x = 5, V = (5, 5 tan theta)
// from p's angle theta, so |V'| continues as 5 sec^2 theta off the reals.
// Near the edge's far end (theta = 1.2, its pole at pi/2) V' . V' = 25
// sec^4 theta turns twice as fast as either factor of |V'| =
// sqrt(V'x + i V'y) sqrt(V'x - i V'y): its own principal root failed beyond R
// = 0.059 there, the factors' hold at 0.08; the length's bound holds at every
// point of the disk.
TEST_CASE("NormalRayInDoubles: the length's bound on a disk near the edge's pole, from |V'|'s factors", "[cells][quadrature]") {
    const Ellipse p(Rational(1), Rational(1), Rational(0), Rational(0), Rational(0));
    const Ellipse q(Rational(1), Rational(1), Rational(0), Rational(10), Rational(0));
    NormalRayInDoubles fast(p, q);
    const double mid = 1.2, R = 0.08;
    const std::optional<NormalRayInDoubles::DiskBounds> bounds = fast.bounds_on_disk(mid, R, R);
    REQUIRE(bounds);
    const double M = bounds->density[MeasureIntervals::length];
    double largest = 0;
    for (int k = 0; k < 64; ++k)
        for (double radius : {R, 0.5 * R}) {
            const std::complex<double> theta(mid + radius * std::cos(k * M_PI / 32), radius * std::sin(k * M_PI / 32));
            const std::complex<double> c = std::cos(theta);
            largest = std::max(largest, 5 / std::norm(c));  // |5 sec^2 theta|
        }
    INFO("largest |V'| " << largest << ", bound " << M);
    CHECK(largest * (1 + 1e-12) <= M);
    // A bound, not a guess at infinity.
    CHECK(M <= 2 * largest);
}

// The same circles: s(theta) = 5 sec theta - 1, analytic but for poles at
// +-pi/2. Disks about 0 and 0.6 of radii 0.4 and 0.22 (about a quarter of
// the distance to the pole) are certified, and their root models hold the
// closed form on the disk's circle. With the residual H = F(x_model, theta)
// as a model of degree 2 the certificate failed beyond 0.29 and 0.17: H's
// terms of degrees 3 and 4 cancel between F's terms, and a degree-2 model
// bounds them one by one (normal_ray_in_doubles.cpp, kResidualDegree).
TEST_CASE("NormalRayInDoubles: the disk certificate reaches a quarter of the way to the pole", "[cells][quadrature]") {
    const Ellipse p(Rational(1), Rational(1), Rational(0), Rational(0), Rational(0));
    const Ellipse q(Rational(1), Rational(1), Rational(0), Rational(10), Rational(0));
    for (const auto& [mid, R] : {std::pair<double, double>{0.0, 0.4}, {0.6, 0.22}}) {
        NormalRayInDoubles fast(p, q);
        INFO("mid " << mid << ", R " << R);
        REQUIRE(fast.bounds_on_disk(mid, R, R));
        const std::optional<NormalRayInDoubles::RootModel> model = fast.root_model(mid, R);
        REQUIRE(model);
        for (int k = 0; k < 64; ++k) {
            const std::complex<double> d = std::polar(R, k * M_PI / 32);
            const std::complex<double> s = 5.0 / std::cos(mid + d) - 1.0;
            const std::complex<double> quadratic = model->s0 + model->s1 * d + model->s2 * d * d;
            CHECK(std::abs(s - quadratic) <= model->quadratic_remainder * (1 + 1e-9));
        }
        // A bound of the size of the truncated terms, not a guess at infinity.
        CHECK(model->quadratic_remainder <= 0.5);
    }
}

TEST_CASE("NormalRayInDoubles: nodes from a disk's proof hold Arb's densities, as narrow as their own tests", "[cells][quadrature]") {
    // After a disk certificate, a node on its real diameter is certified from
    // the disk's contraction (certify_node_in_disk), not by a Krawczyk test of
    // its own; off the disk, by its own.
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> unit(-1, 1);
    int from_disks = 0, compared = 0;
    for_each_certified_disk(rng, 40, [&](int trial, const Ellipse& p, const Ellipse& q, NormalRayInDoubles& fast,
                                         NormalRayBisector& arb, double mid, double R) {
        NormalRayInDoubles own(p, q, trial % 2);
        for (int k = 0; k < 6; ++k) {
            const double theta = mid + R * unit(rng);
            const std::size_t before = fast.disk_nodes();
            const std::optional<MeasureIntervals> d = fast.densities(Interval(theta));
            REQUIRE(d);
            CHECK(fast.disk_nodes() == before + 1);
            ++from_disks;
            NormalRayBisector::Densities reference;
            REQUIRE(densities_at_200_bits(arb, theta, reference));
            INFO("trial " << trial << " theta " << theta);
            check_overlaps(*d, reference);
            ++compared;
            // As narrow as a node's own Krawczyk test (within a factor 2 of
            // its width or 2^-40 of the value).
            const std::optional<MeasureIntervals> e = own.densities(Interval(theta));
            REQUIRE(e);
            CHECK(own.disk_nodes() == 0);
            for (int j = 0; j < MeasureIntervals::count; ++j)
                CHECK(d->m[j].hi - d->m[j].lo <=
                      2 * (e->m[j].hi - e->m[j].lo) + std::ldexp(std::fabs(e->m[j].mid()), -40));
        }
        // Off the disk: its own test.
        const std::size_t before = fast.disk_nodes();
        REQUIRE(fast.densities(Interval(mid + 1.5 * R)));
        CHECK(fast.disk_nodes() == before);
    });
    CHECK(compared >= 120);
    CHECK(from_disks == compared);
}

TEST_CASE("NormalRayInDoubles: nodes in balls from a disk's proof hold Arb's densities at 400 bits, 2^-(prec - 40) wide",
          "[cells][quadrature]") {
    // densities_in_balls: the root refined in balls, its offsets from the
    // disk's proof (no certificate of its own); the reference certifies each
    // node by its own Krawczyk test at 400 bits. Both tie functions; nodes
    // that are not doubles (theta + 2^-80).
    std::mt19937_64 rng(19);
    std::uniform_real_distribution<double> unit(-1, 1);
    int compared = 0;
    for_each_certified_disk(rng, 40, [&](int trial, const Ellipse& p, const Ellipse& q, NormalRayInDoubles& fast,
                                         NormalRayBisector& arb, double mid, double R) {
        for (int k = 0; k < 6; ++k) {
            const long prec = k % 2 ? 114 : 200;
            Ball theta, offset;
            arb_set_d(theta.get(), mid + R * unit(rng));
            arb_one(offset.get());
            arb_mul_2exp_si(offset.get(), offset.get(), -80);
            arb_add(theta.get(), theta.get(), offset.get(), prec);
            NormalRayBisector::Densities d, reference;
            REQUIRE(fast.densities_in_balls(theta, prec, d));
            REQUIRE(arb.densities(ComplexBall(theta), 400, reference));
            for (int j = 0; j < MeasureIntervals::count; ++j) {
                Ball ours, theirs;
                arb_set(ours.get(), acb_realref(d.m[j].get()));
                arb_set(theirs.get(), acb_realref(reference.m[j].get()));
                INFO("trial " << trial << " prec " << prec << " measure " << j << " ours " << ours.str(40) << " Arb's "
                              << theirs.str(40));
                CHECK(arb_is_zero(acb_imagref(d.m[j].get())));
                CHECK(arb_overlaps(ours.get(), theirs.get()));
                CHECK(ours.radius_double() <= std::ldexp(std::max(1.0, std::fabs(ours.mid_double())), 40 - prec));
            }
            ++compared;
        }
        // Off the disk's diameter the proof says nothing.
        Ball off;
        arb_set_d(off.get(), mid + 1.5 * R);
        NormalRayBisector::Densities d;
        CHECK(!fast.densities_in_balls(off, 114, d));
    });
    CHECK(compared >= 120);
}

TEST_CASE("NormalRayInDoubles: a disk's proof encloses the root from any point of X(theta)", "[cells][quadrature]") {
    // root_from_disk is the nodes' proof (certify_node_in_disk) from a given
    // point: x +- delta must hold the root for points far from it too (Newton's
    // are within rounding, which would hide a delta too small). The root: s
    // from Arb at 200 bits, phi q's nearest point to V.
    std::mt19937_64 rng(23);
    std::uniform_real_distribution<double> unit(-1, 1);
    int proofs = 0, far_proofs = 0;
    for_each_certified_disk(rng, 40, [&](int trial, const Ellipse& p, const Ellipse& q, NormalRayInDoubles& fast,
                                         NormalRayBisector& arb, double mid, double R) {
        const EllipseShape ps = EllipseShape::of(p), qs = EllipseShape::of(q);
        for (int k = 0; k < 8; ++k) {
            const double theta = mid + R * unit(rng);
            ComplexBall ball, s;
            arb_set_d(ball.real(), theta);
            REQUIRE(arb.solve(ball, 200, s));
            const double s_root = arf_get_d(arb_midref(acb_realref(s.get())), ARF_RND_NEAR);
            double px, py, nx, ny;
            ps.point(theta, px, py);
            ps.normal(theta, nx, ny);
            const double rho = s_root * std::hypot(ps.b * std::cos(theta), ps.a * std::sin(theta));
            const double phi_root = qs.nearest_angle(px + rho * nx, py + rho * ny);
            for (const double scale : {0.0, 1e-10, 1e-6, 1e-5, 1e-4, 1e-3}) {
                const double x[2] = {s_root * (1 + scale * unit(rng)), phi_root + scale * unit(rng)};
                const std::optional<std::array<Interval, 2>> root = fast.root_from_disk(Interval(theta), x);
                if (!root) continue;
                ++proofs;
                far_proofs += scale >= 1e-5;
                INFO("trial " << trial << " theta " << theta << " scale " << scale);
                CHECK(overlap((*root)[0], s));
                CHECK((*root)[1].lo <= phi_root + 1e-12);
                CHECK(phi_root - 1e-12 <= (*root)[1].hi);
                // A bound, not everything: about the point's distance to the
                // root (in either unknown: the proof's norm couples them).
                const double distance = std::fabs(x[0] - s_root) + (1 + std::fabs(s_root)) * std::fabs(x[1] - phi_root);
                CHECK((*root)[0].hi - (*root)[0].lo <= 1e3 * (distance + 1e-12 * (1 + std::fabs(s_root))));
            }
        }
        // Off the disk: nothing.
        const double x[2] = {1, 0};
        CHECK(!fast.root_from_disk(Interval(mid + 1.5 * R), x));
    });
    INFO("proofs " << proofs << ", from points 1e-5 or farther " << far_proofs);
    CHECK(proofs >= 600);
    CHECK(far_proofs >= 100);
}

// The system of normal_ray_bisector.hpp in complex doubles, for Newton's
// method: F0 = (V - Q) . Q', F1 the squared tie or the signed one
// (principal square roots).
struct ComplexSystem {
    using Z = std::complex<double>;
    EllipseShape p, q;
    bool is_signed;
    struct Frame {
        Z x, y, nx, ny, dx, dy, n2;
    };
    static Frame frame(const EllipseShape& e, Z t) {
        const Z c = std::cos(t), s = std::sin(t);
        const auto rotate = [&e](Z u, Z v, Z& X, Z& Y) { X = u * e.c - v * e.s, Y = u * e.s + v * e.c; };
        Frame f;
        rotate(e.a * c, e.b * s, f.x, f.y);
        f.x += e.xc, f.y += e.yc;
        rotate(e.b * c, e.a * s, f.nx, f.ny);
        rotate(-e.a * s, e.b * c, f.dx, f.dy);
        f.n2 = e.a * e.a * s * s + e.b * e.b * c * c;
        return f;
    }
    void operator()(Z theta, Z s, Z phi, Z (&F)[2]) const {
        const Frame P = frame(p, theta), Q = frame(q, phi);
        const Z vx = P.x + s * P.nx - Q.x, vy = P.y + s * P.ny - Q.y, ex = P.x - Q.x, ey = P.y - Q.y;
        F[0] = vx * Q.dx + vy * Q.dy;
        F[1] = is_signed ? vx * Q.nx + vy * Q.ny - s * std::sqrt(P.n2) * std::sqrt(Q.n2)
                         : ex * ex + ey * ey + 2.0 * s * (ex * P.nx + ey * P.ny);
    }
    // Newton at theta from (s, phi), difference quotients for the Jacobian
    // (the residual, not the Jacobian, decides the root).
    void newton(Z theta, Z& s, Z& phi) const {
        for (int step = 0; step < 40; ++step) {
            Z F[2], Fs[2], Fphi[2];
            const double h = 1e-7;
            (*this)(theta, s, phi, F);
            (*this)(theta, s + h, phi, Fs);
            (*this)(theta, s, phi + h, Fphi);
            const Z a = (Fs[0] - F[0]) / h, b = (Fphi[0] - F[0]) / h, c = (Fs[1] - F[1]) / h, d = (Fphi[1] - F[1]) / h;
            const Z det = a * d - b * c;
            s -= (d * F[0] - b * F[1]) / det;
            phi -= (a * F[1] - c * F[0]) / det;
        }
    }
};

TEST_CASE("NormalRayBisector: on balls off the real axis, the root of the system", "[cells][quadrature]") {
    // The certificate's mean-value form in theta runs from the ball's real
    // middle: over a ball that does not hold it (here points and small balls
    // at mid + t e^(i alpha)) it must take the whole segment, or it encloses
    // a wrong value (2e-4 from the root at t = 0.01, with a radius of 5e-6).
    // The reference: Newton's method on the same system in complex doubles,
    // from the real root at mid, to a residual at rounding level.
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> unit(-1, 1);
    int compared = 0;
    for (int trial = 0; trial < 24; ++trial) {
        const auto [p, q] = random_pair(rng);
        const bool is_signed = trial % 2;
        NormalRayBisector arb(p, q, is_signed);
        const ComplexSystem system{EllipseShape::of(p), EllipseShape::of(q), is_signed};
        const double mid = facing_angle(p, q) + 0.4 * unit(rng);
        ComplexBall theta0, s0;
        arb_set_d(theta0.real(), mid);
        REQUIRE(arb.solve(theta0, 128, s0));
        const double s_mid = arf_get_d(arb_midref(s0.real()), ARF_RND_NEAR);
        double px, py, nx, ny;
        system.p.point(mid, px, py);
        system.p.normal(mid, nx, ny);
        const double rho = s_mid * std::hypot(system.p.b * std::cos(mid), system.p.a * std::sin(mid));
        const double phi_mid = system.q.nearest_angle(px + rho * nx, py + rho * ny);
        for (const double t : {0.003, 0.01, 0.03}) {
            const double alpha = kPi * unit(rng);
            const ComplexSystem::Z theta(mid + t * std::cos(alpha), t * std::sin(alpha));
            ComplexSystem::Z s = s_mid, phi = phi_mid;
            system.newton(theta, s, phi);
            ComplexSystem::Z F[2];
            system(theta, s, phi, F);
            REQUIRE(std::abs(F[0]) + std::abs(F[1]) < 1e-12);
            for (const double radius : {0.0, 0.1 * t}) {
                ComplexBall ball, root;
                arb_set_d(ball.real(), theta.real());
                arb_set_d(ball.imag(), theta.imag());
                mag_set_d(arb_radref(ball.real()), radius);
                if (!arb.solve(ball, 128, root)) continue;
                ++compared;
                // Newton's root, within its rounding, lies in the ball.
                ComplexBall newton;
                arb_set_d(newton.real(), s.real());
                arb_set_d(newton.imag(), s.imag());
                mag_set_d(arb_radref(newton.real()), 1e-12);
                mag_set_d(arb_radref(newton.imag()), 1e-12);
                Ball re, im;
                arb_set(re.get(), root.real());
                arb_set(im.get(), root.imag());
                INFO("trial " << trial << " t " << t << " radius " << radius << " Arb " << re.str(15) << " + i "
                              << im.str(15) << ", Newton " << s.real() << " + i " << s.imag());
                CHECK(acb_overlaps(root.get(), newton.get()));
            }
        }
    }
    CHECK(compared >= 120);
}

TEST_CASE("integrate_edge: the area over an edge piece overlaps Arb's integral", "[cells][quadrature]") {
    std::mt19937_64 rng(7);
    GaussLegendreRules rules;
    int integrated = 0;
    for (int trial = 0; trial < 12; ++trial) {
        const auto [p, q] = random_pair(rng);
        NormalRayBisector reference(p, q);
        NormalRayInDoubles nodes(p, q);
        const double a = facing_angle(p, q) - 0.4, b = a + 0.8;
        // p's center is the origin: X and Y reach about 100.
        const Tolerances tolerance(1e-9, 100);
        const std::optional<MeasureIntervals> I = integrate_edge(nodes, rules, a, b, tolerance.t);
        REQUIRE(I);
        ++integrated;
        for (int j = 0; j < MeasureIntervals::count; ++j) CHECK(I->m[j].hi - I->m[j].lo <= 2 * tolerance.t[j]);
        Ball A, B;
        arb_set_d(A.get(), a);
        arb_set_d(B.get(), b);
        for (int j : {MeasureIntervals::x_dy, MeasureIntervals::y_dx, MeasureIntervals::length, MeasureIntervals::x2y_dy}) {
            const ComplexBall exact = integral_by_arb(reference, j, A, B, 1e-25, 128);
            REQUIRE(acb_is_finite(exact.get()));
            INFO("trial " << trial << " measure " << j << " doubles [" << I->m[j].lo << ", " << I->m[j].hi << "]");
            CHECK(overlap(I->m[j], exact));
        }
    }
    CHECK(integrated == 12);
}

TEST_CASE("integrate_edge_in_arb: 10^-25 over an edge piece, inside Arb's integral at 10^-30", "[cells][quadrature]") {
    std::mt19937_64 rng(11);
    GaussLegendreRules rules;
    const long prec = 128;
    for (int trial = 0; trial < 8; ++trial) {
        const auto [p, q] = random_pair(rng);
        NormalRayBisector nodes(p, q), reference(p, q);
        NormalRayInDoubles bounds(p, q);
        // Ends that are not doubles (a + 2^-70, b - 2^-70): the outer pieces
        // keep them exactly.
        const double a = facing_angle(p, q) - 0.4, b = a + 0.8;
        Ball ends[2];
        arb_set_d(ends[0].get(), a);
        arb_set_d(ends[1].get(), b);
        Ball tiny;
        arb_one(tiny.get());
        arb_mul_2exp_si(tiny.get(), tiny.get(), -70);
        arb_add(ends[0].get(), ends[0].get(), tiny.get(), prec);
        arb_sub(ends[1].get(), ends[1].get(), tiny.get(), prec);
        const Tolerances tolerance(1e-25, 100);
        QuadratureCounts counts;
        const std::optional<NormalRayBisector::Densities> I =
            integrate_edge_in_arb(bounds, nodes, rules, ends, tolerance.t, prec, &counts);
        REQUIRE(I);
        CHECK(counts.pieces >= 1);
        for (int j : {MeasureIntervals::x_dy, MeasureIntervals::y_dx, MeasureIntervals::x3_dy}) {
            const ComplexBall& ours = I->m[j];
            CHECK(mag_get_d(arb_radref(acb_realref(ours.get()))) <= tolerance.t[j]);
            const ComplexBall exact = integral_by_arb(reference, j, ends[0], ends[1], 1e-30, 160);
            REQUIRE(acb_is_finite(exact.get()));
            Ball a, b;
            arb_set(a.get(), acb_realref(ours.get()));
            arb_set(b.get(), acb_realref(exact.get()));
            INFO("trial " << trial << " measure " << j << " nodes in Arb " << a.str(30) << " Arb's " << b.str(30));
            CHECK(acb_overlaps(ours.get(), exact.get()));
        }
    }
}

TEST_CASE("integrate_edge: a range the bisector does not reach is not certified", "[cells][quadrature]") {
    // Two unit circles 10 apart: p's normal rays facing away from q never
    // meet the bisector; the stage must say so, not return a number.
    const Ellipse p = Ellipse::circle(Rational(0), Rational(0), Rational(1));
    const Ellipse q = Ellipse::circle(Rational(10), Rational(0), Rational(1));
    NormalRayInDoubles nodes(p, q);
    GaussLegendreRules rules;
    const Tolerances tolerance(1e-9);
    CHECK(!integrate_edge(nodes, rules, kPi - 0.2, kPi + 0.2, tolerance.t));
    CHECK(!nodes.densities(Interval(kPi)));
    NormalRayBisector arb_nodes(p, q);
    Ball ends[2];
    arb_set_d(ends[0].get(), kPi - 0.2);
    arb_set_d(ends[1].get(), kPi + 0.2);
    CHECK(!integrate_edge_in_arb(nodes, arb_nodes, rules, ends, tolerance.t, 128));
}
