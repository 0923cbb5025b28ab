// Tests of sites/ellipse_polynomials: every polynomial against its geometric
// definition, exactly at rational parameters where possible (constructions
// that force a root), and with Arb balls at the real roots otherwise.
#include "sites/ellipse_polynomials.hpp"

#include <acb.h>
#include <arb_fmpz_poly.h>
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

using namespace ellvor;

namespace {

constexpr long kPrec = 256;

Rational random_rational(std::mt19937_64& rng, long num_range, unsigned long den_max) {
    std::uniform_int_distribution<long> n(-num_range, num_range);
    std::uniform_int_distribution<unsigned long> d(1, den_max);
    return Rational(n(rng), d(rng));
}

Rational random_positive(std::mt19937_64& rng, long num_max, unsigned long den_max) {
    std::uniform_int_distribution<long> n(1, num_max);
    std::uniform_int_distribution<unsigned long> d(1, den_max);
    return Rational(n(rng), d(rng));
}

// A random proper ellipse (a != b, rotated) with small rational data.
Ellipse random_ellipse(std::mt19937_64& rng, long center_range = 10) {
    Rational a = random_positive(rng, 12, 3), b = random_positive(rng, 12, 3);
    while (b == a) b = random_positive(rng, 12, 3);
    Rational w = random_rational(rng, 9, 5);
    while (w.is_zero()) w = random_rational(rng, 9, 5);
    return Ellipse(a, b, w, random_rational(rng, center_range, 3), random_rational(rng, center_range, 3));
}

Ellipse random_circle(std::mt19937_64& rng, long center_range = 10) {
    return Ellipse::circle(random_rational(rng, center_range, 3), random_rational(rng, center_range, 3),
                           random_positive(rng, 12, 3));
}

// Same shape (a, b, w) moved so that its point at parameter t is `target`.
Ellipse moved_so_that(const Ellipse& shape, const Rational& t, const Point& target) {
    Point p = shape.point_at(t);
    return Ellipse(shape.a(), shape.b(), shape.w(), shape.xc() + target.x - p.x, shape.yc() + target.y - p.y);
}

Rational value(const IntPolynomial& p, const Rational& x) {
    Rational v;
    fmpz_poly_evaluate_fmpq(v.get(), p.get(), x.get());
    return v;
}

// The tangent direction T(t) = W^2 dP/dt and the normal direction n = T rotated by +90 degrees.
Point tangent(const Ellipse& e, const Rational& t) { return {value(e.tangent_x(), t), value(e.tangent_y(), t)}; }
Point normal_direction(const Ellipse& e, const Rational& t) {
    Point T = tangent(e, t);
    return {-T.y, T.x};
}
Rational cross(const Point& u, const Point& v) { return u.x * v.y - u.y * v.x; }
Rational dotp(const Point& u, const Point& v) { return u.x * v.x + u.y * v.y; }
Point minus(const Point& u, const Point& v) { return {u.x - v.x, u.y - v.y}; }
Point along(const Point& p, const Rational& k, const Point& d) { return {p.x + k * d.x, p.y + k * d.y}; }

Rational line_value(const LinePolynomials& l, const Rational& t, const Point& q) {
    return value(l.l1, t) * q.x + value(l.l2, t) * q.y + value(l.l3, t);
}

int formal_degree(const LinePolynomials& l) {
    return static_cast<int>(std::max({l.l1.degree(), l.l2.degree(), l.l3.degree()}));
}

// Real roots of p as Arb balls (via its squarefree part).
std::vector<Ball> real_roots(const IntPolynomial& p) {
    std::vector<Ball> out;
    if (p.degree() < 1) return out;
    IntPolynomial dp, g, sqf;
    fmpz_poly_derivative(dp.get(), p.get());
    fmpz_poly_gcd(g.get(), p.get(), dp.get());
    fmpz_poly_div(sqf.get(), p.get(), g.get());
    const long n = sqf.degree();
    acb_ptr roots = _acb_vec_init(n);
    arb_fmpz_poly_complex_roots(roots, sqf.get(), 0, kPrec);
    for (long i = 0; i < n; ++i)
        if (acb_is_real(roots + i)) {
            Ball b;
            arb_set(b.get(), acb_realref(roots + i));
            out.push_back(b);
        }
    _acb_vec_clear(roots, n);
    return out;
}

Ball eval_ball(const IntPolynomial& p, const Ball& x) {
    Ball v;
    arb_fmpz_poly_evaluate_arb(v.get(), p.get(), x.get(), kPrec);
    return v;
}

bool tiny_and_contains_zero(const Ball& x, double scale) {
    return arb_contains_zero(x.get()) && x.radius_double() < 1e-40 * (1.0 + scale);
}

// Squared distance |q - P(t)|^2 at a ball parameter.
Ball squared_distance_at(const Ellipse& e, const Point& q, const Ball& t) {
    BallPoint p = e.point_at(t, kPrec);
    Ball dx(q.x, kPrec), dy(q.y, kPrec), r;
    arb_sub(dx.get(), dx.get(), p.x.get(), kPrec);
    arb_sub(dy.get(), dy.get(), p.y.get(), kPrec);
    arb_sqr(r.get(), dx.get(), kPrec);
    arb_addmul(r.get(), dy.get(), dy.get(), kPrec);
    return r;
}

}  // namespace

