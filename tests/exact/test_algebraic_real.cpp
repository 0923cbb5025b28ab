// Tests of AlgebraicReal: exact comparison (including exact ties decided by
// gcds and near ties), exact signs of polynomials at algebraic numbers, and
// certified enclosures.
#include "exact/algebraic_real.hpp"

#include <catch2/catch.hpp>

#include <flint/flint.h>

#include <vector>

using namespace ellvor;

namespace {

IntPolynomial mul(const IntPolynomial& a, const IntPolynomial& b) {
    IntPolynomial r;
    fmpz_poly_mul(r.get(), a.get(), b.get());
    return r;
}

// The largest real root of p.
AlgebraicReal largest_root(const IntPolynomial& p) {
    auto r = real_roots(p);
    REQUIRE(!r.empty());
    return r.back();
}

// 2^k as a Rational.
Rational pow2(long k) {
    Rational r(1);
    if (k >= 0) fmpq_mul_2exp(r.get(), r.get(), k);
    else fmpq_div_2exp(r.get(), r.get(), -k);
    return r;
}

struct RandState {
    flint_rand_t s;
    RandState() { flint_randinit(s); }
    ~RandState() { flint_randclear(s); }
    RandState(const RandState&) = delete;
    RandState& operator=(const RandState&) = delete;
};

}  // namespace

TEST_CASE("AlgebraicReal: sqrt(2) against rationals and near ties", "[exact]") {
    AlgebraicReal s = largest_root(IntPolynomial{-2, 0, 1});
    REQUIRE(!s.is_rational());
    AlgebraicReal a = AlgebraicReal::from_rational(Rational(14142, 10000));
    AlgebraicReal b = AlgebraicReal::from_rational(Rational(14143, 10000));
    REQUIRE(compare(s, a) == 1);
    REQUIRE(compare(a, s) == -1);
    REQUIRE(compare(s, b) == -1);
    // The dyadic truncation t of sqrt(2) at 140 bits: t < sqrt(2) < t + 2^-140.
    AlgebraicReal s2 = largest_root(IntPolynomial{-2, 0, 1});
    s2.refine(200);
    Rational t = s2.lo();
    {
        Rational scaled = t;
        fmpq_mul_2exp(scaled.get(), scaled.get(), 140);
        Integer fl;
        fmpz_fdiv_q(fl.get(), fmpq_numref(scaled.get()), fmpq_denref(scaled.get()));
        t = Rational(fl) * pow2(-140);
    }
    AlgebraicReal lo = AlgebraicReal::from_rational(t);
    AlgebraicReal hi = AlgebraicReal::from_rational(t + pow2(-140));
    AlgebraicReal s3 = largest_root(IntPolynomial{-2, 0, 1});
    REQUIRE(compare(s3, lo) == 1);
    REQUIRE(compare(s3, hi) == -1);
    // A rational root of a cubic very close to sqrt(2): (2^140 x - n)(x^2 + 1).
    IntPolynomial lin;
    fmpz_poly_set_coeff_fmpz(lin.get(), 1, pow2(140).numerator().get());
    fmpz_poly_set_coeff_fmpz(lin.get(), 0, (-(t * pow2(140)).numerator()).get());
    AlgebraicReal r = largest_root(mul(lin, IntPolynomial{1, 0, 1}));
    AlgebraicReal tr = AlgebraicReal::from_rational(t);
    REQUIRE(compare(r, tr) == 0);  // found as a root of the squarefree cubic
    AlgebraicReal s4 = largest_root(IntPolynomial{-2, 0, 1});
    REQUIRE(compare(s4, r) == 1);
    // sqrt(2 + 2^-130) is a root of 2^130 x^2 - (2^131 + 1), just above sqrt(2).
    IntPolynomial q;
    fmpz_poly_set_coeff_fmpz(q.get(), 2, pow2(130).numerator().get());
    fmpz_poly_set_coeff_fmpz(q.get(), 0, (-(pow2(131).numerator() + Integer(1))).get());
    AlgebraicReal u = largest_root(q);
    AlgebraicReal s5 = largest_root(IntPolynomial{-2, 0, 1});
    REQUIRE(compare(s5, u) == -1);
    REQUIRE(compare(u, s5) == 1);
}

