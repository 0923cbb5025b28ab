// The polynomials of one, two and three ellipses. Every function is a short
// sequence of named steps; the comments cite the paper (Emiris-Tsigaridas-
// Tzoumas 2007, sections 2-3; docs/DESIGN.md).
//
// Notation: P(t) = (X : Y : W)(t), W = L (1 + t^2) with L > 0, and the
// tangent direction T(t) = (Tx, Ty) = (X'W - XW', Y'W - YW') = W^2 dP/dt,
// degree <= 2 and never zero (Tx, Ty have no common complex root).
#include "sites/ellipse_polynomials.hpp"

#include "util/error.hpp"

#include <flint/fmpz_mat.h>
#include <flint/fmpz_poly_mat.h>

#include <algorithm>
#include <vector>

namespace ellvor {

namespace {

// --- small helpers on IntPolynomial -----------------------------------------

IntPolynomial add(const IntPolynomial& a, const IntPolynomial& b) {
    IntPolynomial r;
    fmpz_poly_add(r.get(), a.get(), b.get());
    return r;
}
IntPolynomial sub(const IntPolynomial& a, const IntPolynomial& b) {
    IntPolynomial r;
    fmpz_poly_sub(r.get(), a.get(), b.get());
    return r;
}
IntPolynomial mul(const IntPolynomial& a, const IntPolynomial& b) {
    IntPolynomial r;
    fmpz_poly_mul(r.get(), a.get(), b.get());
    return r;
}
IntPolynomial scale(const IntPolynomial& a, const Integer& c) {
    IntPolynomial r;
    fmpz_poly_scalar_mul_fmpz(r.get(), a.get(), c.get());
    return r;
}
// Divided by its (positive) content: the sign of every value is kept.
IntPolynomial divide_by_positive_content(const IntPolynomial& a) {
    if (a.is_zero()) return a;
    Integer content;
    fmpz_poly_content(content.get(), a.get());
    IntPolynomial r;
    fmpz_poly_scalar_divexact_fmpz(r.get(), a.get(), content.get());
    return r;
}

// Integer scale that clears the denominators of the six conic coefficients
// (a positive scale: the conic stays negative inside).
std::array<Integer, 6> integer_conic(const Ellipse& e) {
    Integer lcm(1);
    for (const auto& c : e.conic()) fmpz_lcm(lcm.get(), lcm.get(), fmpq_denref(c.get()));
    std::array<Integer, 6> k;
    for (int i = 0; i < 6; ++i) k[i] = (e.conic()[i] * Rational(lcm)).numerator();
    return k;
}

// The symmetric conic matrix [[A, B, D], [B, C, E], [D, E, F]] (integer scaled).
using Matrix3 = std::array<std::array<Integer, 3>, 3>;
Matrix3 conic_matrix(const Ellipse& e) {
    const auto k = integer_conic(e);
    return {{{k[0], k[1], k[3]}, {k[1], k[2], k[4]}, {k[3], k[4], k[5]}}};
}

// Adjugate of a 3x3 integer matrix: adj(M)[i][j] = cofactor(M)[j][i].
Matrix3 adjugate(const Matrix3& m) {
    Matrix3 adj;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            // cofactor of entry (j, i)
            const int r0 = (j + 1) % 3, r1 = (j + 2) % 3, c0 = (i + 1) % 3, c1 = (i + 2) % 3;
            adj[i][j] = m[r0][c0] * m[r1][c1] - m[r0][c1] * m[r1][c0];
        }
    return adj;
}

// M (X, Y, W)^T for a symmetric integer matrix and polynomial point.
std::array<IntPolynomial, 3> matrix_times(const Matrix3& m, const std::array<IntPolynomial, 3>& v) {
    std::array<IntPolynomial, 3> r;
    for (int i = 0; i < 3; ++i) r[i] = add(add(scale(v[0], m[i][0]), scale(v[1], m[i][1])), scale(v[2], m[i][2]));
    return r;
}

IntPolynomial dot(const std::array<IntPolynomial, 3>& a, const std::array<IntPolynomial, 3>& b) {
    return add(add(mul(a[0], b[0]), mul(a[1], b[1])), mul(a[2], b[2]));
}

// A rational point as integer homogeneous coordinates (qx d, qy d, d), d > 0.
std::array<Integer, 3> homogeneous(const Point& q) {
    Integer d;
    fmpz_lcm(d.get(), fmpq_denref(q.x.get()), fmpq_denref(q.y.get()));
    return {(q.x * Rational(d)).numerator(), (q.y * Rational(d)).numerator(), d};
}

// l1 q1 + l2 q2 + l3 q3.
IntPolynomial line_at(const LinePolynomials& l, const std::array<Integer, 3>& q) {
    return add(add(scale(l.l1, q[0]), scale(l.l2, q[1])), scale(l.l3, q[2]));
}

// Determinant of the Sylvester matrix of f and g, given by their coefficient
// lists in the eliminated variable (lowest first), each coefficient a
// polynomial in the remaining variable. The sizes of the lists are the FORMAL
// degrees + 1, so vanishing leading coefficients are kept: this is the
// resultant of the homogenized forms, which also sees a common root at
// infinity (the i-point).
IntPolynomial sylvester_resultant(const std::vector<IntPolynomial>& f, const std::vector<IntPolynomial>& g) {
    const long m = static_cast<long>(f.size()) - 1, n = static_cast<long>(g.size()) - 1;
    const long size = m + n;
    IntPolynomialMatrix s(size, size);
    for (long i = 0; i < n; ++i)  // n shifted rows of f
        for (long k = 0; k <= m; ++k) fmpz_poly_set(s.at(i, i + k), f[m - k].get());
    for (long i = 0; i < m; ++i)  // m shifted rows of g
        for (long k = 0; k <= n; ++k) fmpz_poly_set(s.at(n + i, i + k), g[n - k].get());
    IntPolynomial det;
    fmpz_poly_mat_det(det.get(), s.get());
    return det;
}

// --- DensePolynomial helpers ----------------------------------------------

DensePolynomial lift(const IntPolynomial& p, int var) { return DensePolynomial::from_univariate(var, p); }

using DenseRow = std::array<DensePolynomial, 3>;

DenseRow lift(const LinePolynomials& l, int var) { return {lift(l.l1, var), lift(l.l2, var), lift(l.l3, var)}; }

// Cofactor expansion along the first row.
DensePolynomial determinant(const DenseRow& a, const DenseRow& b, const DenseRow& c) {
    return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
           a[2] * (b[0] * c[1] - b[1] * c[0]);
}

// The normal line divided by the gcd of its three polynomials. That gcd
// divides gcd(Tx W, Ty W) = W (Tx and Ty have no common complex root), so it is
// 1 for an ellipse and (1 + t^2) for a circle, whose normal passes through the
// center: Tx X + Ty Y = W (Tx xc + Ty yc). fmpz_poly_gcd has a positive
// leading coefficient, so the divisor is positive on the reals and the
// orientation is kept. Formal degree 4 (ellipse) / 2 (circle).
LinePolynomials reduced_normal_line(const Ellipse& e) {
    LinePolynomials l = normal_line(e);
    IntPolynomial g;
    fmpz_poly_gcd(g.get(), l.l1.get(), l.l2.get());
    fmpz_poly_gcd(g.get(), g.get(), l.l3.get());
    for (IntPolynomial* p : {&l.l1, &l.l2, &l.l3}) {
        IntPolynomial q;
        if (!fmpz_poly_divides(q.get(), p->get(), g.get())) throw Error("normal line: inexact division");
        *p = q;
    }
    return l;
}

}  // namespace