// ---------------------------------------------------------------------------
// One ellipse
// ---------------------------------------------------------------------------

TEST_CASE("normal line passes through P(t) with normal vector a positive multiple of T(t)", "[sites][polynomials]") {
    std::mt19937_64 rng(101);
    for (int trial = 0; trial < 40; ++trial) {
        const bool circle = trial % 4 == 3;
        Ellipse e = circle ? random_circle(rng) : random_ellipse(rng);
        LinePolynomials n = normal_line(e);
        CHECK(formal_degree(n) == 4);
        // (1 + t^2) = W / L divides l1 = Tx W and l2 = Ty W; it divides l3 too
        // exactly for a circle (whose normal passes through the center).
        IntPolynomial one_plus_t2{1, 0, 1}, quotient;
        REQUIRE(fmpz_poly_divides(quotient.get(), n.l1.get(), one_plus_t2.get()));
        REQUIRE(fmpz_poly_divides(quotient.get(), n.l2.get(), one_plus_t2.get()));
        REQUIRE(static_cast<bool>(fmpz_poly_divides(quotient.get(), n.l3.get(), one_plus_t2.get())) == circle);
        for (int k = 0; k < 5; ++k) {
            Rational t = random_rational(rng, 30, 7);
            Point p = e.point_at(t);
            REQUIRE(line_value(n, t, p).is_zero());
            Point nv{value(n.l1, t), value(n.l2, t)};
            Point T = tangent(e, t);
            REQUIRE(cross(nv, T).is_zero());
            REQUIRE(dotp(nv, T).sign() > 0);
            // A circle's normal goes through its center.
            if (circle) REQUIRE(line_value(n, t, e.center()).is_zero());
        }
    }
}

TEST_CASE("tangent side quadratic: negative on the ellipse's side of the tangent", "[sites][polynomials]") {
    std::mt19937_64 rng(202);
    for (int trial = 0; trial < 30; ++trial) {
        Ellipse e = trial % 5 == 4 ? random_circle(rng) : random_ellipse(rng);
        Point q{random_rational(rng, 20, 5), random_rational(rng, 20, 5)};
        IntPolynomial side = tangent_side_quadratic(e, q);
        CHECK(side.degree() <= 2);
        for (int k = 0; k < 8; ++k) {
            Rational t = random_rational(rng, 30, 7);
            Point p = e.point_at(t), T = tangent(e, t);
            const int sq = cross(T, minus(q, p)).sign(), sc = cross(T, minus(e.center(), p)).sign();
            REQUIRE(sc != 0);
            const int expected = sq == 0 ? 0 : (sq == sc ? -1 : 1);
            REQUIRE(side.sign_at(t) == expected);
        }
        // A point on the tangent line at a rational t0 gives an exact root.
        Rational t0 = random_rational(rng, 10, 3);
        Point on = along(e.point_at(t0), random_rational(rng, 5, 4), tangent(e, t0));
        REQUIRE(tangent_side_quadratic(e, on).sign_at(t0) == 0);
    }
}

