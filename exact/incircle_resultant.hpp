// The univariate InCircle resultant of an ordered triple (E1, E2, E3)
// (the paper, section 3.1, system (4), expression (5), Lemma 3.1).
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
// paper's exponents), and return the squarefree part of what is left ("the
// wanted factor"): degree 184 for three ellipses in general position.
//
// Before eliminating, every factor (1 + u^2) of Q is removed (a circle's
// normal carries one); the bisectors have none.
//
// Method: multi-modular with a proven stopping rule. Modulo each word-size
// prime p the formal double resultant
//     R2f(t) = res_r^{(D, deg_r B12)}(R1f, B12),   R1f = res_s^{(deg_s Q, deg_s B31)}(Q, B31),
// (every resultant a Sylvester determinant with the formal degrees,
// D = deg_r Q * deg_s B31) is interpolated from its values at deg R2f + 1
// points t0, each value res_r(R1f(t0, r), B12(t0, r)) with R1f(t0, r)
// interpolated in r from res_s(Q(t0, r0, s), B31(s, t0)); a leading zero of
// R1f(t0, .) or Q(t0, r0, .) is accounted for by the formal-degree identity
// (only roots of lc(B31) or lc(B12) are skipped), so every value is the image
// of one fixed integer polynomial, with no "unlucky" prime or point. A
// Hadamard bound on the Sylvester rows over the unit torus bounds every
// coefficient of R2f (see coefficient_bound_bits); primes are taken until
// their product exceeds twice the bound, and CRT (symmetric residues) gives R2f
// over Z: a proof. R2 = R2f / lc_r(B12)^(D - deg_r R1) (the actual degree,
// proven from the same images), the known factors are divided out exactly
// over Z (their exponents are found, not assumed), and the rest is made
// squarefree and primitive. Images are computed by `threads` workers; a prime
// costs about 8 ms for three ellipses (433 points).
//
// Caveats: a tangency at the i-point (t = infinity) shows only as a degree
// drop, not as a root. Dividing the known factors out "while they divide"
// also removes a root that the wanted factor shares with them (a tritangent
// circle at a collinear-normals parameter, a codimension-1 degeneracy);
// generic_exponents = false flags every departure from the paper's exponents.
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
    // Workers computing modular images (0: one per hardware thread).
    int threads = 0;
};

struct IncircleResultant {
    // Primitive, positive leading coefficient, squarefree part of the wanted
    // factor of R2 (see above). Never the zero polynomial.
    IntPolynomial polynomial;
    long degree = -1;  // polynomial.degree()
    // Every factor divided out, with its exponent, as human-readable labels:
    //   "Q:(1+t^2)" etc.      factors removed from Q before eliminating,
    //   "R2:<factor>"         exponent of the factor in R2 = res_r(R1, B12)
    //                         (exact, by division over Z),
    //   "square-part"         degree removed when taking the squarefree part.
    // <factor> is "1+t^2" or "parnorm12" / "parnorm13" (the parallel-normals
    // polynomial of (E1, E2) / (E1, E3)), or "parnorm12[deg d]" for an
    // irreducible factor of degree d when that polynomial is reducible.
    std::vector<std::pair<std::string, int>> removed_factors;
    // True iff the exponents are exactly the paper's (Lemma 3.1: R1 carries
    // (1+t^2)^4 parnorm13 and res_r(R1', B12) (1+t^2)^28 parnorm12^6, so R2 holds
    // (1+t^2)^52 parnorm13^6 parnorm12^6), the wanted factor is squarefree and
    // has degree 184.
    bool generic_exponents = false;
    // Degree of the wanted factor expected from the triple's type: 184 (no
    // circle), 72 (one circle), 24 (two), 8 (three). Informational: same-shape
    // ellipse pairs and special placements give lower degrees.
    long expected_degree = 0;
    long r1_degree = -1;  // deg_r R1 (below the formal deg_r Q * deg_s B31 for some circles)
    long r2_degree = -1;  // degree of the full R2 = res_r(R1, B12)
    long bound_bits = 0;   // proven bound on the bits of R2f's coefficients
    long primes_used = 0;  // primes whose product exceeds 2^(bound_bits + 1)
    long coefficient_bits = 0;  // max bits of the coefficients of `polynomial`
    double seconds = 0;
};

// Throws Error when the resultant vanishes identically (a common component of
// the system, e.g. some placements of three circles), or when the modular
// computation cannot be made consistent.
IncircleResultant incircle_resultant(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3,
                                     const IncircleResultantOptions& options = {});

}  // namespace ellvor
