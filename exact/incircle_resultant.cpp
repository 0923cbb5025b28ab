// Multi-modular InCircle resultant; see incircle_resultant.hpp.
#include "exact/incircle_resultant.hpp"

#include "sites/dense_polynomial.hpp"
#include "sites/ellipse_polynomials.hpp"
#include "util/error.hpp"

#include <flint/fmpz.h>
#include <flint/fmpz_poly_factor.h>
#include <flint/nmod_poly.h>
#include <flint/nmod_vec.h>
#include <flint/ulong_extras.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <chrono>
#include <map>
#include <thread>

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

// A polynomial mod p of degree <= kMaxSmallDegree on the stack (the
// resultants here have degrees <= 24; a heap allocation per resultant would
// cost more than the arithmetic).
constexpr long kMaxSmallDegree = 31;
struct SmallPolynomial {
    std::array<mp_limb_t, kMaxSmallDegree + 1> c;
    long degree;  // of the last nonzero coefficient; -1 for zero
};

// The resultant of f and g (actual degrees m, n: leading coefficients
// nonzero) as a fraction num / den, den != 0, by the Euclidean algorithm with
// pseudo-remainders: no inversion (inversions dominate the cost at word size).
// Uses res(f, g) = (-1)^{mn} lc(g)^{m-k} res(g, f mod g) and
// prem(f, g) = lc(g)^{m-n+1} (f mod g), m = deg f >= n = deg g, k = deg(f mod g).
void resultant_fraction(const SmallPolynomial& a, const SmallPolynomial& b, nmod_t mod, mp_limb_t& num,
                        mp_limb_t& den) {
    num = 1, den = 1;
    SmallPolynomial fa, fb;  // working copies of the used coefficients only
    std::copy_n(a.c.begin(), a.degree + 1, fa.c.begin()), fa.degree = a.degree;
    std::copy_n(b.c.begin(), b.degree + 1, fb.c.begin()), fb.degree = b.degree;
    SmallPolynomial* f = &fa;
    SmallPolynomial* g = &fb;
    if (f->degree < g->degree) {
        std::swap(f, g);
        if ((f->degree * g->degree) & 1) num = nmod_neg(num, mod);
    }
    for (;;) {
        const long m = f->degree, n = g->degree;
        if (n == 0) {
            num = nmod_mul(num, pow_mod(g->c[0], m, mod), mod);
            return;
        }
        // f <- prem(f, g)
        const mp_limb_t lg = g->c[n];
        for (long d = m; d >= n; --d) {
            // f <- lg f - c x^(d-n) g; the two products of a coefficient are
            // summed in 128 bits and reduced once: 2 (p - 1)^2 < 2^64 p for
            // p < 2^63, so the high word is already below p.
            const mp_limb_t minus_c = nmod_neg(f->c[d], mod);
            for (long i = 0; i < d - n; ++i) f->c[i] = nmod_mul(f->c[i], lg, mod);
            for (long i = 0; i < n; ++i) {
                const unsigned __int128 v = static_cast<unsigned __int128>(f->c[d - n + i]) * lg +
                                            static_cast<unsigned __int128>(minus_c) * g->c[i];
                NMOD_RED2(f->c[d - n + i], static_cast<mp_limb_t>(v >> 64), static_cast<mp_limb_t>(v), mod);
            }
            f->c[d] = 0;
        }
        long k = n - 1;
        while (k >= 0 && f->c[k] == 0) --k;
        if (k < 0) {
            num = 0;
            return;
        }
        f->degree = k;
        if ((m * n) & 1) num = nmod_neg(num, mod);
        // num *= lg^(m - k), den *= lg^((m - n + 1) n), as one power: (m - n + 1) n >= m >= m - k.
        den = nmod_mul(den, pow_mod(lg, (m - n + 1) * n - (m - k), mod), mod);
        std::swap(f, g);  // (f, g) <- (g, prem)
    }
}

