#include "exact/algebraic_real.hpp"

#include "util/error.hpp"

#include <arb_fmpz_poly.h>

#include <algorithm>
#include <utility>

namespace ellvor {

namespace {

IntPolynomial gcd(const IntPolynomial& a, const IntPolynomial& b) {
    IntPolynomial g;
    fmpz_poly_gcd(g.get(), a.get(), b.get());
    return g;
}

// floor(log2 |x|) up to one, for x != 0.
long approx_log2(const Rational& x) {
    return static_cast<long>(fmpz_bits(fmpq_numref(x.get()))) - static_cast<long>(fmpz_bits(fmpq_denref(x.get())));
}

// Decides whether the g (dividing the squarefree polynomials of x and y, and
// nonzero at the endpoints of the open interval (lo, hi)) has its (at most
// one, simple) root in (lo, hi).
bool has_root_inside(const IntPolynomial& g, const Rational& lo, const Rational& hi) {
    if (g.degree() < 1) return false;
    int a = sign_at_rational(g, lo), b = sign_at_rational(g, hi);
    return a != 0 && b != 0 && a != b;
}

// A ball containing [lo, hi].
Ball interval_ball(const Rational& lo, const Rational& hi, long prec) {
    Ball a(lo, prec), b(hi, prec), r;
    arb_union(r.get(), a.get(), b.get(), prec);
    return r;
}

}  // namespace

AlgebraicReal::AlgebraicReal() { set_rational(Rational(0)); }

AlgebraicReal AlgebraicReal::from_rational(const Rational& q) {
    AlgebraicReal a;
    a.set_rational(q);
    return a;
}

AlgebraicReal AlgebraicReal::from_interval(const IntPolynomial& p, const Rational& lo, const Rational& hi) {
    if (p.degree() < 1) throw Error("AlgebraicReal: constant polynomial");
    AlgebraicReal a;
    if (lo == hi) {
        if (p.sign_at(lo) != 0) throw Error("AlgebraicReal: point is not a root");
        a.set_rational(lo);
        return a;
    }
    if (!(lo < hi)) throw Error("AlgebraicReal: empty interval");
    IntPolynomial q = p.primitive_part();
    int sl = sign_at_rational(q, lo), sh = sign_at_rational(q, hi);
    if (sl == 0 || sh == 0 || sl == sh) throw Error("AlgebraicReal: no sign change on the interval");
    if (q.degree() == 1) {
        a.set_rational(Rational(-q.coeff(0), q.coeff(1)));
        return a;
    }
    a.p_ = std::move(q);
    a.lo_ = lo;
    a.hi_ = hi;
    a.sign_lo_ = sl;
    return a;
}

void AlgebraicReal::set_rational(const Rational& q) {
    lo_ = q;
    hi_ = q;
    IntPolynomial p;
    fmpz_poly_set_coeff_fmpz(p.get(), 1, fmpq_denref(q.get()));
    fmpz_poly_set_coeff_fmpz(p.get(), 0, fmpq_numref(q.get()));
    fmpz_neg(p.get()->coeffs, p.get()->coeffs);
    p_ = std::move(p);
    sign_lo_ = 0;
}

void AlgebraicReal::set_polynomial(const IntPolynomial& g) {
    IntPolynomial q = g.primitive_part();
    if (q.degree() == 1) {
        set_rational(Rational(-q.coeff(0), q.coeff(1)));
        return;
    }
    p_ = std::move(q);
    sign_lo_ = sign_at_rational(p_, lo_);
}

const Rational& AlgebraicReal::rational_value() const {
    if (!is_rational()) throw Error("AlgebraicReal: not a rational value");
    return lo_;
}

void AlgebraicReal::refine(long bits) {
    if (is_rational()) return;
    IsolatingInterval iv{std::move(lo_), std::move(hi_), 1};
    ellvor::refine(p_, iv, bits);
    if (iv.is_exact()) {
        set_rational(iv.lo);
    } else {
        lo_ = std::move(iv.lo);
        hi_ = std::move(iv.hi);
    }
}

void AlgebraicReal::split_at(const Rational& x) {
    if (is_rational() || !(lo_ < x) || !(x < hi_)) return;
    int s = sign_at_rational(p_, x);
    if (s == 0) set_rational(x);
    else if (s == sign_lo_) lo_ = x;
    else hi_ = x;
}

Ball AlgebraicReal::to_ball(long prec) {
    if (prec < 2) prec = 2;
    if (!is_rational()) {
        // Get zero out of the closed interval (the root is not zero, else the
        // split makes it rational), then refine relative to the magnitude.
        if (lo_.sign() < 0 && hi_.sign() > 0) split_at(Rational(0));
        for (long bits = 8; !is_rational() && (lo_.is_zero() || hi_.is_zero()); bits *= 2) refine(bits);
    }
    if (!is_rational()) refine(prec - approx_log2(lo_.sign() > 0 ? lo_ : hi_) + 2);
    return interval_ball(lo_, hi_, prec + 16);
}

double AlgebraicReal::to_double() {
    Ball b = to_ball(60);
    return b.mid_double();
}

std::string AlgebraicReal::str() const {
    if (is_rational()) return lo_.str();
    return "root of " + p_.str() + " in (" + lo_.str() + ", " + hi_.str() + ")";
}

int compare(AlgebraicReal& x, AlgebraicReal& y) {
    if (&x == &y) return 0;
    bool equality_checked = false;
    for (long bits = 16;; bits = bits * 2) {
        if (x.is_rational() && y.is_rational()) {
            const Rational &a = x.rational_value(), &b = y.rational_value();
            return a < b ? -1 : (b < a ? 1 : 0);
        }
        if (x.is_rational() || y.is_rational()) {
            bool flip = y.is_rational();
            AlgebraicReal& r = flip ? y : x;  // rational
            AlgebraicReal& a = flip ? x : y;  // interval
            const Rational q = r.rational_value();
            a.split_at(q);
            int c;
            if (a.is_rational()) c = q < a.rational_value() ? -1 : (a.rational_value() < q ? 1 : 0);
            else c = q <= a.lo() ? -1 : 1;  // q is not inside (lo, hi) any more
            return flip ? -c : c;
        }
        if (x.hi() <= y.lo()) return -1;
        if (y.hi() <= x.lo()) return 1;
        if (!equality_checked && bits >= 64) {
            // Overlapping after some refinement: decide equality exactly.
            equality_checked = true;
            IntPolynomial g = gcd(x.polynomial(), y.polynomial());
            const Rational& lo = x.lo() < y.lo() ? y.lo() : x.lo();
            const Rational& hi = x.hi() < y.hi() ? x.hi() : y.hi();
            if (has_root_inside(g, lo, hi)) {
                // Both are the root of g in (lo, hi); share the smaller data.
                Rational l(lo), h(hi);
                AlgebraicReal z = AlgebraicReal::from_interval(g, l, h);
                x = z;
                y = std::move(z);
                return 0;
            }
        }
        x.refine(bits);
        y.refine(bits);
    }
}

int sign_at(const IntPolynomial& q, AlgebraicReal& x) {
    if (q.is_zero()) return 0;
    if (x.is_rational()) return sign_at_rational(q, x.rational_value());
    bool zero_checked = false;
    long bits = std::max<long>(16, -approx_log2(x.hi() - x.lo()));
    for (;;) {
        if (x.is_rational()) return sign_at_rational(q, x.rational_value());
        long prec = bits + 64;
        Ball b = interval_ball(x.lo(), x.hi(), prec), v;
        arb_fmpz_poly_evaluate_arb(v.get(), q.get(), b.get(), prec);
        int s = v.certain_sign();
        if (s != 0) return s;
        if (!zero_checked) {
            zero_checked = true;
            IntPolynomial g = gcd(q, x.polynomial());
            if (has_root_inside(g, x.lo(), x.hi())) {
                Rational lo(x.lo()), hi(x.hi());
                x = AlgebraicReal::from_interval(g, lo, hi);
                return 0;
            }
        }
        bits *= 2;
        x.refine(bits);
    }
}

std::vector<AlgebraicReal> real_roots(const IntPolynomial& p) {
    std::vector<std::pair<IntPolynomial, int>> factors = squarefree_factors(p);
    std::vector<IsolatingInterval> roots = isolate_real_roots(factors);
    std::vector<AlgebraicReal> result;
    result.reserve(roots.size());
    for (const IsolatingInterval& r : roots) {
        if (r.is_exact()) {
            result.push_back(AlgebraicReal::from_rational(r.lo));
            continue;
        }
        const IntPolynomial* owner = nullptr;
        for (const auto& f : factors)
            if (f.second == r.multiplicity) owner = &f.first;
        if (owner == nullptr) throw Error("real_roots: internal error, no owning factor");
        result.push_back(AlgebraicReal::from_interval(*owner, r.lo, r.hi));
    }
    return result;
}

}  // namespace ellvor
