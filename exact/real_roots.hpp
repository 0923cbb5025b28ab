// Exact real root isolation for integer polynomials: Descartes' rule of signs
// with Vincent–Collins–Akritas bisection on exact dyadic intervals, exact
// root counting on a rational interval, and bisection refinement with exact
// signs. Generic: nothing here knows about geometry.
#pragma once

#include "util/flint_types.hpp"

#include <utility>
#include <vector>

namespace ellvor {

// One distinct real root of a polynomial p.
//  - lo == hi: the root is exactly the rational lo.
//  - lo < hi: exactly one distinct real root of p lies in the OPEN interval
//    (lo, hi), and p(lo) != 0, p(hi) != 0.
// multiplicity is the multiplicity of the root in p (>= 1).
struct IsolatingInterval {
    Rational lo, hi;
    int multiplicity = 1;

    bool is_exact() const { return lo == hi; }
    Rational width() const { return hi - lo; }
};

// The squarefree factorization p = c * prod f_i^{e_i}: each f_i is primitive
// with positive leading coefficient, of degree >= 1, the e_i are distinct and
// the f_i pairwise coprime. Throws Error on the zero polynomial.
std::vector<std::pair<IntPolynomial, int>> squarefree_factors(const IntPolynomial& p);

// p / gcd(p, p'), primitive with positive leading coefficient (1 for constants).
// Throws Error on the zero polynomial.
IntPolynomial squarefree_part(const IntPolynomial& p);

// All distinct real roots of p, sorted ascending, pairwise disjoint, with
// multiplicities. Throws Error on the zero polynomial; a nonzero constant has
// no roots. Each open interval contains no root of p other than its own, so
// it isolates that root for squarefree_part(p) and for the squarefree factor
// owning it (the one whose exponent is the multiplicity); p is nonzero at all
// endpoints of non-exact intervals. A rational root is reported exactly only
// when it has a linear squarefree factor or lands on a bisection point;
// otherwise it gets an interval like any other root.
std::vector<IsolatingInterval> isolate_real_roots(const IntPolynomial& p);

// The same for p = prod f_i^{e_i} given by its squarefree factorization
// (as returned by squarefree_factors: squarefree, pairwise coprime, distinct
// e_i); the root owned by f_i gets multiplicity e_i.
std::vector<IsolatingInterval> isolate_real_roots(const std::vector<std::pair<IntPolynomial, int>>& factors);

// Shrinks iv (an interval of the kind above for the squarefree polynomial
// squarefree_p, or for a squarefree factor owning the root) until
// hi - lo <= 2^-bits, or it becomes exact when a bisection point is the root.
// The invariants of IsolatingInterval are preserved. Uses exact signs only.
void refine(const IntPolynomial& squarefree_p, IsolatingInterval& iv, long bits);

// The number of distinct real roots of p in the open interval (lo, hi), exact.
// 0 when lo >= hi. Throws Error on the zero polynomial.
long count_real_roots(const IntPolynomial& p, const Rational& lo, const Rational& hi);

// The exact sign of p at the rational x (Arb-filtered, exact fallback).
int sign_at_rational(const IntPolynomial& p, const Rational& x);

}  // namespace ellvor
