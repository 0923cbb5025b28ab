// Exact signs in quadratic fields (exact/quadratic_number.hpp) against Arb
// balls at 2048 bits: wherever a ball decides, the exact sign must agree;
// exact zeros (sqrt 8 - 2 sqrt 2, a^2 = b^2 d) must come out as 0, where a
// ball can only contain 0. Operands range from small integers to numbers of
// thousands of bits and to magnitudes outside the double range, so that both
// the double pre-check and the exact squaring decide some cases.
#include "exact/quadratic_number.hpp"
#include "util/error.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <string>

using namespace ellvor;

namespace {

using Rng = std::mt19937_64;
constexpr long kPrec = 2048;

// A random integer of up to `bits` bits (uniform bit length first, so small
// and large ones both occur), with a random sign when `signed_`.
Integer random_integer(Rng& rng, long bits, bool signed_ = true) {
    const long length = std::uniform_int_distribution<long>(1, bits)(rng);
    Integer r;
    for (long done = 0; done < length; done += 32) {
        fmpz_mul_2exp(r.get(), r.get(), 32);
        fmpz_add_ui(r.get(), r.get(), rng() & 0xffffffffUL);
    }
    fmpz_fdiv_q_2exp(r.get(), r.get(), (32 - length % 32) % 32);
    if (signed_ && (rng() & 1)) fmpz_neg(r.get(), r.get());
    return r;
}

Rational random_rational(Rng& rng, long bits, bool signed_ = true) {
    Integer den = random_integer(rng, bits, false);
    if (den.is_zero()) den = Integer(1);
    return Rational(random_integer(rng, bits, signed_), den);
}

// Positive: numerator at least 1.
Rational random_positive(Rng& rng, long bits) {
    Integer num = random_integer(rng, bits, false), den = random_integer(rng, bits, false);
    fmpz_add_ui(num.get(), num.get(), 1);
    fmpz_add_ui(den.get(), den.get(), 1);
    return Rational(num, den);
}

Rational square(const Rational& x) { return x * x; }

// a + b sqrt(d) as a ball.
Ball ball(const Rational& a, const Rational& b, const Rational& d) {
    Ball r(a, kPrec), s(d, kPrec), t(b, kPrec);
    arb_sqrt(s.get(), s.get(), kPrec);
    arb_addmul(r.get(), t.get(), s.get(), kPrec);
    return r;
}

std::string show(const Rational& a, const Rational& b, const Rational& d) {
    return a.str() + " + (" + b.str() + ") sqrt(" + d.str() + ")";
}

// An exact sign against its Arb enclosure: an exact zero must give 0 and lie
// in the ball; otherwise, where the ball has a sign, the same sign (counted in
// `decided`). False for an exact zero: nothing more to check.
bool check_against_ball(int got, const Ball& want, bool exact_zero, int& decided) {
    if (exact_zero) {
        CHECK(got == 0);
        CHECK(arb_contains_zero(want.get()));
        return false;
    }
    if (const int s = want.certain_sign()) {
        ++decided;
        CHECK(got == s);
    }
    return true;
}

}  // namespace

TEST_CASE("quadratic number: sign of a + b sqrt(d) agrees with Arb on random operands",
          "[circle-predicates][quadratic_number]") {
    Rng rng(20240611);
    int decided = 0, zeros = 0;
    for (int i = 0; i < 3000; ++i) {
        const long bits = i % 3 == 0 ? 20 : i % 3 == 1 ? 200 : 3000;
        Rational a = random_rational(rng, bits), b = random_rational(rng, bits), d = random_rational(rng, bits, false);
        switch (i % 5) {
            case 0: break;  // independent
            case 1: {       // |a| close to |b| sqrt(d): a = -b s with s^2 within 2^-100 relative of d
                const Rational s = random_rational(rng, bits, false);
                d = square(s) * (Rational(1) + Rational(1, 1UL << 50) * Rational(1, 1UL << 50) *
                                                     Rational(long(i % 2 ? 1 : -1)));
                a = -b * s;
                break;
            }
            case 2: {  // an exact zero: d a perfect square
                const Rational s = random_rational(rng, bits, false);
                d = square(s);
                a = -b * s;
                ++zeros;
                break;
            }
            case 3: a = Rational(0); break;
            case 4: b = Rational(0); break;
        }
        INFO(show(a, b, d));
        const int got = sign_of_quadratic(a, b, d);
        const Ball want = ball(a, b, d);
        if (!check_against_ball(got, want, i % 5 == 2, decided)) continue;
        // The integer version on integer operands (numerators) agrees with the rational one.
        const Integer ia = a.numerator(), ib = b.numerator(), id = d.numerator();
        CHECK(sign_of_quadratic(ia, ib, id) == sign_of_quadratic(Rational(ia), Rational(ib), Rational(id)));
    }
    CHECK(decided > 2000);
    CHECK(zeros == 600);
}

