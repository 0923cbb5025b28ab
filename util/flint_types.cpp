#include "util/flint_types.hpp"

#include "util/error.hpp"

#include <flint/flint.h>

#include <memory>

namespace ellvor {

namespace {
// FLINT returns strings allocated with flint_malloc; this owns one.
struct FlintString {
    char* s;
    ~FlintString() { flint_free(s); }
};
}  // namespace

std::string Integer::str() const {
    FlintString s{fmpz_get_str(nullptr, 10, v_)};
    return s.s;
}

long Rational::bits() const {
    long n = fmpz_bits(fmpq_numref(v_));
    long d = fmpz_bits(fmpq_denref(v_));
    return n > d ? n : d;
}

Rational Rational::of_double(double x) {
    Arf a;
    arf_set_d(a.get(), x);
    Rational r;
    arf_get_fmpq(r.get(), a.get());
    return r;
}

double Rational::to_double() const {
    // One correctly rounded division to 53 bits (no double rounding): the
    // nearest double, which the semi-static filters rely on
    // (circles/semi_static.hpp, rounded_input). Exact in the normal range.
    Arf x;
    arf_set_fmpz(x.get(), fmpq_numref(v_));
    arf_div_fmpz(x.get(), x.get(), fmpq_denref(v_), 53, ARF_RND_NEAR);
    return arf_get_d(x.get(), ARF_RND_NEAR);
}

std::string Rational::str() const {
    FlintString s{fmpq_get_str(nullptr, 10, v_)};
    return s.s;
}

Rational operator/(const Rational& a, const Rational& b) {
    if (b.is_zero()) throw Error("division by zero");
    Rational r;
    fmpq_div(r.get(), a.get(), b.get());
    return r;
}

IntPolynomial::IntPolynomial(std::initializer_list<long> coeffs_low_first) {
    fmpz_poly_init(v_);
    long i = 0;
    for (long c : coeffs_low_first) fmpz_poly_set_coeff_si(v_, i++, c);
}

int IntPolynomial::sign_at(const Rational& x) const {
    Rational y;
    fmpz_poly_evaluate_fmpq(y.get(), v_, x.get());
    return y.sign();
}

std::string IntPolynomial::str() const {
    FlintString s{fmpz_poly_get_str_pretty(v_, "x")};
    return s.s;
}

std::string Ball::str(long digits) const {
    FlintString s{arb_get_str(v_, digits, 0)};
    return s.s;
}

}  // namespace ellvor

namespace ellvor {
void ball_endpoints(const Ball& b, Rational& lo, Rational& hi) {
    Arf x;
    arb_get_lbound_arf(x.get(), b.get(), ARF_PREC_EXACT);
    arf_get_fmpq(lo.get(), x.get());
    arb_get_ubound_arf(x.get(), b.get(), ARF_PREC_EXACT);
    arf_get_fmpq(hi.get(), x.get());
}
Rational power_of_ten(long k) {
    Integer p;
    fmpz_ui_pow_ui(p.get(), 10, static_cast<ulong>(k < 0 ? -k : k));
    return k < 0 ? Rational(Integer(1), p) : Rational(p);
}

}  // namespace ellvor
