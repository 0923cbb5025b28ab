// Tests of exact/incircle_resultant: the degree-184 InCircle polynomial of
// three ellipses (and the lower degrees with circles), checked against the
// independently certified Voronoi circles of subdivision/voronoi_circle_enclosure.
#include "exact/incircle_resultant.hpp"

#include "sites/ellipse_polynomials.hpp"
#include "sites/site_generators.hpp"
#include "subdivision/voronoi_circle_enclosure.hpp"

#include <arb_fmpz_poly.h>
#include <flint/fmpz_mpoly.h>
#include <catch2/catch.hpp>

#include <cstdint>
#include <random>
#include <sstream>

using namespace ellvor;

namespace {

// p/q with q in [1, 2^bits], |p/q| <= range, from our own integer draws.
Rational draw(std::mt19937_64& rng, long lo, long hi, long bits) {
    const std::uint64_t q = 1 + rng() % (1ULL << bits);
    const std::uint64_t span = static_cast<std::uint64_t>(hi - lo) * q;
    const long p = static_cast<long>(rng() % (span + 1)) + lo * static_cast<long>(q);
    return Rational(p, static_cast<unsigned long>(q));
}

Ellipse random_ellipse(std::mt19937_64& rng, long bits, bool circle) {
    Rational a = draw(rng, 1, 4, bits), b = draw(rng, 1, 4, bits);
    while (a == b || a.is_zero() || b.is_zero()) b = draw(rng, 1, 4, bits);
    while (a.is_zero()) a = draw(rng, 1, 4, bits);
    Rational x = draw(rng, -20, 20, bits), y = draw(rng, -20, 20, bits);
    if (circle) return Ellipse::circle(x, y, a);
    return Ellipse(a, b, draw(rng, -3, 3, bits), x, y);
}

// Three pairwise separated sites; circles where mask has a bit.
std::array<Ellipse, 3> random_triple(std::mt19937_64& rng, long bits, int circle_mask = 0) {
    for (;;) {
        Ellipse e1 = random_ellipse(rng, bits, circle_mask & 1), e2 = random_ellipse(rng, bits, circle_mask & 2),
                e3 = random_ellipse(rng, bits, circle_mask & 4);
        if (bounding_circles_separated(e1, e2) && bounding_circles_separated(e1, e3) &&
            bounding_circles_separated(e2, e3))
            return {e1, e2, e3};
    }
}

// |R(t)| at the ball t contains 0 (the ball is evaluated at `prec` bits).
bool vanishes_at(const IntPolynomial& p, const Ball& t, long prec) {
    Ball v;
    arb_fmpz_poly_evaluate_arb(v.get(), p.get(), t.get(), prec);
    return arb_contains_zero(v.get()) != 0;
}

// Relative size of R(t) versus R's value scale (to make sure the enclosure
// test above is not vacuous): true iff the ball is small relative to the sum
// of |coefficient| |t|^i.
bool tight(const IntPolynomial& p, const Ball& t, long prec) {
    Ball v, absv, scale;
    arb_fmpz_poly_evaluate_arb(v.get(), p.get(), t.get(), prec);
    IntPolynomial ap = p;
    for (long i = 0; i <= ap.degree(); ++i) fmpz_abs(ap.get()->coeffs + i, ap.get()->coeffs + i);
    arb_abs(absv.get(), t.get());
    arb_fmpz_poly_evaluate_arb(scale.get(), ap.get(), absv.get(), prec);
    // radius(v) < 2^-500 scale
    Ball bound;
    arb_mul_2exp_si(bound.get(), scale.get(), -500);
    return arf_cmpabs_mag(arb_midref(bound.get()), arb_radref(v.get())) > 0;
}

// The tangency parameters on E1 of the Voronoi circles of (e1, e2, e3) and
// (e1, e3, e2) (the counter-clockwise and clockwise tritangent circles) that
// the subdivision solver certifies.
std::vector<Ball> voronoi_tangency_parameters(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3, long prec) {
    std::vector<Ball> out;
    for (int order = 0; order < 2; ++order) {
        VoronoiCircleSolver solver(e1, order ? e3 : e2, order ? e2 : e3);
        if (!solver.certify() || !solver.refine(prec)) continue;
        Ball t = solver.enclosure().tangency_parameter(0, prec + 64);
        if (arb_is_finite(t.get())) out.push_back(t);
    }
    return out;
}

std::string describe(const IncircleResultant& r) {
    std::ostringstream os;
    os << "degree " << r.degree << " (R2 " << r.r2_degree << ", expected " << r.expected_degree << "), "
       << r.coefficient_bits << " bits, " << r.primes_used << " primes, " << r.seconds << " s, generic "
       << r.generic_exponents << "; removed:";
    for (const auto& f : r.removed_factors) os << " " << f.first << "^" << f.second;
    return os.str();
}

bool squarefree(const IntPolynomial& p) {
    IntPolynomial d, g;
    fmpz_poly_derivative(d.get(), p.get());
    fmpz_poly_gcd(g.get(), p.get(), d.get());
    return g.degree() == 0;
}


// R2 = res_r(res_s(Q, B31), B12) by FLINT's generic multivariate resultant:
// an oracle independent of our modular evaluation/interpolation, CRT and bound.
class MultivariateOracle {
public:
    MultivariateOracle() { fmpz_mpoly_ctx_init(ctx_, 3, ORD_LEX); }  // variables t, r, s
    ~MultivariateOracle() { fmpz_mpoly_ctx_clear(ctx_); }
    MultivariateOracle(const MultivariateOracle&) = delete;
    MultivariateOracle& operator=(const MultivariateOracle&) = delete;

