// A real Arb ball that carries the precision its operations round to, so
// that formulas written once with operators for doubles and intervals (the
// bisector system's templates, cells/normal_ray_in_doubles.cpp) run in balls
// too. An operation rounds to the larger of its operands' precisions; a
// double converts exactly, at precision 0 (two doubles meet at 106 bits,
// where their product is exact). Each result is a new ball: for a few dozen
// operations at a time (below 128 bits Arb allocates nothing).
#pragma once

#include "util/flint_types.hpp"

#include <algorithm>

namespace ellvor {

class FixedPrecisionBall {
public:
    FixedPrecisionBall() = default;
    FixedPrecisionBall(const Ball& value, long prec) : value_(value), prec_(prec) {}
    // Exact.
    FixedPrecisionBall(double value) { arb_set_d(value_.get(), value); }
    FixedPrecisionBall(double value, long prec) : prec_(prec) { arb_set_d(value_.get(), value); }

    const Ball& ball() const { return value_; }
    long precision() const { return prec_; }

    friend FixedPrecisionBall operator+(const FixedPrecisionBall& x, const FixedPrecisionBall& y) {
        FixedPrecisionBall r(x, y);
        arb_add(r.value_.get(), x.value_.get(), y.value_.get(), r.prec_);
        return r;
    }
    friend FixedPrecisionBall operator-(const FixedPrecisionBall& x, const FixedPrecisionBall& y) {
        FixedPrecisionBall r(x, y);
        arb_sub(r.value_.get(), x.value_.get(), y.value_.get(), r.prec_);
        return r;
    }
    friend FixedPrecisionBall operator*(const FixedPrecisionBall& x, const FixedPrecisionBall& y) {
        FixedPrecisionBall r(x, y);
        arb_mul(r.value_.get(), x.value_.get(), y.value_.get(), r.prec_);
        return r;
    }
    friend FixedPrecisionBall operator/(const FixedPrecisionBall& x, const FixedPrecisionBall& y) {
        FixedPrecisionBall r(x, y);
        arb_div(r.value_.get(), x.value_.get(), y.value_.get(), r.prec_);
        return r;
    }
    friend FixedPrecisionBall operator-(const FixedPrecisionBall& x) {
        FixedPrecisionBall r = x;
        arb_neg(r.value_.get(), r.value_.get());
        return r;
    }
    friend FixedPrecisionBall square(const FixedPrecisionBall& x) {
        FixedPrecisionBall r = x;
        arb_sqr(r.value_.get(), x.value_.get(), x.prec_ ? x.prec_ : kDoublesPrecision);
        return r;
    }
    // The square root where the ball is positive; elsewhere an indeterminate
    // ball (NaN midpoint, infinite radius), which fails every later check.
    friend FixedPrecisionBall root_of(const FixedPrecisionBall& x) {
        FixedPrecisionBall r = x;
        if (arb_is_positive(x.value_.get()))
            arb_sqrt(r.value_.get(), x.value_.get(), x.prec_ ? x.prec_ : kDoublesPrecision);
        else
            arb_indeterminate(r.value_.get());
        return r;
    }

private:
    static constexpr long kDoublesPrecision = 106;
    // A result's precision: the larger operand's.
    FixedPrecisionBall(const FixedPrecisionBall& x, const FixedPrecisionBall& y)
        : prec_(std::max({x.prec_, y.prec_, x.prec_ || y.prec_ ? 0L : kDoublesPrecision})) {}

    Ball value_;
    long prec_ = 0;
};

}  // namespace ellvor
