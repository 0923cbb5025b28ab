#include "exact/medial_axis_tangency.hpp"

#include "exact/real_roots.hpp"
#include "sites/medial_axis.hpp"

#include <array>
#include <vector>

namespace ellvor {
namespace {

// An entry of a conic's matrix in the pencil: lambda * circle + site, each a
// polynomial in h.
struct PencilEntry {
    IntPolynomial circle, site;
};

// A polynomial in lambda whose coefficients are polynomials in h (index =
// power of lambda).
using LambdaPolynomial = std::vector<IntPolynomial>;

LambdaPolynomial as_lambda_polynomial(const PencilEntry& e) { return {e.site, e.circle}; }

LambdaPolynomial multiply(const LambdaPolynomial& p, const LambdaPolynomial& q) {
    LambdaPolynomial r(p.size() + q.size() - 1);
    IntPolynomial term;
    for (size_t i = 0; i < p.size(); ++i)
        for (size_t j = 0; j < q.size(); ++j) {
            fmpz_poly_mul(term.get(), p[i].get(), q[j].get());
            fmpz_poly_add(r[i + j].get(), r[i + j].get(), term.get());
        }
    return r;
}

void add_to(LambdaPolynomial& r, const LambdaPolynomial& p, int sign) {
    if (r.size() < p.size()) r.resize(p.size());
    for (size_t i = 0; i < p.size(); ++i) {
        if (sign > 0)
            fmpz_poly_add(r[i].get(), r[i].get(), p[i].get());
        else
            fmpz_poly_sub(r[i].get(), r[i].get(), p[i].get());
    }
}

// Lowest common multiple of the denominators.
Integer common_denominator(const std::vector<const Rational*>& values) {
    Integer l(1);
    for (const Rational* q : values) fmpz_lcm(l.get(), l.get(), fmpq_denref(q->get()));
    return l;
}

// scale * (c0 + c1 h + c2 h^2), an integer polynomial (scale clears the denominators).
IntPolynomial scaled(const Integer& scale, const std::array<Rational, 3>& c) {
    IntPolynomial p;
    for (int k = 0; k < 3; ++k) p.set_coeff(k, (c[k] * Rational(scale)).numerator());
    return p;
}

IntPolynomial product(std::initializer_list<const IntPolynomial*> factors, long constant) {
    IntPolynomial r{constant};
    for (const IntPolynomial* f : factors) fmpz_poly_mul(r.get(), r.get(), f->get());
    return r;
}

}  // namespace

IntPolynomial medial_circle_tangency_polynomial(const Ellipse& e, const Ellipse& f) {
    const std::optional<MedialAxis> axis = medial_axis(e);
    if (!axis) return IntPolynomial();
    // The circle about Q = C + h d of radius^2 s(h) = m^2 (1 - h^2/c^2):
    // x^2 + y^2 - 2 Qx x - 2 Qy y + |Q|^2 - s(h), |d| = 1.
    const Rational zero;
    const std::array<Rational, 3> one{Rational(1), zero, zero}, qx{-axis->cx, -axis->dx, zero},
        qy{-axis->cy, -axis->dy, zero},
        constant{axis->cx * axis->cx + axis->cy * axis->cy - axis->minor2,
                 Rational(2) * (axis->cx * axis->dx + axis->cy * axis->dy), Rational(1) + axis->minor2 / axis->focal2};
    const Integer circle_scale = common_denominator({&qx[0], &qx[1], &qy[0], &qy[1], &constant[0], &constant[1],
                                                     &constant[2]});
    // F's conic {A, B, C, D, E, F}: matrix [[A, B, D], [B, C, E], [D, E, F]]
    // (positive scales change neither conic).
    const auto& k = f.conic();
    const Integer site_scale = common_denominator({&k[0], &k[1], &k[2], &k[3], &k[4], &k[5]});
    const auto site = [&](int i) { return scaled(site_scale, {k[i], zero, zero}); };
    const std::array<std::array<PencilEntry, 3>, 3> m{{
        {{{scaled(circle_scale, one), site(0)}, {IntPolynomial(), site(1)}, {scaled(circle_scale, qx), site(3)}}},
        {{{IntPolynomial(), site(1)}, {scaled(circle_scale, one), site(2)}, {scaled(circle_scale, qy), site(4)}}},
        {{{scaled(circle_scale, qx), site(3)}, {scaled(circle_scale, qy), site(4)},
          {scaled(circle_scale, constant), site(5)}}},
    }};
    // det(lambda C + M) by the rule of Sarrus, a cubic in lambda.
    const auto entry = [&](int i, int j) { return as_lambda_polynomial(m[i][j]); };
    LambdaPolynomial det;
    for (int i = 0; i < 3; ++i) {
        add_to(det, multiply(multiply(entry(0, i), entry(1, (i + 1) % 3)), entry(2, (i + 2) % 3)), +1);
        add_to(det, multiply(multiply(entry(0, i), entry(1, (i + 2) % 3)), entry(2, (i + 1) % 3)), -1);
    }
    det.resize(4);
    const IntPolynomial &a = det[3], &b = det[2], &c = det[1], &d = det[0];
    // 18abcd - 4b^3 d + b^2 c^2 - 4a c^3 - 27 a^2 d^2
    IntPolynomial disc = product({&a, &b, &c, &d}, 18);
    fmpz_poly_add(disc.get(), disc.get(), product({&b, &b, &b, &d}, -4).get());
    fmpz_poly_add(disc.get(), disc.get(), product({&b, &b, &c, &c}, 1).get());
    fmpz_poly_add(disc.get(), disc.get(), product({&a, &c, &c, &c}, -4).get());
    fmpz_poly_add(disc.get(), disc.get(), product({&a, &a, &d, &d}, -27).get());
    return disc.is_zero() ? disc : disc.primitive_part();
}

bool common_medial_axis_tangency(const Ellipse& e, const Ellipse& f, const Ellipse& g, const Rational& f_lo,
                                 const Rational& f_hi, const Rational& g_lo, const Rational& g_hi) {
    const IntPolynomial pf = medial_circle_tangency_polynomial(e, f), pg = medial_circle_tangency_polynomial(e, g);
    if (pf.is_zero() || pg.is_zero()) return false;
    if (count_real_roots(pf, f_lo, f_hi) != 1 || count_real_roots(pg, g_lo, g_hi) != 1) return false;
    IntPolynomial common;
    fmpz_poly_gcd(common.get(), pf.get(), pg.get());
    if (common.degree() < 1) return false;
    const Rational lo = f_lo < g_lo ? g_lo : f_lo, hi = f_hi < g_hi ? f_hi : g_hi;
    return count_real_roots(common, lo, hi) >= 1;
}

}  // namespace ellvor