    IntPolynomial r2(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3) {
        DensePolynomial Q = normals_concurrency_polynomial(e1, e2, e3);
        for (int var = 0; var < 3; ++var) Q.remove_one_plus_square_factors(var);
        const DensePolynomial B12 = bisector_polynomial(e1, e2), B31 = bisector_polynomial(e3, e1);
        fmpz_mpoly_t q, b12, b31, r1, r2;
        for (auto* p : {q, b12, b31, r1, r2}) fmpz_mpoly_init(p, ctx_);
        set(q, Q, {0, 1, 2});
        set(b12, B12, {0, 1, 2});
        set(b31, B31, {2, 0, 1});  // B31's variables are (s, t)
        REQUIRE(fmpz_mpoly_resultant(r1, q, b31, 2, ctx_));
        REQUIRE(fmpz_mpoly_resultant(r2, r1, b12, 1, ctx_));
        IntPolynomial out;
        std::vector<ulong> e(3);
        for (slong i = 0; i < fmpz_mpoly_length(r2, ctx_); ++i) {
            fmpz_mpoly_get_term_exp_ui(e.data(), r2, i, ctx_);
            REQUIRE(e[1] == 0);
            REQUIRE(e[2] == 0);
            fmpz_poly_set_coeff_fmpz(out.get(), static_cast<slong>(e[0]), fmpz_mpoly_term_coeff_ref(r2, i, ctx_));
        }
        for (auto* p : {q, b12, b31, r1, r2}) fmpz_mpoly_clear(p, ctx_);
        return out;
    }

private:
    // P's variable v becomes the oracle's variable slot[v].
    void set(fmpz_mpoly_t out, const DensePolynomial& P, std::array<int, 3> slot) {
        fmpz_mpoly_zero(out, ctx_);
        for (int i = 0; i <= std::max(P.degree(0), 0); ++i)
            for (int j = 0; j <= std::max(P.degree(1), 0); ++j)
                for (int k = 0; k <= std::max(P.degree(2), 0); ++k) {
                    const Integer c = P.coeff(i, j, k);
                    std::vector<ulong> e(3, 0);
                    e[slot[0]] += i, e[slot[1]] += j, e[slot[2]] += k;
                    fmpz_mpoly_set_coeff_fmpz_ui(out, c.get(), e.data(), ctx_);
                }
    }
    fmpz_mpoly_ctx_t ctx_;
};

// The wanted factor from a full R2 by the same definition as incircle_resultant:
// (1+t^2) and the parallel-normals factors divided out while they divide,
// squarefree, primitive, positive leading coefficient.
IntPolynomial wanted_factor(IntPolynomial r2, const Ellipse& e1, const Ellipse& e2, const Ellipse& e3) {
    IntFactorization all;
    for (const IntPolynomial& p : {IntPolynomial{1, 0, 1}, parallel_normals_polynomial(e1, e3),
                                   parallel_normals_polynomial(e1, e2)}) {
        IntFactorization f;
        fmpz_poly_factor(f.get(), p.get());
        for (slong i = 0; i < f.get()->num; ++i) {
            IntPolynomial quotient;
            while (fmpz_poly_degree(f.get()->p + i) > 0 && fmpz_poly_divides(quotient.get(), r2.get(), f.get()->p + i))
                r2 = quotient;
        }
    }
    IntPolynomial d, g;
    fmpz_poly_derivative(d.get(), r2.get());
    fmpz_poly_gcd(g.get(), r2.get(), d.get());
    if (g.degree() > 0) fmpz_poly_div(r2.get(), r2.get(), g.get());
    fmpz_poly_primitive_part(r2.get(), r2.get());
    if (fmpz_sgn(fmpz_poly_lead(r2.get())) < 0) fmpz_poly_neg(r2.get(), r2.get());
    return r2;
}
}  // namespace