// A known extraneous factor: an irreducible primitive integer polynomial in t.
struct KnownFactor {
    IntPolynomial poly;
    std::string label;
};

// res(f, g) for f of formal degree `formal` (f's actual degree may be lower,
// f may be zero; f->degree is set here) and g of full degree n >= 0: the
// Sylvester determinant with `formal` rows of g, expanded along the leading
// zeros of f:
//     res_formal(f, g) = (-1)^{(formal - m) n} lc(g)^{formal - m} res(f, g),  m = deg f.
// Returned as num / den, den != 0.
void formal_resultant_fraction(SmallPolynomial& f, long formal, const SmallPolynomial& g, nmod_t mod, mp_limb_t& num,
                               mp_limb_t& den) {
    long m = formal;
    while (m >= 0 && f.c[m] == 0) --m;
    f.degree = m;
    if (m < 0) {
        num = 0, den = 1;
        return;
    }
    resultant_fraction(f, g, mod, num, den);
    num = nmod_mul(num, pow_mod(g.c[g.degree], formal - m, mod), mod);
    if (((formal - m) * g.degree) & 1) num = nmod_neg(num, mod);
}

// The integer system as flat coefficient tables (read concurrently by the
// workers: no FLINT object is created or changed through it).
struct IntegerSystem {
    IntegerSystem(const DensePolynomial& q, const DensePolynomial& b12, const DensePolynomial& b31)
        : dQt(q.degree(0)), dQr(q.degree(1)), dQs(q.degree(2)), d31s(b31.degree(0)), d31t(b31.degree(1)),
          d12t(b12.degree(0)), d12r(b12.degree(1)) {
        for (int i = 0; i <= dQt; ++i)  // Q[(i (dQr + 1) + j) (dQs + 1) + k] = t^i r^j s^k
            for (int j = 0; j <= dQr; ++j)
                for (int k = 0; k <= dQs; ++k) Q.push_back(q.coeff(i, j, k));
        for (int i = 0; i <= d31t; ++i)  // B31[i (d31s + 1) + k] = t^i s^k
            for (int k = 0; k <= d31s; ++k) B31.push_back(b31.coeff(k, i));
        for (int i = 0; i <= d12t; ++i)  // B12[i (d12r + 1) + j] = t^i r^j
            for (int j = 0; j <= d12r; ++j) B12.push_back(b12.coeff(i, j));
    }
    int dQt, dQr, dQs, d31s, d31t, d12t, d12r;
    std::vector<Integer> Q, B31, B12;
};

// The system reduced modulo one prime; evaluates the formal double resultant
//     R2f(t) = res_r^{(D, n12)}( R1f(t, r), B12(t, r) ),   R1f = res_s^{(dQs, n31)}(Q, B31),
// every resultant taken with the formal degrees (D = deg_r Q * deg_s B31 the
// formal r-degree of R1f), so that each value is the image of one fixed
// integer polynomial whatever the prime and the point.
class ModularSystem {
public:
    ModularSystem(mp_limb_t p, const IntegerSystem& system)
        : dQt_(system.dQt), dQr_(system.dQr), dQs_(system.dQs), d31s_(system.d31s), d31t_(system.d31t),
          d12t_(system.d12t), d12r_(system.d12r) {
        nmod_init(&mod_, p);
        // (p - 1)^2 < 2^(2 bits): 2^(128 - 2 bits) products fit in 128 bits.
        dot_group_ = std::min(8L, 1L << std::min(3L, 128 - 2 * static_cast<long>(FLINT_BIT_COUNT(p))));
        if (r1_formal_degree() > kMaxSmallDegree || std::max({dQs_, d31s_, d12r_}) > kMaxSmallDegree)
            throw Error("incircle_resultant: degrees beyond the modular kernel's capacity");
        // Tables transposed so that every specialization is a dot product over t's powers.
        Q_.resize(system.Q.size()), B31_.resize(system.B31.size()), B12_.resize(system.B12.size());
        for (int i = 0; i <= dQt_; ++i)
            for (int j = 0; j <= dQr_; ++j)
                for (int k = 0; k <= dQs_; ++k)
                    Q_[((k * (dQr_ + 1) + j) * (dQt_ + 1)) + i] =
                        reduce(system.Q[static_cast<size_t>((i * (dQr_ + 1) + j) * (dQs_ + 1) + k)]);
        for (int i = 0; i <= d31t_; ++i)
            for (int k = 0; k <= d31s_; ++k)
                B31_[k * (d31t_ + 1) + i] = reduce(system.B31[static_cast<size_t>(i * (d31s_ + 1) + k)]);
        for (int i = 0; i <= d12t_; ++i)
            for (int j = 0; j <= d12r_; ++j)
                B12_[j * (d12t_ + 1) + i] = reduce(system.B12[static_cast<size_t>(i * (d12r_ + 1) + j)]);
        const long points = r1_formal_degree() + 1;  // r0 = 1 .. points
        r_powers_.assign(static_cast<size_t>(points * (dQr_ + 1)), 0);
        for (long i = 0; i < points; ++i) {
            mp_limb_t x = 1;
            for (int j = 0; j <= dQr_; ++j, x = nmod_mul(x, static_cast<mp_limb_t>(i + 1), mod_))
                r_powers_[i * (dQr_ + 1) + j] = x;
        }
        build_lagrange(points);
    }

