// Random rationals and a sufficient disjointness test, shared by the tests
// that draw random sites.
#pragma once

#include "sites/ellipse.hpp"

#include <algorithm>
#include <random>

namespace ellvor::test {

// num/den with num uniform in [lo_num, hi_num].
inline Rational random_fraction(std::mt19937_64& rng, long lo_num, long hi_num, long den) {
    std::uniform_int_distribution<long> n(lo_num, hi_num);
    return Rational(n(rng), static_cast<unsigned long>(den));
}

// Bounding circles (radius max(a, b)) strictly apart: the ellipses are disjoint.
inline bool bounding_circles_apart(const Ellipse& e1, const Ellipse& e2) {
    const Rational r = std::max(e1.a(), e1.b()) + std::max(e2.a(), e2.b());
    const Rational dx = e1.xc() - e2.xc(), dy = e1.yc() - e2.yc();
    return dx * dx + dy * dy > r * r;
}

}  // namespace ellvor::test