TEST_CASE("foot point quartic: proportional to W(t) T(t).(q - P(t)), exact root on the normal",
          "[sites][polynomials]") {
    std::mt19937_64 rng(303);
    for (int trial = 0; trial < 30; ++trial) {
        const bool circle = trial % 3 == 2;
        Ellipse e = circle ? random_circle(rng) : random_ellipse(rng);
        Point q{random_rational(rng, 20, 5), random_rational(rng, 20, 5)};
        IntPolynomial f = foot_point_quartic(e, q);
        CHECK(f.degree() == 4);
        // f(t) = kappa * W(t) * T(t).(q - P(t)) for one constant kappa.
        Rational kappa;
        for (int k = 0; k < 6; ++k) {
            Rational t = random_rational(rng, 30, 7);
            Rational direct = dotp(tangent(e, t), minus(q, e.point_at(t))) * value(e.W(), t);
            REQUIRE(!direct.is_zero());
            Rational ratio = value(f, t) / direct;
            if (k == 0) kappa = ratio;
            REQUIRE(ratio == kappa);
        }
        // q on the normal at a rational t0: exact root.
        Rational t0 = random_rational(rng, 10, 3);
        Point on = along(e.point_at(t0), random_rational(rng, 5, 4), normal_direction(e, t0));
        REQUIRE(foot_point_quartic(e, on).sign_at(t0) == 0);
    }
}

TEST_CASE("squared distance quartic: circles give (|q-c| -+ r)^2 exactly", "[sites][polynomials]") {
    std::mt19937_64 rng(404);
    for (int trial = 0; trial < 30; ++trial) {
        Ellipse c = trial % 2 ? random_circle(rng)
                              : Ellipse(Rational(7, 2), Rational(7, 2), random_rational(rng, 5, 3), 1, -2);
        Point q{random_rational(rng, 20, 5), random_rational(rng, 20, 5)};
        // (s - (d + r)^2)(s - (d - r)^2) = s^2 - 2 (d^2 + r^2) s + (d^2 - r^2)^2, d^2 = |q - c|^2.
        const Rational d2 = dotp(minus(q, c.center()), minus(q, c.center())), r2 = c.a() * c.a();
        fmpq_poly_t expected;
        fmpq_poly_init(expected);
        fmpq_poly_set_coeff_si(expected, 2, 1);
        fmpq_poly_set_coeff_fmpq(expected, 1, (Rational(-2) * (d2 + r2)).get());
        fmpq_poly_set_coeff_fmpq(expected, 0, ((d2 - r2) * (d2 - r2)).get());
        IntPolynomial expected_int;
        fmpq_poly_get_numerator(expected_int.get(), expected);
        fmpq_poly_clear(expected);
        fmpz_poly_primitive_part(expected_int.get(), expected_int.get());
        REQUIRE(squared_distance_quartic(c, q) == expected_int);
    }
    // The center of a circle: every boundary point is at squared distance r^2.
    Ellipse c = Ellipse::circle(Rational(1, 3), 2, Rational(5, 2));
    REQUIRE(squared_distance_quartic(c, c.center()) == IntPolynomial({-25, 4}));
}