TEST_CASE("quadratic number: sign of x + y sqrt(d1) + z sqrt(d2) agrees with Arb, exact zeros included",
          "[circle-predicates][quadratic_number]") {
    // sqrt 8 - 2 sqrt 2 = 0, and its neighbours.
    CHECK(sign_of_two_roots(Rational(0), Rational(1), Rational(8), Rational(-2), Rational(2)) == 0);
    CHECK(sign_of_two_roots(Rational(1, 1000000), Rational(1), Rational(8), Rational(-2), Rational(2)) == 1);
    CHECK(sign_of_two_roots(Rational(0), Rational(1), Rational(8), Rational(-2000001, 1000000UL), Rational(2)) == -1);
    CHECK(compare(QuadraticNumber(0, 1, 8), QuadraticNumber(0, 2, 2)) == 0);
    CHECK(QuadraticNumber(0, 1, 8) == QuadraticNumber(0, 2, 2));
    // Rational square roots: 3 + sqrt(4) - sqrt(25) = 0.
    CHECK(sign_of_two_roots(Rational(3), Rational(1), Rational(4), Rational(-1), Rational(25)) == 0);
    // One radicand twice, a missing root, a rational u.
    CHECK(sign_of_two_roots(Rational(1), Rational(2), Rational(5), Rational(-3), Rational(5)) == -1);
    CHECK(sign_of_two_roots(Rational(0), Rational(2), Rational(5), Rational(-2), Rational(5)) == 0);
    CHECK(sign_of_two_roots(Rational(1), Rational(-1), Rational(2), Rational(0), Rational(3)) == -1);
    CHECK(sign_of_two_roots(Rational(2), Rational(0), Rational(7), Rational(-1), Rational(4)) == 0);
    CHECK(sign_of_two_roots(Rational(2), Rational(5), Rational(0), Rational(-1), Rational(50)) == -1);

    Rng rng(77);
    int decided = 0;
    for (int i = 0; i < 3000; ++i) {
        const long bits = i % 3 == 0 ? 16 : i % 3 == 1 ? 150 : 2000;
        Rational x = random_rational(rng, bits), y = random_rational(rng, bits), z = random_rational(rng, bits);
        Rational d1 = random_rational(rng, bits, false), d2 = random_rational(rng, bits, false);
        bool exact_zero = false;
        switch (i % 4) {
            case 0: break;
            case 1: {  // one field in disguise: d1 = s1^2 t, d2 = s2^2 t, y s1 + z s2 = 0, x = 0
                const Rational t = random_positive(rng, bits), s1 = random_positive(rng, bits),
                               s2 = random_positive(rng, bits);
                d1 = square(s1) * t, d2 = square(s2) * t;
                z = -y * s1 / s2;
                x = Rational(0);
                exact_zero = true;
                break;
            }
            case 2: {  // x cancels the two roots to within a part in 2^200 (a rational approximation)
                Ball s = ball(Rational(0), y, d1), t = ball(Rational(0), z, d2);
                arb_add(s.get(), s.get(), t.get(), kPrec);
                arb_neg(s.get(), s.get());
                Rational lo, hi;
                ball_endpoints(s, lo, hi);
                x = lo + (hi - lo) * Rational(1, 3);
                Rational eps(1);
                fmpq_div_2exp(eps.get(), eps.get(), 200);
                x = x + (i % 8 == 2 ? eps : -eps) * (Rational(1) + (x.sign() < 0 ? -x : x));
                break;
            }
            case 3:  // x and y sqrt(d1) of opposite signs: more work for the squaring
                y = x.sign() < 0 ? (y.sign() < 0 ? -y : y) : (y.sign() > 0 ? -y : y);
                break;
        }
        INFO(x.str() << " + (" << y.str() << ") sqrt(" << d1.str() << ") + (" << z.str() << ") sqrt(" << d2.str()
                     << ")");
        const int got = sign_of_two_roots(x, y, d1, z, d2);
        Ball want = ball(x, y, d1), part = ball(Rational(0), z, d2);
        arb_add(want.get(), want.get(), part.get(), kPrec);
        if (!check_against_ball(got, want, exact_zero, decided)) continue;
        // compare() is the same sign.
        CHECK(compare(QuadraticNumber(x, y, d1), QuadraticNumber(Rational(0), -z, d2)) == got);
        // The integer version on integer operands (numerators) agrees with the rational one.
        const Integer ix = x.numerator(), iy = y.numerator(), iz = z.numerator(), i1 = d1.numerator(),
                      i2 = d2.numerator();
        CHECK(sign_of_two_roots(ix, iy, i1, iz, i2) ==
              sign_of_two_roots(Rational(ix), Rational(iy), Rational(i1), Rational(iz), Rational(i2)));
    }
    CHECK(decided > 2000);
}

