// Interval division by a positive divisor with two quotients instead of
// operator/'s four: the hot path of ArrivalNormalBox (κ2's and κ4's filter,
// predicates/support_function.hpp). Its own header so that util/interval.hpp,
// which nearly every file includes, stays as it is.
#pragma once

#include "util/interval.hpp"

namespace ellvor {

// a / b for b.lo > 0 (callers check): the interval operator/ gives, bit for
// bit. Dividing by a positive number, the least quotient is lo / hi for
// lo >= 0 (lo / lo for lo < 0), the greatest hi / lo for hi >= 0 (hi / hi for
// hi < 0), so these are operator/'s minimum and maximum (rounding is
// monotone); a NaN (inf / inf), which operator/'s NaN-ignoring hull skips,
// goes to operator/.
inline Interval divide_by_positive(Interval a, Interval b) {
    const double lo = a.lo / (a.lo >= 0 ? b.hi : b.lo), hi = a.hi / (a.hi >= 0 ? b.lo : b.hi);
    if (lo != lo || hi != hi) return a / b;
    return {Interval::down(lo), Interval::up(hi)};
}

}  // namespace ellvor