TEST_CASE("squared distance quartic: roots at real foot points, the minimum is the distance", "[sites][polynomials]") {
    std::mt19937_64 rng(505);
    for (int trial = 0; trial < 25; ++trial) {
        Ellipse e = random_ellipse(rng);
        // Exact: q on the normal at a rational t0 has squared distance k^2 |n|^2 to P(t0).
        Rational t0 = random_rational(rng, 10, 3), k = random_rational(rng, 5, 4);
        Point n = normal_direction(e, t0);
        Point q = along(e.point_at(t0), k, n);
        IntPolynomial dist = squared_distance_quartic(e, q);
        REQUIRE(dist.degree() == 4);
        REQUIRE(dist.sign_at(k * k * dotp(n, n)) == 0);

        // Numeric: at every real foot point, |q - P|^2 is a root; the smallest
        // one is below every sampled boundary distance.
        Point q2{random_rational(rng, 20, 5), random_rational(rng, 20, 5)};
        IntPolynomial foot = foot_point_quartic(e, q2), dist2 = squared_distance_quartic(e, q2);
        REQUIRE(foot.degree() == 4);
        REQUIRE(dist2.degree() == 4);
        std::vector<Ball> feet = real_roots(foot);
        REQUIRE(feet.size() >= 2);  // the nearest and the farthest point at least
        double smallest = INFINITY;
        for (const Ball& t : feet) {
            Ball d = squared_distance_at(e, q2, t);
            REQUIRE(tiny_and_contains_zero(eval_ball(dist2, d), std::pow(std::fabs(d.mid_double()) + 1, 4) * 1e12));
            smallest = std::min(smallest, d.mid_double());
        }
        const double qx = q2.x.to_double(), qy = q2.y.to_double();
        for (int i = 0; i < 720; ++i) {
            const double th = i * M_PI / 360, tt = std::tan(th / 2);
            if (!std::isfinite(tt) || std::fabs(tt) > 1e6) continue;
            Point p = e.point_at(Rational(static_cast<long>(std::llround(tt * 1e6)), 1000000UL));
            const double dx = qx - p.x.to_double(), dy = qy - p.y.to_double();
            REQUIRE(smallest <= dx * dx + dy * dy + 1e-9);
        }
    }
}

TEST_CASE("squared distance quartic keeps the i-point when it is a foot point", "[sites][polynomials]") {
    std::mt19937_64 rng(606);
    for (int trial = 0; trial < 20; ++trial) {
        const bool circle = trial % 4 == 3;
        Ellipse e = circle ? random_circle(rng) : random_ellipse(rng);
        // q on the a-axis line C + lambda u: the normal at the i-point C - a u.
        const Rational lambda = trial % 2 ? -(e.a() + random_positive(rng, 10, 3)) : random_rational(rng, 10, 3);
        Point q{e.xc() + lambda * e.cos_rotation(), e.yc() + lambda * e.sin_rotation()};
        if (q.x == e.xc() && q.y == e.yc() && circle) continue;
        IntPolynomial foot = foot_point_quartic(e, q);
        CHECK(foot.degree() < 4);  // the i-point is a root at infinity
        IntPolynomial dist = squared_distance_quartic(e, q);
        CHECK(dist.degree() == (circle ? 2 : 4));
        Point ip = e.i_point();
        REQUIRE(dist.sign_at(dotp(minus(q, ip), minus(q, ip))) == 0);
        // ... and the opposite vertex C + a u at t = 0, a finite foot point.
        Point v = e.point_at(Rational(0));
        REQUIRE(dist.sign_at(dotp(minus(q, v), minus(q, v))) == 0);
    }
}

// ---------------------------------------------------------------------------
// Two ellipses
// ---------------------------------------------------------------------------

TEST_CASE("intersection quartic: sign is the side of P1(t) w.r.t. E2, exact roots", "[sites][polynomials]") {
    std::mt19937_64 rng(707);
    for (int trial = 0; trial < 30; ++trial) {
        Ellipse e1 = trial % 5 == 4 ? random_circle(rng, 3) : random_ellipse(rng, 3);
        Ellipse e2 = trial % 3 == 2 ? random_circle(rng, 3) : random_ellipse(rng, 3);
        IntPolynomial p = intersection_quartic(e1, e2);
        CHECK(p.degree() == 4);
        for (int k = 0; k < 10; ++k) {
            Rational t = random_rational(rng, 30, 7);
            Point q = e1.point_at(t);
            REQUIRE(p.sign_at(t) == e2.side_of_point(q.x, q.y));
        }
        // E2 moved through P1(t0): exact root.
        Rational t0 = random_rational(rng, 10, 3), r0 = random_rational(rng, 10, 3);
        Ellipse through = moved_so_that(e2, r0, e1.point_at(t0));
        REQUIRE(intersection_quartic(e1, through).sign_at(t0) == 0);
    }
    Ellipse e = random_ellipse(rng);
    REQUIRE(intersection_quartic(e, e).is_zero());
}

