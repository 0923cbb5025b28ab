// Taylor models (util/complex_taylor_model.hpp), complex and real
// coefficients, against Arb at 200 bits: for random centers (real ones for
// real coefficients) and disk radii (0 included), each operation and
// a longer expression built from them, the exact function minus the model's
// polynomial, at random points of the disk and on its circle, is within the
// remainder, and the function lies in the model's enclosure of the disk; and
// the remainders are of the order the degree promises.
#include "util/complex_taylor_model.hpp"

#include "util/complex_ball.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <iterator>
#include <random>
#include <vector>

using namespace ellvor;

namespace {

constexpr long kPrec = 200;

ComplexInterval point(double re, double im) { return {Interval(re), Interval(im)}; }

// |truth - polynomial(d)| <= remainder, the polynomial evaluated in Arb
// from its exact coefficients.
void set_coefficient(ComplexBall& b, const taylor_model_detail::Complex& z) { acb_set_d_d(b.get(), z.re, z.im); }
void set_coefficient(ComplexBall& b, double x) { acb_set_d(b.get(), x); }

template <class Model>
bool within(const Model& model, const ComplexBall& d, const ComplexBall& truth) {
    ComplexBall p, coefficient;
    for (int k = static_cast<int>(std::size(model.c)) - 1; k >= 0; --k) {
        acb_mul(p.get(), p.get(), d.get(), kPrec);
        set_coefficient(coefficient, model.c[k]);
        acb_add(p.get(), p.get(), coefficient.get(), kPrec);
    }
    acb_sub(p.get(), truth.get(), p.get(), kPrec);
    Ball distance;
    acb_abs(distance.get(), p.get(), kPrec);
    Arf upper, remainder;
    arb_get_ubound_arf(upper.get(), distance.get(), kPrec);
    arf_set_d(remainder.get(), model.remainder);
    return arb_is_finite(distance.get()) && arf_cmp(upper.get(), remainder.get()) <= 0;
}

// The rectangle holds the ball.
bool holds(const ComplexInterval& rectangle, const ComplexBall& z) {
    const auto part_holds = [](const Interval& x, const arb_t y) {
        Arf lo, hi;
        arb_get_lbound_arf(lo.get(), y, kPrec);
        arb_get_ubound_arf(hi.get(), y, kPrec);
        return arb_is_finite(y) && arf_cmp_d(lo.get(), x.lo) >= 0 && arf_cmp_d(hi.get(), x.hi) <= 0;
    };
    return part_holds(rectangle.re, acb_realref(z.get())) && part_holds(rectangle.im, acb_imagref(z.get()));
}

// A function of theta in both arithmetics.
template <class Model>
struct Case {
    const char* name;
    std::function<Model(const Model&)> model;
    std::function<void(ComplexBall&, const ComplexBall&)> exact;
};

template <class M>
std::vector<Case<M>> cases() {
    const auto ball = [](double x) {
        ComplexBall b;
        acb_set_d(b.get(), x);
        return b;
    };
    return {
        {"sin", [](const M& t) { M s, c; sin_cos(t, s, c); return s; },
         [](ComplexBall& r, const ComplexBall& t) { acb_sin(r.get(), t.get(), kPrec); }},
        {"cos", [](const M& t) { M s, c; sin_cos(t, s, c); return c; },
         [](ComplexBall& r, const ComplexBall& t) { acb_cos(r.get(), t.get(), kPrec); }},
        // The powers of w by products (w is not d itself).
        {"cos(t + t^2 / 4)", [](const M& t) { M s, c; sin_cos(t + Interval(0.25) * square(t), s, c); return c; },
         [](ComplexBall& r, const ComplexBall& t) {
             acb_sqr(r.get(), t.get(), kPrec);
             acb_mul_2exp_si(r.get(), r.get(), -2);
             acb_add(r.get(), r.get(), t.get(), kPrec);
             acb_cos(r.get(), r.get(), kPrec);
         }},
        {"principal root of t^2 + 4", [](const M& t) { return principal_root(square(t) + Interval(4.0)); },
         [](ComplexBall& r, const ComplexBall& t) {
             acb_sqr(r.get(), t.get(), kPrec);
             acb_add_ui(r.get(), r.get(), 4, kPrec);
             acb_sqrt(r.get(), r.get(), kPrec);
         }},
        {"1 / (t + 5)", [](const M& t) { return reciprocal(t + Interval(5.0)); },
         [](ComplexBall& r, const ComplexBall& t) {
             acb_add_ui(r.get(), t.get(), 5, kPrec);
             acb_inv(r.get(), r.get(), kPrec);
         }},
        {"[0.7, 0.7 + 2^-45] t^2 at its upper end (a real interval times a model)",
         [](const M& t) { return Interval(0.7, 0.7 + 0x1p-45) * square(t); },
         [ball](ComplexBall& r, const ComplexBall& t) {
             acb_sqr(r.get(), t.get(), kPrec);
             ComplexBall k = ball(0.7);
             arb_add(acb_realref(k.get()), acb_realref(k.get()), acb_realref(ball(0x1p-45).get()), kPrec);
             acb_mul(r.get(), r.get(), k.get(), kPrec);
         }},
        {"sin t cos(t + 1) t^2 - 2.5 t / (cos t + 3) + (1/3) t",
         [](const M& t) {
             M s, c, s1, c1;
             sin_cos(t, s, c);
             sin_cos(t + Interval(1.0), s1, c1);
             return s * c1 * square(t) - 2.5 * t / (c + Interval(3.0)) + (Interval(1.0) / Interval(3.0)) * t;
         },
         [ball](ComplexBall& r, const ComplexBall& t) {
             ComplexBall s, c, c1, a, b;
             acb_sin_cos(s.get(), c.get(), t.get(), kPrec);
             acb_add_ui(a.get(), t.get(), 1, kPrec);
             acb_cos(c1.get(), a.get(), kPrec);
             acb_mul(a.get(), s.get(), c1.get(), kPrec);
             acb_mul(a.get(), a.get(), t.get(), kPrec);
             acb_mul(a.get(), a.get(), t.get(), kPrec);
             acb_add_ui(b.get(), c.get(), 3, kPrec);
             acb_div(b.get(), t.get(), b.get(), kPrec);
             acb_mul(b.get(), b.get(), ball(2.5).get(), kPrec);
             acb_sub(r.get(), a.get(), b.get(), kPrec);
             acb_div_ui(a.get(), t.get(), 3, kPrec);
             acb_add(r.get(), r.get(), a.get(), kPrec);
         }},
    };
}

template <class Model>
void check_against_arb(unsigned seed) {
    constexpr int N = static_cast<int>(std::size(Model().c)) - 1;
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> unit(0, 1);
    const double radii[] = {0, 1e-6, 1e-3, 0.05, 0.3};
    int checked = 0;
    for (const Case<Model>& c : cases<Model>())
        for (double R : radii)
            for (int trial = 0; trial < 6; ++trial) {
                const double re = -3 + 6 * unit(random), im = Model::is_real ? 0 : -0.5 + unit(random);
                // Half the trials start from a rectangle, not a point: the
                // model's constant is then uncertain, and the exact theta is
                // anywhere in it.
                const double width = trial % 2 ? 1e-9 : 0;
                const ComplexInterval center(Interval(re - width, re + width), Interval(im - width, im + width));
                const Model theta = Model::variable(center, R);
                const Model model = c.model(theta);
                INFO(c.name << " at " << re << " + " << im << "i, R = " << R << ", remainder " << model.remainder);
                REQUIRE(std::isfinite(model.remainder));
                for (int sample = 0; sample < 12; ++sample) {
                    const double rho = sample < 4 ? R : R * std::sqrt(unit(random)), angle = 6.283185307179586 * unit(random);
                    // Points of the disk in doubles: pull them in by a relative 2^-40.
                    const double dx = rho * std::cos(angle) * (1 - 0x1p-40), dy = rho * std::sin(angle) * (1 - 0x1p-40);
                    // theta = c + d for a point c of the rectangle (a double,
                    // well inside it).
                    const double sx = width * (2 * unit(random) - 1) * 0.99, sy = width * (2 * unit(random) - 1) * 0.99;
                    ComplexBall d, t, truth;
                    acb_set_d_d(d.get(), dx, dy);
                    acb_set_d_d(t.get(), re + sx, im + sy);
                    acb_add(t.get(), t.get(), d.get(), kPrec);
                    c.exact(truth, t);
                    CHECK(within(model, d, truth));
                    CHECK(holds(model.enclose_disk(), truth));
                    ++checked;
                }
                // Of the order the degree promises: R^(N+1) times the size of
                // the derivatives (at most a few hundred here), plus the
                // rounding and the constant's uncertainty.
                CHECK(model.remainder <= 300 * std::pow(R, N + 1) + 1e-12 + 1e3 * width);
            }
    CHECK(checked == static_cast<int>(cases<Model>().size()) * 5 * 6 * 12);
}

}  // namespace