    long r1_formal_degree() const { return static_cast<long>(dQr_) * d31s_; }
    long r1_t_degree_bound() const { return static_cast<long>(dQt_) * d31s_ + static_cast<long>(d31t_) * dQs_; }
    long r2_degree_bound() const { return r1_t_degree_bound() * d12r_ + static_cast<long>(d12t_) * r1_formal_degree(); }

    // The leading coefficients lc_s(B31)(t) and lc_r(B12)(t) are nonzero mod p,
    // so that all but finitely many points t0 are usable.
    bool usable() const {
        auto nonzero = [](const mp_limb_t* v, int n) { return std::any_of(v, v + n, [](mp_limb_t x) { return x != 0; }); };
        return nonzero(&B31_[d31s_ * (d31t_ + 1)], d31t_ + 1) && nonzero(&B12_[d12r_ * (d12t_ + 1)], d12t_ + 1);
    }

    // R2f(t0) mod p, and the actual r-degree of R1f(t0, r) (-1 when zero);
    // false when t0 is a root of one of the leading coefficients above.
    bool r2_value(mp_limb_t t0, mp_limb_t& value, long& r1_degree) {
        specialize_t(t0);
        if (b12t_.c[d12r_] == 0 || b31t_.c[d31s_] == 0) return false;
        SmallPolynomial r1 = r1_polynomial();
        mp_limb_t num, den;
        formal_resultant_fraction(r1, r1_formal_degree(), b12t_, mod_, num, den);
        r1_degree = r1.degree;
        value = nmod_mul(num, n_invmod(den, mod_.n), mod_);
        return true;
    }

private:
    mp_limb_t reduce(const Integer& c) const { return fmpz_fdiv_ui(c.get(), mod_.n); }
    // sum a[i] b[i] mod p, reducing once per group of products whose sum fits
    // in 128 bits (FLINT's general dot product costs more for these short vectors).
    mp_limb_t dot(const mp_limb_t* a, const mp_limb_t* b, long n) const {
        mp_limb_t result = 0;
        for (long start = 0; start < n; start += dot_group_) {
            unsigned __int128 acc = 0;
            for (long i = start; i < std::min(n, start + dot_group_); ++i)
                acc += static_cast<unsigned __int128>(a[i]) * b[i];
            mp_limb_t r;
            NMOD2_RED2(r, static_cast<mp_limb_t>(acc >> 64), static_cast<mp_limb_t>(acc), mod_);
            result = nmod_add(result, r, mod_);
        }
        return result;
    }