namespace {
// The line through P1(t) along T1(t) against the conic of E2: discriminant of
// the quadratic conic2(P + lambda T) in lambda (> 0 crossing, 0 tangent, < 0 miss).
Rational crossing_discriminant(const Ellipse& e1, const Ellipse& e2, const Rational& t) {
    Point p = e1.point_at(t), T = tangent(e1, t);
    auto f = [&](const Rational& lambda) {
        Point x = along(p, lambda, T);
        return e2.conic_value(x.x, x.y);
    };
    const Rational f0 = f(0), f1 = f(1), fm = f(-1);
    const Rational a = (f1 + fm) / Rational(2) - f0, b = (f1 - fm) / Rational(2);
    return b * b - Rational(4) * a * f0;
}
}  // namespace

TEST_CASE("bitangent quartic: > 0 when the tangent line misses E2, < 0 when it crosses, exact roots", "[sites][polynomials]") {
    std::mt19937_64 rng(808);
    for (int trial = 0; trial < 30; ++trial) {
        Ellipse e1 = trial % 5 == 4 ? random_circle(rng, 4) : random_ellipse(rng, 4);
        Ellipse e2 = trial % 3 == 2 ? random_circle(rng, 4) : random_ellipse(rng, 4);
        IntPolynomial p = bitangent_quartic(e1, e2);
        CHECK(p.degree() == 4);
        // Positive when the tangent line misses E2, negative when it crosses.
        for (int k = 0; k < 10; ++k) {
            Rational t = random_rational(rng, 30, 7);
            const int disc = crossing_discriminant(e1, e2, t).sign();
            REQUIRE(disc != 0);
            REQUIRE(p.sign_at(t) == -disc);
        }
        // E2 moved along the tangent line of E1 at t0 with the same shape as E1:
        // its tangent at the moved point is that same line.
        Rational t0 = random_rational(rng, 10, 3);
        Point target = along(e1.point_at(t0), random_rational(rng, 6, 5), tangent(e1, t0));
        Ellipse copy = moved_so_that(e1, t0, target);
        REQUIRE(bitangent_quartic(e1, copy).sign_at(t0) == 0);
    }
    // Two disjoint ellipses have four common tangents: four real roots (the
    // i-point counts when the degree drops).
    Ellipse e1(3, 1, Rational(1, 3), 0, 0), e2(Rational(5, 2), Rational(3, 2), Rational(-2, 7), 12, 1);
    IntPolynomial p = bitangent_quartic(e1, e2);
    REQUIRE(p.degree() == 4);
    REQUIRE(real_roots(p).size() == 4);
    for (const Ball& t : real_roots(p)) {
        // at a root, the tangent line is tangent: check the discriminant numerically
        // through a nearby rational parameter is tiny relative to its neighbours
        arf_t m;
        arf_init(m);
        arf_set(m, arb_midref(t.get()));
        Rational tq;
        arf_get_fmpq(tq.get(), m);
        arf_clear(m);
        REQUIRE(std::fabs(crossing_discriminant(e1, e2, tq).to_double()) < 1e-50);
    }
}