TEST_CASE("quadratic number: sign of a + b sqrt(d1) + c sqrt(d2) + e sqrt(d1 d2) agrees with Arb, exact zeros included",
          "[circle-predicates][quadratic_number]") {
    // (1 + sqrt 2)(1 - sqrt 3) = 1 + sqrt 2 - sqrt 3 - sqrt 6 < 0; then sums that vanish exactly.
    CHECK(sign_of_biquadratic(Integer(1), Integer(1), Integer(-1), Integer(-1), Integer(2), Integer(3)) == -1);
    // sqrt 2 sqrt 8 - 4 = 0; 2 sqrt 2 - sqrt 8 = 0.
    CHECK(sign_of_biquadratic(Integer(-4), Integer(0), Integer(0), Integer(1), Integer(2), Integer(8)) == 0);
    CHECK(sign_of_biquadratic(Integer(0), Integer(2), Integer(-1), Integer(0), Integer(2), Integer(8)) == 0);
    CHECK(sign_of_biquadratic(Integer(0), Integer(0), Integer(0), Integer(0), Integer(5), Integer(7)) == 0);
    Rng rng(2029);
    int decided = 0;
    for (int i = 0; i < 3000; ++i) {
        const long bits = i % 3 == 0 ? 12 : i % 3 == 1 ? 120 : 1500;
        Integer a = random_integer(rng, bits), b = random_integer(rng, bits), c = random_integer(rng, bits),
                e = random_integer(rng, bits), d1 = random_integer(rng, bits, false), d2 = random_integer(rng, bits, false);
        bool exact_zero = false;
        if (i % 4 == 1) {
            // d2 = d1 k^2: sqrt(d1 d2) = k d1 is rational and sqrt d2 = k sqrt d1, so
            // a = -e k d1 and b = -c k make the sum exactly 0 in a field in disguise.
            const Integer k = random_integer(rng, 8, false) + Integer(1);
            d2 = d1 * k * k;
            a = -(e * k * d1);
            b = -(c * k);
            exact_zero = true;
        }
        INFO(a.str() << " + " << b.str() << " sqrt(" << d1.str() << ") + " << c.str() << " sqrt(" << d2.str()
                     << ") + " << e.str() << " sqrt(d1 d2)");
        const int got = sign_of_biquadratic(a, b, c, e, d1, d2);
        Ball r1(Rational(d1), kPrec), r2(Rational(d2), kPrec), want(Rational(a), kPrec), t;
        arb_sqrt(r1.get(), r1.get(), kPrec);
        arb_sqrt(r2.get(), r2.get(), kPrec);
        arb_mul(t.get(), Ball(Rational(b), kPrec).get(), r1.get(), kPrec);
        arb_add(want.get(), want.get(), t.get(), kPrec);
        arb_mul(t.get(), Ball(Rational(c), kPrec).get(), r2.get(), kPrec);
        arb_add(want.get(), want.get(), t.get(), kPrec);
        arb_mul(t.get(), r1.get(), r2.get(), kPrec);
        arb_mul(t.get(), t.get(), Ball(Rational(e), kPrec).get(), kPrec);
        arb_add(want.get(), want.get(), t.get(), kPrec);
        check_against_ball(got, want, exact_zero, decided);
    }
    CHECK(decided > 2000);
}

