// Tests of exact/incircle_resultant: the degree-184 InCircle polynomial of
// three ellipses (and the lower degrees with circles), checked against the
// independently certified Voronoi circles of subdivision/voronoi_circle_enclosure.
#include "exact/incircle_resultant.hpp"

#include "sites/site_generators.hpp"
#include "subdivision/voronoi_circle_enclosure.hpp"

#include <arb_fmpz_poly.h>
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
