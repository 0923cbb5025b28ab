// Independent oracles for the two-site predicates, written from first
// principles for the tests (they never call ellvor's predicates):
//  * circles: closed forms evaluated exactly in rationals where possible and
//    otherwise with Arb balls at high precision; every oracle reports whether
//    its ball answer is certain;
//  * ellipses: brute-force numerics in long double (dense sampling plus local
//    refinement), used only away from ties (the caller demands a margin).
#pragma once

#include <random>

#include "sites/ellipse.hpp"
#include "tests/support/apollonius_oracle.hpp"

#include <arb.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

namespace oracle {

using ellvor::Ball;
using ellvor::Ellipse;
using ellvor::Point;
using ellvor::Rational;

constexpr long kPrec = 256;

struct Circle {
    Rational x, y, r;
    Ellipse ellipse() const { return Ellipse::circle(x, y, r); }
};

// A replayable .ell snippet (one site a line) for INFO messages.
inline std::string ell(std::initializer_list<const Ellipse*> sites) {
    std::ostringstream s;
    s << "\n# .ell\n";
    for (const Ellipse* e : sites) s << e->str() << "\n";
    return s.str();
}
inline std::string ell_point(const Point& p) { return "# point " + p.x.str() + " " + p.y.str() + "\n"; }

// ---------------------------------------------------------------------------
// Small Arb helpers (results are fresh Balls).
inline Ball ball(const Rational& q) { return Ball(q, kPrec); }
inline Ball add(const Ball& a, const Ball& b) { Ball r; arb_add(r.get(), a.get(), b.get(), kPrec); return r; }
inline Ball sub(const Ball& a, const Ball& b) { Ball r; arb_sub(r.get(), a.get(), b.get(), kPrec); return r; }
inline Ball mul(const Ball& a, const Ball& b) { Ball r; arb_mul(r.get(), a.get(), b.get(), kPrec); return r; }
inline Ball div(const Ball& a, const Ball& b) { Ball r; arb_div(r.get(), a.get(), b.get(), kPrec); return r; }
inline Ball sqrt_(const Ball& a) { Ball r; arb_sqrt(r.get(), a.get(), kPrec); return r; }
inline Ball hypot_(const Ball& dx, const Ball& dy) { return sqrt_(add(mul(dx, dx), mul(dy, dy))); }

// Sign of a ball: -1/+1 when certain, 0 when it is exactly zero, 2 when undecided.
inline int ball_sign(const Ball& b) {
    if (arb_is_zero(b.get())) return 0;
    int s = b.certain_sign();
    return s == 0 ? 2 : s;
}

// ---------------------------------------------------------------------------
// kappa1 on circles: sign((|p - c2| - r2) - (|p - c1| - r1)); +1 = closer to c1.
// Returns 2 when the ball does not decide (never for random data at 256 bits).
inline int side_of_bisector(const Circle& c1, const Circle& c2, const Point& p) {
    Ball d1 = sub(hypot_(ball(p.x - c1.x), ball(p.y - c1.y)), ball(c1.r));
    Ball d2 = sub(hypot_(ball(p.x - c2.x), ball(p.y - c2.y)), ball(c2.r));
    return ball_sign(sub(d2, d1));
}

// ---------------------------------------------------------------------------
// kappa2 on circles. With D = c2 - c1 and dr = r1 - r2, the unit normal n of the
// external bitangent L pointing into H solves n.D = dr and lies on the side
// where cross(D, n) > 0 (H on the left of T1 -> T2):
//   n = (dr D + sqrt(|D|^2 - dr^2) rot90(D)) / |D|^2.
// Support value h(n) = n.c + r. Conflict (-1) iff h_Q(n) > h_1(n); +1 iff <.
// On a tie, CGAL's rule: -1 iff Q's contact point c_q + r_q n lies strictly
// between T1 and T2 along L. Returns 2 if a ball does not decide.
struct InfiniteConflict {
    int sign = 2;       // -1, +1, or 2 (undecided)
    bool tie = false;   // h_Q == h_1 decided exactly (only with rational sqrt)
};
inline InfiniteConflict infinite_vertex_conflict(const Circle& c1, const Circle& c2, const Circle& q) {
    const Rational Dx = c2.x - c1.x, Dy = c2.y - c1.y, dr = c1.r - c2.r;
    const Rational D2 = Dx * Dx + Dy * Dy;
    Ball s = sqrt_(ball(D2 - dr * dr));
    Ball nx = div(sub(ball(dr * Dx), mul(s, ball(Dy))), ball(D2));
    Ball ny = div(add(ball(dr * Dy), mul(s, ball(Dx))), ball(D2));
    auto h = [&](const Circle& c) { return add(add(mul(nx, ball(c.x)), mul(ny, ball(c.y))), ball(c.r)); };
    InfiniteConflict out;
    int sg = ball_sign(sub(h(q), h(c1)));
    if (sg == 1) { out.sign = -1; return out; }
    if (sg == -1) { out.sign = 1; return out; }
    if (sg == 2) return out;
    out.tie = true;
    // Direction along L from T1 to T2: t = (ny, -nx) (H = n on its left).
    auto along = [&](const Circle& c) {
        Ball px = add(ball(c.x), mul(ball(c.r), nx)), py = add(ball(c.y), mul(ball(c.r), ny));
        return sub(mul(px, ny), mul(py, nx));
    };
    Ball a1 = along(c1), a2 = along(c2), aq = along(q);
    int s1 = ball_sign(sub(aq, a1)), s2 = ball_sign(sub(a2, aq));
    if (s1 == 2 || s2 == 2) return out;
    out.sign = (s1 == 1 && s2 == 1) ? -1 : 1;
    return out;
}

// ---------------------------------------------------------------------------
// Voronoi circles of three circles: the circles (X, R), R > 0, with
// |X - c_i| = R + r_i for i = 1, 2, 3 (external tangency; with only three
// sites such a disk is automatically empty of them). Subtracting the first
// equation from the others gives two linear equations m_i . (x, y, R) = b_i,
// solved exactly: (x, y, R) = P + s k with k = m2 x m3; the first equation then
// is a quadratic in s with rational coefficients. Tangency points are
// X + R (c_i - X)/|c_i - X|; their orientation decides CCW vs CW.
enum class Count { none, ccw_only, cw_only, both, undecided };
inline const char* count_name(Count c) {
    switch (c) {
        case Count::none: return "none";
        case Count::ccw_only: return "ccw_only";
        case Count::cw_only: return "cw_only";
        case Count::both: return "both";
        case Count::undecided: return "undecided";
    }
    return "?";
}
// Which Voronoi circles the triple has, from the closed-form Apollonius
// circles of apollonius_oracle.hpp (R > 0 and the tangency points'
// orientation, both decided in Arb); undecided when a sign is not.
inline Count voronoi_circles(const Circle& c1, const Circle& c2, const Circle& c3) {
    // (c_i, r_i) on one line of R^3: distance minus radius along the line is
    // strictly convex in the line's parameter, so no point has three equal
    // values: no circle (the closed form's linear system is singular there).
    const Rational ux = c2.x - c1.x, uy = c2.y - c1.y, ur = c2.r - c1.r;
    const Rational vx = c3.x - c1.x, vy = c3.y - c1.y, vr = c3.r - c1.r;
    if ((uy * vr - ur * vy).is_zero() && (ur * vx - ux * vr).is_zero() && (ux * vy - uy * vx).is_zero())
        return Count::none;
    const apollonius::Result r =
        apollonius::voronoi_circles({c1.x, c1.y, c1.r}, {c2.x, c2.y, c2.r}, {c3.x, c3.y, c3.r}, 1024);
    const int ccw = r.ccw_count(), cw = r.cw_count();
    // Two circles of one orientation would contradict the theory.
    if (!r.certain || ccw > 1 || cw > 1 || ccw + cw != static_cast<int>(r.solutions.size())) return Count::undecided;
    return ccw && cw ? Count::both : ccw ? Count::ccw_only : cw ? Count::cw_only : Count::none;
}

// ---------------------------------------------------------------------------
// Ellipses by brute force in long double.
using LD = long double;
constexpr LD kPi = 3.141592653589793238462643383279502884L;

struct NumEllipse {
    LD a, b, c, s, x, y;  // semi-axes, cos/sin of the rotation, center
};
inline LD ld(const Rational& q) {
    // Through Arb: exact to long double's precision (to_double is only 53 bits).
    Ball v = ball(q);
    char* str = arb_get_str(v.get(), 30, ARB_STR_NO_RADIUS);
    LD r = std::strtold(str, nullptr);
    flint_free(str);
    return r;
}
inline NumEllipse num(const Ellipse& e) {
    return {ld(e.a()), ld(e.b()), ld(e.cos_rotation()), ld(e.sin_rotation()), ld(e.xc()), ld(e.yc())};
}

// Unsigned distance from (px, py) to the boundary of e.
inline LD boundary_distance(const NumEllipse& e, LD px, LD py) {
    const LD dx = px - e.x, dy = py - e.y;
    const LD xi = e.c * dx + e.s * dy, eta = -e.s * dx + e.c * dy;
    auto f = [&](LD th) {
        LD u = e.a * std::cos(th) - xi, v = e.b * std::sin(th) - eta;
        return u * u + v * v;
    };
    const int N = 720;
    std::vector<LD> vals(N);
    for (int i = 0; i < N; ++i) vals[i] = f(2 * kPi * i / N);
    LD best = vals[0];
    for (int i = 0; i < N; ++i) {
        if (vals[i] > vals[(i + N - 1) % N] || vals[i] > vals[(i + 1) % N]) continue;  // not a local min
        // Golden-section search on [th - h, th + h].
        LD lo = 2 * kPi * (i - 1) / N, hi = 2 * kPi * (i + 1) / N;
        const LD g = (std::sqrt(5.0L) - 1) / 2;
        LD x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo), f1 = f(x1), f2 = f(x2);
        for (int it = 0; it < 120; ++it) {
            if (f1 < f2) { hi = x2; x2 = x1; f2 = f1; x1 = hi - g * (hi - lo); f1 = f(x1); }
            else { lo = x1; x1 = x2; f1 = f2; x2 = lo + g * (hi - lo); f2 = f(x2); }
        }
        best = std::min({best, f1, f2, vals[i]});
    }
    return std::sqrt(best);
}
// Signed distance (negative inside), the inside test done exactly.
inline LD signed_distance(const Ellipse& e, const Point& p) {
    LD d = boundary_distance(num(e), ld(p.x), ld(p.y));
    return e.side_of_point(p.x, p.y) < 0 ? -d : d;
}