// ===========================================================================
// One ellipse
// ===========================================================================

LinePolynomials tangent_line(const Ellipse& e) {
    // Polar line of P(t) with respect to the conic: (l1, l2, l3) = M (X, Y, W).
    const auto l = matrix_times(conic_matrix(e), {e.X(), e.Y(), e.W()});
    return {l[0], l[1], l[2]};
}

LinePolynomials normal_line(const Ellipse& e) {
    // Seed eq. (1): x'(t) x + y'(t) y - x'(t) x(t) - y'(t) y(t) = 0. With
    // x = X/W and (x', y') = T / W^2, multiplying by W^3 gives
    //   Tx W x + Ty W y - (Tx X + Ty Y) = 0.
    // Divided by the positive integer content only: formal degree 4 for every
    // site, and (l1, l2) stays a positive multiple of T(t).
    const IntPolynomial &Tx = e.tangent_x(), &Ty = e.tangent_y();
    LinePolynomials l{mul(Tx, e.W()), mul(Ty, e.W()), sub(IntPolynomial(), add(mul(Tx, e.X()), mul(Ty, e.Y())))};
    Integer content, c;
    for (const IntPolynomial* p : {&l.l1, &l.l2, &l.l3}) {
        fmpz_poly_content(c.get(), p->get());
        fmpz_gcd(content.get(), content.get(), c.get());
    }
    for (IntPolynomial* p : {&l.l1, &l.l2, &l.l3}) fmpz_poly_scalar_divexact_fmpz(p->get(), p->get(), content.get());
    return l;
}