TEST_CASE("bisector polynomial: degrees and equidistant normal intersections", "[sites][polynomials]") {
    std::mt19937_64 rng(909);
    struct Case {
        bool c1, c2;
        int dt, dr;
    };
    // (6, 6) for two ellipses (the paper, section 3); a circle E1 gives degree 2 in t,
    // two circles (2, 2).
    const Case cases[] = {{false, false, 6, 6}, {true, false, 2, 6}, {false, true, 6, 2}, {true, true, 2, 2}};
    long real_found = 0;
    for (const Case& cs : cases)
        for (int trial = 0; trial < 4; ++trial) {
            Ellipse e1 = cs.c1 ? random_circle(rng) : random_ellipse(rng);
            Ellipse e2 = cs.c2 ? random_circle(rng) : random_ellipse(rng);
            DensePolynomial b = bisector_polynomial(e1, e2);
            REQUIRE(b.degree(0) == cs.dt);
            REQUIRE(b.degree(1) == cs.dr);
            REQUIRE(b.degree(2) == 0);
            // Symmetric: B12(t, r) = +-B21(r, t).
            DensePolynomial swapped = bisector_polynomial(e2, e1).swap_variables(0, 1);
            REQUIRE((swapped == b || swapped == -b));
            const LinePolynomials n1 = normal_line(e1), n2 = normal_line(e2);
            for (int k = 0; k < 3; ++k) {
                Rational t = random_rational(rng, 20, 7);
                IntPolynomial in_r = b.substitute(0, t).to_univariate(1);
                Ball tb(t, kPrec);
                for (const Ball& r : real_roots(in_r)) {
                    ++real_found;
                    // V = N1(t) x N2(r) (Cramer), then |V - P1|^2 = |V - P2|^2.
                    Ball a1(value(n1.l1, t), kPrec), b1(value(n1.l2, t), kPrec), c1(value(n1.l3, t), kPrec);
                    Ball a2 = eval_ball(n2.l1, r), b2 = eval_ball(n2.l2, r), c2 = eval_ball(n2.l3, r);
                    Ball det, vx, vy, tmp;
                    arb_mul(det.get(), a1.get(), b2.get(), kPrec);
                    arb_submul(det.get(), b1.get(), a2.get(), kPrec);
                    REQUIRE(!arb_contains_zero(det.get()));
                    arb_mul(vx.get(), b1.get(), c2.get(), kPrec);
                    arb_submul(vx.get(), c1.get(), b2.get(), kPrec);
                    arb_div(vx.get(), vx.get(), det.get(), kPrec);
                    arb_mul(vy.get(), c1.get(), a2.get(), kPrec);
                    arb_submul(vy.get(), a1.get(), c2.get(), kPrec);
                    arb_div(vy.get(), vy.get(), det.get(), kPrec);
                    BallPoint p1 = e1.point_at(tb, kPrec), p2 = e2.point_at(r, kPrec);
                    auto sq = [&](const BallPoint& p) {
                        Ball dx, dy, s;
                        arb_sub(dx.get(), vx.get(), p.x.get(), kPrec);
                        arb_sub(dy.get(), vy.get(), p.y.get(), kPrec);
                        arb_sqr(s.get(), dx.get(), kPrec);
                        arb_addmul(s.get(), dy.get(), dy.get(), kPrec);
                        return s;
                    };
                    Ball d1 = sq(p1), d2 = sq(p2), diff;
                    arb_sub(diff.get(), d1.get(), d2.get(), kPrec);
                    REQUIRE(tiny_and_contains_zero(diff, std::fabs(d1.mid_double()) * 1e20));
                }
            }
        }
    REQUIRE(real_found >= 16);
}

TEST_CASE("parallel normals polynomial: degree 12, exact roots at common normals", "[sites][polynomials]") {
    std::mt19937_64 rng(1010);
    for (int trial = 0; trial < 20; ++trial) {
        Ellipse e1 = random_ellipse(rng);
        Ellipse e2 = random_ellipse(rng);
        IntPolynomial p = parallel_normals_polynomial(e1, e2);
        REQUIRE(p.degree() == 12);
        // A homothetic copy (same w, scaled axes) has parallel tangents at the
        // same parameter; move it so P2(t0) is on the normal of E1 at t0.
        Rational t0 = random_rational(rng, 10, 3), k = random_rational(rng, 8, 3);
        Rational scale_factor = random_positive(rng, 5, 3);
        Ellipse shape(e1.a() * scale_factor, e1.b() * scale_factor, e1.w(), 0, 0);
        Ellipse e3 = moved_so_that(shape, t0, along(e1.point_at(t0), k, normal_direction(e1, t0)));
        IntPolynomial q = parallel_normals_polynomial(e1, e3);
        REQUIRE(q.sign_at(t0) == 0);
        // Parallel tangents at the antipode -1/t0 of the copy also count.
        if (!t0.is_zero()) {
            Rational anti = Rational(-1) / t0;
            Ellipse e4 = moved_so_that(shape, anti, along(e1.point_at(t0), k, normal_direction(e1, t0)));
            REQUIRE(parallel_normals_polynomial(e1, e4).sign_at(t0) == 0);
        }
    }
}

