// Rectangles of the complex plane with double-interval sides
// (util/interval.hpp): each operation contains the exact result for every
// pair of points of its operands, so a certificate built on them claims only
// what is true.
#pragma once

#include "util/interval.hpp"

#include <algorithm>
#include <cmath>

namespace ellvor {

struct ComplexInterval {
    Interval re{0.0}, im{0.0};

    ComplexInterval() = default;
    ComplexInterval(const Interval& r, const Interval& i = Interval(0.0)) : re(r), im(i) {}

    friend ComplexInterval operator+(const ComplexInterval& a, const ComplexInterval& b) {
        return {a.re + b.re, a.im + b.im};
    }
    friend ComplexInterval operator-(const ComplexInterval& a, const ComplexInterval& b) {
        return {a.re - b.re, a.im - b.im};
    }
    ComplexInterval operator-() const { return {-re, -im}; }
    friend ComplexInterval operator*(const ComplexInterval& a, const ComplexInterval& b) {
        return {a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re};
    }
    friend ComplexInterval operator*(const Interval& a, const ComplexInterval& b) { return {a * b.re, a * b.im}; }
    friend ComplexInterval operator*(const ComplexInterval& a, const Interval& b) { return b * a; }
    friend ComplexInterval operator*(double a, const ComplexInterval& b) { return {a * b.re, a * b.im}; }
    friend ComplexInterval operator+(const ComplexInterval& a, const Interval& b) { return {a.re + b, a.im}; }
    friend ComplexInterval operator-(const ComplexInterval& a, const Interval& b) { return {a.re - b, a.im}; }
    // a b* / |b|^2; |b|^2 must not contain zero (callers check zero_free()).
    friend ComplexInterval operator/(const ComplexInterval& a, const ComplexInterval& b) {
        const Interval d = b.re.square() + b.im.square();
        return {(a.re * b.re + a.im * b.im) / d, (a.im * b.re - a.re * b.im) / d};
    }
    bool zero_free() const { return (re.square() + im.square()).positive(); }
    bool finite() const { return re.finite() && im.finite(); }
    // An upper bound of |z| over the rectangle: sqrt(x^2 + y^2) for the
    // largest |Re z| and |Im z|, each operation rounded up (the square root
    // is correctly rounded).
    double magnitude() const {
        const double x = std::max(std::fabs(re.lo), std::fabs(re.hi)), y = std::max(std::fabs(im.lo), std::fabs(im.hi));
        return Interval::up(std::sqrt(Interval::up(Interval::up(x * x) + Interval::up(y * y))));
    }
};

}  // namespace ellvor