    // Q(t0, r, s) as a table qt_[k (dQr + 1) + j] (coefficient of r^j s^k),
    // B31(s, t0) in s and B12(t0, r) in r.
    void specialize_t(mp_limb_t t0) {
        std::array<mp_limb_t, kMaxSmallDegree + 1> pw{};
        const int top = std::max({dQt_, d31t_, d12t_});
        if (top > kMaxSmallDegree) throw Error("incircle_resultant: degree in t beyond the kernel's capacity");
        pw[0] = 1;
        for (int i = 1; i <= top; ++i) pw[i] = nmod_mul(pw[i - 1], t0, mod_);
        qt_.resize(static_cast<size_t>((dQr_ + 1) * (dQs_ + 1)));
        for (size_t kj = 0; kj < qt_.size(); ++kj) qt_[kj] = dot(&Q_[kj * (dQt_ + 1)], pw.data(), dQt_ + 1);
        b31t_.degree = d31s_;
        for (int k = 0; k <= d31s_; ++k) b31t_.c[k] = dot(&B31_[k * (d31t_ + 1)], pw.data(), d31t_ + 1);
        b12t_.degree = d12r_;
        for (int j = 0; j <= d12r_; ++j) b12t_.c[j] = dot(&B12_[j * (d12t_ + 1)], pw.data(), d12t_ + 1);
    }

    // R1f(t0, r) in r (after specialize_t, with lc_s(B31)(t0) != 0),
    // interpolated from its values at r0 = 1 .. D + 1 with the precomputed
    // Lagrange basis (one batch inversion of the resultants' denominators).
    SmallPolynomial r1_polynomial() const {
        const long n = r1_formal_degree() + 1;
        std::array<mp_limb_t, kMaxSmallDegree + 1> ys{}, dens{}, prefix{};
        SmallPolynomial q{};
        for (long i = 0; i < n; ++i) {
            for (int k = 0; k <= dQs_; ++k) q.c[k] = dot(&qt_[k * (dQr_ + 1)], &r_powers_[i * (dQr_ + 1)], dQr_ + 1);
            formal_resultant_fraction(q, dQs_, b31t_, mod_, ys[i], dens[i]);
        }
        mp_limb_t acc = 1;
        for (long i = 0; i < n; ++i) prefix[i] = acc, acc = nmod_mul(acc, dens[i], mod_);
        mp_limb_t inv = n_invmod(acc, mod_.n);
        for (long i = n - 1; i >= 0; --i) {
            ys[i] = nmod_mul(ys[i], nmod_mul(inv, prefix[i], mod_), mod_);
            inv = nmod_mul(inv, dens[i], mod_);
        }
        SmallPolynomial out{};
        for (long k = 0; k < n; ++k) out.c[k] = dot(ys.data(), &lagrange_[k * n], n);
        return out;
    }

    // lagrange_[k * n + i]: coefficient of r^k in the Lagrange basis
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
            for (long k = 0; k < n; ++k) lagrange_[k * n + i] = nmod_mul(w, q[k], mod_);
        }
    }

    int dQt_, dQr_, dQs_, d31s_, d31t_, d12t_, d12r_;
    nmod_t mod_{};
    long dot_group_ = 1;
    std::vector<mp_limb_t> Q_, B31_, B12_;  // transposed: t's power varies fastest
    std::vector<mp_limb_t> r_powers_, lagrange_;
    std::vector<mp_limb_t> qt_;
    SmallPolynomial b31t_{}, b12t_{};
};

// R2f modulo one prime: its coefficients (r2_degree_bound() + 1 of them,
// interpolated from as many points) and the largest r-degree of R1f(t0, r)
// seen at those points. `usable` is false when the prime must be skipped.
struct PrimeImage {
    mp_limb_t prime = 0;
    bool usable = false;
    std::vector<mp_limb_t> coefficients;
    long r1_degree = -1;
};