// Support function h(n) = n.C + sqrt(a^2 (n.u)^2 + b^2 (n.v)^2), n = (cos phi, sin phi).
inline LD support(const NumEllipse& e, LD phi) {
    const LD nx = std::cos(phi), ny = std::sin(phi);
    const LD nu = nx * e.c + ny * e.s, nv = -nx * e.s + ny * e.c;
    return nx * e.x + ny * e.y + std::sqrt(e.a * e.a * nu * nu + e.b * e.b * nv * nv);
}
// The normal angle of kappa2's bitangent L of (E1, E2). With f = h1 - h2,
// h'(phi) = T(phi).rot90(n) (T = support point), so f' = (T1 - T2).rot90(n);
// "H = side of n is on the left of T1 -> T2" means n.rot90(T2 - T1) > 0, i.e.
// (T1 - T2).rot90(n) > 0: L is the zero of f where f increases. Returns false
// if the sampling does not find exactly one such crossing.
inline bool bitangent_normal(const NumEllipse& e1, const NumEllipse& e2, LD& phi_out) {
    const int N = 4096;
    auto f = [&](LD phi) { return support(e1, phi) - support(e2, phi); };
    int found = 0;
    LD prev = f(0);
    for (int i = 1; i <= N; ++i) {
        LD phi = 2 * kPi * i / N, cur = f(phi);
        if (prev < 0 && cur >= 0) {
            LD lo = 2 * kPi * (i - 1) / N, hi = phi;
            for (int it = 0; it < 100; ++it) {
                LD mid = (lo + hi) / 2;
                (f(mid) < 0 ? lo : hi) = mid;
            }
            phi_out = (lo + hi) / 2;
            ++found;
        }
        prev = cur;
    }
    return found == 1;
}


// Random test data shared by the predicate tests.
using Rng = std::mt19937_64;

// p/den with p uniform in [lo*den, hi*den].
inline Rational rnd(Rng& rng, long lo, long hi, long den) {
    std::uniform_int_distribution<long> n(lo * den, hi * den);
    return Rational(n(rng), static_cast<unsigned long>(den));
}
// Uniform in (0, hi] with denominator den.
inline Rational rnd_pos(Rng& rng, long hi, long den) {
    std::uniform_int_distribution<long> n(1, hi * den);
    return Rational(n(rng), static_cast<unsigned long>(den));
}
// Disjoint closed disks.
inline bool circles_apart(const Circle& a, const Circle& b) {
    const Rational dx = a.x - b.x, dy = a.y - b.y, r = a.r + b.r;
    return dx * dx + dy * dy > r * r;
}

}  // namespace oracle
