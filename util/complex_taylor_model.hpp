// Taylor models of holomorphic functions of one complex variable d on a disk
// |d| <= R: a polynomial of degree N with floating-point complex
// coefficients and a remainder radius e, meaning
//     f(d) in sum_k c_k d^k + D(0, e)   for every |d| <= R
// (Berz and Makino's Taylor models, here in one complex variable, with the
// coefficients' rounding errors moved into e as Rump does for midpoint-radius
// arithmetic). Products keep the terms up to d^N and move the higher ones,
// bounded on the disk, into the remainder; sine, cosine, square root and
// reciprocal add their series' tails. Unlike an interval evaluation over the
// disk, the dependence of every intermediate quantity on d is carried to
// order N, so a long expression overestimates only by remainders of order
// N + 1 in R (and the rounding). With R = 0 a model is a value.
//
// The coefficients are complex (`ComplexTaylorModel`) or real
// (`RealTaylorModel`): a function real on the reals, about a real center, has
// real Taylor coefficients, and its model's arithmetic then costs a quarter
// of the complex one's products; the remainder is a complex disk either way.
//
// Rounding: round-to-nearest, unit u = 2^-53. A floating-point sum of n
// real products errs by at most gamma_n = n u / (1 - n u) times the sum of
// their magnitudes (Higham, Accuracy and Stability, Lemma 3.1 and eq. 3.5;
// a fused multiply-add only removes roundings); a complex coefficient is two
// such sums, so its error is at most gamma_n times the sum of the products
// of the factors' 1-norms |re| + |im| (a real one: one sum of n products).
// Bounds are sums and products of nonnegative doubles rounded to nearest:
// a chain of n such operations errs by a factor of at most (1 - u)^-n, so
// every stored bound is the computed one times 1 + 2^-40 (`inflated`),
// enough for chains of thousands of operations. A NaN or infinite bound fails every later comparison.
#pragma once

#include "util/complex_interval.hpp"
#include "util/interval_trig.hpp"

#include <cmath>
#include <type_traits>

namespace ellvor {

namespace taylor_model_detail {

struct Complex {
    double re = 0, im = 0;
};

// The coefficients' operations, complex and real.
inline double norm1(const Complex& z) { return std::fabs(z.re) + std::fabs(z.im); }
inline double norm1(double x) { return std::fabs(x); }
inline double modulus(const Complex& z) { return std::sqrt(z.re * z.re + z.im * z.im); }
inline double modulus(double x) { return std::fabs(x); }
inline Complex plus(const Complex& a, const Complex& b, double sign) {
    return {a.re + sign * b.re, a.im + sign * b.im};
}
inline double plus(double a, double b, double sign) { return a + sign * b; }
inline Complex negated(const Complex& z) { return {-z.re, -z.im}; }
inline double negated(double x) { return -x; }
inline Complex scaled(double m, const Complex& z) { return {m * z.re, m * z.im}; }
inline double scaled(double m, double x) { return m * x; }
inline void add_product(Complex& sum, const Complex& x, const Complex& y) {
    sum.re += x.re * y.re - x.im * y.im;
    sum.im += x.re * y.im + x.im * y.re;
}
inline void add_product(double& sum, double x, double y) { sum += x * y; }
inline bool equals(const Complex& z, double x) { return z.re == x && z.im == 0; }
inline bool equals(double z, double x) { return z == x; }
inline ComplexInterval point(const Complex& z) { return {Interval(z.re), Interval(z.im)}; }
inline ComplexInterval point(double x) { return ComplexInterval(Interval(x)); }
// The real products a coefficient's product is made of, per sum: 2 (complex), 1.
template <class C>
constexpr int kProductsPerTerm = 2;
template <>
constexpr int kProductsPerTerm<double> = 1;

inline double inflated(double bound) { return bound * (1 + 0x1p-40); }

// gamma_n <= (n + 1) u for n u < 2^-20.
constexpr double gamma(int n) { return (n + 1) * 0x1p-53; }

// A rectangle as a point and a radius holding it: midpoints, and the
// half-widths' 1-norm (a real point: the imaginary part's magnitude too).
inline void split(const ComplexInterval& z, Complex& center, double& radius) {
    center = {z.re.mid(), z.im.mid()};
    const double r = Interval::max(z.re.hi - center.re, center.re - z.re.lo);
    const double i = Interval::max(z.im.hi - center.im, center.im - z.im.lo);
    radius = inflated(r + i);
    if (!std::isfinite(center.re) || !std::isfinite(center.im)) radius = INFINITY;
}
inline void split(const ComplexInterval& z, double& center, double& radius) {
    center = z.re.mid();
    const double r = Interval::max(z.re.hi - center, center - z.re.lo);
    const double i = Interval::max(z.im.hi, -z.im.lo);
    radius = inflated(r + i);
    if (!std::isfinite(center)) radius = INFINITY;
}

}  // namespace taylor_model_detail

template <int N, class Coefficient>
struct TaylorModel {
    static_assert(N >= 1, "a model of degree 0 is a disk");
    static constexpr bool is_real = std::is_same_v<Coefficient, double>;
    // The constant term as an enclosure: a real interval for real coefficients.
    using Constant = std::conditional_t<is_real, Interval, ComplexInterval>;
    Coefficient c[N + 1]{};
    double remainder = 0;
    double radius = 0;  // R

