#include "sites/ellipse.hpp"

#include "util/error.hpp"

#include <arb_fmpz_poly.h>
#include <flint/fmpq_poly.h>

namespace ellvor {

namespace {

// Integer polynomials (X, Y, W) from rational coefficient lists, scaled by the
// least common multiple of all denominators (a common factor of a homogeneous
// point changes nothing).
void scale_to_integers(const std::array<std::array<Rational, 3>, 3>& rational_coeffs,
                       std::array<IntPolynomial*, 3> out) {
    Integer lcm(1);
    for (const auto& poly : rational_coeffs)
        for (const auto& c : poly) fmpz_lcm(lcm.get(), lcm.get(), fmpq_denref(c.get()));
    for (int n = 0; n < 3; ++n) {
        IntPolynomial p;
        for (int i = 0; i < 3; ++i) {
            Rational scaled = rational_coeffs[n][i] * Rational(lcm);
            p.set_coeff(i, scaled.numerator());
        }
        *out[n] = p;
    }
}

}  // namespace

IntPolynomial homogeneous_tangent(const IntPolynomial& P, const IntPolynomial& W) {
    IntPolynomial dP, dW, a, b, r;
    fmpz_poly_derivative(dP.get(), P.get());
    fmpz_poly_derivative(dW.get(), W.get());
    fmpz_poly_mul(a.get(), dP.get(), W.get());
    fmpz_poly_mul(b.get(), P.get(), dW.get());
    fmpz_poly_sub(r.get(), a.get(), b.get());
    return r;
}

Ellipse::Ellipse(Rational a, Rational b, Rational w, Rational xc, Rational yc)
    : a_(std::move(a)), b_(std::move(b)), w_(std::move(w)), xc_(std::move(xc)), yc_(std::move(yc)) {
    if (a_.sign() <= 0) throw Error("semi-axis a must be positive, got " + a_.str());
    if (b_.sign() <= 0) throw Error("semi-axis b must be positive, got " + b_.str());
    enclosure_ = {enclose(a_), enclose(b_), enclose(cos_rotation()), enclose(sin_rotation()), enclose(xc_), enclose(yc_)};
    circle_ = a_ == b_;
    dyadic_circle_ = circle_ && a_.is_small_dyadic() && xc_.is_small_dyadic() && yc_.is_small_dyadic();
}

Rational Ellipse::cos_rotation() const {
    if (w_.is_zero()) return Rational(1);
    const Rational w2 = w_ * w_, one(1);
    return (one - w2) / (one + w2);
}

Rational Ellipse::sin_rotation() const {
    if (w_.is_zero()) return Rational(0);
    return Rational(2) * w_ / (Rational(1) + w_ * w_);
}

const Ellipse::Polynomials& Ellipse::polynomials() const {
    if (std::shared_ptr<const Polynomials> ready = std::atomic_load(&polynomials_)) return *ready;
    auto made = std::make_shared<Polynomials>();
    const Rational one(1), two(2);
    // Coefficients (constant, t, t^2):
    //   X = xc (1 + t^2) + a cos (1 - t^2) - 2 b sin t
    //   Y = yc (1 + t^2) + a sin (1 - t^2) + 2 b cos t
    //   W = 1 + t^2
    const Rational c = cos_rotation(), s = sin_rotation();
    const Rational ac = a_ * c, as = a_ * s;
    std::array<std::array<Rational, 3>, 3> coeffs = {{
        {xc_ + ac, -(two * b_ * s), xc_ - ac},
        {yc_ + as, two * b_ * c, yc_ - as},
        {one, Rational(0), one},
    }};
    scale_to_integers(coeffs, {&made->X, &made->Y, &made->W});
    made->Tx = homogeneous_tangent(made->X, made->W);
    made->Ty = homogeneous_tangent(made->Y, made->W);

    // b^2 xi^2 + a^2 eta^2 - a^2 b^2 with xi = c dx + s dy, eta = -s dx + c dy.
    const auto [A, B, C] = quadratic_form();
    const Rational a2 = a_ * a_, b2 = b_ * b_;
    Rational D = -(A * xc_ + B * yc_);
    Rational E = -(B * xc_ + C * yc_);
    Rational F = A * xc_ * xc_ + two * B * xc_ * yc_ + C * yc_ * yc_ - a2 * b2;
    made->conic = {A, B, C, D, E, F};
    std::shared_ptr<const Polynomials> expected;
    std::shared_ptr<const Polynomials> mine = std::move(made);
    // Another thread may have been first: keep its (equal) values.
    if (!std::atomic_compare_exchange_strong(&polynomials_, &expected, mine)) return *expected;
    return *mine;
}

Ellipse Ellipse::circle(const Rational& x, const Rational& y, const Rational& r) {
    return Ellipse(r, r, Rational(0), x, y);
}

Point Ellipse::point_at(const Rational& t) const {
    Rational x, y, w;
    fmpz_poly_evaluate_fmpq(x.get(), X().get(), t.get());
    fmpz_poly_evaluate_fmpq(y.get(), Y().get(), t.get());
    fmpz_poly_evaluate_fmpq(w.get(), W().get(), t.get());
    return {x / w, y / w};
}

Point Ellipse::i_point() const { return {xc_ - a_ * cos_rotation(), yc_ - a_ * sin_rotation()}; }

BallPoint Ellipse::point_at(const Ball& t, long prec) const {
    BallPoint p;
    Ball w;
    arb_fmpz_poly_evaluate_arb(p.x.get(), X().get(), t.get(), prec);
    arb_fmpz_poly_evaluate_arb(p.y.get(), Y().get(), t.get(), prec);
    arb_fmpz_poly_evaluate_arb(w.get(), W().get(), t.get(), prec);
    arb_div(p.x.get(), p.x.get(), w.get(), prec);
    arb_div(p.y.get(), p.y.get(), w.get(), prec);
    return p;
}

Rational Ellipse::conic_value(const Rational& x, const Rational& y) const {
    const auto& k = conic();
    const Rational two(2);
    return k[0] * x * x + two * k[1] * x * y + k[2] * y * y + two * k[3] * x + two * k[4] * y + k[5];
}

int Ellipse::side_of_point(const Rational& x, const Rational& y) const { return conic_value(x, y).sign(); }

std::string Ellipse::str() const {
    return a_.str() + " " + b_.str() + " " + w_.str() + " " + xc_.str() + " " + yc_.str();
}

bool operator==(const Ellipse& p, const Ellipse& q) {
    return p.a_ == q.a_ && p.b_ == q.b_ && p.w_ == q.w_ && p.xc_ == q.xc_ && p.yc_ == q.yc_;
}

std::array<Rational, 3> Ellipse::quadratic_form() const {
    const Rational a2 = a_ * a_, b2 = b_ * b_;
    const Rational c = cos_rotation(), s = sin_rotation();
    return {b2 * c * c + a2 * s * s, (b2 - a2) * c * s, b2 * s * s + a2 * c * c};
}

Ellipse::PointSetKey Ellipse::point_set_key() const {
    // From the quadratic form alone: a reader keys every site, and the conic
    // is made only on first use (polynomials()).
    const Rational scale = a_ * a_ * b_ * b_;
    const auto [A, B, C] = quadratic_form();
    return {xc_, yc_, A / scale, B / scale, C / scale};
}

}  // namespace ellvor
