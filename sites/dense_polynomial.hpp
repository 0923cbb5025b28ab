// Dense polynomials with integer coefficients in up to three variables
// (t, r, s = variables 0, 1, 2). The polynomials of one, two and three ellipses
// have small degrees in each variable (at most 12), so a dense array of
// coefficients is both the simplest and the fastest representation, and it
// evaluates directly in Arb balls and modulo word-size primes.
#pragma once

#include "util/flint_types.hpp"

#include <array>
#include <vector>

namespace ellvor {

class DensePolynomial {
public:
    static constexpr int kMaxVariables = 3;
    using Degrees = std::array<int, kMaxVariables>;

    DensePolynomial();  // the zero polynomial
    static DensePolynomial constant(const Integer& c);
    // x_var^power
    static DensePolynomial monomial(int var, int power, const Integer& c = Integer(1));
    // A univariate polynomial in variable var.
    static DensePolynomial from_univariate(int var, const IntPolynomial& p);

    // Degree in variable var (-1 for the zero polynomial).
    int degree(int var) const;
    bool is_zero() const;
    // Coefficient of t^i r^j s^k (zero when out of range).
    Integer coeff(int i, int j = 0, int k = 0) const;
    void set_coeff(int i, int j, int k, const Integer& c);

    DensePolynomial operator+(const DensePolynomial& o) const;
    DensePolynomial operator-(const DensePolynomial& o) const;
    DensePolynomial operator*(const DensePolynomial& o) const;
    DensePolynomial operator*(const Integer& c) const;
    DensePolynomial operator-() const;
    bool operator==(const DensePolynomial& o) const;
    bool operator!=(const DensePolynomial& o) const { return !(*this == o); }

    // Divides by (1 + x_var^2) if that divides exactly; returns false (and
    // leaves *this unchanged) otherwise.
    bool divide_by_one_plus_square(int var);
    // Removes every factor (1 + x_var^2); returns how many were removed.
    int remove_one_plus_square_factors(int var);
    // Content-free, with a positive leading coefficient in the lexicographic
    // order s > r > t (so the representation is canonical up to sign).
    DensePolynomial primitive_part() const;

    // Value at rational points (all variables). Unused variables are ignored.
    Rational evaluate(const Rational& t, const Rational& r = Rational(0), const Rational& s = Rational(0)) const;
    // Value at balls, at working precision prec.
    Ball evaluate(const Ball& t, const Ball& r, const Ball& s, long prec) const;
    // Substitutes x_var = value, giving a polynomial with integer coefficients
    // scaled by the denominator power (primitive part not taken).
    DensePolynomial substitute(int var, const Rational& value) const;
    // The polynomial as univariate in var; throws if another variable occurs.
    IntPolynomial to_univariate(int var) const;

    // A swap of two variables, e.g. B(t, r) -> B(r, t).
    DensePolynomial swap_variables(int a, int b) const;

    // Largest coefficient size in bits.
    long max_bits() const;

private:
    Degrees deg_{-1, -1, -1};
    std::vector<Integer> c_;  // index i + (d0+1)*(j + (d1+1)*k)
    size_t index(int i, int j, int k) const;
    void reshape(const Degrees& d);  // keeps the coefficients
    void trim();
};

}  // namespace ellvor