    TaylorModel() = default;
    // The rectangle k, as a constant on the disk of radius R (a real
    // model's constant is Re k's middle, the rest in the remainder).
    TaylorModel(const ComplexInterval& k, double R) : radius(R) { taylor_model_detail::split(k, c[0], remainder); }
    // A real model as a complex one.
    template <class C = Coefficient, class = std::enable_if_t<!std::is_same_v<C, double>>>
    explicit TaylorModel(const TaylorModel<N, double>& a) : remainder(a.remainder), radius(a.radius) {
        for (int k = 0; k <= N; ++k) c[k] = {a.c[k], 0};
    }
    // center + d.
    static TaylorModel variable(const ComplexInterval& center, double R) {
        TaylorModel x(center, R);
        x.c[1] = Coefficient{1};
        return x;
    }
    // Any function on the disk: what an operation gives outside its domain.
    static TaylorModel unbounded(double R) {
        TaylorModel x;
        x.radius = R;
        x.remainder = INFINITY;
        return x;
    }
    Constant constant() const {
        if constexpr (is_real)
            return Interval(c[0]);
        else
            return taylor_model_detail::point(c[0]);
    }

    // R^k for k = 0 .. 2N (computed: the callers' inflation covers them).
    void radius_powers(double (&power)[2 * N + 1]) const {
        power[0] = 1;
        for (int k = 1; k <= 2 * N; ++k) power[k] = power[k - 1] * radius;
    }
    // The polynomial part's modulus on the disk, bounded by 1-norms
    // (computed: the callers' inflation covers it).
    double polynomial_bound() const {
        double b = taylor_model_detail::norm1(c[N]);
        for (int k = N - 1; k >= 0; --k) b = b * radius + taylor_model_detail::norm1(c[k]);
        return b;
    }
    // An upper bound of |f| on the disk (moduli of the coefficients).
    double bound() const {
        double b = 0;
        for (int k = N; k >= 0; --k) b = b * radius + taylor_model_detail::modulus(c[k]);
        return taylor_model_detail::inflated(b + remainder);
    }
    // A rectangle holding f(d) for every d on the disk: c_0 +- (the
    // variation's bound).
    ComplexInterval enclose_disk() const {
        const double e = variation().bound();
        const Interval spread(-e, e);
        const ComplexInterval c0 = taylor_model_detail::point(c[0]);
        return {c0.re + spread, c0.im + spread};
    }
    // A rectangle holding f(d) for every d in the rectangle `d` (which must
    // lie in the disk): the polynomial by Horner's rule in intervals, plus
    // the remainder.
    ComplexInterval enclose(const ComplexInterval& d) const {
        ComplexInterval p = taylor_model_detail::point(c[N]);
        for (int k = N - 1; k >= 0; --k) p = p * d + taylor_model_detail::point(c[k]);
        const Interval e(-remainder, remainder);
        return {p.re + e, p.im + e};
    }

