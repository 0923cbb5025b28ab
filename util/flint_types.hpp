// RAII value types over FLINT/Arb objects: Integer (fmpz), Rational (fmpq),
// IntPolynomial (fmpz_poly) and Ball (arb). Each owns exactly one FLINT object,
// is copyable and movable, and exposes the raw object through get() for calls
// into FLINT/Arb. Nothing here allocates global state.
#pragma once

#include <flint/fmpz.h>
#include <flint/fmpq.h>
#include <flint/fmpz_poly.h>
#include <arb.h>

#include <string>
#include <utility>

namespace ellvor {

class Integer {
public:
    Integer() { fmpz_init(v_); }
    Integer(long x) { fmpz_init_set_si(v_, x); }  // NOLINT: implicit from small integers is intended
    Integer(int x) { fmpz_init_set_si(v_, x); }   // NOLINT
    explicit Integer(const fmpz_t x) { fmpz_init_set(v_, x); }
    Integer(const Integer& o) { fmpz_init_set(v_, o.v_); }
    Integer(Integer&& o) noexcept { fmpz_init(v_); fmpz_swap(v_, o.v_); }
    Integer& operator=(const Integer& o) { fmpz_set(v_, o.v_); return *this; }
    Integer& operator=(Integer&& o) noexcept { fmpz_swap(v_, o.v_); return *this; }
    ~Integer() { fmpz_clear(v_); }

    fmpz* get() { return v_; }
    const fmpz* get() const { return v_; }
    int sign() const { return fmpz_sgn(v_); }
    bool is_zero() const { return fmpz_is_zero(v_); }
    std::string str() const;

    friend bool operator==(const Integer& a, const Integer& b) { return fmpz_equal(a.v_, b.v_); }
    friend bool operator!=(const Integer& a, const Integer& b) { return !(a == b); }
    friend bool operator<(const Integer& a, const Integer& b) { return fmpz_cmp(a.v_, b.v_) < 0; }
    friend Integer operator+(const Integer& a, const Integer& b) { Integer r; fmpz_add(r.v_, a.v_, b.v_); return r; }
    friend Integer operator-(const Integer& a, const Integer& b) { Integer r; fmpz_sub(r.v_, a.v_, b.v_); return r; }
    friend Integer operator*(const Integer& a, const Integer& b) { Integer r; fmpz_mul(r.v_, a.v_, b.v_); return r; }
    Integer operator-() const { Integer r; fmpz_neg(r.v_, v_); return r; }

private:
    fmpz_t v_;
};

class Rational {
public:
    Rational() { fmpq_init(v_); }
    Rational(long x) { fmpq_init(v_); fmpq_set_si(v_, x, 1); }  // NOLINT: implicit is intended
    Rational(int x) { fmpq_init(v_); fmpq_set_si(v_, x, 1); }   // NOLINT
    Rational(long num, unsigned long den) { fmpq_init(v_); fmpq_set_si(v_, num, den); }
    explicit Rational(const Integer& x) { fmpq_init(v_); fmpq_set_fmpz_frac(v_, x.get(), Integer(1).get()); }
    Rational(const Integer& num, const Integer& den) { fmpq_init(v_); fmpq_set_fmpz_frac(v_, num.get(), den.get()); }
    explicit Rational(const fmpq_t x) { fmpq_init(v_); fmpq_set(v_, x); }
    Rational(const Rational& o) { fmpq_init(v_); fmpq_set(v_, o.v_); }
    Rational(Rational&& o) noexcept { fmpq_init(v_); fmpq_swap(v_, o.v_); }
    Rational& operator=(const Rational& o) { fmpq_set(v_, o.v_); return *this; }
    Rational& operator=(Rational&& o) noexcept { fmpq_swap(v_, o.v_); return *this; }
    ~Rational() { fmpq_clear(v_); }

    fmpq* get() { return v_; }
    const fmpq* get() const { return v_; }
    Integer numerator() const { return Integer(fmpq_numref(v_)); }
    Integer denominator() const { return Integer(fmpq_denref(v_)); }
    int sign() const { return fmpq_sgn(v_); }
    bool is_zero() const { return fmpq_is_zero(v_); }
    bool is_integer() const { return fmpz_is_one(fmpq_denref(v_)); }
    // Bits of the larger of |numerator| and denominator.
    long bits() const;
    double to_double() const;  // the nearest double (in the normal range)
    static Rational of_double(double x);  // x's exact value (x finite)
    // n / 2^k with |n| < 2^53 and 2^k a single-word integer: exactly a
    // double, a multiple of 2^-61 below 2^53 in magnitude (the inputs of the
    // semi-static filters, circles/semi_static.hpp).
    bool is_small_dyadic() const {
        const fmpz n = *fmpq_numref(v_), d = *fmpq_denref(v_);
        constexpr slong kMantissa = slong(1) << 53;
        return !COEFF_IS_MPZ(n) && !COEFF_IS_MPZ(d) && (d & (d - 1)) == 0 && n < kMantissa && n > -kMantissa;
    }
    std::string str() const;  // "p/q" or "p"

