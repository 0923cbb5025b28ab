// Tests of exact real root isolation, counting and refinement, against Arb's
// certified complex root finder as an independent oracle.
#include "exact/real_roots.hpp"

#include <catch2/catch.hpp>

#include <acb.h>
#include <arb_fmpz_poly.h>
#include <flint/flint.h>

#include <vector>

using namespace ellvor;

namespace {

struct RandState {
    flint_rand_t s;
    RandState() { flint_randinit(s); }
    ~RandState() { flint_randclear(s); }
    RandState(const RandState&) = delete;
    RandState& operator=(const RandState&) = delete;
};

// The real roots of p (as Arb balls, ascending) from arb_fmpz_poly_complex_roots
// applied to the squarefree part of p.
std::vector<Ball> arb_real_roots(const IntPolynomial& p, long prec) {
    IntPolynomial s = squarefree_part(p);
    long n = s.degree();
    std::vector<Ball> out;
    if (n < 1) return out;
    acb_ptr roots = _acb_vec_init(n);
    arb_fmpz_poly_complex_roots(roots, s.get(), 0, prec);
    for (long i = 0; i < n; ++i) {
        if (acb_is_real(roots + i)) {
            Ball b;
            arb_set(b.get(), acb_realref(roots + i));
            out.push_back(b);
        }
    }
    _acb_vec_clear(roots, n);
    return out;
}

IntPolynomial random_poly(RandState& st, long deg, long bits) {
    IntPolynomial p;
    for (long i = 0; i <= deg; ++i) {
        Integer c;
        fmpz_randbits(c.get(), st.s, bits);
        p.set_coeff(i, c);
    }
    if (p.coeff(deg).is_zero()) p.set_coeff(deg, Integer(1));
    return p;
}

// Is the Arb ball certainly inside the open interval (lo, hi), or equal to lo
// when the interval is exact?
bool ball_in(const Ball& x, const IsolatingInterval& iv) {
    if (iv.is_exact()) return x.contains(iv.lo);
    long prec = std::max(iv.lo.bits(), iv.hi.bits()) + 64;
    Ball lo(iv.lo, prec), hi(iv.hi, prec);
    return arb_lt(lo.get(), x.get()) && arb_lt(x.get(), hi.get());
}

// Structural checks of an isolation of p: sorted, disjoint, exact endpoint
// signs, and a one-to-one match with Arb's real roots.
void check_isolation(const IntPolynomial& p, const std::vector<IsolatingInterval>& r, long arb_prec = 128) {
    INFO("p = " << p.str());
    IntPolynomial s = squarefree_part(p);
    for (size_t i = 0; i < r.size(); ++i) {
        INFO("root " << i << " in [" << r[i].lo.str() << ", " << r[i].hi.str() << "]");
        REQUIRE(r[i].lo <= r[i].hi);
        REQUIRE(r[i].multiplicity >= 1);
        if (i + 1 < r.size()) REQUIRE(r[i].hi <= r[i + 1].lo);
        if (r[i].is_exact()) {
            REQUIRE(p.sign_at(r[i].lo) == 0);
        } else {
            int a = s.sign_at(r[i].lo), b = s.sign_at(r[i].hi);
            REQUIRE(a != 0);
            REQUIRE(b != 0);
            REQUIRE(a == -b);
            REQUIRE(p.sign_at(r[i].lo) != 0);
            REQUIRE(p.sign_at(r[i].hi) != 0);
        }
    }
    std::vector<Ball> arb = arb_real_roots(p, arb_prec);
    REQUIRE(arb.size() == r.size());
    std::vector<int> hits(r.size(), 0);
    for (const Ball& x : arb) {
        INFO("Arb root " << x.str());
        int inside = 0;
        for (size_t i = 0; i < r.size(); ++i)
            if (ball_in(x, r[i])) { ++inside; ++hits[i]; }
        REQUIRE(inside == 1);
    }
    for (int h : hits) REQUIRE(h == 1);
}

IntPolynomial linear(long num, long den) { return IntPolynomial{-num, den}; }  // den x - num

IntPolynomial mul(const IntPolynomial& a, const IntPolynomial& b) {
    IntPolynomial r;
    fmpz_poly_mul(r.get(), a.get(), b.get());
    return r;
}

IntPolynomial power(const IntPolynomial& a, long e) {
    IntPolynomial r;
    fmpz_poly_pow(r.get(), a.get(), e);
    return r;
}

}  // namespace