    // Sums: each coefficient's rounding, at most u |result| per part.
    friend TaylorModel operator+(const TaylorModel& a, const TaylorModel& b) { return sum(a, b, 1); }
    friend TaylorModel operator-(const TaylorModel& a, const TaylorModel& b) { return sum(a, b, -1); }
    TaylorModel operator-() const {
        TaylorModel a = *this;
        for (Coefficient& x : a.c) x = taylor_model_detail::negated(x);
        return a;
    }
    friend TaylorModel operator+(const TaylorModel& a, const Interval& k) {
        return a + TaylorModel(ComplexInterval(k), a.radius);
    }
    friend TaylorModel operator-(const TaylorModel& a, const Interval& k) {
        return a - TaylorModel(ComplexInterval(k), a.radius);
    }

    // k a for a rectangle k = m + D(0, rho) (complex models): m a's
    // coefficients (rounding: gamma_2 |m|_1 |c_j|_1 each, gamma_2 |m|_1 |p_a|
    // on the disk), and rho |a| + |m| e.
    friend TaylorModel operator*(const ComplexInterval& k, const TaylorModel& a) {
        static_assert(!is_real, "a complex constant times a real model: convert the model");
        using namespace taylor_model_detail;
        Complex m;
        double rho;
        split(k, m, rho);
        TaylorModel p;
        p.radius = a.radius;
        const double m1 = norm1(m), bound = a.polynomial_bound();
        for (int j = 0; j <= N; ++j)
            p.c[j] = {m.re * a.c[j].re - m.im * a.c[j].im, m.re * a.c[j].im + m.im * a.c[j].re};
        p.remainder = inflated(gamma(2) * (m1 * bound) + rho * (bound + a.remainder) + m1 * a.remainder);
        return p;
    }
    // k a for a real interval k = m + [-rho, rho]: as above with one rounding
    // per part (gamma_1 |m| |c_j|_1, gamma_1 |m| |p_a| on the disk): the
    // sites' numbers times models in the box certificate (as complex
    // rectangles they were 9% of a cell's instructions).
    friend TaylorModel operator*(const Interval& k, const TaylorModel& a) {
        using namespace taylor_model_detail;
        const double m = k.mid(), above = k.hi - m, below = m - k.lo;
        const double rho = std::isfinite(m) ? inflated(above > below ? above : below) : INFINITY;
        TaylorModel p;
        p.radius = a.radius;
        const double m1 = std::fabs(m), bound = a.polynomial_bound();
        for (int j = 0; j <= N; ++j) p.c[j] = scaled(m, a.c[j]);
        p.remainder = inflated(gamma(1) * (m1 * bound) + rho * (bound + a.remainder) + m1 * a.remainder);
        return p;
    }
    friend TaylorModel operator*(const TaylorModel& a, const Interval& k) { return k * a; }
    friend TaylorModel operator*(double k, const TaylorModel& a) { return Interval(k) * a; }

    // (p_a + e_a)(p_b + e_b): the product's terms up to d^N (rounding: at
    // most gamma_(N+1) times the sum of |a_i|_1 |b_j|_1 R^k for real
    // coefficients, gamma_(2N+2) for complex ones, a sum at most |p_a| |p_b|
    // bounded by 1-norms); its terms d^k, k > N, bounded by the 1-norms of
    // their products times R^k; and |p_a| e_b + |p_b| e_a + e_a e_b.
    friend TaylorModel operator*(const TaylorModel& a, const TaylorModel& b) {
        using namespace taylor_model_detail;
        TaylorModel p;
        p.radius = Interval::max(a.radius, b.radius);
        double power[2 * N + 1], na[N + 1], nb[N + 1];
        p.radius_powers(power);
        for (int k = 0; k <= N; ++k) na[k] = norm1(a.c[k]), nb[k] = norm1(b.c[k]);
        for (int k = 0; k <= N; ++k) {
            Coefficient sum{};
            for (int i = 0; i <= k; ++i) add_product(sum, a.c[i], b.c[k - i]);
            p.c[k] = sum;
        }
        double high = 0;
        for (int k = N + 1; k <= 2 * N; ++k) {
            double magnitudes = 0;
            for (int i = k - N; i <= N; ++i) magnitudes += na[i] * nb[k - i];
            high += magnitudes * power[k];  // |sum of products| <= sum of |products|
        }
        // polynomial_bound() of each, from the 1-norms above.
        double bound_a = na[N], bound_b = nb[N];
        for (int k = N - 1; k >= 0; --k) bound_a = bound_a * a.radius + na[k], bound_b = bound_b * b.radius + nb[k];
        const double cross = bound_a * b.remainder + bound_b * a.remainder;
        p.remainder = inflated(gamma(kProductsPerTerm<Coefficient> * (N + 1)) * (bound_a * bound_b) + high + cross +
                               a.remainder * b.remainder);
        return p;
    }