    friend bool operator==(const Rational& a, const Rational& b) { return fmpq_equal(a.v_, b.v_); }
    friend bool operator!=(const Rational& a, const Rational& b) { return !(a == b); }
    friend bool operator<(const Rational& a, const Rational& b) { return fmpq_cmp(a.v_, b.v_) < 0; }
    friend bool operator>(const Rational& a, const Rational& b) { return b < a; }
    friend bool operator<=(const Rational& a, const Rational& b) { return !(b < a); }
    friend bool operator>=(const Rational& a, const Rational& b) { return !(a < b); }
    friend Rational operator+(const Rational& a, const Rational& b) { Rational r; fmpq_add(r.v_, a.v_, b.v_); return r; }
    friend Rational operator-(const Rational& a, const Rational& b) { Rational r; fmpq_sub(r.v_, a.v_, b.v_); return r; }
    friend Rational operator*(const Rational& a, const Rational& b) { Rational r; fmpq_mul(r.v_, a.v_, b.v_); return r; }
    friend Rational operator/(const Rational& a, const Rational& b);  // throws on division by zero
    Rational operator-() const { Rational r; fmpq_neg(r.v_, v_); return r; }

private:
    fmpq_t v_;
};

class IntPolynomial {
public:
    IntPolynomial() { fmpz_poly_init(v_); }
    explicit IntPolynomial(const fmpz_poly_t p) { fmpz_poly_init(v_); fmpz_poly_set(v_, p); }
    IntPolynomial(std::initializer_list<long> coeffs_low_first);
    IntPolynomial(const IntPolynomial& o) { fmpz_poly_init(v_); fmpz_poly_set(v_, o.v_); }
    IntPolynomial(IntPolynomial&& o) noexcept { fmpz_poly_init(v_); fmpz_poly_swap(v_, o.v_); }
    IntPolynomial& operator=(const IntPolynomial& o) { fmpz_poly_set(v_, o.v_); return *this; }
    IntPolynomial& operator=(IntPolynomial&& o) noexcept { fmpz_poly_swap(v_, o.v_); return *this; }
    ~IntPolynomial() { fmpz_poly_clear(v_); }

    fmpz_poly_struct* get() { return v_; }
    const fmpz_poly_struct* get() const { return v_; }
    long degree() const { return fmpz_poly_degree(v_); }  // -1 for the zero polynomial
    bool is_zero() const { return fmpz_poly_is_zero(v_); }
    Integer coeff(long i) const { Integer c; fmpz_poly_get_coeff_fmpz(c.get(), v_, i); return c; }
    void set_coeff(long i, const Integer& c) { fmpz_poly_set_coeff_fmpz(v_, i, c.get()); }
    // Sign of p(x) at a rational x, exactly.
    int sign_at(const Rational& x) const;
    // p divided by its content, leading coefficient positive (FLINT's
    // primitive part): the canonical representative of p's roots.
    IntPolynomial primitive_part() const {
        IntPolynomial r;
        fmpz_poly_primitive_part(r.v_, v_);
        return r;
    }
    std::string str() const;

    friend bool operator==(const IntPolynomial& a, const IntPolynomial& b) { return fmpz_poly_equal(a.v_, b.v_); }
    friend bool operator!=(const IntPolynomial& a, const IntPolynomial& b) { return !(a == b); }

private:
    fmpz_poly_t v_;
};

// An Arb ball [mid +/- rad]. Operations take an explicit working precision.
class Ball {
public:
    Ball() { arb_init(v_); }
    Ball(const Rational& q, long prec) { arb_init(v_); arb_set_fmpq(v_, q.get(), prec); }
    Ball(const Ball& o) { arb_init(v_); arb_set(v_, o.v_); }
    Ball(Ball&& o) noexcept { arb_init(v_); arb_swap(v_, o.v_); }
    Ball& operator=(const Ball& o) { arb_set(v_, o.v_); return *this; }
    Ball& operator=(Ball&& o) noexcept { arb_swap(v_, o.v_); return *this; }
    ~Ball() { arb_clear(v_); }