TEST_CASE("isolate_real_roots: random polynomials of degree 1..40 match Arb", "[exact]") {
    RandState st;
    for (long deg = 1; deg <= 40; ++deg) {
        for (long bits : {8L, 60L, 150L}) {
            IntPolynomial p = random_poly(st, deg, bits);
            check_isolation(p, isolate_real_roots(p));
        }
    }
}

TEST_CASE("isolate_real_roots: random degree-184 polynomials with 200-bit coefficients", "[exact]") {
    RandState st;
    for (int t = 0; t < 2; ++t) {
        IntPolynomial p = random_poly(st, 184, 200);
        check_isolation(p, isolate_real_roots(p));
    }
}

TEST_CASE("isolate_real_roots: trivial inputs", "[exact]") {
    REQUIRE_THROWS(isolate_real_roots(IntPolynomial()));
    REQUIRE(isolate_real_roots(IntPolynomial{5}).empty());
    REQUIRE(isolate_real_roots(IntPolynomial{1, 0, 1}).empty());  // x^2 + 1
    auto r = isolate_real_roots(IntPolynomial{0, 0, 0, 7});       // 7 x^3
    REQUIRE(r.size() == 1);
    REQUIRE(r[0].is_exact());
    REQUIRE(r[0].lo == Rational(0));
    REQUIRE(r[0].multiplicity == 3);
}

TEST_CASE("isolate_real_roots: products of linear factors with multiplicities", "[exact]") {
    struct Root { long num, den; int mult; };
    std::vector<std::vector<Root>> cases = {
        {{0, 1, 1}, {1, 2, 1}, {3, 4, 1}, {1, 3, 1}},
        {{0, 1, 2}, {1, 2, 3}, {-3, 4, 1}, {1, 3, 2}, {-1, 3, 3}},
        {{5, 7, 1}, {-5, 7, 2}, {1000, 1, 1}, {-1, 1000, 3}, {1, 1, 2}},
        {{1, 1, 1}, {2, 1, 1}, {4, 1, 1}, {-8, 1, 1}, {1, 1024, 2}},
        {{22, 7, 1}, {355, 113, 1}},  // two close non-dyadic rationals
    };
    for (const auto& roots : cases) {
        IntPolynomial p{3};
        for (const Root& r : roots) p = mul(p, power(linear(r.num, r.den), r.mult));
        p = mul(p, IntPolynomial{-2, 0, 1});  // and sqrt(2), -sqrt(2) simple
        INFO("p = " << p.str());
        auto iso = isolate_real_roots(p);
        check_isolation(p, iso);
        REQUIRE(iso.size() == roots.size() + 2);
        for (const Root& r : roots) {
            Rational x(r.num, static_cast<unsigned long>(r.den));
            INFO("root " << x.str());
            int found = 0;
            for (const auto& iv : iso) {
                bool in = iv.is_exact() ? iv.lo == x : (iv.lo < x && x < iv.hi);
                if (in) {
                    ++found;
                    REQUIRE(iv.multiplicity == r.mult);
                }
            }
            REQUIRE(found == 1);
        }
    }
}

TEST_CASE("isolate_real_roots: Mignotte-like clustered polynomials", "[exact]") {
    // x^d - 2 (33 x - 1)^2 has two roots about 33^(-d/2) apart near 1/33.
    for (long d : {20L, 25L, 30L, 40L, 50L, 60L}) {
        IntPolynomial p;
        fmpz_poly_set_coeff_si(p.get(), d, 1);
        IntPolynomial sq = mul(IntPolynomial{-1, 33}, IntPolynomial{-1, 33});
        fmpz_poly_scalar_mul_si(sq.get(), sq.get(), 2);
        fmpz_poly_sub(p.get(), p.get(), sq.get());
        INFO("d = " << d);
        auto iso = isolate_real_roots(p);
        REQUIRE(iso.size() == static_cast<size_t>(d % 2 == 0 ? 4 : 3));
        // Exactly two roots within 2^-40 of 1/33, in distinct intervals.
        Rational c(1, 33), eps(1, 1UL << 40);
        REQUIRE(count_real_roots(p, c - eps, c + eps) == 2);
        int near = 0;
        for (auto& iv : iso) {
            IntPolynomial s = squarefree_part(p);
            refine(s, iv, 60);
            if (c - eps < iv.lo && iv.hi < c + eps) ++near;
        }
        REQUIRE(near == 2);
        if (d <= 40) check_isolation(p, iso, 256);
    }
}

