#include "sites/ellipse.hpp"

#include "util/error.hpp"

#include <arb_fmpz_poly.h>
#include <flint/fmpq_poly.h>

#include <cmath>
#include <memory>

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

namespace {

// The rational a double stands for (finite), exactly: m 2^e with m an integer
// of 53 bits at most.
Rational exact_rational(double d) {
    Rational r;
    if (d == 0) return r;
    int e = 0;
    const double m = std::frexp(d, &e);  // d = m 2^e, 1/2 <= |m| < 1
    fmpq_set_si(r.get(), static_cast<slong>(std::ldexp(m, 53)), 1);
    if (e >= 53)
        fmpq_mul_2exp(r.get(), r.get(), static_cast<ulong>(e - 53));
    else
        fmpq_div_2exp(r.get(), r.get(), static_cast<ulong>(53 - e));
    return r;
}

// cos and sin of the rotation angle of w = tan(omega/2): (1 - w^2)/(1 + w^2), 2w/(1 + w^2).
Rational cos_of(const Rational& w) {
    if (w.is_zero()) return Rational(1);
    const Rational w2 = w * w, one(1);
    return (one - w2) / (one + w2);
}

Rational sin_of(const Rational& w) {
    if (w.is_zero()) return Rational(0);
    return Rational(2) * w / (Rational(1) + w * w);
}

}  // namespace

Ellipse::Exact::Exact(Rational a, Rational b, Rational w, Rational xc, Rational yc)
    : a(std::move(a)), b(std::move(b)), w(std::move(w)), xc(std::move(xc)), yc(std::move(yc)) {
    enclosure = {enclose(this->a),         enclose(this->b),  enclose(cos_of(this->w)),
                 enclose(sin_of(this->w)), enclose(this->xc), enclose(this->yc)};
}

Ellipse::Exact::~Exact() { delete polynomials.load(std::memory_order_acquire); }

bool Ellipse::is_compact(const Rational& a, const Rational& b, const Rational& w, const Rational& xc,
                         const Rational& yc) {
    return w.is_zero() && a == b && a.is_small_dyadic() && xc.is_small_dyadic() && yc.is_small_dyadic();
}

Ellipse::Ellipse(Rational a, Rational b, Rational w, Rational xc, Rational yc) {
    if (a.sign() <= 0) throw Error("semi-axis a must be positive, got " + a.str());
    if (b.sign() <= 0) throw Error("semi-axis b must be positive, got " + b.str());
    circle_ = a == b;
    dyadic_circle_ = circle_ && a.is_small_dyadic() && xc.is_small_dyadic() && yc.is_small_dyadic();
    compact_ = is_compact(a, b, w, xc, yc);
    if (compact_) {
        // Its doubles are exact: its parameters come back from them (make_exact).
        near_ = {a.to_double(), xc.to_double(), yc.to_double()};
        return;
    }
    exact_.store(new Exact(std::move(a), std::move(b), std::move(w), std::move(xc), std::move(yc)),
                 std::memory_order_relaxed);
}

Ellipse& Ellipse::operator=(const Ellipse& o) noexcept {
    if (this == &o) return *this;
    Exact* mine = share(o.exact_.load(std::memory_order_acquire));
    release(exact_.exchange(mine, std::memory_order_acq_rel));
    near_ = o.near_;
    circle_ = o.circle_;
    dyadic_circle_ = o.dyadic_circle_;
    compact_ = o.compact_;
    return *this;
}

Ellipse Ellipse::unshared() const {
    Ellipse copy(*this);
    copy.make_own();
    return copy;
}

std::vector<Ellipse> Ellipse::unshared_copies(const std::vector<Ellipse>& sites) {
    constexpr std::size_t kAhead = 8;
    std::vector<Ellipse> out;
    out.reserve(sites.size());
    for (std::size_t k = 0; k < sites.size(); ++k) {
        if (k + kAhead < sites.size()) sites[k + kAhead].prefetch();
        out.push_back(sites[k].unshared());
    }
    return out;
}

void Ellipse::make_own() {
    Exact* e = exact_.load(std::memory_order_acquire);
    if (!compact_ && e->references.load(std::memory_order_acquire) == 1) return;
    Exact* own = compact_ ? nullptr : new Exact(*e);
    release(exact_.exchange(own, std::memory_order_acq_rel));
}

const Ellipse::Exact& Ellipse::make_exact() const {
    const Rational r = exact_rational(near_[0]);
    auto* made = new Exact(r, r, Rational(0), exact_rational(near_[1]), exact_rational(near_[2]));
    Exact* expected = nullptr;
    // Another thread may have been first: keep its (equal) values.
    if (!exact_.compare_exchange_strong(expected, made, std::memory_order_acq_rel, std::memory_order_acquire)) {
        delete made;
        return *expected;
    }
    return *made;
}

Rational Ellipse::cos_rotation() const { return compact_ ? Rational(1) : cos_of(w()); }

Rational Ellipse::sin_rotation() const { return compact_ ? Rational(0) : sin_of(w()); }

const Ellipse::Polynomials& Ellipse::polynomials() const {
    const Exact& e = exact();
    if (const Polynomials* ready = e.polynomials.load(std::memory_order_acquire)) return *ready;
    auto made = std::make_unique<Polynomials>();
    const Rational one(1), two(2);
    const Rational &a_ = e.a, &b_ = e.b, &xc_ = e.xc, &yc_ = e.yc;
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
    const Polynomials* expected = nullptr;
    // Another thread may have been first: keep its (equal) values.
    if (!e.polynomials.compare_exchange_strong(expected, made.get(), std::memory_order_acq_rel,
                                               std::memory_order_acquire))
        return *expected;
    return *made.release();
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

Point Ellipse::i_point() const { return {xc() - a() * cos_rotation(), yc() - a() * sin_rotation()}; }

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
    const Exact& e = exact();
    return e.a.str() + " " + e.b.str() + " " + e.w.str() + " " + e.xc.str() + " " + e.yc.str();
}

bool operator==(const Ellipse& p, const Ellipse& q) {
    // Compactness follows from the values: two compact circles are equal
    // exactly when their (exact) doubles are, and never equal another site.
    if (p.compact_ || q.compact_)
        return p.compact_ && q.compact_ && p.near_ == q.near_;
    const Ellipse::Exact &e = p.exact(), &f = q.exact();
    return e.a == f.a && e.b == f.b && e.w == f.w && e.xc == f.xc && e.yc == f.yc;
}

std::array<Rational, 3> Ellipse::quadratic_form() const {
    const Rational a2 = a() * a(), b2 = b() * b();
    const Rational c = cos_rotation(), s = sin_rotation();
    return {b2 * c * c + a2 * s * s, (b2 - a2) * c * s, b2 * s * s + a2 * c * c};
}

Ellipse::PointSetKey Ellipse::point_set_key() const {
    // From the quadratic form alone: a reader keys every site, and the conic
    // is made only on first use (polynomials()).
    if (compact_) {
        // r^2 (x^2 + y^2) / r^4, without making the circle's Exact (a
        // reader keys every site).
        const Rational r = exact_rational(near_[0]), inverse = Rational(1) / (r * r);
        return {exact_rational(near_[1]), exact_rational(near_[2]), inverse, Rational(0), inverse};
    }
    const Rational scale = a() * a() * b() * b();
    const auto [A, B, C] = quadratic_form();
    return {xc(), yc(), A / scale, B / scale, C / scale};
}

}  // namespace ellvor