IntPolynomial tangent_side_quadratic(const Ellipse& e, const Point& q) {
    // The polar line at (qx, qy, 1), times the positive denominator of q, then
    // divided by the positive content: the sign is the side.
    return divide_by_positive_content(line_at(tangent_line(e), homogeneous(q)));
}

IntPolynomial foot_point_quartic(const Ellipse& e, const Point& q) {
    // Seed eq. (1) at (x, y) = q: W(t) T(t) . (q - P(t)) = 0; formal degree 4
    // (a circle keeps the non-real factor (1 + t^2)).
    return line_at(normal_line(e), homogeneous(q)).primitive_part();
}

IntPolynomial squared_distance_quartic(const Ellipse& e, const Point& q) {
    // F(t): the foot points, from the REDUCED normal line (for a circle the
    // factor (1 + t^2) would make the resultant vanish: G(s, +-i) = 0
    // identically, as (X, Y)(+-i) is isotropic for a circle).
    // G(s, t) = s W^2 - |q W - (X, Y)|^2 vanishes iff s = |q - P(t)|^2.
    // res_t(F, G), taken with the FORMAL degree of F (4 for an ellipse, 2 for
    // a circle), is a constant times the product over the roots t_i of F --
    // including t = infinity when deg F drops -- of W(t_i)^2 (s - |q - P(t_i)|^2);
    // at infinity, G's leading coefficient is w2^2 (s - |q - i-point|^2).
    const LinePolynomials n = reduced_normal_line(e);
    const IntPolynomial F = line_at(n, homogeneous(q)).primitive_part();
    if (F.is_zero()) {
        // q is the center of a circle: every point is a foot point, distance a.
        const Rational r2 = e.a() * e.a();
        IntPolynomial p;
        p.set_coeff(1, r2.denominator());
        p.set_coeff(0, -r2.numerator());
        return p.primitive_part();
    }
    const long formal_degree = std::max({n.l1.degree(), n.l2.degree(), n.l3.degree()});

    // Coefficients of F in t, constants as polynomials in s.
    std::vector<IntPolynomial> f(formal_degree + 1);
    for (long i = 0; i <= formal_degree; ++i) f[i].set_coeff(0, F.coeff(i));

    // G(s, t) = s W^2 - (qx W - X)^2 - (qy W - Y)^2, with q = (Qx, Qy)/d:
    // times d^2 to stay integral.
    const auto qh = homogeneous(q);
    const IntPolynomial dx = sub(scale(e.W(), qh[0]), scale(e.X(), qh[2]));
    const IntPolynomial dy = sub(scale(e.W(), qh[1]), scale(e.Y(), qh[2]));
    const IntPolynomial s_part = scale(mul(e.W(), e.W()), qh[2] * qh[2]);  // coefficient of s
    const IntPolynomial constant_part = sub(IntPolynomial(), add(mul(dx, dx), mul(dy, dy)));
    const long g_degree = 2 * e.W().degree();  // 4
    std::vector<IntPolynomial> g(g_degree + 1);
    for (long i = 0; i <= g_degree; ++i) {
        g[i].set_coeff(0, constant_part.coeff(i));
        g[i].set_coeff(1, s_part.coeff(i));
    }
    return sylvester_resultant(f, g).primitive_part();
}

// ===========================================================================
// Two ellipses
// ===========================================================================

IntPolynomial intersection_quartic(const Ellipse& e1, const Ellipse& e2) {
    // (X, Y, W) M2 (X, Y, W)^T = P1 . (M2 P1): the conic of E2 at P1(t) times
    // W1(t)^2 > 0; keep the sign (negative where P1(t) is inside E2).
    const std::array<IntPolynomial, 3> p = {e1.X(), e1.Y(), e1.W()};
    return divide_by_positive_content(dot(p, matrix_times(conic_matrix(e2), p)));
}

