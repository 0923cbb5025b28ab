// The univariate InCircle resultant of an ordered triple (E1, E2, E3)
// (seed section 3.1, system (4), expression (5), Lemma 3.1).
//
// With t, r, s the boundary parameters of E1, E2, E3:
//     Q(t, r, s) = 0      the three normals are concurrent,
//     B12(t, r)  = 0      bisector_polynomial(E1, E2),
//     B31(s, t)  = 0      bisector_polynomial(E3, E1) (s is E3's parameter),
//     R1(t, r) = res_s(Q, B31),   R2(t) = res_r(R1, B12).
// The tangency parameter t (on E1) of every circle tangent to the three
// ellipses at (t, r, s) with finite parameters is a root of R2. R2 carries
// known extraneous factors: powers of (1 + t^2) and of the parallel-normals
// polynomials of (E1, E3) and (E1, E2). We remove every one of them as far as
// it divides (the exponents are detected, not assumed: circles break the
// seed's exponents), and return the squarefree part of what is left ("the
// wanted factor"): degree 184 for three ellipses in general position.
//
// Before eliminating, every factor (1 + u^2) of Q is removed (a circle's
// normal carries one); the bisectors have none.
//
// Method: multi-modular. For each word-size prime p, the wanted factor mod p
// is interpolated from its values at t0 in Z/p; each value is
//     res_r( R1(t0, r), B12(t0, r) ) / (known factors)(t0),
// R1(t0, r) itself being interpolated in r from res_s(Q(t0, r0, s), B31(s, t0)).
// Points where a leading coefficient vanishes are skipped, so every value is
// the image of the resultant with the formal (= actual integer) degrees.
// The factor structure (exponents, degree) is found on the first prime from
// the full R2 mod p. The integer coefficients come from CRT (symmetric
// residues); we stop once the candidate reproduces the images modulo
// `verification_primes` + 1 successive fresh primes (stabilisation, then
// re-verification), which makes a wrong answer vanishingly unlikely but is not
// a proof (no coefficient bound is used). The small resultants use a
// division-free (pseudo-remainder) Euclidean algorithm and the r-interpolation
// a precomputed Lagrange basis, so a prime costs about 3-4 ms.
//
// Caveats: a tangency at the i-point (t = infinity) shows only as a degree
// drop, not as a root. Dividing the known factors out "while they divide"
// also removes a root that the wanted factor shares with them (a tritangent
// circle at a collinear-normals parameter, a codimension-1 degeneracy);
// generic_exponents = false flags every departure from the seed's exponents.
#pragma once

#include "sites/ellipse.hpp"
#include "util/flint_types.hpp"

#include <string>
#include <utility>
#include <vector>

namespace ellvor {

struct IncircleResultantOptions {
    // The primes are the successive primes above this value (< 2^63).
    unsigned long first_prime = (1UL << 62);
    // Fresh primes that must reproduce the candidate after it stabilised.
    int verification_primes = 3;
};

struct IncircleResultant {
    // Primitive, positive leading coefficient, squarefree part of the wanted
    // factor of R2 (see above). Never the zero polynomial.
    IntPolynomial polynomial;
    long degree = -1;  // polynomial.degree()
    // Every factor divided out, with its exponent, as human-readable labels:
    //   "Q:(1+t^2)" etc.      factors removed from Q before eliminating,
    //   "R1:<factor>"         exponent of the factor in R1 = res_s(Q, B31),
    //   "R2:<factor>"         exponent in the seed's R2 = res_r(R1', B12),
    //                         R1' = R1 without its known factors,
    //   "square-part"         degree removed when taking the squarefree part.
    // <factor> is "1+t^2" or "parnorm12" / "parnorm13" (the parallel-normals
    // polynomial of (E1, E2) / (E1, E3)), or "parnorm12[deg d]" for an
    // irreducible factor of degree d when that polynomial is reducible.
    std::vector<std::pair<std::string, int>> removed_factors;
    // True iff the exponents are exactly the seed's (R1: (1+t^2)^4 parnorm13;
    // R2: (1+t^2)^28 parnorm12^6), the wanted factor is squarefree and has
    // degree 184.
    bool generic_exponents = false;
    // Degree of the wanted factor expected from the triple's type: 184 (no
    // circle), 72 (one circle), 24 (two), 8 (three). Informational: same-shape
    // ellipse pairs and special placements give lower degrees.
    long expected_degree = 0;
    long r2_degree = -1;  // degree of the full R2 = res_r(R1, B12)
    long primes_used = 0;
    long coefficient_bits = 0;  // max bits of the coefficients of `polynomial`
    double seconds = 0;
};

// Throws Error when the resultant vanishes identically (a common component of
// the system, e.g. some placements of three circles), or when the modular
// computation cannot be made consistent.
IncircleResultant incircle_resultant(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3,
                                     const IncircleResultantOptions& options = {});

}  // namespace ellvor