TEST_CASE("quadratic number: the double pre-check only decides what it proves at the edges of the double range",
          "[circle-predicates][quadratic_number]") {
    // a and b sqrt(d) of opposite signs and equal to 2^-1100 relative: the
    // pre-check cannot separate them, the squares do. Beyond the double range
    // (2^2000, 2^-2000) the pre-check is skipped.
    for (long e : {0L, 60L, 2000L, -2000L}) {
        Rational scale(1);
        if (e >= 0) fmpq_mul_2exp(scale.get(), scale.get(), e);
        else fmpq_div_2exp(scale.get(), scale.get(), -e);
        Rational tiny(1);
        fmpq_div_2exp(tiny.get(), tiny.get(), 1100);
        const Rational s(7, 3UL);
        const Rational b = Rational(-5) * scale, d = s * s, a = Rational(5) * scale * s;
        INFO("scale 2^" << e);
        CHECK(sign_of_quadratic(a, b, d) == 0);
        CHECK(sign_of_quadratic(a + tiny * scale, b, d) == 1);
        CHECK(sign_of_quadratic(a - tiny * scale, b, d) == -1);
        // Integers just above 2^53 (not exact in doubles, still one word).
        const Integer big((1L << 53) + 1);
        CHECK(sign_of_quadratic(big, Integer(-1), big * big) == 0);
        CHECK(sign_of_quadratic(big, Integer(-1), big * big + Integer(1)) == -1);
    }
}

TEST_CASE("quadratic number: arithmetic in one field, errors across fields", "[circle-predicates][quadratic_number]") {
    const QuadraticNumber x(Rational(1, 2UL), Rational(3), Rational(5)), y(Rational(-2), Rational(1, 7UL), Rational(5));
    // (1/2 + 3 r)(-2 + r/7) = -1 + 15/7 + (1/14 - 6) r, r = sqrt 5
    const QuadraticNumber product = x * y;
    CHECK(product.rational_part() == Rational(8, 7UL));
    CHECK(product.root_coefficient() == Rational(-83, 14UL));
    CHECK(product.radicand() == Rational(5));
    CHECK((x + y).rational_part() == Rational(-3, 2UL));
    CHECK((x - y).root_coefficient() == Rational(20, 7UL));
    CHECK((-x).sign() == -1);
    // The conjugate product is rational: (1/2)^2 - 9 * 5.
    const QuadraticNumber conjugate(Rational(1, 2UL), Rational(-3), Rational(5));
    CHECK((x * conjugate).is_rational());
    CHECK((x * conjugate).rational_part() == Rational(-179, 4UL));
    // A rational operand joins any field.
    CHECK((x + QuadraticNumber(Rational(1))).radicand() == Rational(5));
    CHECK((QuadraticNumber(Rational(2)) * x).root_coefficient() == Rational(6));
    // Normalization: b = 0 or d = 0 is a rational.
    CHECK(QuadraticNumber(Rational(1), Rational(0), Rational(7)).is_rational());
    CHECK(QuadraticNumber(Rational(1), Rational(3), Rational(0)).is_rational());
    // Errors.
    CHECK_THROWS_AS(QuadraticNumber(Rational(1), Rational(1), Rational(-2)), Error);
    CHECK_THROWS_AS(x + QuadraticNumber(Rational(0), Rational(1), Rational(7)), Error);
    // Enclosure and text.
    CHECK(x.to_ball(128).certain_sign() == 1);
    CHECK(std::abs(x.to_ball(128).mid_double() - (0.5 + 3 * std::sqrt(5.0))) < 1e-12);
    CHECK(x.str() == "1/2 + 3*sqrt(5)");
    CHECK(QuadraticNumber(Rational(-4)).str() == "-4");
}