void compute_image(PrimeImage& image, const IntegerSystem& system) {
    ModularSystem sys(image.prime, system);
    if (!sys.usable()) return;
    const long n = sys.r2_degree_bound() + 1;
    std::vector<mp_limb_t> xs, ys;
    mp_limb_t value = 0;
    long degree = -1;
    // At most deg lc_s(B31) + deg lc_r(B12) points are skipped.
    for (mp_limb_t t0 = 1; static_cast<long>(xs.size()) < n; ++t0) {
        if (!sys.r2_value(t0, value, degree)) continue;
        image.r1_degree = std::max(image.r1_degree, degree);
        xs.push_back(t0), ys.push_back(value);
    }
    NmodPoly r2(image.prime);
    nmod_poly_interpolate_nmod_vec(r2.get(), xs.data(), ys.data(), n);
    image.coefficients.assign(static_cast<size_t>(n), 0);
    for (long k = 0; k < n; ++k) image.coefficients[k] = r2.coeff(k);
    image.usable = true;
}

// RAII over FLINT's subproduct tree for multi-modular reconstruction.
class PrimeComb {
public:
    explicit PrimeComb(const std::vector<mp_limb_t>& primes) {
        fmpz_comb_init(comb_, primes.data(), static_cast<slong>(primes.size()));
        fmpz_comb_temp_init(temp_, comb_);
    }
    PrimeComb(const PrimeComb&) = delete;
    PrimeComb& operator=(const PrimeComb&) = delete;
    ~PrimeComb() {
        fmpz_comb_temp_clear(temp_);
        fmpz_comb_clear(comb_);
    }
    // The integer of least absolute value with the given residues.
    void reconstruct(Integer& out, const std::vector<mp_limb_t>& residues) {
        fmpz_multi_CRT_ui(out.get(), residues.data(), comb_, temp_, 1);
    }

private:
    fmpz_comb_t comb_;
    fmpz_comb_temp_t temp_;
};

// sum over the coefficients P_k of var^k of (sum of |coefficients of P_k|)^2:
// the squared 2-norm bound, on the unit polydisc, of a Sylvester row of P.
Integer squared_row_bound(const DensePolynomial& P, int var) {
    std::vector<Integer> one_norms(static_cast<size_t>(P.degree(var) + 1));
    Integer a;
    for (int i = 0; i <= std::max(P.degree(0), 0); ++i)
        for (int j = 0; j <= std::max(P.degree(1), 0); ++j)
            for (int k = 0; k <= std::max(P.degree(2), 0); ++k) {
                const int index[3] = {i, j, k};
                fmpz_abs(a.get(), P.coeff(i, j, k).get());
                fmpz_add(one_norms[index[var]].get(), one_norms[index[var]].get(), a.get());
            }
    Integer sum;
    for (const Integer& n : one_norms) fmpz_addmul(sum.get(), n.get(), n.get());
    return sum;
}

// Bits of a proven bound on every coefficient of R2f (Hadamard twice):
// for |t| = |r| = 1 a Sylvester row of Q (in s) has 2-norm at most
// sqrt(sum_k ||Q_k||_1^2), so |R1f(t, r)| <= q^{n31} b31^{dQs} =: h1 on the torus;
// for |t| = 1 a row of R1f's coefficients in r has 2-norm ||R1f(t, .)||_2 <= h1
// (Parseval), so |R2f(t)| <= h1^{n12} b12^{D} on the unit circle, and by
// Cauchy's formula every coefficient of R2f is below that. h1 also bounds the
// coefficients of R1f.
long coefficient_bound_bits(const DensePolynomial& Q, const DensePolynomial& B12, const DensePolynomial& B31) {
    const Integer q2 = squared_row_bound(Q, 2), b31 = squared_row_bound(B31, 0), b12 = squared_row_bound(B12, 1);
    const unsigned long n31 = static_cast<unsigned long>(B31.degree(0)), n12 = static_cast<unsigned long>(B12.degree(1)),
                        dQs = static_cast<unsigned long>(Q.degree(2)), D = static_cast<unsigned long>(Q.degree(1)) * n31;
    Integer squared, f;
    fmpz_pow_ui(squared.get(), q2.get(), n31 * n12);
    fmpz_pow_ui(f.get(), b31.get(), dQs * n12);
    fmpz_mul(squared.get(), squared.get(), f.get());
    fmpz_pow_ui(f.get(), b12.get(), D);
    fmpz_mul(squared.get(), squared.get(), f.get());
    return static_cast<long>((fmpz_bits(squared.get()) + 1) / 2);  // bound^2 < 2^bits
}

