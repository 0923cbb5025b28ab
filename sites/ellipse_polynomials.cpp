#include "sites/ellipse_polynomials.hpp"

#include "util/error.hpp"

namespace ellvor {

namespace {

// Integer scale that clears the denominators of the six conic coefficients.
std::array<Integer, 6> integer_conic(const Ellipse& e) {
    Integer lcm(1);
    for (const auto& c : e.conic()) fmpz_lcm(lcm.get(), lcm.get(), fmpq_denref(c.get()));
    std::array<Integer, 6> k;
    for (int i = 0; i < 6; ++i) k[i] = (e.conic()[i] * Rational(lcm)).numerator();
    return k;
}

IntPolynomial add(const IntPolynomial& a, const IntPolynomial& b) {
    IntPolynomial r;
    fmpz_poly_add(r.get(), a.get(), b.get());
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
IntPolynomial primitive(const IntPolynomial& a) {
    IntPolynomial r;
    fmpz_poly_primitive_part(r.get(), a.get());  // positive leading coefficient
    return r;
}

}  // namespace

LinePolynomials tangent_line(const Ellipse& e) {
    // (l1, l2, l3) = M (X, Y, W) with M = [[A, B, D], [B, C, E], [D, E, F]].
    const auto k = integer_conic(e);
    const IntPolynomial &X = e.X(), &Y = e.Y(), &W = e.W();
    LinePolynomials l;
    l.l1 = add(add(scale(X, k[0]), scale(Y, k[1])), scale(W, k[3]));
    l.l2 = add(add(scale(X, k[1]), scale(Y, k[2])), scale(W, k[4]));
    l.l3 = add(add(scale(X, k[3]), scale(Y, k[4])), scale(W, k[5]));
    return l;
}

IntPolynomial intersection_quartic(const Ellipse& e1, const Ellipse& e2) {
    // (X, Y, W) M2 (X, Y, W)^T = X*l1 + Y*l2 + W*l3 with l = M2 (X, Y, W).
    const auto k = integer_conic(e2);
    const IntPolynomial &X = e1.X(), &Y = e1.Y(), &W = e1.W();
    IntPolynomial l1 = add(add(scale(X, k[0]), scale(Y, k[1])), scale(W, k[3]));
    IntPolynomial l2 = add(add(scale(X, k[1]), scale(Y, k[2])), scale(W, k[4]));
    IntPolynomial l3 = add(add(scale(X, k[3]), scale(Y, k[4])), scale(W, k[5]));
    IntPolynomial q = add(add(mul(X, l1), mul(Y, l2)), mul(W, l3));
    if (q.is_zero()) return q;
    // Keep the sign meaning (negative where P1(t) is inside E2): the scale is
    // positive, so take the content without flipping the sign.
    Integer content;
    fmpz_poly_content(content.get(), q.get());
    IntPolynomial r;
    fmpz_poly_scalar_divexact_fmpz(r.get(), q.get(), content.get());
    (void)primitive;
    return r;
}

}  // namespace ellvor
