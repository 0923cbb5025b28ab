// Multi-modular InCircle resultant; see incircle_resultant.hpp.
#include "exact/incircle_resultant.hpp"

#include "sites/dense_polynomial.hpp"
#include "sites/ellipse_polynomials.hpp"
#include "util/error.hpp"

#include <flint/fmpz_poly_factor.h>
#include <flint/nmod_poly.h>
#include <flint/nmod_vec.h>
#include <flint/ulong_extras.h>

#include <algorithm>
#include <chrono>
#include <map>

namespace ellvor {

namespace {

// RAII over nmod_poly_t.
class NmodPoly {
public:
    explicit NmodPoly(mp_limb_t n) { nmod_poly_init(p_, n); }
    NmodPoly(const NmodPoly& o) {
        nmod_poly_init_mod(p_, o.p_->mod);
        nmod_poly_set(p_, o.p_);
    }
    NmodPoly& operator=(const NmodPoly& o) {
        if (this != &o) {
            nmod_poly_clear(p_);
            nmod_poly_init_mod(p_, o.p_->mod);
            nmod_poly_set(p_, o.p_);
        }
        return *this;
    }
    ~NmodPoly() { nmod_poly_clear(p_); }
    nmod_poly_struct* get() { return p_; }
    const nmod_poly_struct* get() const { return p_; }
    long degree() const { return nmod_poly_degree(p_); }
    mp_limb_t coeff(long i) const { return nmod_poly_get_coeff_ui(p_, i); }

private:
    nmod_poly_t p_;
};

mp_limb_t pow_mod(mp_limb_t a, long e, nmod_t mod) { return n_powmod2_ui_preinv(a, static_cast<ulong>(e), mod.n, mod.ninv); }

// The resultant of f and g (coefficients low first, the last one nonzero:
// the actual degrees) as a fraction num / den, den != 0, by the Euclidean
// algorithm with pseudo-remainders: no inversion (inversions dominate the
// cost at word size). Uses res(f, g) = (-1)^{mn} lc(g)^{m-k} res(g, f mod g)
// and prem(f, g) = lc(g)^{m-n+1} (f mod g), m = deg f >= n = deg g, k = deg(f mod g).
void resultant_fraction(std::vector<mp_limb_t> f, std::vector<mp_limb_t> g, nmod_t mod, mp_limb_t& num,
                        mp_limb_t& den) {
    num = 1, den = 1;
    long m = static_cast<long>(f.size()) - 1, n = static_cast<long>(g.size()) - 1;
    if (m < n) {
        std::swap(f, g), std::swap(m, n);
        if ((m * n) & 1) num = nmod_neg(num, mod);
    }
    for (;;) {
        if (n == 0) {
            num = nmod_mul(num, pow_mod(g[0], m, mod), mod);
            return;
        }
        // f <- prem(f, g)
        const mp_limb_t lg = g[n];
        for (long d = m; d >= n; --d) {
            const mp_limb_t c = f[d];
            for (long i = 0; i < d; ++i) f[i] = nmod_mul(f[i], lg, mod);
            if (c != 0)
                for (long i = 0; i < n; ++i) f[d - n + i] = nmod_sub(f[d - n + i], nmod_mul(c, g[i], mod), mod);
            f[d] = 0;
        }
        long k = n - 1;
        while (k >= 0 && f[k] == 0) --k;
        if (k < 0) {
            num = 0;
            return;
        }
        f.resize(static_cast<size_t>(k + 1));
        if ((m * n) & 1) num = nmod_neg(num, mod);
        num = nmod_mul(num, pow_mod(lg, m - k, mod), mod);
        den = nmod_mul(den, pow_mod(lg, (m - n + 1) * n, mod), mod);
        std::swap(f, g);  // (f, g) <- (g, prem)
        m = n, n = k;
    }
}

// A known extraneous factor: an irreducible primitive integer polynomial in t.
struct KnownFactor {
    IntPolynomial poly;
    std::string label;
};

// The system reduced modulo one prime.
class ModularSystem {
public:
    ModularSystem(mp_limb_t p, const DensePolynomial& Q, const DensePolynomial& B12, const DensePolynomial& B31,
                  const std::vector<KnownFactor>& known)
        : p_(p) {
        nmod_init(&mod_, p);
        dQt_ = Q.degree(0), dQr_ = Q.degree(1), dQs_ = Q.degree(2);
        Q_.resize(static_cast<size_t>((dQt_ + 1) * (dQr_ + 1) * (dQs_ + 1)));
        for (int i = 0; i <= dQt_; ++i)
            for (int j = 0; j <= dQr_; ++j)
                for (int k = 0; k <= dQs_; ++k) Q_[qi(i, j, k)] = reduce(Q.coeff(i, j, k));
        // B31: variable 0 = s, variable 1 = t.
        d31s_ = B31.degree(0), d31t_ = B31.degree(1);
        B31_.resize(static_cast<size_t>((d31t_ + 1) * (d31s_ + 1)));
        for (int i = 0; i <= d31t_; ++i)
            for (int k = 0; k <= d31s_; ++k) B31_[i * (d31s_ + 1) + k] = reduce(B31.coeff(k, i));
        d12t_ = B12.degree(0), d12r_ = B12.degree(1);
        B12_.resize(static_cast<size_t>((d12t_ + 1) * (d12r_ + 1)));
        for (int i = 0; i <= d12t_; ++i)
            for (int j = 0; j <= d12r_; ++j) B12_[i * (d12r_ + 1) + j] = reduce(B12.coeff(i, j));
        for (const KnownFactor& f : known) {
            factors_.emplace_back(p);
            fmpz_poly_get_nmod_poly(factors_.back().get(), f.poly.get());
        }
    }