TEST_CASE("InCircle resultant of generic ellipse triples has degree 184 and vanishes at the Voronoi circles",
          "[exact][resultant]") {
    std::mt19937_64 rng(20261121);
    const long prec = 2048;
    int checked_roots = 0;
    for (int iter = 0; iter < 3; ++iter) {
        auto e = random_triple(rng, 10);
        INFO(e[0].str() << " | " << e[1].str() << " | " << e[2].str());
        IncircleResultant r = incircle_resultant(e[0], e[1], e[2]);
        INFO(describe(r));
        CHECK(r.degree == 184);
        CHECK(r.generic_exponents);
        CHECK(r.r2_degree == 312 + 120);
        CHECK(fmpz_sgn(fmpz_poly_lead(r.polynomial.get())) > 0);
        IntPolynomial pp;
        fmpz_poly_primitive_part(pp.get(), r.polynomial.get());
        CHECK(pp == r.polynomial);
        CHECK(squarefree(r.polynomial));
        for (const Ball& t : voronoi_tangency_parameters(e[0], e[1], e[2], prec)) {
            INFO("t = " << t.str(30));
            CHECK(vanishes_at(r.polynomial, t, prec + 4 * r.coefficient_bits));
            CHECK(tight(r.polynomial, t, prec + 4 * r.coefficient_bits));
            ++checked_roots;
        }
    }
    CHECK(checked_roots >= 3);
}

TEST_CASE("InCircle resultant: the wanted factor also vanishes at internal circles of crossing ellipses",
          "[exact][resultant][overlap]") {
    // Three pairwise crossing ellipses (a = 3, b = 2) with a small common
    // part: the counter-clockwise circle is internal (rho < 0, certified by
    // the signed-distance certificate, DESIGN.md §4.1). Its tangency
    // parameter on E1 is a root of the same degree-184 factor (§9): the ball
    // of the value contains 0, is tight, and the factor changes sign across
    // t -+ 2^-250.
    const long prec = 1024;
    const Ellipse e1(Rational(3), Rational(2), Rational(0), Rational(0), Rational(0));
    const Ellipse e2(Rational(3), Rational(2), Rational(1), Rational(4), Rational(0));
    for (const Rational& y3 : {Rational(3), Rational(7, 2UL)}) {
        const Ellipse e3(Rational(3), Rational(2), Rational(1, 3UL), Rational(2), y3);
        INFO(e1.str() << " | " << e2.str() << " | " << e3.str());
        VoronoiCircleSolver solver(e1, e2, e3);
        REQUIRE(solver.certify());
        REQUIRE(solver.refine(prec));
        CHECK(arb_is_negative(solver.enclosure().radius.get()));
        const Ball t = solver.enclosure().tangency_parameter(0, prec + 64);
        const IncircleResultant r = incircle_resultant(e1, e2, e3);
        INFO(describe(r));
        CHECK(r.degree == 184);
        CHECK(vanishes_at(r.polynomial, t, prec + 4 * r.coefficient_bits));
        CHECK(tight(r.polynomial, t, prec + 4 * r.coefficient_bits));
        int signs[2];
        for (int side : {0, 1}) {
            Ball x, v;
            arb_get_mid_arb(x.get(), t.get());
            Ball step;
            arb_set_si(step.get(), side ? 1 : -1);
            arb_mul_2exp_si(step.get(), step.get(), -250);
            arb_add(x.get(), x.get(), step.get(), prec);
            arb_fmpz_poly_evaluate_arb(v.get(), r.polynomial.get(), x.get(), prec + 4 * r.coefficient_bits);
            signs[side] = v.certain_sign();
        }
        CHECK(signs[0] * signs[1] == -1);
    }
}