TEST_CASE("parallel normals polynomial: documented circle cases", "[sites][polynomials]") {
    std::mt19937_64 rng(1111);
    for (int trial = 0; trial < 6; ++trial) {
        Ellipse e = random_ellipse(rng);
        Ellipse c = random_circle(rng);
        // Circle E1, ellipse E2: (1 + t^2)^2 times the degree-8 condition (the
        // 4 normals from the center of E1 to E2 meet the circle twice each).
        IntPolynomial one_plus_t2{1, 0, 1}, square, rest;
        fmpz_poly_sqr(square.get(), one_plus_t2.get());
        const IntPolynomial ce = parallel_normals_polynomial(c, e);
        REQUIRE(ce.degree() == 12);
        REQUIRE(fmpz_poly_divides(rest.get(), ce.get(), square.get()));
        IntPolynomial unused;
        REQUIRE(!fmpz_poly_divides(unused.get(), rest.get(), one_plus_t2.get()));
        // Ellipse E1, circle E2: foot(E1, c2)^2 (Tx^2 + Ty^2), the last factor without real roots.
        IntPolynomial foot = foot_point_quartic(e, c.center());
        IntPolynomial iso, f2, expected;
        IntPolynomial tx2, ty2;
        fmpz_poly_sqr(tx2.get(), e.tangent_x().get());
        fmpz_poly_sqr(ty2.get(), e.tangent_y().get());
        fmpz_poly_add(iso.get(), tx2.get(), ty2.get());
        fmpz_poly_sqr(f2.get(), foot.get());
        fmpz_poly_mul(expected.get(), f2.get(), iso.get());
        fmpz_poly_primitive_part(expected.get(), expected.get());
        REQUIRE(parallel_normals_polynomial(e, c) == expected);
        // Two circles: (the line c1 c2 on E1)^2 (1 + t^2)^4; the foot-point
        // quartic of c2 on E1 is already (1 + t^2) times that line's quadratic.
        Ellipse c2 = random_circle(rng);
        if (c2.center().x == c.center().x && c2.center().y == c.center().y) continue;
        IntPolynomial line_on_c, cc;
        fmpz_poly_mul(line_on_c.get(), foot_point_quartic(c, c2.center()).get(), one_plus_t2.get());
        fmpz_poly_sqr(cc.get(), line_on_c.get());
        fmpz_poly_primitive_part(cc.get(), cc.get());
        REQUIRE(parallel_normals_polynomial(c, c2) == cc);
    }
}

// ---------------------------------------------------------------------------
// Three ellipses
// ---------------------------------------------------------------------------