IntPolynomial bitangent_quartic(const Ellipse& e1, const Ellipse& e2) {
    // A line l is tangent to the (non-degenerate) conic M2 iff l^T adj(M2) l = 0
    // (dual conic). l = tangent line of E1 at t, degree 2, so degree 4.
    const LinePolynomials l = tangent_line(e1);
    const std::array<IntPolynomial, 3> lv = {l.l1, l.l2, l.l3};
    // Keep the sign: negative where the line crosses E2, positive where it
    // misses (the adjugate of a conic that is negative inside).
    return divide_by_positive_content(dot(lv, matrix_times(adjugate(conic_matrix(e2)), lv)));
}

DensePolynomial bisector_polynomial(const Ellipse& e1, const Ellipse& e2) {
    // Seed eqs. (1)-(2): the normals N1(t), N2(r) and the perpendicular
    // bisector of P1(t) P2(r),
    //   2 (x2 - x1) v1 + 2 (y2 - y1) v2 + x1^2 + y1^2 - x2^2 - y2^2 = 0,
    // are concurrent. With x_i = X_i / W_i, times W1^2 W2^2 the bisector row is
    //   (2 W1 W2 (X2 W1 - X1 W2), 2 W1 W2 (Y2 W1 - Y1 W2),
    //    (X1^2 + Y1^2) W2^2 - (X2^2 + Y2^2) W1^2).
    const int T = 0, R = 1;
    const DenseRow n1 = lift(normal_line(e1), T);
    const DenseRow n2 = lift(normal_line(e2), R);
    const DensePolynomial X1 = lift(e1.X(), T), Y1 = lift(e1.Y(), T), W1 = lift(e1.W(), T);
    const DensePolynomial X2 = lift(e2.X(), R), Y2 = lift(e2.Y(), R), W2 = lift(e2.W(), R);
    const DensePolynomial two_w1w2 = W1 * W2 * Integer(2);
    const DenseRow bisector_row = {two_w1w2 * (X2 * W1 - X1 * W2), two_w1w2 * (Y2 * W1 - Y1 * W2),
                                   (X1 * X1 + Y1 * Y1) * W2 * W2 - (X2 * X2 + Y2 * Y2) * W1 * W1};
    DensePolynomial b = determinant(n1, n2, bisector_row);
    // Seed: "after eliminating nonzero factors of (1 + t^2) and (1 + r^2)".
    b.remove_one_plus_square_factors(T);
    b.remove_one_plus_square_factors(R);
    return b.primitive_part();
}

IntPolynomial parallel_normals_polynomial(const Ellipse& e1, const Ellipse& e2) {
    // A(t, r) = N1(t) . (X2, Y2, W2)(r): the normal of E1 at t passes through
    //           P2(r); bidegree (4, 2).
    // C(t, r) = T1x(t) T2y(r) - T1y(t) T2x(r): parallel tangents, (2, 2).
    // Both together: the normal of E1 at t is the normal of E2 at r.
    // res_r(A, C) with formal degrees 2 and 2 in r: degree 2*4 + 2*2 = 12 in t.
    const LinePolynomials n1 = normal_line(e1);
    const IntPolynomial &X2 = e2.X(), &Y2 = e2.Y(), &W2 = e2.W();
    std::vector<IntPolynomial> a(3), c(3);
    for (long j = 0; j <= 2; ++j) {
        // coefficient of r^j
        a[j] = add(add(scale(n1.l1, X2.coeff(j)), scale(n1.l2, Y2.coeff(j))), scale(n1.l3, W2.coeff(j)));
        c[j] = sub(scale(e1.tangent_x(), e2.tangent_y().coeff(j)), scale(e1.tangent_y(), e2.tangent_x().coeff(j)));
    }
    return sylvester_resultant(a, c).primitive_part();
}

// ===========================================================================
// Three ellipses
// ===========================================================================

DensePolynomial normals_concurrency_polynomial(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3) {
    // Seed system (4): Q(t, r, s) = det [N1(t); N2(r); N3(s)].
    return determinant(lift(normal_line(e1), 0), lift(normal_line(e2), 1), lift(normal_line(e3), 2))
        .primitive_part();
}

}  // namespace ellvor