TEST_CASE("AlgebraicReal: exact equality through gcds", "[exact]") {
    AlgebraicReal s = largest_root(IntPolynomial{-2, 0, 1});
    // (x^2 - 2)(x^3 - 5): roots -sqrt2, sqrt2, cbrt5; sqrt2 is the middle one.
    auto r = real_roots(mul(IntPolynomial{-2, 0, 1}, IntPolynomial{-5, 0, 0, 1}));
    REQUIRE(r.size() == 3);
    REQUIRE(compare(s, r[1]) == 0);
    REQUIRE(compare(r[1], s) == 0);
    REQUIRE(compare(s, r[2]) == -1);
    REQUIRE(compare(r[0], s) == -1);
    // The positive root of x^6 - 4 is 2^(1/3), the real root of x^3 - 2.
    AlgebraicReal c1 = largest_root(IntPolynomial{-4, 0, 0, 0, 0, 0, 1});
    AlgebraicReal c2 = largest_root(IntPolynomial{-2, 0, 0, 1});
    REQUIRE(compare(c1, c2) == 0);
    REQUIRE(c1.polynomial().degree() == 3);  // replaced by the gcd
    // cbrt(2) < sqrt(2); cbrt(3) > sqrt(2).
    AlgebraicReal c3 = largest_root(IntPolynomial{-3, 0, 0, 1});
    REQUIRE(compare(c2, s) == -1);
    REQUIRE(compare(c3, s) == 1);
    // Roots that are equal but come from very different factorizations.
    AlgebraicReal d1 = largest_root(mul(mul(IntPolynomial{-3, 0, 0, 1}, IntPolynomial{-7, 1, 1}), IntPolynomial{-100, 1}));
    AlgebraicReal hundred = AlgebraicReal::from_rational(Rational(100));
    REQUIRE(compare(d1, hundred) == 0);
    REQUIRE(d1.is_rational());  // the gcd with x - 100 made it rational
    auto d2 = real_roots(mul(IntPolynomial{-3, 0, 0, 1}, IntPolynomial{-7, 1, 1}));
    AlgebraicReal c4 = largest_root(IntPolynomial{-3, 0, 0, 1});
    int zeros = 0;
    for (auto& x : d2) zeros += compare(x, c4) == 0;
    REQUIRE(zeros == 1);
    // A rational root defined by a higher degree factor compares equal to it.
    AlgebraicReal h = AlgebraicReal::from_interval(mul(IntPolynomial{-1, 3}, IntPolynomial{-2, 0, 1}), Rational(0), Rational(1));
    REQUIRE(h.is_rational() == false);
    AlgebraicReal third = AlgebraicReal::from_rational(Rational(1, 3));
    REQUIRE(compare(h, third) == 0);
    REQUIRE(compare(third, h) == 0);
}

TEST_CASE("AlgebraicReal: from_interval validation", "[exact]") {
    REQUIRE_THROWS(AlgebraicReal::from_interval(IntPolynomial{-2, 0, 1}, Rational(2), Rational(3)));
    REQUIRE_THROWS(AlgebraicReal::from_interval(IntPolynomial{-2, 0, 1}, Rational(2), Rational(1)));
    REQUIRE_THROWS(AlgebraicReal::from_interval(IntPolynomial{-2, 0, 1}, Rational(1), Rational(1)));
    REQUIRE_THROWS(AlgebraicReal::from_interval(IntPolynomial{3}, Rational(0), Rational(1)));
    AlgebraicReal x = AlgebraicReal::from_interval(IntPolynomial{-4, 0, 1}, Rational(2), Rational(2));
    REQUIRE(x.is_rational());
    AlgebraicReal y = AlgebraicReal::from_interval(IntPolynomial{-2, 0, 1}, Rational(-2), Rational(-1));
    REQUIRE(y.to_double() == Approx(-1.4142135623730951).epsilon(1e-15));
}