    // The model without its constant term.
    TaylorModel variation() const {
        TaylorModel v = *this;
        v.c[0] = Coefficient{};
        return v;
    }

private:
    static TaylorModel sum(const TaylorModel& a, const TaylorModel& b, double sign) {
        using namespace taylor_model_detail;
        TaylorModel s;
        s.radius = Interval::max(a.radius, b.radius);
        double power[2 * N + 1], rounding = 0;
        s.radius_powers(power);
        for (int k = 0; k <= N; ++k) {
            s.c[k] = plus(a.c[k], b.c[k], sign);
            rounding += norm1(s.c[k]) * power[k];
        }
        // |x + y - fl(x + y)| <= u |x + y| <= 2u |fl(x + y)|, per part.
        s.remainder = inflated(a.remainder + b.remainder + 0x1p-52 * rounding);
        return s;
    }
};

template <int N>
using ComplexTaylorModel = TaylorModel<N, taylor_model_detail::Complex>;
template <int N>
using RealTaylorModel = TaylorModel<N, double>;

// The model of degree M <= N of the same function: the terms above d^M
// bounded on the disk (moduli times R^k), into the remainder.
template <int M, int N, class C>
TaylorModel<M, C> truncated(const TaylorModel<N, C>& a) {
    static_assert(M <= N, "a truncation lowers the degree");
    TaylorModel<M, C> t;
    t.radius = a.radius;
    for (int k = 0; k <= M; ++k) t.c[k] = a.c[k];
    double high = 0, power = 1;
    for (int k = 1; k <= N; ++k) {
        power *= a.radius;
        if (k > M) high += taylor_model_detail::modulus(a.c[k]) * power;
    }
    t.remainder = taylor_model_detail::inflated(a.remainder + high);
    return t;
}

template <int N, class C>
TaylorModel<N, C> square(const TaylorModel<N, C>& x) {
    return x * x;
}

// The sum of coefficient[m] w^m, m = 0..N, of a model w with no constant
// term, plus `tail` added to the remainder.
template <int N, class C>
TaylorModel<N, C> power_series(const TaylorModel<N, C>& w, const Interval (&coefficient)[N + 1], double tail) {
    TaylorModel<N, C> sum(ComplexInterval(coefficient[0]), w.radius), power = w;
    for (int m = 1; m <= N; ++m) {
        if (m > 1) power = power * w;
        sum = sum + coefficient[m] * power;
    }
    sum.remainder = Interval::up(sum.remainder + tail);
    return sum;
}

// W^(N+1) / (1 - W) rounded up, for 0 <= W < 1 (infinite otherwise): the
// tail of a series whose coefficients are at most 1 in magnitude.
template <int N>
double geometric_tail(double W) {
    if (!(W < 1)) return INFINITY;
    Interval p(1.0);
    for (int m = 0; m <= N; ++m) p = p * Interval(W);
    return (p / (Interval(1.0) - Interval(W))).hi;
}

// sin and cos of u = u0 + w: sin u0 cos w + cos u0 sin w and cos u0 cos w -
// sin u0 sin w, the series of cos w and sin w to w^N (sharing the powers of
// w; when w is d itself, as for an angle's own variable, the powers are
// monomials and need no products), their tails at most sum over m > N of
// W^m / m! <= W^(N+1) e^W / (N + 1)! for |w| <= W.
template <int N, class C>
void sin_cos(const TaylorModel<N, C>& u, TaylorModel<N, C>& sin, TaylorModel<N, C>& cos) {
    using Model = TaylorModel<N, C>;
    typename Model::Constant s, c;
    sin_cos(u.constant(), s, c);
    const Model w = u.variation();
    const double W = w.bound();
    bool monomial = w.remainder == 0 && taylor_model_detail::equals(w.c[1], 1);
    for (int k = 2; k <= N; ++k) monomial = monomial && taylor_model_detail::equals(w.c[k], 0);
    Interval tail = Interval(W);
    for (int m = 1; m <= N; ++m) tail = tail * Interval(W) / Interval(static_cast<double>(m + 1));
    // e^W rounded up: the library's exp is within an ulp, a few ulps cover it.
    const double tail_bound = Interval::up((tail * Interval(std::exp(W) * (1 + 0x1p-48))).hi);
    Model cos_w(ComplexInterval(Interval(1.0)), w.radius), sin_w = w, power = w;
    Interval inverse_factorial(1.0);
    for (int m = 2; m <= N; ++m) {
        inverse_factorial = inverse_factorial / Interval(static_cast<double>(m));
        if (monomial) {
            power.c[m - 1] = C{};
            power.c[m] = C{1};
        } else {
            power = power * w;
        }
        const Interval term = (m / 2) % 2 ? -inverse_factorial : inverse_factorial;
        if (m % 2)
            sin_w = sin_w + term * power;
        else
            cos_w = cos_w + term * power;
    }
    cos_w.remainder = Interval::up(cos_w.remainder + tail_bound);
    sin_w.remainder = Interval::up(sin_w.remainder + tail_bound);
    // u's own remainder is in w (u0 is a point).
    sin = s * cos_w + c * sin_w;
    cos = c * cos_w - s * sin_w;
}

// 1/a = (1/a0) sum (-z)^m with z = (a - a0)/a0, |z| <= Z < 1; the tail is
// at most Z^(N+1)/(1 - Z). a0 must be nonzero, else the remainder is
// infinite.
template <int N, class C>
TaylorModel<N, C> reciprocal(const TaylorModel<N, C>& a) {
    using Constant = typename TaylorModel<N, C>::Constant;
    const Constant a0 = a.constant();
    if constexpr (TaylorModel<N, C>::is_real) {
        if (!a0.square().positive()) return TaylorModel<N, C>::unbounded(a.radius);
    } else {
        if (!a0.zero_free()) return TaylorModel<N, C>::unbounded(a.radius);
    }
    const Constant inverse = Constant(Interval(1.0)) / a0;
    const TaylorModel<N, C> z = inverse * a.variation();
    Interval coefficient[N + 1];
    for (int m = 0; m <= N; ++m) coefficient[m] = Interval(m % 2 ? -1.0 : 1.0);
    return inverse * power_series(z, coefficient, geometric_tail<N>(z.bound()));
}

template <int N, class C>
TaylorModel<N, C> operator/(const TaylorModel<N, C>& a, const TaylorModel<N, C>& b) {
    return a * reciprocal(b);
}

// The principal square root where Re a0 > 0: sqrt(a0) sqrt(1 + z), z = (a -
// a0)/a0, |z| <= Z < 1 (then sqrt(1 + z) is the principal branch, and the
// product, of real part > 0 and square a, is the principal root of a). The
// binomial coefficients (1/2 choose m) are dyadic up to m = 6 and at most
// 1/8 in magnitude from m = 2 on: tail <= Z^(N+1)/(8 (1 - Z)). Elsewhere an
// infinite remainder.
template <int N, class C>
TaylorModel<N, C> principal_root(const TaylorModel<N, C>& a) {
    static_assert(N <= 6, "the binomial coefficients below");
    using Constant = typename TaylorModel<N, C>::Constant;
    const Constant a0 = a.constant();
    Constant root0;
    if constexpr (TaylorModel<N, C>::is_real) {
        if (!(a0.lo > 0)) return TaylorModel<N, C>::unbounded(a.radius);
        root0 = a0.sqrt();
    } else {
        if (!(a0.re.lo > 0)) return TaylorModel<N, C>::unbounded(a.radius);
        // u = sqrt((|a0| + Re a0)/2) > 0, v = Im a0 / (2u).
        const Interval u = (((a0.re.square() + a0.im.square()).sqrt() + a0.re) * Interval(0.5)).sqrt();
        root0 = ComplexInterval(u, a0.im / (Interval(2.0) * u));
    }
    const TaylorModel<N, C> z = (Constant(Interval(1.0)) / a0) * a.variation();
    static constexpr double binomial[7] = {1, 0.5, -0.125, 0.0625, -0.0390625, 0.02734375, -0.0205078125};
    Interval coefficient[N + 1];
    for (int m = 0; m <= N; ++m) coefficient[m] = Interval(binomial[m]);
    const double tail = Interval::up(geometric_tail<N>(z.bound()) * 0.125);
    return root0 * power_series(z, coefficient, tail);
}

}  // namespace ellvor