TEST_CASE("isolate_real_roots: Chebyshev and Wilkinson polynomials", "[exact]") {
    for (unsigned long n : {10UL, 31UL, 64UL}) {
        IntPolynomial t;
        fmpz_poly_chebyshev_t(t.get(), n);
        INFO("T_" << n);
        auto iso = isolate_real_roots(t);
        REQUIRE(iso.size() == n);
        // Root k is cos((2k - 1) pi / (2n)), in ascending order k = n..1.
        for (unsigned long i = 0; i < n; ++i) {
            Ball x, pi;
            arb_const_pi(pi.get(), 200);
            arb_mul_ui(x.get(), pi.get(), 2 * (n - i) - 1, 200);
            arb_div_ui(x.get(), x.get(), 2 * n, 200);
            arb_cos(x.get(), x.get(), 200);
            INFO("root " << i << " " << x.str());
            REQUIRE(ball_in(x, iso[i]));
        }
    }
    IntPolynomial w{1};
    for (long k = 1; k <= 20; ++k) w = mul(w, IntPolynomial{-k, 1});
    auto iso = isolate_real_roots(w);
    REQUIRE(iso.size() == 20);
    for (long k = 1; k <= 20; ++k) {
        const auto& iv = iso[k - 1];
        Rational x(k);
        INFO("k = " << k);
        REQUIRE((iv.is_exact() ? iv.lo == x : (iv.lo < x && x < iv.hi)));
    }
    // Wilkinson's perturbation: w - 2^-23 x^19 has complex roots.
    IntPolynomial pw = w;
    fmpz_poly_scalar_mul_2exp(pw.get(), pw.get(), 23);
    fmpz_poly_set_coeff_fmpz(pw.get(), 19, (pw.coeff(19) - Integer(1)).get());
    check_isolation(pw, isolate_real_roots(pw), 256);
}

TEST_CASE("count_real_roots on rational windows matches Arb", "[exact]") {
    RandState st;
    for (int t = 0; t < 60; ++t) {
        long deg = 2 + n_randint(st.s, 25);
        IntPolynomial p = random_poly(st, deg, 40);
        if (t % 3 == 0) p = mul(p, mul(IntPolynomial{-1, 3}, IntPolynomial{-1, 3}));  // double root 1/3
        std::vector<Ball> arb = arb_real_roots(p, 200);
        for (int w = 0; w < 5; ++w) {
            long a = static_cast<long>(n_randint(st.s, 81)) - 40, b = static_cast<long>(n_randint(st.s, 81)) - 40;
            Rational lo(a, 3 + n_randint(st.s, 5)), hi(b, 3 + n_randint(st.s, 5));
            if (w == 0) { lo = Rational(1, 3); hi = Rational(2); }  // a root at an endpoint is excluded
            INFO("p = " << p.str() << " on (" << lo.str() << ", " << hi.str() << ")");
            long expected = 0;
            bool ambiguous = false;
            Ball l(lo, 256), h(hi, 256);
            for (const Ball& x : arb) {
                if (arb_lt(l.get(), x.get()) && arb_lt(x.get(), h.get())) ++expected;
                else if (arb_overlaps(x.get(), l.get()) || arb_overlaps(x.get(), h.get())) ambiguous = true;
            }
            if (ambiguous) continue;
            REQUIRE(count_real_roots(p, lo, hi) == (lo < hi ? expected : 0));
        }
    }
}

TEST_CASE("refine: widths, exact sign changes and containment of Arb roots", "[exact]") {
    RandState st;
    for (int t = 0; t < 40; ++t) {
        long deg = 2 + n_randint(st.s, 30);
        IntPolynomial p = random_poly(st, deg, 30 + n_randint(st.s, 100));
        IntPolynomial s = squarefree_part(p);
        auto iso = isolate_real_roots(p);
        std::vector<Ball> arb = arb_real_roots(p, 1200);
        REQUIRE(arb.size() == iso.size());
        for (size_t i = 0; i < iso.size(); ++i) {
            size_t j = arb.size();
            for (size_t k = 0; k < arb.size(); ++k)
                if (ball_in(arb[k], iso[i])) j = k;
            REQUIRE(j < arb.size());
            for (long bits : {10L, 53L, 200L, 1000L}) {
                INFO("p = " << p.str() << ", root " << i << ", bits " << bits);
                refine(s, iso[i], bits);
                IsolatingInterval& iv = iso[i];
                if (iv.is_exact()) {
                    REQUIRE(s.sign_at(iv.lo) == 0);
                } else {
                    Rational w = iv.width();
                    fmpq_mul_2exp(w.get(), w.get(), bits);
                    REQUIRE(w <= Rational(1));
                    REQUIRE(s.sign_at(iv.lo) == -s.sign_at(iv.hi));
                    REQUIRE(s.sign_at(iv.lo) != 0);
                }
                REQUIRE(ball_in(arb[j], iv));
            }
        }
    }
}