// The images of R2f modulo enough primes for their product to exceed twice
// the coefficient bound, computed by `threads` workers.
std::vector<PrimeImage> prime_images(mp_limb_t first_prime, long bound_bits, int threads,
                                     const IntegerSystem& system) {
    std::vector<PrimeImage> images;
    mp_limb_t p = first_prime;
    double usable_bits = 0;
    while (usable_bits < bound_bits + 2) {  // product > 2^(bound + 1)
        // Primes are drawn for the missing bits; unusable ones (a leading
        // coefficient vanishing mod p, in practice never) are replaced next round.
        const size_t begin = images.size();
        for (double bits = usable_bits; bits < bound_bits + 2; bits += std::log2(static_cast<double>(p))) {
            p = n_nextprime(p, 1);
            if (p >= (1UL << 63)) throw Error("incircle_resultant: ran out of word-size primes");
            images.push_back(PrimeImage{});
            images.back().prime = p;
        }
        std::atomic<size_t> next{begin};
        auto worker = [&]() {
            for (size_t i = next++; i < images.size(); i = next++) compute_image(images[i], system);
        };
        std::vector<std::thread> pool;
        for (int w = 1; w < threads; ++w) pool.emplace_back(worker);
        worker();
        for (std::thread& t : pool) t.join();
        for (size_t i = begin; i < images.size(); ++i)
            if (images[i].usable) usable_bits += std::log2(static_cast<double>(images[i].prime)) - 1e-9;
    }
    images.erase(std::remove_if(images.begin(), images.end(), [](const PrimeImage& i) { return !i.usable; }),
                 images.end());
    return images;
}

