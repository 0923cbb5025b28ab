#include "exact/real_roots.hpp"

#include "util/error.hpp"

#include <flint/fmpz_poly_factor.h>
#include <arb_fmpz_poly.h>

#include <algorithm>

namespace ellvor {

namespace {

long sign_variations(const fmpz_poly_struct* p) {
    long v = 0;
    int last = 0;
    for (long i = 0; i < p->length; ++i) {
        int s = fmpz_sgn(p->coeffs + i);
        if (s == 0) continue;
        if (last != 0 && s != last) ++v;
        last = s;
    }
    return v;
}

// Descartes' bound on the number of roots of q in the open interval (0, 1):
// the sign variations of (x+1)^n q(1/(x+1)).
long descartes_unit(const IntPolynomial& q) {
    IntPolynomial r;
    fmpz_poly_reverse(r.get(), q.get(), q.get()->length);
    Integer one(1);
    fmpz_poly_taylor_shift(r.get(), r.get(), one.get());
    return sign_variations(r.get());
}

// 2^n q(x/2) with n = deg q: the left half of (0,1) mapped to (0,1).
IntPolynomial halve(const IntPolynomial& q) {
    IntPolynomial r(q);
    long n = q.degree();
    for (long i = 0; i < n; ++i) fmpz_mul_2exp(r.get()->coeffs + i, r.get()->coeffs + i, n - i);
    return r;
}

// A polynomial Q with Q(t) = 0 iff p(a + (b - a) t) = 0, a != b (same degree).
IntPolynomial to_unit(const IntPolynomial& p, const Rational& a, const Rational& b) {
    Rational w = b - a;
    const fmpz* an = fmpq_numref(a.get());
    const fmpz* ad = fmpq_denref(a.get());
    const fmpz* wn = fmpq_numref(w.get());
    const fmpz* wd = fmpq_denref(w.get());
    long n = p.degree();
    // x = (A + W t) / D with D = ad*wd, A = an*wd, W = wn*ad.
    Integer D, A, W, pw;
    fmpz_mul(D.get(), ad, wd);
    fmpz_mul(A.get(), an, wd);
    fmpz_mul(W.get(), wn, ad);
    IntPolynomial q(p);
    fmpz* c = q.get()->coeffs;
    if (!fmpz_is_one(D.get())) {
        fmpz_one(pw.get());
        for (long i = n; i >= 0; --i) {
            fmpz_mul(c + i, c + i, pw.get());
            fmpz_mul(pw.get(), pw.get(), D.get());
        }
    }
    if (!A.is_zero()) fmpz_poly_taylor_shift(q.get(), q.get(), A.get());
    c = q.get()->coeffs;
    fmpz_one(pw.get());
    for (long i = 0; i <= n; ++i) {
        fmpz_mul(c + i, c + i, pw.get());
        fmpz_mul(pw.get(), pw.get(), W.get());
    }
    fmpz_poly_primitive_part(q.get(), q.get());
    return q;
}

// A dyadic subinterval (c/2^k, (c+1)/2^k) of (0,1), or the point c/2^k.
struct Dyadic {
    Integer c;
    long k;
};

struct VcaNode {
    IntPolynomial q;  // roots in (0,1) <-> roots of the input in this node's interval
    Integer c;
    long k;
    long v;  // Descartes bound, >= 2
};

// Vincent–Collins–Akritas bisection on (0,1) for a squarefree Q of degree >= 1.
// Appends isolating open dyadic intervals and exact dyadic roots (never 0 or 1).
void vca(const IntPolynomial& Q, std::vector<Dyadic>& intervals, std::vector<Dyadic>& points) {
    long v0 = descartes_unit(Q);
    if (v0 == 0) return;
    if (v0 == 1) { intervals.push_back({Integer(0), 0}); return; }
    std::vector<VcaNode> stack;
    stack.push_back({Q, Integer(0), 0, v0});
    Integer one(1);
    while (!stack.empty()) {
        VcaNode node = std::move(stack.back());
        stack.pop_back();
        IntPolynomial left = halve(node.q);
        Integer c2;
        fmpz_mul_2exp(c2.get(), node.c.get(), 1);
        long k = node.k + 1;
        // left(1) = 2^n q(1/2): the midpoint is a root iff the coefficients sum to 0.
        Integer sum;
        for (long i = 0; i < left.get()->length; ++i) fmpz_add(sum.get(), sum.get(), left.get()->coeffs + i);
        IntPolynomial right;
        fmpz_poly_taylor_shift(right.get(), left.get(), one.get());
        Integer c2p1 = c2 + Integer(1);
        if (sum.is_zero()) {
            points.push_back({c2p1, k});
            fmpz_poly_shift_right(right.get(), right.get(), 1);
        }
        long vl = descartes_unit(left);
        // Descartes bounds are subadditive: V(left) + V(right) <= V(node).
        long vr = vl == node.v ? 0 : descartes_unit(right);
        if (vl == 1) intervals.push_back({c2, k});
        if (vr == 1) intervals.push_back({c2p1, k});
        if (vr >= 2) stack.push_back({std::move(right), c2p1, k, vr});
        if (vl >= 2) stack.push_back({std::move(left), c2, k, vl});
    }
}

// a + (b - a) c / 2^k.
Rational unit_to_x(const Rational& a, const Rational& w, const Integer& c, long k) {
    Rational t;
    fmpz_set(fmpq_numref(t.get()), c.get());
    fmpz_one(fmpq_denref(t.get()));
    fmpq_div_2exp(t.get(), t.get(), k);
    return a + w * t;
}

IntPolynomial derivative(const IntPolynomial& p) {
    IntPolynomial d;
    fmpz_poly_derivative(d.get(), p.get());
    return d;
}

// The sign of the squarefree f on (x, x + eps) for small eps > 0.
int sign_right_of(const IntPolynomial& f, const Rational& x) {
    int s = sign_at_rational(f, x);
    if (s != 0) return s;
    return sign_at_rational(derivative(f), x);  // simple root
}

// One bisection step of an isolating interval of the squarefree f, where
// s_lo is the sign of f on (lo, root).
void bisect_step(const IntPolynomial& f, IsolatingInterval& iv, int s_lo) {
    Rational m = iv.lo + iv.hi;
    fmpq_div_2exp(m.get(), m.get(), 1);
    int s = sign_at_rational(f, m);
    if (s == 0) {
        iv.lo = m;
        iv.hi = m;
    } else if (s == s_lo) {
        iv.lo = std::move(m);
    } else {
        iv.hi = std::move(m);
    }
}

// lo + j (hi - lo) / 2^e.
Rational grid_point(const Rational& lo, const Rational& w, const Integer& j, long e) {
    return unit_to_x(lo, w, j, e);
}

// One quadratic-interval-refinement attempt (Abbott): guesses the root's
// position by a secant step on a grid of 2^e cells and checks the guessed
// cell with two exact signs. Returns true when the interval shrank by 2^e.
bool qir_step(const IntPolynomial& f, IsolatingInterval& iv, int s_lo, long e) {
    long prec = std::max(iv.lo.bits(), iv.hi.bits()) + 2 * e + 64;
    Ball a(iv.lo, prec), b(iv.hi, prec), fa, fb, t;
    arb_fmpz_poly_evaluate_arb(fa.get(), f.get(), a.get(), prec);
    arb_fmpz_poly_evaluate_arb(fb.get(), f.get(), b.get(), prec);
    if (fa.certain_sign() == 0 || fb.certain_sign() == 0) return false;
    arb_sub(t.get(), fa.get(), fb.get(), prec);
    arb_div(t.get(), fa.get(), t.get(), prec);
    arb_mul_2exp_si(t.get(), t.get(), e);
    if (!arb_is_finite(t.get())) return false;
    Integer j, N;
    fmpz_one(N.get());
    fmpz_mul_2exp(N.get(), N.get(), e);
    arf_get_fmpz(j.get(), arb_midref(t.get()), ARF_RND_NEAR);
    if (fmpz_cmp_si(j.get(), 1) < 0) fmpz_one(j.get());
    Integer Nm1 = N - Integer(1);
    if (fmpz_cmp(j.get(), Nm1.get()) > 0) j = Nm1;
    Rational w = iv.width();
    Rational g = grid_point(iv.lo, w, j, e);
    int s = sign_at_rational(f, g);
    if (s == 0) { iv.lo = g; iv.hi = g; return true; }
    if (s == s_lo) {
        // root in (g, hi)
        Integer j1 = j + Integer(1);
        if (j1 == N) { iv.lo = std::move(g); return true; }
        Rational g1 = grid_point(iv.lo, w, j1, e);
        int s1 = sign_at_rational(f, g1);
        if (s1 == 0) { iv.lo = g1; iv.hi = g1; return true; }
        if (s1 != s_lo) { iv.lo = std::move(g); iv.hi = std::move(g1); return true; }
        iv.lo = std::move(g1);
        return false;
    }
    // root in (lo, g)
    Integer j1 = j - Integer(1);
    if (j1.is_zero()) { iv.hi = std::move(g); return true; }
    Rational g1 = grid_point(iv.lo, w, j1, e);
    int s1 = sign_at_rational(f, g1);
    if (s1 == 0) { iv.lo = g1; iv.hi = g1; return true; }
    if (s1 == s_lo) { iv.lo = std::move(g1); iv.hi = std::move(g); return true; }
    iv.hi = std::move(g1);
    return false;
}

// width <= 2^-bits ?
bool narrow_enough(const IsolatingInterval& iv, long bits) {
    // width <= 2^-bits; bits < 0 (a root far above 1 wanted to a few bits)
    // divides instead: fmpq_mul_2exp takes an unsigned exponent.
    Rational w = iv.width();
    if (bits >= 0)
        fmpq_mul_2exp(w.get(), w.get(), static_cast<ulong>(bits));
    else
        fmpq_div_2exp(w.get(), w.get(), static_cast<ulong>(-bits));
    return fmpz_cmp(fmpq_numref(w.get()), fmpq_denref(w.get())) <= 0;
}

// Isolates the roots of one squarefree factor f (degree >= 1) into out.
void isolate_squarefree(const IntPolynomial& f, int mult, std::vector<IsolatingInterval>& out) {
    if (f.degree() == 1) {
        Rational r(-f.coeff(0), f.coeff(1));
        out.push_back({r, r, mult});
        return;
    }
    IntPolynomial g(f);
    if (fmpz_is_zero(g.get()->coeffs)) {
        out.push_back({Rational(0), Rational(0), mult});
        fmpz_poly_shift_right(g.get(), g.get(), 1);
    }
    if (g.degree() <= 0) return;
    Integer bound;
    fmpz_poly_bound_roots(bound.get(), g.get());
    long k = fmpz_bits(bound.get());  // 2^k > bound
    Integer B(1);
    fmpz_mul_2exp(B.get(), B.get(), k);
    const Rational zero(0);
    for (int side = 0; side < 2; ++side) {
        Rational b(side == 0 ? B : -B);
        IntPolynomial Q = to_unit(g, zero, b);
        std::vector<Dyadic> intervals, points;
        vca(Q, intervals, points);
        for (const Dyadic& d : points) {
            Rational x = unit_to_x(zero, b, d.c, d.k);
            out.push_back({x, x, mult});
        }
        for (const Dyadic& d : intervals) {
            Rational x0 = unit_to_x(zero, b, d.c, d.k);
            Rational x1 = unit_to_x(zero, b, d.c + Integer(1), d.k);
            if (side == 0) out.push_back({std::move(x0), std::move(x1), mult});
            else out.push_back({std::move(x1), std::move(x0), mult});
        }
    }
}

bool by_position(const IsolatingInterval& a, const IsolatingInterval& b) {
    if (a.lo != b.lo) return a.lo < b.lo;
    return a.hi < b.hi;
}

}  // namespace

int sign_at_rational(const IntPolynomial& p, const Rational& x) {
    if (p.is_zero()) return 0;
    long prec = x.bits() + 64;
    Ball xb(x, prec), y;
    for (int attempt = 0; attempt < 2; ++attempt) {
        if (attempt > 0) {
            prec *= 2;
            xb = Ball(x, prec);
        }
        arb_fmpz_poly_evaluate_arb(y.get(), p.get(), xb.get(), prec);
        int s = y.certain_sign();
        if (s != 0) return s;
    }
    return p.sign_at(x);
}

std::vector<std::pair<IntPolynomial, int>> squarefree_factors(const IntPolynomial& p) {
    if (p.is_zero()) throw Error("squarefree_factors: zero polynomial");
    std::vector<std::pair<IntPolynomial, int>> result;
    if (p.degree() == 0) return result;
    IntFactorization fac;
    fmpz_poly_factor_squarefree(fac.get(), p.get());
    for (long i = 0; i < fac.get()->num; ++i) {
        IntPolynomial f(fac.get()->p + i);
        if (f.degree() < 1) continue;
        result.emplace_back(f.primitive_part(), static_cast<int>(fac.get()->exp[i]));
    }
    return result;
}

IntPolynomial squarefree_part(const IntPolynomial& p) {
    if (p.is_zero()) throw Error("squarefree_part: zero polynomial");
    if (p.degree() == 0) return IntPolynomial{1};
    IntPolynomial d = derivative(p), g, q;
    fmpz_poly_gcd(g.get(), p.get(), d.get());
    fmpz_poly_div(q.get(), p.get(), g.get());
    return q.primitive_part();
}

std::vector<IsolatingInterval> isolate_real_roots(const std::vector<std::pair<IntPolynomial, int>>& factors) {
    std::vector<IsolatingInterval> roots;
    std::vector<size_t> owner;
    for (size_t i = 0; i < factors.size(); ++i) {
        isolate_squarefree(factors[i].first, factors[i].second, roots);
        owner.resize(roots.size(), i);
    }
    // Sort by position and refine overlapping neighbours (roots of different
    // factors); the intervals of one factor are disjoint already.
    std::vector<size_t> order(roots.size());
    for (;;) {
        for (size_t i = 0; i < order.size(); ++i) order[i] = i;
        std::sort(order.begin(), order.end(),
                  [&](size_t a, size_t b) { return by_position(roots[a], roots[b]); });
        bool clean = true;
        for (size_t i = 0; i + 1 < order.size(); ++i) {
            IsolatingInterval& a = roots[order[i]];
            IsolatingInterval& b = roots[order[i + 1]];
            if (!(b.lo < a.hi)) continue;
            clean = false;
            // Refine the wider non-exact one (both cannot be exact: distinct roots).
            size_t pick = order[i];
            if (a.is_exact() || (!b.is_exact() && a.width() < b.width())) pick = order[i + 1];
            const IntPolynomial& f = factors[owner[pick]].first;
            bisect_step(f, roots[pick], sign_right_of(f, roots[pick].lo));
        }
        if (clean) break;
    }
    // Endpoints must not be roots of p. Intervals are disjoint, so only exact
    // roots (of any factor, including the owner's bisection points) can be.
    std::vector<Rational> exact;
    for (const IsolatingInterval& r : roots)
        if (r.is_exact()) exact.push_back(r.lo);
    std::sort(exact.begin(), exact.end());
    auto is_root = [&](const Rational& x) { return std::binary_search(exact.begin(), exact.end(), x); };
    for (size_t i = 0; i < roots.size(); ++i) {
        IsolatingInterval& r = roots[i];
        const IntPolynomial& f = factors[owner[i]].first;
        while (!r.is_exact() && (is_root(r.lo) || is_root(r.hi)))
            bisect_step(f, r, sign_right_of(f, r.lo));
    }
    std::sort(roots.begin(), roots.end(), by_position);
    return roots;
}

std::vector<IsolatingInterval> isolate_real_roots(const IntPolynomial& p) {
    return isolate_real_roots(squarefree_factors(p));
}

void refine(const IntPolynomial& f, IsolatingInterval& iv, long bits) {
    if (iv.is_exact() || narrow_enough(iv, bits)) return;
    int s_lo = sign_right_of(f, iv.lo);
    long e = 1;  // the secant guess works on a grid of 2^e cells
    while (!iv.is_exact() && !narrow_enough(iv, bits)) {
        if (e >= 2 && qir_step(f, iv, s_lo, e)) {
            e *= 2;
        } else {
            e = std::max<long>(1, e / 2);
            bisect_step(f, iv, s_lo);
            if (e == 1) e = 2;
        }
    }
}

long count_real_roots(const IntPolynomial& p, const Rational& lo, const Rational& hi) {
    if (p.is_zero()) throw Error("count_real_roots: zero polynomial");
    if (!(lo < hi)) return 0;
    IntPolynomial s = squarefree_part(p);
    if (s.degree() < 1) return 0;
    IntPolynomial Q = to_unit(s, lo, hi);
    std::vector<Dyadic> intervals, points;
    vca(Q, intervals, points);
    return static_cast<long>(intervals.size() + points.size());
}

}  // namespace ellvor
