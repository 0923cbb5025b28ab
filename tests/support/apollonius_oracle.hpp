// An independent closed-form oracle for the Voronoi circles of three circles
// (the Apollonius problem restricted to external tangency), written for the
// tests from first principles; it never calls ellvor's predicates or solvers.
//
// Unknowns: the center V = (X, Y) and the radius R > 0 of a circle externally
// tangent to the circles (c_i, r_i), i = 1, 2, 3:
//     |V - c_i| = R + r_i.
// Squaring, |V|^2 - 2 c_i.V + |c_i|^2 = R^2 + 2 r_i R + r_i^2; the difference
// of equation i and equation 1 is linear in (X, Y, R):
//     2 (c_i - c_1).V + 2 (r_i - r_1) R = (|c_i|^2 - r_i^2) - (|c_1|^2 - r_1^2),  i = 2, 3.
// One unknown s (R when the centers are not collinear, otherwise X or Y) is
// kept free and the other two are solved for exactly in rationals, so every
// unknown is affine in s; equation 1 is then a quadratic in s with rational
// coefficients. Its roots need one square root, evaluated with Arb at the
// oracle's precision. A root is a Voronoi circle iff R > 0 (then R + r_i > 0
// for every i, so the squared equations give back |V - c_i| = R + r_i; the
// open disk touches each circle from outside and so misses all three).
// The tangency points T_i = V + R (c_i - V) / (R + r_i) decide the
// orientation: counter-clockwise iff orient(T1, T2, T3) > 0.
// With signed distances (overlapping circles; `signed_radii`), a root is a
// Voronoi circle iff R + r_i > 0 for every i: then |V - c_i| - r_i = R, the
// signed distance, also for R <= 0 (V inside all three), and the T_i above
// are still the points of the circles nearest to V.
#pragma once

#include "sites/ellipse.hpp"
#include "util/ball_arithmetic.hpp"

#include <arb.h>

#include <algorithm>
#include <array>
#include <sstream>
#include <string>
#include <vector>

