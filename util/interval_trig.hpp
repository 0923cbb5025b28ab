// Sine and cosine over double intervals and complex rectangles
// (util/interval.hpp, util/complex_interval.hpp), without Arb in the common
// case: the cell quadrature (cells/normal_ray_in_doubles.cpp) needs hundreds
// of thousands of them, and Arb's at 64 bits, converted back, cost about ten
// times these.
//
// At a double x: Cody-Waite reduction by pi/2 (x = k pi/2 + r, |r| <= pi/4
// and a little, the split pi/2 = C1 + C2 + C3 + d, C1 and C2 of 33 bits so
// that k C1 and k C2 are exact for |k| < 2^20, |d| <= 2^-122), the two
// differences carried exactly (TwoSum), the rest in interval operations, so r
// is enclosed, to a few of its own ulps; then the Taylor
// polynomials of sin and cos (to r^17 and r^18) in interval arithmetic with
// coefficients 1/n! enclosed by interval division, plus Lagrange's remainder
// |r|^19/19! and |r|^20/20! (every derivative is at most 1 in modulus), and
// the quadrant's signs and swap. Over an interval m +- h (m its middle):
// sin(m + t) = sin m cos t + cos m sin t with cos t in [1 - h^2/2, 1] and
// |sin t| <= min(h, 1); cos likewise. Over a rectangle x + iy: sin = sin x
// cosh y + i cos x sinh y, cos = cos x cosh y - i sin x sinh y, with sinh and
// cosh of the sides' ends by Taylor (to y^17, y^18) after halving y to
// |y| <= 1/2 (the remainders bounded with cosh 1/2 <= 2), then doubled back (sinh 2y = 2 sinh y cosh y, cosh 2y = 1 + 2 sinh^2 y). Arguments
// beyond 2^19 (sines) or 16 (hyperbolic) go to Arb at 128 bits.
// tests/util/test_interval_trig.cpp checks the constants and every path
// against Arb.
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
