#include "sites/dense_polynomial.hpp"

#include "util/error.hpp"

#include <algorithm>

namespace ellvor {

DensePolynomial::DensePolynomial() = default;

size_t DensePolynomial::index(int i, int j, int k) const {
    return static_cast<size_t>(i) + static_cast<size_t>(deg_[0] + 1) *
                                        (static_cast<size_t>(j) + static_cast<size_t>(deg_[1] + 1) * k);
}

DensePolynomial DensePolynomial::constant(const Integer& c) {
    DensePolynomial p;
    if (c.is_zero()) return p;
    p.deg_ = {0, 0, 0};
    p.c_.assign(1, c);
    return p;
}

DensePolynomial DensePolynomial::monomial(int var, int power, const Integer& c) {
    DensePolynomial p;
    if (c.is_zero()) return p;
    p.deg_ = {0, 0, 0};
    p.deg_[var] = power;
    p.c_.assign(power + 1, Integer(0));
    p.c_[power] = c;
    return p;
}

DensePolynomial DensePolynomial::from_univariate(int var, const IntPolynomial& q) {
    DensePolynomial p;
    for (long i = 0; i <= q.degree(); ++i) p = p + monomial(var, static_cast<int>(i), q.coeff(i));
    return p;
}

int DensePolynomial::degree(int var) const { return deg_[var]; }
bool DensePolynomial::is_zero() const { return deg_[0] < 0; }

Integer DensePolynomial::coeff(int i, int j, int k) const {
    if (is_zero() || i > deg_[0] || j > deg_[1] || k > deg_[2] || i < 0 || j < 0 || k < 0) return Integer(0);
    return c_[index(i, j, k)];
}

void DensePolynomial::reshape(const Degrees& d) {
    if (d == deg_) return;
    std::vector<Integer> c(static_cast<size_t>(d[0] + 1) * (d[1] + 1) * (d[2] + 1), Integer(0));
    if (!is_zero()) {
        for (int k = 0; k <= std::min(deg_[2], d[2]); ++k)
            for (int j = 0; j <= std::min(deg_[1], d[1]); ++j)
                for (int i = 0; i <= std::min(deg_[0], d[0]); ++i)
                    c[i + static_cast<size_t>(d[0] + 1) * (j + static_cast<size_t>(d[1] + 1) * k)] =
                        std::move(c_[index(i, j, k)]);
    }
    deg_ = d;
    c_ = std::move(c);
}

void DensePolynomial::set_coeff(int i, int j, int k, const Integer& c) {
    if (is_zero()) {
        if (c.is_zero()) return;
        deg_ = {0, 0, 0};
        c_.assign(1, Integer(0));
    }
    Degrees d = {std::max(deg_[0], i), std::max(deg_[1], j), std::max(deg_[2], k)};
    reshape(d);
    c_[index(i, j, k)] = c;
    trim();
}

// Shrinks the degree bounds to the true degrees (and to "zero" if all vanish).
void DensePolynomial::trim() {
    if (is_zero()) return;
    Degrees d = {-1, -1, -1};
    for (int k = 0; k <= deg_[2]; ++k)
        for (int j = 0; j <= deg_[1]; ++j)
            for (int i = 0; i <= deg_[0]; ++i)
                if (!c_[index(i, j, k)].is_zero()) {
                    d[0] = std::max(d[0], i);
                    d[1] = std::max(d[1], j);
                    d[2] = std::max(d[2], k);
                }
    if (d[0] < 0) {
        deg_ = {-1, -1, -1};
        c_.clear();
        return;
    }
    reshape(d);
}

DensePolynomial DensePolynomial::operator+(const DensePolynomial& o) const {
    if (o.is_zero()) return *this;
    if (is_zero()) return o;
    DensePolynomial r = *this;
    r.reshape({std::max(deg_[0], o.deg_[0]), std::max(deg_[1], o.deg_[1]), std::max(deg_[2], o.deg_[2])});
    for (int k = 0; k <= o.deg_[2]; ++k)
        for (int j = 0; j <= o.deg_[1]; ++j)
            for (int i = 0; i <= o.deg_[0]; ++i) {
                fmpz* dst = r.c_[r.index(i, j, k)].get();
                fmpz_add(dst, dst, o.c_[o.index(i, j, k)].get());
            }
    r.trim();
    return r;
}

DensePolynomial DensePolynomial::operator-() const {
    DensePolynomial r = *this;
    for (auto& c : r.c_) fmpz_neg(c.get(), c.get());
    return r;
}

DensePolynomial DensePolynomial::operator-(const DensePolynomial& o) const { return *this + (-o); }

DensePolynomial DensePolynomial::operator*(const Integer& c) const {
    if (c.is_zero()) return DensePolynomial();
    DensePolynomial r = *this;
    for (auto& x : r.c_) fmpz_mul(x.get(), x.get(), c.get());
    return r;
}

DensePolynomial DensePolynomial::operator*(const DensePolynomial& o) const {
    DensePolynomial r;
    if (is_zero() || o.is_zero()) return r;
    r.deg_ = {deg_[0] + o.deg_[0], deg_[1] + o.deg_[1], deg_[2] + o.deg_[2]};
    r.c_.assign(static_cast<size_t>(r.deg_[0] + 1) * (r.deg_[1] + 1) * (r.deg_[2] + 1), Integer(0));
    for (int k = 0; k <= deg_[2]; ++k)
        for (int j = 0; j <= deg_[1]; ++j)
            for (int i = 0; i <= deg_[0]; ++i) {
                const fmpz* a = c_[index(i, j, k)].get();
                if (fmpz_is_zero(a)) continue;
                for (int k2 = 0; k2 <= o.deg_[2]; ++k2)
                    for (int j2 = 0; j2 <= o.deg_[1]; ++j2)
                        for (int i2 = 0; i2 <= o.deg_[0]; ++i2)
                            fmpz_addmul(r.c_[r.index(i + i2, j + j2, k + k2)].get(), a,
                                        o.c_[o.index(i2, j2, k2)].get());
            }
    r.trim();
    return r;
}

bool DensePolynomial::operator==(const DensePolynomial& o) const {
    if (deg_ != o.deg_) return false;
    for (size_t n = 0; n < c_.size(); ++n)
        if (c_[n] != o.c_[n]) return false;
    return true;
}

bool DensePolynomial::divide_by_one_plus_square(int var) {
    if (is_zero() || deg_[var] < 2) return false;
    // Synthetic division along var for every fixed exponent of the other
    // variables: q_n = p_{n+2} - q_{n+2}, remainder must vanish.
    Degrees qd = deg_;
    qd[var] -= 2;
    DensePolynomial q;
    q.deg_ = qd;
    q.c_.assign(static_cast<size_t>(qd[0] + 1) * (qd[1] + 1) * (qd[2] + 1), Integer(0));
    int other[2], m = 0;
    for (int v = 0; v < kMaxVariables; ++v)
        if (v != var) other[m++] = v;
    for (int b = 0; b <= deg_[other[1]]; ++b)
        for (int a = 0; a <= deg_[other[0]]; ++a) {
            auto at = [&](int n) {
                std::array<int, 3> e{};
                e[var] = n;
                e[other[0]] = a;
                e[other[1]] = b;
                return e;
            };
            std::vector<Integer> quot(deg_[var] - 1, Integer(0));
            for (int n = deg_[var] - 2; n >= 0; --n) {
                auto e = at(n + 2);
                Integer v = c_[index(e[0], e[1], e[2])];
                if (n + 2 <= deg_[var] - 2) v = v - quot[n + 2];
                quot[n] = v;
            }
            // Remainder: p_1 - q_1 (x term) and p_0 - q_0 (constant term) must vanish.
            for (int n = 0; n <= 1; ++n) {
                auto e = at(n);
                Integer rem = c_[index(e[0], e[1], e[2])] - (n <= deg_[var] - 2 ? quot[n] : Integer(0));
                if (!rem.is_zero()) return false;
            }
            for (int n = 0; n <= deg_[var] - 2; ++n) {
                auto e = at(n);
                q.c_[q.index(e[0], e[1], e[2])] = quot[n];
            }
        }
    q.trim();
    *this = std::move(q);
    return true;
}

int DensePolynomial::remove_one_plus_square_factors(int var) {
    int n = 0;
    while (divide_by_one_plus_square(var)) ++n;
    return n;
}

DensePolynomial DensePolynomial::primitive_part() const {
    if (is_zero()) return *this;
    Integer g;
    for (const auto& c : c_) fmpz_gcd(g.get(), g.get(), c.get());
    // Leading coefficient: highest k, then j, then i.
    int lead_sign = 0;
    for (size_t n = c_.size(); n-- > 0 && lead_sign == 0;) lead_sign = c_[n].sign();
    if (lead_sign < 0) fmpz_neg(g.get(), g.get());
    DensePolynomial r = *this;
    for (auto& c : r.c_) fmpz_divexact(c.get(), c.get(), g.get());
    return r;
}

Rational DensePolynomial::evaluate(const Rational& t, const Rational& r, const Rational& s) const {
    // Horner in s, then r, then t, exactly.
    Rational result;
    if (is_zero()) return result;
    for (int k = deg_[2]; k >= 0; --k) {
        Rational in_r;
        for (int j = deg_[1]; j >= 0; --j) {
            Rational in_t;
            for (int i = deg_[0]; i >= 0; --i) in_t = in_t * t + Rational(c_[index(i, j, k)]);
            in_r = in_r * r + in_t;
        }
        result = result * s + in_r;
    }
    return result;
}

DensePolynomial DensePolynomial::substitute(int var, const Rational& value) const {
    if (is_zero() || deg_[var] == 0) return *this;
    // sum_n c_n (p/q)^n scaled by q^d:  sum_n c_n p^n q^(d-n)
    const int d = deg_[var];
    std::vector<Integer> weight(d + 1);
    for (int n = 0; n <= d; ++n) {
        Integer pn, qn;
        fmpz_pow_ui(pn.get(), fmpq_numref(value.get()), n);
        fmpz_pow_ui(qn.get(), fmpq_denref(value.get()), d - n);
        weight[n] = pn * qn;
    }
    DensePolynomial r;
    Degrees rd = deg_;
    rd[var] = 0;
    r.deg_ = rd;
    r.c_.assign(static_cast<size_t>(rd[0] + 1) * (rd[1] + 1) * (rd[2] + 1), Integer(0));
    for (int k = 0; k <= deg_[2]; ++k)
        for (int j = 0; j <= deg_[1]; ++j)
            for (int i = 0; i <= deg_[0]; ++i) {
                std::array<int, 3> e{i, j, k};
                int n = e[var];
                e[var] = 0;
                fmpz_addmul(r.c_[r.index(e[0], e[1], e[2])].get(), c_[index(i, j, k)].get(), weight[n].get());
            }
    r.trim();
    return r;
}

Ball DensePolynomial::evaluate(const Ball& t, const Ball& r, const Ball& s, long prec) const {
    // Horner in s, then r, then t.
    Ball result;
    if (is_zero()) return result;
    Ball inner_r, inner_t, tmp;
    for (int k = deg_[2]; k >= 0; --k) {
        arb_zero(inner_r.get());
        for (int j = deg_[1]; j >= 0; --j) {
            arb_zero(inner_t.get());
            for (int i = deg_[0]; i >= 0; --i) {
                arb_mul(inner_t.get(), inner_t.get(), t.get(), prec);
                arb_add_fmpz(inner_t.get(), inner_t.get(), c_[index(i, j, k)].get(), prec);
            }
            arb_mul(inner_r.get(), inner_r.get(), r.get(), prec);
            arb_add(inner_r.get(), inner_r.get(), inner_t.get(), prec);
        }
        arb_mul(result.get(), result.get(), s.get(), prec);
        arb_add(result.get(), result.get(), inner_r.get(), prec);
    }
    return result;
}

IntPolynomial DensePolynomial::to_univariate(int var) const {
    IntPolynomial p;
    if (is_zero()) return p;
    for (int v = 0; v < kMaxVariables; ++v)
        if (v != var && deg_[v] > 0) throw Error("to_univariate: polynomial depends on another variable");
    for (int n = 0; n <= deg_[var]; ++n) {
        std::array<int, 3> e{0, 0, 0};
        e[var] = n;
        p.set_coeff(n, c_[index(e[0], e[1], e[2])]);
    }
    return p;
}

DensePolynomial DensePolynomial::swap_variables(int a, int b) const {
    if (is_zero() || a == b) return *this;
    DensePolynomial r;
    Degrees d = deg_;
    std::swap(d[a], d[b]);
    r.deg_ = d;
    r.c_.assign(c_.size(), Integer(0));
    for (int k = 0; k <= deg_[2]; ++k)
        for (int j = 0; j <= deg_[1]; ++j)
            for (int i = 0; i <= deg_[0]; ++i) {
                std::array<int, 3> e{i, j, k};
                std::swap(e[a], e[b]);
                r.c_[r.index(e[0], e[1], e[2])] = c_[index(i, j, k)];
            }
    return r;
}

long DensePolynomial::max_bits() const {
    long b = 0;
    for (const auto& c : c_) b = std::max(b, static_cast<long>(fmpz_bits(c.get())));
    return b;
}

}  // namespace ellvor
