// An ellipse site with exact rational parameters (docs/DESIGN.md §2): semi-axes a, b > 0,
// rotation w = tan(omega/2) of the a-axis, center (xc, yc).
//
// Boundary (the paper, section 2), with t = tan(theta/2):
//   P(t) = C + a cos(theta) u + b sin(theta) v,   u = (cos w, sin w), v = (-sin w, cos w),
//   cos(theta) = (1 - t^2)/(1 + t^2),  sin(theta) = 2t/(1 + t^2).
// We keep it homogeneous: P(t) = (X(t) : Y(t) : W(t)) with integer polynomials of
// degree 2 and W = L (1 + t^2). The point at t = infinity (theta = pi), the
// "i-point" C - a u, is a real boundary point; parameters live on the projective
// line and every routine that walks the boundary must treat t = infinity.
#pragma once

#include "util/flint_types.hpp"
#include "util/interval.hpp"

#include <array>
#include <atomic>
#include <string>
#include <vector>

namespace ellvor {

struct Point {
    Rational x, y;
};

struct BallPoint {
    Ball x, y;
};

// P' W - P W' for a coordinate P of a homogeneous parametrization (P : W):
// W^2 times the derivative of P / W.
IntPolynomial homogeneous_tangent(const IntPolynomial& P, const IntPolynomial& W);

class Ellipse {
public:
    // Throws Error unless a > 0 and b > 0.
    Ellipse(Rational a, Rational b, Rational w, Rational xc, Rational yc);
    // A circle of radius r centered at (x, y).
    static Ellipse circle(const Rational& x, const Rational& y, const Rational& r);
    // Copies share the exact parameters (immutable, reference counted); a
    // move is a copy (no moved-from state to guard).
    Ellipse(const Ellipse& o) noexcept
        : near_(o.near_), circle_(o.circle_), dyadic_circle_(o.dyadic_circle_), compact_(o.compact_) {
        exact_.store(share(o.exact_.load(std::memory_order_acquire)), std::memory_order_relaxed);
    }
    Ellipse& operator=(const Ellipse& o) noexcept;
    // A copy that shares nothing with this one (its own exact parameters,
    // their polynomials not made yet; a compact circle none): what a holder
    // of sites that counts its own storage keeps.
    Ellipse unshared() const;
    // The same in place, and nothing to do when no other copy shares them
    // (a vector of sites moved to its holder: most of them).
    void make_own();
    // Unshared copies of all `sites`, in one pass that fetches each site's
    // exact parameters a few sites ahead (they lie scattered in memory: the
    // cache misses, not the copies, cost most).
    static std::vector<Ellipse> unshared_copies(const std::vector<Ellipse>& sites);
    // Asks the cache for this ellipse's exact parameters, for a loop over
    // many sites to call a few sites ahead; nothing for a compact circle.
    void prefetch() const {
        if (const Exact* e = exact_.load(std::memory_order_relaxed))
            for (std::size_t byte = 0; byte < sizeof(Exact); byte += 64)
                __builtin_prefetch(reinterpret_cast<const char*>(e) + byte);
    }
    ~Ellipse() { release(exact_.load(std::memory_order_acquire)); }

    const Rational& a() const { return exact().a; }
    const Rational& b() const { return exact().b; }
    const Rational& w() const { return exact().w; }
    const Rational& xc() const { return exact().xc; }
    const Rational& yc() const { return exact().yc; }
    Point center() const { return {xc(), yc()}; }
    // a == b, decided once: every predicate's cascade asks first.
    bool is_circle() const { return circle_; }
    // A circle whose center and radius are small dyadic rationals
    // (Rational::is_small_dyadic): exact doubles, the input of the circles'
    // semi-static filters. Decided once: those filters ask it of every site
    // of every call.
    bool is_dyadic_circle() const { return dyadic_circle_; }
    // cos and sin of the rotation angle, exactly: (1-w^2)/(1+w^2), 2w/(1+w^2).
    // Computed on each call (1 and 0 for w = 0): only exact and Arb stages
    // ask, and keeping them cost 32 bytes a site; the filters read the
    // enclosures.
    Rational cos_rotation() const;
    Rational sin_rotation() const;

    // Double enclosures of a, b, cos, sin of the rotation and the center, for
    // the floating-point filters: enclose(q) of each (util/interval.hpp),
    // [down(x^), up(x^)] around its nearest double x^. An ellipse keeps them
    // with its exact parameters (made once: the filters ask on every call);
    // a compact circle makes them from its three doubles, inlined always so
    // that a caller's unused fields are not computed.
    struct Enclosure {
        Interval a, b, cos, sin, xc, yc;
    };
    [[gnu::always_inline]] Enclosure enclosure() const {
        if (compact_) {
            const Interval r = Interval::around(near_[0]);
            return {r, r, Interval::around(1.0), Interval::around(0.0), Interval::around(near_[1]),
                    Interval::around(near_[2])};
        }
        return exact_.load(std::memory_order_relaxed)->enclosure;  // made with the ellipse, never null
    }