    mp_limb_t prime() const { return p_; }
    nmod_t mod() const { return mod_; }
    const std::vector<NmodPoly>& factors() const { return factors_; }
    long r1_degree_bound() const { return static_cast<long>(dQr_) * d31s_; }
    long r1_t_degree_bound() const { return static_cast<long>(dQt_) * d31s_ + static_cast<long>(d31t_) * dQs_; }
    long r2_degree_bound(long r1_r_degree) const { return r1_t_degree_bound() * d12r_ + static_cast<long>(d12t_) * r1_r_degree; }

    // Q(t0, r, s) as a table [j][k] and B31(s, t0) as coefficients in s.
    void specialize_t(mp_limb_t t0) {
        std::vector<mp_limb_t> pw(static_cast<size_t>(std::max({dQt_, d31t_, d12t_}) + 1));
        pw[0] = 1;
        for (size_t i = 1; i < pw.size(); ++i) pw[i] = nmod_mul(pw[i - 1], t0, mod_);
        qt_.assign(static_cast<size_t>((dQr_ + 1) * (dQs_ + 1)), 0);
        for (int i = 0; i <= dQt_; ++i)
            for (int jk = 0; jk < (dQr_ + 1) * (dQs_ + 1); ++jk)
                qt_[jk] = nmod_add(qt_[jk], nmod_mul(Q_[i * (dQr_ + 1) * (dQs_ + 1) + jk], pw[i], mod_), mod_);
        b31t_.assign(static_cast<size_t>(d31s_ + 1), 0);
        for (int i = 0; i <= d31t_; ++i)
            for (int k = 0; k <= d31s_; ++k)
                b31t_[k] = nmod_add(b31t_[k], nmod_mul(B31_[i * (d31s_ + 1) + k], pw[i], mod_), mod_);
        b12t_.assign(static_cast<size_t>(d12r_ + 1), 0);
        for (int i = 0; i <= d12t_; ++i)
            for (int j = 0; j <= d12r_; ++j)
                b12t_[j] = nmod_add(b12t_[j], nmod_mul(B12_[i * (d12r_ + 1) + j], pw[i], mod_), mod_);
    }