TEST_CASE("complex Taylor models of degree 2 hold Arb's values on their disks", "[taylor_model]") {
    check_against_arb<ComplexTaylorModel<2>>(20261128);
}

TEST_CASE("complex Taylor models of degree 3 hold Arb's values on their disks", "[taylor_model]") {
    check_against_arb<ComplexTaylorModel<3>>(11282026);
}

TEST_CASE("real Taylor models of degrees 2 and 4 hold Arb's values on their disks", "[taylor_model]") {
    // Real centers: the functions are real on the reals, their Taylor
    // coefficients real; the disks are complex all the same.
    check_against_arb<RealTaylorModel<2>>(20261129);
    check_against_arb<RealTaylorModel<4>>(29112026);
}

TEST_CASE("real Taylor models: the same polynomial as the complex ones, a remainder no larger", "[taylor_model]") {
    // The expression of the last case above, about real centers in both
    // arithmetics: the real model's coefficients are the complex one's real
    // parts (their imaginary parts 0), and its remainder, with a quarter of
    // the products' roundings, is at most the complex one's.
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> unit(-3, 3);
    for (int trial = 0; trial < 50; ++trial) {
        const ComplexInterval center(Interval(unit(random)));
        const double R = 0.1 * std::fabs(unit(random));
        const auto expression = [](const auto& t) {
            auto s = t, c = t, s1 = t, c1 = t;
            sin_cos(t, s, c);
            sin_cos(t + Interval(1.0), s1, c1);
            return principal_root(s * c1 * square(t) + Interval(5.0)) - 2.5 * t / (c + Interval(3.0));
        };
        const RealTaylorModel<2> real = expression(RealTaylorModel<2>::variable(center, R));
        const ComplexTaylorModel<2> complex = expression(ComplexTaylorModel<2>::variable(center, R));
        for (int k = 0; k <= 2; ++k) {
            CHECK(complex.c[k].im == 0);
            CHECK(std::fabs(real.c[k] - complex.c[k].re) <= 1e-13 * (1 + std::fabs(complex.c[k].re)));
        }
        CHECK(real.remainder <= complex.remainder * (1 + 1e-9));
        // And a real model converted is the complex one of the same function.
        const ComplexTaylorModel<2> converted(real);
        CHECK(converted.c[1].re == real.c[1]);
        CHECK(converted.remainder == real.remainder);
    }
}