TEST_CASE("InCircle resultant is reproducible and independent of the primes", "[exact][resultant]") {
    std::mt19937_64 rng(777);
    auto e = random_triple(rng, 8);
    IncircleResultant a = incircle_resultant(e[0], e[1], e[2]);
    IncircleResultant b = incircle_resultant(e[0], e[1], e[2]);
    IncircleResultantOptions other;
    other.first_prime = (1UL << 62) + (1UL << 60);
    IncircleResultant c = incircle_resultant(e[0], e[1], e[2], other);
    INFO(describe(a));
    CHECK(a.polynomial == b.polynomial);
    CHECK(a.polynomial == c.polynomial);
    CHECK(a.removed_factors == c.removed_factors);
    CHECK(a.degree == 184);
}

TEST_CASE("InCircle resultant with circles", "[exact][resultant]") {
    std::mt19937_64 rng(4242);
    const long prec = 1024;
    // mask: which of E1, E2, E3 are circles; expected degrees from exact-notes.md.
    const std::pair<int, long> cases[] = {{1, 72}, {2, 72}, {4, 72}, {5, 24}, {7, 8}};
    for (const auto& c : cases) {
        auto e = random_triple(rng, 8, c.first);
        INFO("circle mask " << c.first << ": " << e[0].str() << " | " << e[1].str() << " | " << e[2].str());
        IncircleResultant r = incircle_resultant(e[0], e[1], e[2]);
        INFO(describe(r));
        REQUIRE(r.degree > 0);
        CHECK(r.expected_degree == c.second);
        CHECK(r.degree == c.second);
        CHECK_FALSE(r.generic_exponents);
        CHECK_FALSE(r.removed_factors.empty());
        CHECK(squarefree(r.polynomial));
        for (const Ball& t : voronoi_tangency_parameters(e[0], e[1], e[2], prec))
            CHECK(vanishes_at(r.polynomial, t, prec + 4 * r.coefficient_bits));
    }
}

TEST_CASE("InCircle resultant agrees with FLINT's multivariate resultant, within the proven bound",
          "[exact][resultant]") {
    std::mt19937_64 rng(91);
    MultivariateOracle oracle;
    // Generic ellipses (the paper's exponents), then circles: the r-degree of R1
    // drops below the formal one there, so R2f carries lc_r(B12) powers.
    const int masks[] = {0, 0, 1, 7};
    bool formal_degree_dropped = false;
    for (int mask : masks) {
        auto e = random_triple(rng, 3, mask);
        INFO("mask " << mask << ": " << e[0].str() << " | " << e[1].str() << " | " << e[2].str());
        const IncircleResultant r = incircle_resultant(e[0], e[1], e[2]);
        INFO(describe(r));
        const IntPolynomial r2 = oracle.r2(e[0], e[1], e[2]);
        CHECK(r2.degree() == r.r2_degree);
        CHECK(std::labs(fmpz_poly_max_bits(r2.get())) <= r.bound_bits);  // the bound holds
        CHECK(r.primes_used * 63 >= r.bound_bits + 2);                    // and the primes cover it
        CHECK(wanted_factor(r2, e[0], e[1], e[2]) == r.polynomial);
        const long formal = normals_concurrency_polynomial(e[0], e[1], e[2]).degree(1) * 6;
        formal_degree_dropped = formal_degree_dropped || r.r1_degree < formal;
    }
    CHECK(formal_degree_dropped);
}

TEST_CASE("InCircle resultant does not depend on the number of workers", "[exact][resultant]") {
    std::mt19937_64 rng(5150);
    auto e = random_triple(rng, 6);
    IncircleResultantOptions one, two;
    one.threads = 1, two.threads = 2;
    const IncircleResultant a = incircle_resultant(e[0], e[1], e[2], one), b = incircle_resultant(e[0], e[1], e[2], two);
    CHECK(a.degree == 184);
    CHECK(a.polynomial == b.polynomial);
    CHECK(a.primes_used == b.primes_used);
}