    // res_s(Q(t0, r0, s), B31(s, t0)) = num / den after specialize_t(t0);
    // false when a leading coefficient in s vanishes.
    bool r1_fraction(mp_limb_t r0, mp_limb_t& num, mp_limb_t& den) {
        if (b31t_[d31s_] == 0) return false;
        mp_limb_t pw = 1;
        std::vector<mp_limb_t> q(static_cast<size_t>(dQs_ + 1), 0);
        for (int j = 0; j <= dQr_; ++j) {
            for (int k = 0; k <= dQs_; ++k) q[k] = nmod_add(q[k], nmod_mul(qt_[j * (dQs_ + 1) + k], pw, mod_), mod_);
            pw = nmod_mul(pw, r0, mod_);
        }
        if (q[dQs_] == 0) return false;
        resultant_fraction(q, b31t_, mod_, num, den);
        return true;
    }

    bool r1_value(mp_limb_t r0, mp_limb_t& value) {
        mp_limb_t num, den;
        if (!r1_fraction(r0, num, den)) return false;
        value = nmod_mul(num, n_invmod(den, mod_.n), mod_);
        return true;
    }

    // R1(t0, r) in r after specialize_t(t0), interpolated from r1_degree_bound() + 1
    // values; false when no such set of values is found (B31's leading coefficient vanishes).
    bool r1_polynomial(NmodPoly& out) {
        if (b31t_[d31s_] == 0) return false;
        const long n = r1_degree_bound() + 1;
        xs_.clear(), ys_.clear(), dens_.clear();
        mp_limb_t num = 0, den = 0;
        for (mp_limb_t r0 = 1; static_cast<long>(xs_.size()) < n; ++r0) {
            if (r0 > static_cast<mp_limb_t>(n + 200)) return false;
            if (!r1_fraction(r0, num, den)) continue;
            xs_.push_back(r0), ys_.push_back(num), dens_.push_back(den);
        }
        // Batch inversion of the denominators (one inversion).
        std::vector<mp_limb_t> prefix(static_cast<size_t>(n));
        mp_limb_t acc = 1;
        for (long i = 0; i < n; ++i) prefix[i] = acc, acc = nmod_mul(acc, dens_[i], mod_);
        mp_limb_t inv = n_invmod(acc, mod_.n);
        for (long i = n - 1; i >= 0; --i) {
            ys_[i] = nmod_mul(ys_[i], nmod_mul(inv, prefix[i], mod_), mod_);
            inv = nmod_mul(inv, dens_[i], mod_);
        }
        if (xs_.back() == static_cast<mp_limb_t>(n)) {  // the points 1..n: precomputed Lagrange basis
            if (lagrange_.empty()) build_lagrange(n);
            std::vector<mp_limb_t> c(static_cast<size_t>(n), 0);
            for (long i = 0; i < n; ++i) {
                const mp_limb_t y = ys_[i];
                if (y == 0) continue;
                const mp_limb_t* row = lagrange_.data() + i * n;
                for (long k = 0; k < n; ++k) c[k] = nmod_add(c[k], nmod_mul(y, row[k], mod_), mod_);
            }
            nmod_poly_zero(out.get());
            for (long k = n - 1; k >= 0; --k)
                if (c[k] != 0) nmod_poly_set_coeff_ui(out.get(), k, c[k]);
        } else {
            nmod_poly_interpolate_nmod_vec(out.get(), xs_.data(), ys_.data(), n);
        }
        return true;
    }

    enum class Outcome { ok, skip, inconsistent };

