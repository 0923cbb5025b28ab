#include "subdivision/inscribed_disk.hpp"

#include <algorithm>
#include <array>
#include <optional>
#include <vector>

// Why the test proves the disk inside E (docs/DESIGN.md §4.1, §9). Fix one
// (V, rho, t) of the balls with P(t) + rho nu(t) = V and rho < 0, and let
// g(s) = |P(s) - V|^2 - rho^2 over the whole boundary.
//  - g(t) = 0 (|rho nu| = |rho|) and g'(t) = -2 rho P'(t).nu(t) = 0.
//  - In a chart, P = (X, Y)/W with W = L (1 + s^2) > 0, so g = Q/W^2 with
//    Q = (X - Vx W)^2 + (Y - Vy W)^2 - rho^2 W^2 a quartic; Q(t) = Q'(t) = 0.
//  - Local: if Q'' > 0 on an interval N holding t (proven for all V, rho in
//    the balls, so for this one), Taylor's theorem at t gives
//    Q(s) = Q''(xi)/2 (s - t)^2 > 0 for s in N, s != t.
//  - Global: Q > 0 on the rest of the boundary, proven on intervals of both
//    charts that cover it, the i-point (u = 0 of the flipped chart) included.
// So the closed disk D of radius |rho| about V meets the boundary only at
// P(t). D minus P(t) is connected and misses the boundary, so it lies
// entirely inside or entirely outside E; it contains P(t) - eps nu(t) for
// small eps > 0, which is inside E (nu is the outward normal). Hence
// D lies in E, V (at distance |rho| > 0 from P(t)) is interior, every other
// boundary point is farther than |rho|, and delta(V, E) = -|rho| = rho.
// (At rho = 0 the disk is the point P(t) itself; that case is not this
// test's: the certificate of §4.1 covers it.)
// With a mirror (V on an axis of symmetry of E, proven by the caller), g is
// the same at a boundary point and at its mirror image, so the local step
// also gives g > 0 on the mirror image of N minus t's image; the bisection
// covers the rest. Then D meets the boundary at most at P(t) and its mirror
// image; D minus two boundary points is still connected, and the same
// argument puts D in E.