    arb_struct* get() { return v_; }
    const arb_struct* get() const { return v_; }
    // -1/+1 when the whole ball has that sign, 0 when it contains zero (undecided).
    int certain_sign() const {
        if (arb_is_positive(v_)) return 1;
        if (arb_is_negative(v_)) return -1;
        return 0;
    }
    bool contains(const Rational& q) const { return arb_contains_fmpq(v_, q.get()); }
    double mid_double() const { return arf_get_d(arb_midref(v_), ARF_RND_NEAR); }
    double radius_double() const { return mag_get_d(arb_radref(v_)); }
    std::string str(long digits = 20) const;

private:
    arb_t v_;
};

}  // namespace ellvor

namespace ellvor {
// Rational endpoints [lo, hi] of a ball (exact: Arb's endpoints are dyadic).
void ball_endpoints(const Ball& b, Rational& lo, Rational& hi);
// 10^k exactly, for k of either sign (decimal data: offsets, perturbations).
Rational power_of_ten(long k);
}  // namespace ellvor

#include <arb_mat.h>

namespace ellvor {

// An Arb matrix of balls (arb_mat), rows x cols, zero-initialized.
class BallMatrix {
public:
    BallMatrix(long rows, long cols) { arb_mat_init(m_, rows, cols); }
    BallMatrix(const BallMatrix& o) {
        arb_mat_init(m_, arb_mat_nrows(o.m_), arb_mat_ncols(o.m_));
        arb_mat_set(m_, o.m_);
    }
    BallMatrix& operator=(const BallMatrix& o) {
        if (this != &o) {
            arb_mat_clear(m_);
            arb_mat_init(m_, arb_mat_nrows(o.m_), arb_mat_ncols(o.m_));
            arb_mat_set(m_, o.m_);
        }
        return *this;
    }
    ~BallMatrix() { arb_mat_clear(m_); }

    arb_mat_struct* get() { return m_; }
    const arb_mat_struct* get() const { return m_; }
    arb_struct* at(long i, long j) { return arb_mat_entry(m_, i, j); }
    const arb_struct* at(long i, long j) const { return arb_mat_entry(m_, i, j); }
    long rows() const { return arb_mat_nrows(m_); }
    long cols() const { return arb_mat_ncols(m_); }

private:
    arb_mat_t m_;
};

}  // namespace ellvor

#include <flint/fmpz_poly_factor.h>
#include <flint/fmpz_poly_mat.h>

namespace ellvor {

// Owners of the FLINT/Arb objects that ellvor only uses as scratch: an integer
// polynomial factorization, an integer polynomial matrix, an Arb magnitude
// and an Arb float. Not copyable.
class IntFactorization {
public:
    IntFactorization() { fmpz_poly_factor_init(v_); }
    IntFactorization(const IntFactorization&) = delete;
    IntFactorization& operator=(const IntFactorization&) = delete;
    ~IntFactorization() { fmpz_poly_factor_clear(v_); }
    fmpz_poly_factor_struct* get() { return v_; }

private:
    fmpz_poly_factor_t v_;
};

class IntPolynomialMatrix {
public:
    IntPolynomialMatrix(long rows, long cols) { fmpz_poly_mat_init(v_, rows, cols); }
    IntPolynomialMatrix(const IntPolynomialMatrix&) = delete;
    IntPolynomialMatrix& operator=(const IntPolynomialMatrix&) = delete;
    ~IntPolynomialMatrix() { fmpz_poly_mat_clear(v_); }
    fmpz_poly_mat_struct* get() { return v_; }
    fmpz_poly_struct* at(long i, long j) { return fmpz_poly_mat_entry(v_, i, j); }

private:
    fmpz_poly_mat_t v_;
};

class Mag {
public:
    Mag() { mag_init(v_); }
    Mag(const Mag&) = delete;
    Mag& operator=(const Mag&) = delete;
    ~Mag() { mag_clear(v_); }
    mag_struct* get() { return v_; }

private:
    mag_t v_;
};

class Arf {
public:
    Arf() { arf_init(v_); }
    Arf(const Arf&) = delete;
    Arf& operator=(const Arf&) = delete;
    ~Arf() { arf_clear(v_); }
    arf_struct* get() { return v_; }

private:
    arf_t v_;
};

}  // namespace ellvor