    // R2(t0) = res_r(R1(t0, r), B12(t0, r)) with R1 of degree r1_deg in r.
    Outcome r2_value(mp_limb_t t0, long r1_deg, mp_limb_t& value) {
        specialize_t(t0);
        if (b12t_[d12r_] == 0) return Outcome::skip;
        NmodPoly r1(p_);
        if (!r1_polynomial(r1)) return Outcome::skip;
        if (r1.degree() > r1_deg) return Outcome::inconsistent;
        if (r1.degree() < r1_deg || r1_deg < 0) return Outcome::skip;
        std::vector<mp_limb_t> a(static_cast<size_t>(r1_deg + 1));
        for (long j = 0; j <= r1_deg; ++j) a[j] = r1.coeff(j);
        mp_limb_t num, den;
        resultant_fraction(a, b12t_, mod_, num, den);
        value = nmod_mul(num, n_invmod(den, mod_.n), mod_);
        return Outcome::ok;
    }

private:
    // lagrange_[i * n + k]: coefficient of r^k in the Lagrange basis
    // polynomial of the point i + 1 among the points 1..n.
    void build_lagrange(long n) {
        std::vector<mp_limb_t> M(static_cast<size_t>(n + 1), 0);  // prod (r - x_j)
        M[0] = 1;
        for (long j = 1; j <= n; ++j) {
            const mp_limb_t x = static_cast<mp_limb_t>(j) % mod_.n;
            for (long k = j; k >= 1; --k) M[k] = nmod_sub(M[k - 1], nmod_mul(x, M[k], mod_), mod_);
            M[0] = nmod_neg(nmod_mul(x, M[0], mod_), mod_);
        }
        lagrange_.assign(static_cast<size_t>(n * n), 0);
        std::vector<mp_limb_t> q(static_cast<size_t>(n));
        for (long i = 0; i < n; ++i) {
            const mp_limb_t x = static_cast<mp_limb_t>(i + 1) % mod_.n;
            // q = M / (r - x) by synthetic division
            mp_limb_t carry = M[n];
            for (long k = n - 1; k >= 0; --k) {
                q[k] = carry;
                carry = nmod_add(M[k], nmod_mul(carry, x, mod_), mod_);
            }
            mp_limb_t qx = 0;
            for (long k = n - 1; k >= 0; --k) qx = nmod_add(nmod_mul(qx, x, mod_), q[k], mod_);
            const mp_limb_t w = n_invmod(qx, mod_.n);
            for (long k = 0; k < n; ++k) lagrange_[i * n + k] = nmod_mul(w, q[k], mod_);
        }
    }

    mp_limb_t reduce(const Integer& c) const {
        return fmpz_fdiv_ui(c.get(), p_);
    }
    size_t qi(int i, int j, int k) const { return static_cast<size_t>((i * (dQr_ + 1) + j) * (dQs_ + 1) + k); }