namespace ellvor {

namespace {

// Cap on the parameter intervals examined per call, local walk and global
// bisection together: a certifiable circle needs a few dozen; a center
// beyond the medial axis, where another boundary point is nearer, ends
// long before on a point where Q is certainly negative.
constexpr long kMaxPieces = 4096;
// The local walk starts with steps of 1/16 of a chart's [-1, 1] and goes
// at most 1 beyond the ball t on each side, so N never wraps around the
// boundary (the rest is left to the bisection).
constexpr long kFirstStepLog2 = -4, kMaxStepLog2 = -2;
// The walk stops when its step falls below 2^-4 of N's width on that side.
constexpr long kRelativeStepLog2 = 4;

// Polynomials of degree <= 4 as coefficient balls, lowest degree first.
using Poly = std::array<Ball, 5>;

// Exact dyadic arithmetic on zero-radius balls (the interval endpoints).
Ball exact_add(const Ball& a, const Ball& b) {
    Ball r;
    arb_add(r.get(), a.get(), b.get(), ARF_PREC_EXACT);
    return r;
}
Ball exact_sub(const Ball& a, const Ball& b) {
    Ball r;
    arb_sub(r.get(), a.get(), b.get(), ARF_PREC_EXACT);
    return r;
}
Ball exact_half(const Ball& a) {
    Ball r;
    arb_mul_2exp_si(r.get(), a.get(), -1);
    return r;
}
Ball power_of_two(long e) {
    Ball r;
    arb_one(r.get());
    arb_mul_2exp_si(r.get(), r.get(), e);
    return r;
}
// The ball's lower (upper) end as an exact ball.
Ball end_of(const Ball& b, long prec, bool upper) {
    Ball r;
    Arf x;
    if (upper) arb_get_ubound_arf(x.get(), b.get(), prec);
    else arb_get_lbound_arf(x.get(), b.get(), prec);
    arb_set_arf(r.get(), x.get());
    return r;
}
Ball lower_end(const Ball& b, long prec) { return end_of(b, prec, false); }
Ball upper_end(const Ball& b, long prec) { return end_of(b, prec, true); }
bool less(const Ball& a, const Ball& b) { return arf_cmp(arb_midref(a.get()), arb_midref(b.get())) < 0; }

// u^4 p(-1/u): the quartic in the flipped chart (each of X, Y, W becomes
// u^2 p(-1/u), BoundaryChart).
Poly flip(const Poly& p) {
    Poly r;
    for (int j = 0; j <= 4; ++j) {
        arb_set(r[j].get(), p[4 - j].get());
        if (j % 2) arb_neg(r[j].get(), r[j].get());
    }
    return r;
}

enum class Sign { positive, negative_at_midpoint, unknown };

// Is p (degree <= deg) positive on [lo, hi]? The Taylor form at the midpoint
// m, p(m + h) = sum c_k h^k with |h| <= r: c_0 minus the odd terms' largest
// magnitude plus the even terms' most negative values. Exact up to the
// balls' own width where p is monotone or convex on the interval, so the
// bisection converges quadratically near a positive minimum. Also reports
// a midpoint value certainly negative: then no bisection can succeed.
Sign sign_on(const Poly& p, int deg, const Ball& lo, const Ball& hi, long prec) {
    const Ball m = exact_half(exact_add(lo, hi));
    const Ball r = exact_half(exact_sub(hi, lo));
    Poly c = p;
    // Taylor shift by repeated synthetic division.
    for (int i = 0; i < deg; ++i)
        for (int j = deg - 1; j >= i; --j) arb_addmul(c[j].get(), m.get(), c[j + 1].get(), prec);
    if (arb_is_negative(c[0].get())) return Sign::negative_at_midpoint;
    Ball bound = c[0], rk, term;
    arb_one(rk.get());
    for (int k = 1; k <= deg; ++k) {
        arb_mul(rk.get(), rk.get(), r.get(), prec);
        if (k % 2) {
            arb_abs(term.get(), c[k].get());
            arb_submul(bound.get(), term.get(), rk.get(), prec);
        } else if (!arb_is_nonnegative(c[k].get())) {
            // c_k h^k >= min(0, c_k) r^k: the ball c_k r^k reaches below that.
            arb_addmul(bound.get(), c[k].get(), rk.get(), prec);
        }
    }
    return arb_is_positive(bound.get()) ? Sign::positive : Sign::unknown;
}

// Q(s) = (X - Vx W)^2 + (Y - Vy W)^2 - rho^2 W^2 in the unflipped chart,
// with the ellipse's center subtracted first (exactly) so that the
// coefficients have the size of the ellipse, not of its position.
Poly distance_quartic(const Ellipse& e, const Ball& rho, const Ball& vx, const Ball& vy, long prec) {
    Ball dx, dy, rho2;
    arb_sub(dx.get(), vx.get(), Ball(e.xc(), prec).get(), prec);
    arb_sub(dy.get(), vy.get(), Ball(e.yc(), prec).get(), prec);
    arb_sqr(rho2.get(), rho.get(), prec);
    std::array<Ball, 3> A, B, W;
    for (int k = 0; k <= 2; ++k) {
        const Rational w(e.W().coeff(k));
        W[k] = Ball(w, prec);
        A[k] = Ball(Rational(e.X().coeff(k)) - e.xc() * w, prec);
        B[k] = Ball(Rational(e.Y().coeff(k)) - e.yc() * w, prec);
        arb_submul(A[k].get(), dx.get(), W[k].get(), prec);
        arb_submul(B[k].get(), dy.get(), W[k].get(), prec);
    }
    Poly q;
    Ball ww;
    for (int i = 0; i <= 2; ++i)
        for (int j = 0; j <= 2; ++j) {
            arb_addmul(q[i + j].get(), A[i].get(), A[j].get(), prec);
            arb_addmul(q[i + j].get(), B[i].get(), B[j].get(), prec);
            arb_mul(ww.get(), W[i].get(), W[j].get(), prec);
            arb_submul(q[i + j].get(), rho2.get(), ww.get(), prec);
        }
    return q;
}

struct Piece {
    bool flipped;
    Ball lo, hi;
    bool within(const Piece& o) const { return flipped == o.flipped && !less(lo, o.lo) && !less(o.hi, hi); }
};

// Bisects the pieces until Q > 0 on all of them (positive), Q is certainly
// negative at a midpoint (negative_at_midpoint), or `count` passes the cap
// (unknown). q_t and q_u are Q in the unflipped and the flipped chart. A
// piece within `known` (where Q > 0 is proven otherwise, if given) is done.
Sign sign_on_pieces(std::vector<Piece> stack, const Poly& q_t, const Poly& q_u, long prec, long& count,
                    const Piece* known = nullptr) {
    while (!stack.empty()) {
        if (++count > kMaxPieces) return Sign::unknown;
        Piece p = std::move(stack.back());
        stack.pop_back();
        if (known && p.within(*known)) continue;
        const Sign s = sign_on(p.flipped ? q_u : q_t, 4, p.lo, p.hi, prec);
        if (s == Sign::positive) continue;
        if (s == Sign::negative_at_midpoint) return s;
        const Ball mid = exact_half(exact_add(p.lo, p.hi));
        stack.push_back({p.flipped, mid, p.hi});
        stack.push_back({p.flipped, std::move(p.lo), mid});
    }
    return Sign::positive;
}

}  // namespace

int inside_distance_minus(const Ellipse& e, const Ball& r, const Ball& vx, const Ball& vy, long prec) {
    if (!arb_is_positive(r.get()) || !arb_is_finite(vx.get()) || !arb_is_finite(vy.get())) return 0;
    // Q > 0 on the whole boundary (both charts' [-1, 1]): the closed disk of
    // radius r about V misses the boundary, and holding V (inside E) it lies
    // in E, so every boundary point is farther than r. A boundary point
    // certainly nearer than r proves the opposite.
    const Poly q_t = distance_quartic(e, r, vx, vy, prec);
    const Ball one(Rational(1), prec), minus_one(Rational(-1), prec);
    long count = 0;
    switch (sign_on_pieces({{false, minus_one, one}, {true, minus_one, one}}, q_t, flip(q_t), prec, count)) {
        case Sign::positive: return 1;
        case Sign::negative_at_midpoint: return -1;
        case Sign::unknown: break;
    }
    return 0;
}

bool disk_inside_ellipse(const Ellipse& e, bool flipped, const Ball& t, const Ball& rho, const Ball& vx,
                         const Ball& vy, long prec, long* pieces, AxisMirror mirror) {
    long count = 0;
    if (pieces) *pieces = 0;
    // rho = 0 and rho > 0 are not this test's (see the top of this file).
    if (!arb_is_negative(rho.get())) return false;
    // A chart parameter far outside the chart, or a loose ball, would let
    // the local interval N wrap around the boundary.
    const Ball one(Rational(1), prec), minus_one(Rational(-1), prec), two(Rational(2), prec),
        quarter(Rational(1, 4), prec);
    if (!arb_is_finite(t.get()) || !arb_is_finite(vx.get()) || !arb_is_finite(vy.get())) return false;
    Ball abs_t;
    arb_get_abs_ubound_arf(arb_midref(abs_t.get()), t.get(), prec);
    if (!arb_lt(abs_t.get(), two.get())) return false;
    Ball rad_t;
    arf_set_mag(arb_midref(rad_t.get()), arb_radref(t.get()));
    if (!arb_lt(rad_t.get(), quarter.get())) return false;

    const Poly q_t = distance_quartic(e, rho, vx, vy, prec);
    const Poly q_u = flip(q_t);
    const Poly& q = flipped ? q_u : q_t;  // the chart of t
    Poly q2;  // Q''
    for (int k = 0; k <= 2; ++k) arb_mul_si(q2[k].get(), q[k + 2].get(), (k + 2) * (k + 1), prec);

    // Local: N = [n_lo, n_hi] grows from the ball t while Q'' > 0, with steps
    // doubling on success and halving on failure (down to h_min, or to a
    // sixteenth of N's width on that side), at most 1 each way. N must reach
    // well beyond t's ball: Q grows like (s - t)^2 there, and the balls' width
    // blurs Q by about their radius, so the bisection can only take over at
    // a distance of about the square root of that.
    const Ball t_lo = lower_end(t, prec), t_hi = upper_end(t, prec);
    ++count;
    if (sign_on(q2, 2, t_lo, t_hi, prec) != Sign::positive) {
        if (pieces) *pieces = count;
        return false;
    }
    Ball h_min = power_of_two(-prec / 2);
    if (less(h_min, rad_t)) h_min = upper_end(rad_t, prec);
    auto walk = [&](int dir) {
        const Ball start = dir > 0 ? t_hi : t_lo;
        Ball edge = start;
        long step = kFirstStepLog2;
        while (count < kMaxPieces) {
            Ball h = power_of_two(step);
            // Once N has some width, pinning down where Q'' stops being
            // positive gains nothing: the bisection takes over.
            Ball width = exact_sub(edge, start);
            arb_abs(width.get(), width.get());
            arb_mul_2exp_si(width.get(), width.get(), -kRelativeStepLog2);
            if (less(h, h_min) || less(h, width)) break;
            if (dir < 0) arb_neg(h.get(), h.get());
            const Ball next = exact_add(edge, h);
            Ball reach = exact_sub(next, start);
            arb_abs(reach.get(), reach.get());
            if (less(one, reach)) break;
            ++count;
            if (sign_on(q2, 2, dir > 0 ? edge : next, dir > 0 ? next : edge, prec) == Sign::positive) {
                edge = next;
                step = std::min(step + 1, kMaxStepLog2);
            } else {
                --step;
            }
        }
        return edge;
    };
    const Ball n_hi = walk(1), n_lo = walk(-1);
    if (!less(t_hi, n_hi) || !less(n_lo, t_lo)) {  // N no wider than t's ball: hopeless
        if (pieces) *pieces = count;
        return false;
    }

    // Global: the boundary outside N, as pieces of the two charts' [-1, 1].
    // In t's chart: [n_hi, 1] and [-1, n_lo] when not empty. The other chart
    // holds |s| >= 1 of t's chart, s = -1/u: from s = max(1, n_hi) through
    // the i-point (u = 0) to s = min(-1, n_lo). Its ends are rounded
    // outwards: covering a little of N again only asks Q > 0 on more points
    // (at s >= n_hi - 2^-prec, far from t's ball), never weakens the proof.
    std::vector<Piece> stack;
    if (less(n_hi, one)) stack.push_back({flipped, n_hi, one});
    if (less(minus_one, n_lo)) stack.push_back({flipped, minus_one, n_lo});
    Ball u_start = minus_one, u_end = one, inv;
    if (!less(n_hi, one)) {
        arb_inv(inv.get(), n_hi.get(), prec);
        arb_neg(inv.get(), inv.get());
        u_start = lower_end(inv, prec);
    }
    if (!less(minus_one, n_lo)) {
        arb_inv(inv.get(), n_lo.get(), prec);
        arb_neg(inv.get(), inv.get());
        u_end = upper_end(inv, prec);
    }
    stack.push_back({!flipped, u_start, u_end});

    // The mirror image of N: s -> -s, in N's chart or the other one.
    std::optional<Piece> image;
    if (mirror != AxisMirror::none) {
        Ball lo, hi;
        arb_neg(lo.get(), n_hi.get());
        arb_neg(hi.get(), n_lo.get());
        image = Piece{mirror == AxisMirror::same_chart ? flipped : !flipped, lo, hi};
    }

    // Not proven at the cap, or a boundary point certainly nearer than |rho|.
    const bool proven =
        sign_on_pieces(std::move(stack), q_t, q_u, prec, count, image ? &*image : nullptr) == Sign::positive;
    if (pieces) *pieces = std::min(count, kMaxPieces);
    return proven;
}

}  // namespace ellvor