TEST_CASE("Taylor models truncated to a lower degree hold Arb's values on their disks", "[taylor_model]") {
    // sin(t) cos(t + 1) / (t + 3) of degree 4 about random real centers,
    // truncated to degrees 2 and 1: the dropped terms are in the remainder.
    std::mt19937_64 random(31);
    std::uniform_real_distribution<double> unit(0, 1);
    for (int trial = 0; trial < 40; ++trial) {
        const double center = -3 + 6 * unit(random), R = 0.4 * unit(random);
        using M = RealTaylorModel<4>;
        const M t = M::variable(ComplexInterval(Interval(center)), R);
        M s, c, s1, c1;
        sin_cos(t, s, c);
        sin_cos(t + Interval(1.0), s1, c1);
        const M f = s * c1 / (t + Interval(3.0));
        const RealTaylorModel<2> f2 = truncated<2>(f);
        const RealTaylorModel<1> f1 = truncated<1>(f);
        CHECK(f2.remainder >= f.remainder);
        CHECK(f1.remainder >= f2.remainder);
        for (int sample = 0; sample < 16; ++sample) {
            const double rho = R * (1 - 0x1p-40) * (sample < 4 ? 1 : std::sqrt(unit(random)));
            const double angle = 6.283185307179586 * unit(random);
            ComplexBall d, theta, truth, a, b;
            acb_set_d_d(d.get(), rho * std::cos(angle), rho * std::sin(angle));
            acb_set_d(theta.get(), center);
            acb_add(theta.get(), theta.get(), d.get(), kPrec);
            acb_sin(truth.get(), theta.get(), kPrec);
            acb_add_ui(a.get(), theta.get(), 1, kPrec);
            acb_cos(a.get(), a.get(), kPrec);
            acb_mul(truth.get(), truth.get(), a.get(), kPrec);
            acb_add_ui(b.get(), theta.get(), 3, kPrec);
            acb_div(truth.get(), truth.get(), b.get(), kPrec);
            INFO("center " << center << ", R " << R);
            CHECK(within(f2, d, truth));
            CHECK(within(f1, d, truth));
        }
    }
}

TEST_CASE("complex Taylor models: outside their domains the remainder is infinite", "[taylor_model]") {
    using M = ComplexTaylorModel<2>;
    const M t = M::variable(point(0.5, 0), 0.1);
    // A square root whose argument's real part is not positive at the center.
    CHECK(std::isinf(principal_root(t - Interval(1.0)).remainder));
    // A reciprocal of a model whose variation is as large as its constant.
    CHECK(std::isinf(reciprocal(t - Interval(0.45)).remainder));
    // Fine with room.
    CHECK(std::isfinite(reciprocal(t + Interval(1.0)).remainder));
}