    mp_limb_t p_;
    nmod_t mod_{};
    int dQt_, dQr_, dQs_, d31s_, d31t_, d12t_, d12r_;
    std::vector<mp_limb_t> Q_, B31_, B12_;
    std::vector<mp_limb_t> qt_, b31t_, b12t_;
    std::vector<mp_limb_t> xs_, ys_, dens_, lagrange_;
    std::vector<NmodPoly> factors_;
};

// Exponent of f in g (mod p), dividing g in place.
int strip_factor(NmodPoly& g, const NmodPoly& f) {
    if (f.degree() < 1 || g.degree() < 0) return 0;
    int e = 0;
    NmodPoly q(g.get()->mod.n), r(g.get()->mod.n);
    for (;;) {
        nmod_poly_divrem(q.get(), r.get(), g.get(), f.get());
        if (r.degree() >= 0) return e;
        nmod_poly_swap(g.get(), q.get());
        ++e;
    }
}

// The factor structure found on one prime.
struct Structure {
    long r1_r_degree = -1;        // deg_r R1
    long r2_degree = -1;          // deg R2 (full, = res_r(R1, B12))
    std::vector<int> r1_exponents;  // per known factor, in R1(t, r)
    std::vector<int> r2_exponents;  // per known factor, in the full R2
    long wanted_degree = -1;
    bool squarefree = false;      // the wanted factor mod p is squarefree
};

// The known factors mod p are usable: same degree, squarefree, pairwise coprime.
bool factors_usable(const ModularSystem& sys, const std::vector<KnownFactor>& known) {
    const auto& f = sys.factors();
    for (size_t i = 0; i < f.size(); ++i) {
        if (f[i].degree() != known[i].poly.degree()) return false;
        NmodPoly d(sys.prime()), g(sys.prime());
        nmod_poly_derivative(d.get(), f[i].get());
        nmod_poly_gcd(g.get(), f[i].get(), d.get());
        if (g.degree() > 0) return false;
        for (size_t j = 0; j < i; ++j) {
            nmod_poly_gcd(g.get(), f[i].get(), f[j].get());
            if (g.degree() > 0) return false;
        }
    }
    return true;
}

// Interpolates R1(t, r0) for a fixed r0 (to read the exponents of the known factors in R1).
bool r1_at_fixed_r(ModularSystem& sys, mp_limb_t r0, NmodPoly& out) {
    long n = sys.r1_t_degree_bound() + 1;
    std::vector<mp_limb_t> xs, ys;
    mp_limb_t v = 0;
    for (mp_limb_t t0 = 1; static_cast<long>(xs.size()) < n; ++t0) {
        if (t0 > static_cast<mp_limb_t>(n + 200)) return false;
        sys.specialize_t(t0);
        if (!sys.r1_value(r0, v)) continue;
        xs.push_back(t0), ys.push_back(v);
    }
    nmod_poly_interpolate_nmod_vec(out.get(), xs.data(), ys.data(), n);
    return true;
}

// Finds the structure on this prime and the wanted factor mod p. False when
// the prime is unusable.
bool find_structure(ModularSystem& sys, const std::vector<KnownFactor>& known, Structure& st, NmodPoly& wanted) {
    if (!factors_usable(sys, known)) return false;
    // deg_r R1: the largest degree seen at a few t0.
    st.r1_r_degree = -1;
    int seen = 0;
    for (mp_limb_t t0 = 1000003; seen < 4 && t0 < 1000003 + 100; ++t0) {
        sys.specialize_t(t0);
        NmodPoly r1(sys.prime());
        if (!sys.r1_polynomial(r1)) continue;
        st.r1_r_degree = std::max(st.r1_r_degree, r1.degree());
        ++seen;
    }
    if (seen < 4) return false;
    if (st.r1_r_degree < 0)
        throw Error("incircle_resultant: res_s(Q, B31) vanishes identically (common component)");
    // Exponents in R1 (as a polynomial in t at a random r0).
    NmodPoly r1t(sys.prime());
    if (!r1_at_fixed_r(sys, 7919000111UL % sys.prime(), r1t)) return false;
    if (r1t.degree() < 0) return false;
    st.r1_exponents.clear();
    for (const NmodPoly& f : sys.factors()) st.r1_exponents.push_back(strip_factor(r1t, f));
    // The full R2.
    long n = sys.r2_degree_bound(st.r1_r_degree) + 1;
    std::vector<mp_limb_t> xs, ys;
    mp_limb_t v = 0;
    for (mp_limb_t t0 = 1; static_cast<long>(xs.size()) < n; ++t0) {
        if (t0 > static_cast<mp_limb_t>(n + 1000)) return false;
        auto outcome = sys.r2_value(t0, st.r1_r_degree, v);
        if (outcome == ModularSystem::Outcome::inconsistent) return false;
        if (outcome == ModularSystem::Outcome::skip) continue;
        xs.push_back(t0), ys.push_back(v);
    }
    nmod_poly_interpolate_nmod_vec(wanted.get(), xs.data(), ys.data(), n);
    st.r2_degree = wanted.degree();
    if (st.r2_degree < 0)
        throw Error("incircle_resultant: res_r(R1, B12) vanishes identically (common component)");
    st.r2_exponents.clear();
    for (const NmodPoly& f : sys.factors()) st.r2_exponents.push_back(strip_factor(wanted, f));
    st.wanted_degree = wanted.degree();
    NmodPoly d(sys.prime()), g(sys.prime());
    nmod_poly_derivative(d.get(), wanted.get());
    nmod_poly_gcd(g.get(), wanted.get(), d.get());
    st.squarefree = g.degree() == 0;
    return true;
}

// The wanted factor mod p from its values (known factors divided out at
// each point). Returns false when the prime is unusable (degree drop);
// `inconsistent` is set when the values contradict the structure.
bool wanted_mod_p(ModularSystem& sys, const Structure& st, NmodPoly& out, bool& inconsistent) {
    inconsistent = false;
    const auto& f = sys.factors();
    long n = st.wanted_degree + 2;  // one more than needed: a consistency check
    std::vector<mp_limb_t> xs, ys;
    mp_limb_t v = 0;
    nmod_t mod = sys.mod();
    for (mp_limb_t t0 = 1; static_cast<long>(xs.size()) < n; ++t0) {
        if (t0 > static_cast<mp_limb_t>(n + 1000)) return false;
        mp_limb_t c = 1;
        for (size_t i = 0; i < f.size(); ++i)
            if (st.r2_exponents[i] > 0)
                c = nmod_mul(c, pow_mod(nmod_poly_evaluate_nmod(f[i].get(), t0), st.r2_exponents[i], mod), mod);
        if (c == 0) continue;
        auto outcome = sys.r2_value(t0, st.r1_r_degree, v);
        if (outcome == ModularSystem::Outcome::inconsistent) {
            inconsistent = true;
            return false;
        }
        if (outcome == ModularSystem::Outcome::skip) continue;
        xs.push_back(t0), ys.push_back(nmod_mul(v, n_invmod(c, mod.n), mod));
    }
    nmod_poly_interpolate_nmod_vec(out.get(), xs.data(), ys.data(), n);
    if (out.degree() > st.wanted_degree) {
        inconsistent = true;
        return false;
    }
    return out.degree() == st.wanted_degree;
}

// Irreducible factors of 1 + t^2, parnorm(E1, E3), parnorm(E1, E2), deduplicated.
std::vector<KnownFactor> known_factors(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3) {
    std::vector<KnownFactor> out;
    auto add = [&out](const IntPolynomial& p, const std::string& name) {
        IntFactorization fac;
        fmpz_poly_factor(fac.get(), p.get());
        long count = fac.get()->num;
        std::map<long, int> per_degree;
        for (long i = 0; i < count; ++i) ++per_degree[fmpz_poly_degree(fac.get()->p + i)];
        std::map<long, int> index;
        for (long i = 0; i < count; ++i) {
            IntPolynomial g(fac.get()->p + i);
            if (g.degree() < 1) continue;
            if (fmpz_sgn(fmpz_poly_lead(g.get())) < 0) fmpz_poly_neg(g.get(), g.get());
            bool dup = false;
            for (const KnownFactor& k : out) dup = dup || k.poly == g;
            long d = g.degree();
            int idx = ++index[d];
            if (dup) continue;
            std::string label = name;
            if (count > 1 || fac.get()->exp[0] > 1) {
                label += "[deg " + std::to_string(d);
                if (per_degree[d] > 1) label += " #" + std::to_string(idx);
                label += "]";
            }
            out.push_back({g, label});
        }
    };
    add(IntPolynomial{1, 0, 1}, "1+t^2");
    add(parallel_normals_polynomial(e1, e3), "parnorm13");
    add(parallel_normals_polynomial(e1, e2), "parnorm12");
    return out;
}

}  // namespace

IncircleResultant incircle_resultant(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3,
                                     const IncircleResultantOptions& options) {
    auto start = std::chrono::steady_clock::now();
    IncircleResultant result;
    int circles = int(e1.is_circle()) + int(e2.is_circle()) + int(e3.is_circle());
    static const long kExpected[4] = {184, 72, 24, 8};
    result.expected_degree = kExpected[circles];

    DensePolynomial Q = normals_concurrency_polynomial(e1, e2, e3);
    static const char* kQNames[3] = {"Q:(1+t^2)", "Q:(1+r^2)", "Q:(1+s^2)"};
    bool q_reduced = false;
    for (int var = 0; var < 3; ++var) {
        int k = Q.remove_one_plus_square_factors(var);
        if (k > 0) result.removed_factors.emplace_back(kQNames[var], k), q_reduced = true;
    }
    DensePolynomial B12 = bisector_polynomial(e1, e2);  // (t, r)
    DensePolynomial B31 = bisector_polynomial(e3, e1);  // (s, t)
    std::vector<KnownFactor> known = known_factors(e1, e2, e3);

    mp_limb_t p = options.first_prime;
    auto next_prime = [&p]() {
        p = n_nextprime(p, 1);
        if (p >= (1UL << 63)) throw Error("incircle_resultant: ran out of primes");
        return p;
    };

    Structure st;
    IntPolynomial candidate;
    Integer modulus(1);
    int restarts = 0;
    long primes = 0;
    for (;;) {  // one structure attempt
        // Structure prime.
        NmodPoly wanted(2);
        for (int tries = 0;; ++tries) {
            if (tries > 20) throw Error("incircle_resultant: no usable prime");
            ModularSystem sys(next_prime(), Q, B12, B31, known);
            ++primes;
            NmodPoly w(p);
            if (find_structure(sys, known, st, w)) {
                wanted = w;
                break;
            }
        }
        fmpz_poly_zero(candidate.get());
        fmpz_one(modulus.get());
        fmpz_poly_CRT_ui(candidate.get(), candidate.get(), modulus.get(), wanted.get(), 1);
        fmpz_set_ui(modulus.get(), wanted.get()->mod.n);

        int agreements = 0, inconsistencies = 0, unusable = 0;
        bool restart = false;
        while (agreements < options.verification_primes + 1) {
            ModularSystem sys(next_prime(), Q, B12, B31, known);
            ++primes;
            NmodPoly w(p);
            bool inconsistent = false;
            if (!wanted_mod_p(sys, st, w, inconsistent)) {
                if (inconsistent) ++inconsistencies;
                else ++unusable;
                if (inconsistencies >= 2 || unusable >= 20) {
                    restart = true;
                    break;
                }
                continue;
            }
            NmodPoly image(p);
            fmpz_poly_get_nmod_poly(image.get(), candidate.get());
            if (nmod_poly_equal(image.get(), w.get())) {
                ++agreements;
                continue;
            }
            agreements = 0;
            fmpz_poly_CRT_ui(candidate.get(), candidate.get(), modulus.get(), w.get(), 1);
            fmpz_mul_ui(modulus.get(), modulus.get(), p);
        }
        if (!restart) break;
        if (++restarts > 3) throw Error("incircle_resultant: inconsistent modular images");
    }

    // The wanted factor over Z, then its squarefree part.
    IntPolynomial w = candidate;
    if (!st.squarefree) {
        IntPolynomial d, g;
        fmpz_poly_derivative(d.get(), w.get());
        fmpz_poly_gcd(g.get(), w.get(), d.get());
        if (g.degree() > 0) {
            result.removed_factors.emplace_back("square-part", static_cast<int>(g.degree()));
            fmpz_poly_div(w.get(), w.get(), g.get());
        }
    }
    fmpz_poly_primitive_part(w.get(), w.get());
    if (fmpz_sgn(fmpz_poly_lead(w.get())) < 0) fmpz_poly_neg(w.get(), w.get());

    long b12_r = B12.degree(1);
    bool generic = !q_reduced && st.squarefree && st.wanted_degree == 184;
    for (size_t i = 0; i < known.size(); ++i) {
        int e1_exp = st.r1_exponents[i];
        int e2_exp = st.r2_exponents[i] - static_cast<int>(b12_r) * e1_exp;
        if (e1_exp > 0) result.removed_factors.emplace_back("R1:" + known[i].label, e1_exp);
        if (e2_exp != 0) result.removed_factors.emplace_back("R2:" + known[i].label, e2_exp);
        int want1 = known[i].label == "1+t^2" ? 4 : known[i].label == "parnorm13" ? 1 : -1;
        int want2 = known[i].label == "1+t^2" ? 28 : known[i].label == "parnorm12" ? 6 : -1;
        if (want1 < 0 && want2 < 0) generic = false;  // a split or unexpected factor
        if (known[i].label == "parnorm12" && e1_exp != 0) generic = false;
        if (known[i].label == "parnorm13" && e2_exp != 0) generic = false;
        if (want1 >= 0 && e1_exp != want1) generic = false;
        if (want2 >= 0 && e2_exp != want2) generic = false;
    }
    result.polynomial = w;
    result.degree = w.degree();
    result.generic_exponents = generic;
    result.r2_degree = st.r2_degree;
    result.primes_used = primes;
    result.coefficient_bits = std::labs(fmpz_poly_max_bits(w.get()));
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

}  // namespace ellvor