namespace apollonius {

using ellvor::Ball;
using ellvor::Ellipse;
using ellvor::Rational;

struct Circle {
    Rational x, y, r;
    Ellipse ellipse() const { return Ellipse::circle(x, y, r); }
};

struct Solution {
    Ball x, y, radius;
    int orientation = 0;  // +1 counter-clockwise tangency points, -1 clockwise, 0 undecided
};

struct Result {
    std::vector<Solution> solutions;  // the circles with R certainly > 0
    bool certain = true;              // false when a sign (R, orientation) was not decided
                                      // or the linear system was degenerate
    // The counter-clockwise circle, or nullptr.
    const Solution* ccw() const {
        const Solution* found = nullptr;
        for (const Solution& s : solutions)
            if (s.orientation == 1) found = &s;
        return found;
    }
    int ccw_count() const {
        int n = 0;
        for (const Solution& s : solutions) n += s.orientation == 1;
        return n;
    }
    int cw_count() const {
        int n = 0;
        for (const Solution& s : solutions) n += s.orientation == -1;
        return n;
    }
};

namespace detail {

// An affine function alpha + beta s of the free unknown.
struct Affine {
    Rational alpha, beta;
};

}  // namespace detail

// All Voronoi circles of the three circles, at `prec` bits.
inline Result voronoi_circles(const Circle& c1, const Circle& c2, const Circle& c3, long prec = 4096,
                              bool signed_radii = false) {
    Result out;
    const ellvor::BallArithmetic A{prec};
    // Rows (coefficients of X, Y, R | right-hand side) for i = 2, 3.
    auto power = [](const Circle& c) { return c.x * c.x + c.y * c.y - c.r * c.r; };
    std::array<std::array<Rational, 3>, 2> m;
    std::array<Rational, 2> h;
    const Circle* others[2] = {&c2, &c3};
    for (int k = 0; k < 2; ++k) {
        const Circle& c = *others[k];
        m[k] = {Rational(2) * (c.x - c1.x), Rational(2) * (c.y - c1.y), Rational(2) * (c.r - c1.r)};
        h[k] = power(c) - power(c1);
    }
    // Free unknown f; the others g, g2 solved from the 2x2 minor.
    int f = -1, g = 0, g2 = 0;
    Rational det;
    for (int cand : {2, 1, 0}) {
        const int a = cand == 0 ? 1 : 0, b = cand == 2 ? 1 : 2;
        const Rational d = m[0][a] * m[1][b] - m[0][b] * m[1][a];
        if (!d.is_zero()) {
            f = cand, g = a, g2 = b, det = d;
            break;
        }
    }
    if (f < 0) {  // (c_i, r_i) collinear in R^3: degenerate for this oracle
        out.certain = false;
        return out;
    }
    std::array<detail::Affine, 3> v;
    v[f] = {Rational(0), Rational(1)};
    // [m0g m0g2; m1g m1g2] (vg, vg2) = h - m[.][f] s   (Cramer)
    const Rational h0 = h[0], h1 = h[1], f0 = -m[0][f], f1 = -m[1][f];
    v[g] = {(h0 * m[1][g2] - m[0][g2] * h1) / det, (f0 * m[1][g2] - m[0][g2] * f1) / det};
    v[g2] = {(m[0][g] * h1 - h0 * m[1][g]) / det, (m[0][g] * f1 - f0 * m[1][g]) / det};
    // Equation 1: (X - x1)^2 + (Y - y1)^2 - (R + r1)^2 = qa s^2 + qb s + qc.
    const detail::Affine ex{v[0].alpha - c1.x, v[0].beta}, ey{v[1].alpha - c1.y, v[1].beta},
        er{v[2].alpha + c1.r, v[2].beta};
    const Rational qa = ex.beta * ex.beta + ey.beta * ey.beta - er.beta * er.beta;
    const Rational qb = Rational(2) * (ex.alpha * ex.beta + ey.alpha * ey.beta - er.alpha * er.beta);
    const Rational qc = ex.alpha * ex.alpha + ey.alpha * ey.alpha - er.alpha * er.alpha;
    std::vector<Ball> roots;
    if (qa.is_zero()) {
        if (qb.is_zero()) {
            if (qc.is_zero()) out.certain = false;  // a continuum of solutions
            return out;
        }
        roots.push_back(A.q(-qc / qb));
    } else {
        const Rational disc = qb * qb - Rational(4) * qa * qc;
        if (disc.sign() < 0) return out;
        const Ball sq = A.sqrt(A.q(disc));
        const Ball den = A.q(Rational(2) * qa);
        roots.push_back(A.div(A.sub(A.q(-qb), sq), den));
        if (disc.sign() > 0) roots.push_back(A.div(A.add(A.q(-qb), sq), den));
    }
    for (const Ball& s : roots) {
        auto at = [&](const detail::Affine& a) { return A.add(A.q(a.alpha), A.mul(A.q(a.beta), s)); };
        Solution sol;
        sol.x = at(v[0]);
        sol.y = at(v[1]);
        sol.radius = at(v[2]);
        const Rational smallest = std::min({c1.r, c2.r, c3.r});
        const int rs = (signed_radii ? A.add(sol.radius, A.q(smallest)) : sol.radius).certain_sign();
        if (rs < 0) continue;
        if (rs == 0) {
            out.certain = false;
            continue;
        }
        std::array<Ball, 3> tx, ty;
        const Circle* cs[3] = {&c1, &c2, &c3};
        for (int i = 0; i < 3; ++i) {
            const Ball scale = A.div(sol.radius, A.add(sol.radius, A.q(cs[i]->r)));
            tx[i] = A.add(sol.x, A.mul(scale, A.sub(A.q(cs[i]->x), sol.x)));
            ty[i] = A.add(sol.y, A.mul(scale, A.sub(A.q(cs[i]->y), sol.y)));
        }
        const Ball orient = A.sub(A.mul(A.sub(tx[1], tx[0]), A.sub(ty[2], ty[0])),
                                  A.mul(A.sub(ty[1], ty[0]), A.sub(tx[2], tx[0])));
        sol.orientation = orient.certain_sign();
        if (sol.orientation == 0) out.certain = false;
        out.solutions.push_back(sol);
    }
    return out;
}

// InCircle oracle: sign of |V - c_q| - R - r_q for the counter-clockwise
// circle (+1 no conflict, -1 conflict, 0 exactly zero as a ball, 2 undecided);
// -1 (CGAL's rule) when there is no counter-clockwise circle; 3 when the
// oracle itself is not certain about the circles. Q's signed distance is
// compared with R, never squared, so it serves signed radii too.
inline int incircle(const Circle& c1, const Circle& c2, const Circle& c3, const Circle& q, long prec = 1024,
                    bool signed_radii = false) {
    const Result r = voronoi_circles(c1, c2, c3, prec, signed_radii);
    if (!r.certain || r.ccw_count() > 1) return 3;
    const Solution* s = r.ccw();
    if (!s) return -1;
    const ellvor::BallArithmetic A{prec};
    const Ball dx = A.sub(s->x, A.q(q.x)), dy = A.sub(s->y, A.q(q.y));
    const Ball d = A.sqrt(A.add(A.mul(dx, dx), A.mul(dy, dy)));
    const Ball diff = A.sub(d, A.add(s->radius, A.q(q.r)));
    if (arb_is_zero(diff.get())) return 0;
    const int sg = diff.certain_sign();
    return sg == 0 ? 2 : sg;
}

// A replayable .ell text (one site a line) for INFO messages.
inline std::string ell(std::initializer_list<const Ellipse*> sites) {
    std::ostringstream s;
    s << "\n# .ell\n";
    for (const Ellipse* e : sites) s << e->str() << "\n";
    return s.str();
}

}  // namespace apollonius