TEST_CASE("normals concurrency polynomial: degrees, determinant of the normals, concurrent triples",
          "[sites][polynomials]") {
    std::mt19937_64 rng(1212);
    for (int trial = 0; trial < 8; ++trial) {
        const bool c3 = trial % 4 == 3;
        Ellipse e1 = random_ellipse(rng), e2 = random_ellipse(rng), e3 = c3 ? random_circle(rng) : random_ellipse(rng);
        DensePolynomial q = normals_concurrency_polynomial(e1, e2, e3);
        REQUIRE(q.degree(0) == 4);
        REQUIRE(q.degree(1) == 4);
        REQUIRE(q.degree(2) == 4);
        // A circle E3 (only) makes (1 + s^2) a factor.
        DensePolynomial reduced = q;
        REQUIRE(reduced.remove_one_plus_square_factors(2) == (c3 ? 1 : 0));
        REQUIRE(reduced.remove_one_plus_square_factors(0) == 0);
        // Q = kappa * W1 W2 W3 * det[(T, -T.P)_i] at rational points.
        const Ellipse* es[3] = {&e1, &e2, &e3};
        Rational kappa;
        for (int k = 0; k < 6; ++k) {
            Rational p[3] = {random_rational(rng, 20, 7), random_rational(rng, 20, 7), random_rational(rng, 20, 7)};
            Rational m[3][3];
            Rational weight(1);
            for (int i = 0; i < 3; ++i) {
                Point T = tangent(*es[i], p[i]), P = es[i]->point_at(p[i]);
                m[i][0] = T.x;
                m[i][1] = T.y;
                m[i][2] = -dotp(T, P);
                weight = weight * value(es[i]->W(), p[i]);
            }
            Rational det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                           m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
            REQUIRE(!det.is_zero());
            Rational ratio = q.evaluate(p[0], p[1], p[2]) / (weight * det);
            if (k == 0) kappa = ratio;
            REQUIRE(ratio == kappa);
        }
        // Three ellipses placed so that their normals at t1, t2, t3 pass through V.
        Point V{random_rational(rng, 10, 3), random_rational(rng, 10, 3)};
        Rational t[3];
        Ellipse placed[3] = {e1, e2, e3};
        for (int i = 0; i < 3; ++i) {
            t[i] = random_rational(rng, 10, 3);
            Point target = along(V, random_rational(rng, 4, 3), normal_direction(*es[i], t[i]));
            placed[i] = moved_so_that(*es[i], t[i], target);
        }
        DensePolynomial qc = normals_concurrency_polynomial(placed[0], placed[1], placed[2]);
        REQUIRE(qc.evaluate(t[0], t[1], t[2]).is_zero());
    }
}

TEST_CASE("polynomial degrees for generic ellipses match the paper", "[sites][polynomials]") {
    Ellipse e1(3, 1, Rational(1, 3), 0, 0), e2(Rational(5, 2), Rational(3, 2), Rational(-2, 7), 6, 1),
        e3(2, 1, Rational(1, 5), 1, 7);
    Point q{Rational(3, 2), Rational(-7, 3)};
    CHECK(formal_degree(normal_line(e1)) == 4);
    CHECK(tangent_side_quadratic(e1, q).degree() == 2);
    CHECK(foot_point_quartic(e1, q).degree() == 4);
    CHECK(squared_distance_quartic(e1, q).degree() == 4);
    CHECK(intersection_quartic(e1, e2).degree() == 4);
    CHECK(bitangent_quartic(e1, e2).degree() == 4);
    DensePolynomial b = bisector_polynomial(e1, e2);
    CHECK(b.degree(0) == 6);
    CHECK(b.degree(1) == 6);
    CHECK(parallel_normals_polynomial(e1, e2).degree() == 12);
    DensePolynomial qq = normals_concurrency_polynomial(e1, e2, e3);
    CHECK(qq.degree(0) == 4);
    CHECK(qq.degree(1) == 4);
    CHECK(qq.degree(2) == 4);
    // Circles: the same formal degrees, except the squared distance and the bisector.
    Ellipse c1 = Ellipse::circle(1, -5, 2), c2 = Ellipse::circle(-4, 3, Rational(3, 2)), c3 = Ellipse::circle(7, 7, 1);
    CHECK(formal_degree(normal_line(c1)) == 4);
    CHECK(foot_point_quartic(c1, q).degree() == 4);
    CHECK(squared_distance_quartic(c1, q).degree() == 2);
    CHECK(intersection_quartic(c1, c2).degree() == 4);
    CHECK(bitangent_quartic(c1, c2).degree() == 4);
    DensePolynomial bc = bisector_polynomial(c1, c2);
    CHECK(bc.degree(0) == 2);
    CHECK(bc.degree(1) == 2);
    CHECK(parallel_normals_polynomial(c1, c2).degree() == 12);
    DensePolynomial qc = normals_concurrency_polynomial(c1, c2, c3);
    CHECK(qc.degree(0) == 4);
    CHECK(qc.degree(1) == 4);
    CHECK(qc.degree(2) == 4);
    DensePolynomial qr = qc;
    CHECK(qr.remove_one_plus_square_factors(0) == 1);
    CHECK(qr.remove_one_plus_square_factors(1) == 1);
    CHECK(qr.remove_one_plus_square_factors(2) == 1);
}
