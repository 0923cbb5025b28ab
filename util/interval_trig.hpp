// Sine and cosine over double intervals and complex rectangles
// (util/interval.hpp, util/complex_interval.hpp), without Arb in the common
// case: the cell quadrature (cells/normal_ray_in_doubles.cpp) needs hundreds
// of thousands of them, and Arb's at 64 bits, converted back, cost about ten
// times these.
//
// At a double x: Cody-Waite reduction by pi/2 (x = k pi/2 + r, |r| <= pi/4
// + 2^-31 for |x| <= 2^19, the split pi/2 = C1 + C2 + C3 + d, C1 and C2 of
// 33 bits so that k C1 and k C2 are exact for |k| < 2^20, |d| <= 2^-122), the
// two differences carried exactly (TwoSum), the rest in interval operations:
// r is enclosed to a few of its own ulps. Then at r's middle (the result
// widened by r's radius: |sin'|, |cos'| <= 1) the Taylor polynomials, in
// doubles: sin r = r - r z A(-z) to r^17, cos r = 1 - z B(-z) to r^18, z =
// r^2, A and B by Horner with the coefficients of SeriesCoefficients (each
// within 2^-53 of its value). In the standard model (|fl(a o b) - a o b| <=
// u |a o b|, u = 2^-53, no underflow above |r| = 2^-26), Horner's term k
// carries at most 2k + 1 roundings (Higham, Accuracy and Stability, eq.
// 5.3), its coefficient 1, z^k k more, and the products r z, z and the last
// one 2 or 1: term k of T = r z A(-z) errs by gamma_(3k+5) of its modulus,
// of U = z B(-z) by gamma_(3k+4), so |T^ - T| <= u |r| z (0.84 + 0.07 z) and
// |U^ - U| <= u z (2.01 + 0.31 z) for z <= 0.618 (the sums are 0.876 and
// 2.19 at z = 0.618, gamma_m <= m u (1 + 2^-45)), which also covers the
// remainders |r|^19/19! and r^20/20! (every derivative is at most 1); the
// last subtraction's rounding is enclosed by one ulp each way. Below |r| =
// 2^-26: |sin r - r| <= |r|^3, |cos r - 1| <= r^2. sinh and cosh: the same
// series with A(z), B(z) (cosh r <= 1.2 bounds the remainders) after halving
// y to at most 1/2, doubled back in intervals (sinh 2y = 2 sinh y cosh y,
// cosh 2y = 1 + 2 sinh^2 y). Over an interval m +- h: sin(m + t) = sin m cos
// t + cos m sin t with cos t in [1 - h^2/2, 1] and |sin t| <= min(h, 1); cos
// likewise. Over a rectangle x + iy: sin = sin x cosh y + i cos x sinh y, cos
// = cos x cosh y - i sin x sinh y, with sinh, cosh of the imaginary side's
// ends (monotone in |y|). Arguments beyond 2^19 (sines) or 16 (hyperbolic)
// go to Arb at 128 bits. tests/util/test_interval_trig.cpp checks the
// constants and every path against Arb.
#pragma once

#include "util/complex_interval.hpp"
#include "util/interval.hpp"

namespace ellvor {

// Encloses sin x and cos x for every x in `x`; NaN ends give NaN results.
void sin_cos(const Interval& x, Interval& sin, Interval& cos);
// Encloses sinh y and cosh y for every y in `y`.
void sinh_cosh(const Interval& y, Interval& sinh, Interval& cosh);
// Encloses sin z and cos z for every z in the rectangle `z`.
void sin_cos(const ComplexInterval& z, ComplexInterval& sin, ComplexInterval& cos);

// The series' coefficients, rounded to nearest (within 2^-53 of each value;
// the test checks them against Arb): odd[k] = 1/(2k + 3)!, even[k] =
// 1/(2k + 2)!.
struct SeriesCoefficients {
    static constexpr int kOddTerms = 8, kEvenTerms = 9;
    static constexpr double odd[kOddTerms] = {0x1.5555555555555p-3,  0x1.1111111111111p-7,  0x1.a01a01a01a01ap-13,
                                              0x1.71de3a556c734p-19, 0x1.ae64567f544e4p-26, 0x1.6124613a86d09p-33,
                                              0x1.ae7f3e733b81fp-41, 0x1.952c77030ad4ap-49};
    static constexpr double even[kEvenTerms] = {0x1.0000000000000p-1,  0x1.5555555555555p-5,  0x1.6c16c16c16c17p-10,
                                                0x1.a01a01a01a01ap-16, 0x1.27e4fb7789f5cp-22, 0x1.1eed8eff8d898p-29,
                                                0x1.93974a8c07c9dp-37, 0x1.ae7f3e733b81fp-45, 0x1.6827863b97d97p-53};
};

// The Cody-Waite split of pi/2 (above), for the test against Arb.
struct HalfPiSplit {
    static constexpr double c1 = 0x1.921fb54400000p+0;
    static constexpr double c2 = 0x1.0b4611a600000p-34;
    static constexpr double c3 = 0x1.3198a2e037073p-69;
    // |pi/2 - c1 - c2 - c3| <= error.
    static constexpr double error = 0x1p-122;
    // |k| below this keeps k c1 and k c2 exact (33-bit constants).
    static constexpr double max_quadrants = 0x1p20;
};

}  // namespace ellvor