    // Homogeneous parametrization (X : Y : W), integer polynomials in t.
    const IntPolynomial& X() const { return polynomials().X; }
    const IntPolynomial& Y() const { return polynomials().Y; }
    const IntPolynomial& W() const { return polynomials().W; }
    // Tangent direction (dX/dt W - X dW/dt, dY/dt W - Y dW/dt), degree <= 2.
    const IntPolynomial& tangent_x() const { return polynomials().Tx; }
    const IntPolynomial& tangent_y() const { return polynomials().Ty; }

    // Boundary point at a rational parameter, exactly.
    Point point_at(const Rational& t) const;
    // The i-point, P(infinity) = C - a u.
    Point i_point() const;
    // Boundary point at a ball parameter (finite), at precision prec.
    BallPoint point_at(const Ball& t, long prec) const;

    // Implicit conic A x^2 + 2B xy + C y^2 + 2D x + 2E y + F, scaled so that its
    // value is negative inside: {A, B, C, D, E, F} = b^2 xi^2 + a^2 eta^2 - a^2 b^2
    // in the ellipse's own frame (xi, eta).
    const std::array<Rational, 6>& conic() const { return polynomials().conic; }
    // Value of the conic at (x, y).
    Rational conic_value(const Rational& x, const Rational& y) const;
    // -1 strictly inside, 0 on the boundary, +1 strictly outside.
    int side_of_point(const Rational& x, const Rational& y) const;

    // "a b w xc yc" exactly as read (lossless).
    std::string str() const;

    friend bool operator==(const Ellipse& p, const Ellipse& q);
    friend bool operator!=(const Ellipse& p, const Ellipse& q) { return !(p == q); }
    // Equal for two ellipses exactly when they are the same point set (a
    // circle's rotation does not matter; swapped axes with a quarter turn are
    // the same ellipse): the center and the quadratic form divided by a^2 b^2,
    // R diag(1/a^2, 1/b^2) R^T. Ordered, so that a reader finds duplicates in
    // O(log n) a site.
    using PointSetKey = std::array<Rational, 5>;
    PointSetKey point_set_key() const;

private:
    // The parametrization and the conic: only the exact and Arb stages read
    // them (a few sites of a large build), so they are made on first use.
    struct Polynomials {
        IntPolynomial X, Y, W, Tx, Ty;
        std::array<Rational, 6> conic;
    };
    // The exact parameters, shared by copies. A compact circle (is_compact)
    // has none until an exact stage asks: its doubles are its parameters.
    struct Exact {
        Rational a, b, w, xc, yc;
        Enclosure enclosure;
        // Written once, by whichever thread asks first (compare and swap: a
        // lost race only computes the same values twice).
        mutable std::atomic<const Polynomials*> polynomials{nullptr};
        std::atomic<long> references{1};
        Exact(Rational a, Rational b, Rational w, Rational xc, Rational yc);
        // The parameters and their enclosures (not remade: ~1 µs of Arb
        // divisions), without the polynomials; what make_own copies.
        explicit Exact(const Exact& o)
            : a(o.a), b(o.b), w(o.w), xc(o.xc), yc(o.yc), enclosure(o.enclosure) {}
        ~Exact();
    };
    // A circle of rotation 0 whose radius and center are small dyadic
    // rationals: its doubles give them back exactly, so a large build of
    // circles keeps 40 bytes a site (an ellipse adds its Exact, about 210).
    static bool is_compact(const Rational& a, const Rational& b, const Rational& w, const Rational& xc,
                           const Rational& yc);
    const Exact& exact() const {
        if (const Exact* e = exact_.load(std::memory_order_acquire)) return *e;
        return make_exact();
    }
    const Exact& make_exact() const;  // a compact circle's, from its doubles
    static Exact* share(Exact* e) {
        if (e) e->references.fetch_add(1, std::memory_order_relaxed);
        return e;
    }
    static void release(Exact* e) {
        if (e && e->references.fetch_sub(1, std::memory_order_acq_rel) == 1) delete e;
    }
    const Polynomials& polynomials() const;
    // The conic's quadratic part {A, B, C}.
    std::array<Rational, 3> quadratic_form() const;

    // A compact circle's radius and center, exact doubles (unused else).
    std::array<double, 3> near_{};
    mutable std::atomic<Exact*> exact_{nullptr};
    bool circle_ = false, dyadic_circle_ = false, compact_ = false;
};

}  // namespace ellvor