// Divides the nonzero r by the largest power of f that divides it over Z and
// returns the exponent. The exponent modulo a prime p that keeps f's degree
// is an upper bound; one exact division by that power usually proves it
// (a 50000-bit R2 makes each division costly, so no division one at a time).
int divide_out(IntPolynomial& r, const IntPolynomial& f, mp_limb_t p) {
    int e = 0;
    NmodPoly rp(p), fp(p), q(p), rem(p);
    fmpz_poly_get_nmod_poly(rp.get(), r.get());
    fmpz_poly_get_nmod_poly(fp.get(), f.get());
    if (fp.degree() == f.degree() && rp.degree() >= 0) {
        for (;;) {
            nmod_poly_divrem(q.get(), rem.get(), rp.get(), fp.get());
            if (rem.degree() >= 0) break;
            nmod_poly_swap(rp.get(), q.get());
            ++e;
        }
    } else {
        e = static_cast<int>(r.degree() / std::max(1L, f.degree()));  // the degree bound
    }
    IntPolynomial power, quotient;
    for (; e > 0; --e) {
        fmpz_poly_pow(power.get(), f.get(), static_cast<ulong>(e));
        if (fmpz_poly_divides(quotient.get(), r.get(), power.get())) {
            r = std::move(quotient);
            return e;
        }
    }
    return 0;
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

    // R2f over Z from its images modulo primes whose product exceeds twice
    // the proven coefficient bound: every image is exact (formal degrees), so
    // the reconstruction is a proof, not a stabilisation.
    result.bound_bits = coefficient_bound_bits(Q, B12, B31);
    const int threads = options.threads > 0 ? options.threads
                                            : static_cast<int>(std::max(1U, std::thread::hardware_concurrency()));
    const std::vector<PrimeImage> images = prime_images(options.first_prime, result.bound_bits, threads, IntegerSystem(Q, B12, B31));
    result.primes_used = static_cast<long>(images.size());
    std::vector<mp_limb_t> primes;
    long r1_degree = -1;
    for (const PrimeImage& i : images) primes.push_back(i.prime), r1_degree = std::max(r1_degree, i.r1_degree);
    // deg_r R1 over Z is r1_degree: it is reached mod some prime (a lower
    // bound), and every coefficient of a higher power of r is a polynomial in t
    // of degree < the number of points of each image, zero at all of them mod
    // every prime, and bounded by h1 < the bound: zero over Z.
    if (r1_degree < 0) throw Error("incircle_resultant: res_s(Q, B31) vanishes identically (common component)");
    IntPolynomial r2;
    {
        PrimeComb comb(primes);
        std::vector<mp_limb_t> residues(primes.size());
        Integer c;
        const size_t n = images.front().coefficients.size();
        for (size_t k = 0; k < n; ++k) {
            for (size_t i = 0; i < images.size(); ++i) residues[i] = images[i].coefficients[k];
            comb.reconstruct(c, residues);
            fmpz_poly_set_coeff_fmpz(r2.get(), static_cast<slong>(k), c.get());
        }
    }
    // The paper's R2 = res_r(R1, B12) with R1's actual r-degree:
    // R2f = +-lc_r(B12)^{D - deg_r R1} R2.
    const long r1_formal = static_cast<long>(Q.degree(1)) * B31.degree(0);
    if (r1_degree < r1_formal) {
        IntPolynomial lead, power, quotient;
        for (int i = 0; i <= B12.degree(0); ++i)
            fmpz_poly_set_coeff_fmpz(lead.get(), i, B12.coeff(i, B12.degree(1)).get());
        fmpz_poly_pow(power.get(), lead.get(), static_cast<ulong>(r1_formal - r1_degree));
        if (!fmpz_poly_divides(quotient.get(), r2.get(), power.get()))
            throw Error("incircle_resultant: internal inconsistency (R2 not divisible by lc(B12)^k)");
        r2 = std::move(quotient);
    }
    if (r2.is_zero()) throw Error("incircle_resultant: res_r(R1, B12) vanishes identically (common component)");
    result.r1_degree = r1_degree;
    result.r2_degree = r2.degree();

    // Exponents of the known factors in R2, by exact division over Z.
    std::vector<KnownFactor> known = known_factors(e1, e2, e3);
    IntPolynomial w = r2;
    std::vector<int> exponents;
    for (const KnownFactor& f : known) {
        const int e = divide_out(w, f.poly, primes.front());
        exponents.push_back(e);
        if (e > 0) result.removed_factors.emplace_back("R2:" + f.label, e);
    }
    // The squarefree part of what is left.
    {
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

    // Seed, Lemma 3.1: R1 = (1+t^2)^4 parnorm13 R1', R2 = (1+t^2)^28 parnorm12^6 res_r(R1', B12)
    // with deg_r B12 = 6, so R2 holds (1+t^2)^52 parnorm13^6 parnorm12^6.
    bool generic = !q_reduced && w.degree() == 184 && known.size() == 3;
    for (size_t i = 0; i < known.size() && generic; ++i) {
        const std::string& label = known[i].label;
        const int expected = label == "1+t^2" ? 52 : (label == "parnorm13" || label == "parnorm12") ? 6 : -1;
        generic = exponents[i] == expected;
    }
    generic = generic && std::none_of(result.removed_factors.begin(), result.removed_factors.end(),
                                      [](const auto& f) { return f.first == "square-part"; });
    result.polynomial = w;
    result.degree = w.degree();
    result.generic_exponents = generic;
    result.coefficient_bits = std::labs(fmpz_poly_max_bits(w.get()));
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

}  // namespace ellvor