TEST_CASE("sign_at: vanishing and nearly vanishing polynomials", "[exact]") {
    AlgebraicReal s = largest_root(IntPolynomial{-2, 0, 1});
    REQUIRE(sign_at(IntPolynomial{-1, 1}, s) == 1);
    REQUIRE(sign_at(IntPolynomial{-2, 1}, s) == -1);
    REQUIRE(sign_at(mul(IntPolynomial{-2, 0, 1}, IntPolynomial{3, 1}), s) == 0);
    REQUIRE(sign_at(mul(IntPolynomial{-2, 0, 1}, IntPolynomial{-3, 1}), s) == 0);
    // A root of q sits 2^-131-ish above sqrt(2): q = 2^130 x^2 - (2^131 + 1),
    // q(sqrt2) = -1 exactly.
    IntPolynomial q;
    fmpz_poly_set_coeff_fmpz(q.get(), 2, pow2(130).numerator().get());
    fmpz_poly_set_coeff_fmpz(q.get(), 0, (-(pow2(131).numerator() + Integer(1))).get());
    AlgebraicReal s2 = largest_root(IntPolynomial{-2, 0, 1});
    REQUIRE(sign_at(q, s2) == -1);
    IntPolynomial mq = q;
    fmpz_poly_neg(mq.get(), mq.get());
    REQUIRE(sign_at(mq, s2) == 1);
    // At a rational value, and with the zero polynomial.
    AlgebraicReal half = AlgebraicReal::from_rational(Rational(1, 2));
    REQUIRE(sign_at(IntPolynomial{-1, 2}, half) == 0);
    REQUIRE(sign_at(IntPolynomial{0, 0, 1}, half) == 1);
    REQUIRE(sign_at(IntPolynomial(), s2) == 0);
    // Mignotte cluster: m = x^30 - 2(33x-1)^2 has two roots ~33^-15 apart
    // on either side of 1/33; m' has opposite signs at them.
    IntPolynomial m;
    fmpz_poly_set_coeff_si(m.get(), 30, 1);
    IntPolynomial sq = mul(IntPolynomial{-1, 33}, IntPolynomial{-1, 33});
    fmpz_poly_scalar_mul_si(sq.get(), sq.get(), 2);
    fmpz_poly_sub(m.get(), m.get(), sq.get());
    auto mr = real_roots(m);
    REQUIRE(mr.size() == 4);
    IntPolynomial dm;
    fmpz_poly_derivative(dm.get(), m.get());
    // Ascending: negative root, the close pair near 1/33, the root near 1.
    REQUIRE(sign_at(dm, mr[1]) == -sign_at(dm, mr[2]));
    REQUIRE(sign_at(m, mr[1]) == 0);
    REQUIRE(sign_at(IntPolynomial{-1, 33}, mr[1]) == -1);
    REQUIRE(sign_at(IntPolynomial{-1, 33}, mr[2]) == 1);
}

TEST_CASE("AlgebraicReal: to_ball is certified and accurate", "[exact]") {
    AlgebraicReal s = largest_root(IntPolynomial{-2, 0, 1});
    for (long prec : {10L, 53L, 300L, 2000L}) {
        Ball b = s.to_ball(prec);
        Ball exact, two;
        arb_set_ui(two.get(), 2);
        arb_sqrt(exact.get(), two.get(), prec + 64);
        INFO("prec " << prec << ": " << b.str());
        REQUIRE(arb_overlaps(b.get(), exact.get()));
        REQUIRE(arb_rel_accuracy_bits(b.get()) >= prec - 4);
    }
    // Tiny roots +-sqrt(3) 2^-100 of 2^200 x^2 - 3: relative accuracy.
    IntPolynomial tiny;
    fmpz_poly_set_coeff_fmpz(tiny.get(), 2, pow2(200).numerator().get());
    fmpz_poly_set_coeff_si(tiny.get(), 0, -3);
    auto tr = real_roots(tiny);
    REQUIRE(tr.size() == 2);
    Ball b = tr[0].to_ball(100);
    REQUIRE(arb_is_negative(b.get()));
    REQUIRE(arb_rel_accuracy_bits(b.get()) >= 96);
}

TEST_CASE("compare: antisymmetry, transitivity and agreement with Arb", "[exact]") {
    RandState st;
    std::vector<AlgebraicReal> pool;
    for (int t = 0; t < 25; ++t) {
        long deg = 1 + n_randint(st.s, 6);
        IntPolynomial p;
        for (long i = 0; i <= deg; ++i) fmpz_poly_set_coeff_si(p.get(), i, static_cast<long>(n_randint(st.s, 21)) - 10);
        if (p.degree() < 1) continue;
        if (t % 4 == 0) p = mul(p, IntPolynomial{-2, 0, 1});  // shared sqrt(2): exact ties
        for (auto& x : real_roots(p)) pool.push_back(x);
    }
    REQUIRE(pool.size() > 20);
    std::vector<Ball> balls;
    for (auto& x : pool) balls.push_back(x.to_ball(200));
    for (int t = 0; t < 400; ++t) {
        size_t i = n_randint(st.s, pool.size()), j = n_randint(st.s, pool.size()), k = n_randint(st.s, pool.size());
        INFO(pool[i].str() << " / " << pool[j].str() << " / " << pool[k].str());
        int ij = compare(pool[i], pool[j]), ji = compare(pool[j], pool[i]);
        REQUIRE(ij == -ji);
        int jk = compare(pool[j], pool[k]), ik = compare(pool[i], pool[k]);
        if (ij <= 0 && jk <= 0) REQUIRE(ik <= 0);
        if (ij >= 0 && jk >= 0) REQUIRE(ik >= 0);
        if (ij == 0 && jk == 0) REQUIRE(ik == 0);
        if (arb_lt(balls[i].get(), balls[j].get())) REQUIRE(ij == -1);
        if (arb_gt(balls[i].get(), balls[j].get())) REQUIRE(ij == 1);
        if (ij == 0) REQUIRE(arb_overlaps(balls[i].get(), balls[j].get()));
    }
}
