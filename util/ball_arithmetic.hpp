// Ball arithmetic as expressions at one fixed precision, for oracles in tests
// and experiments that compute a few formulas at a high precision (the
// library itself manages its precision call by call).
#pragma once

#include "util/flint_types.hpp"

namespace ellvor {

struct BallArithmetic {
    long prec;
    Ball q(const Rational& v) const { return Ball(v, prec); }
    Ball add(const Ball& a, const Ball& b) const { Ball r; arb_add(r.get(), a.get(), b.get(), prec); return r; }
    Ball sub(const Ball& a, const Ball& b) const { Ball r; arb_sub(r.get(), a.get(), b.get(), prec); return r; }
    Ball mul(const Ball& a, const Ball& b) const { Ball r; arb_mul(r.get(), a.get(), b.get(), prec); return r; }
    Ball div(const Ball& a, const Ball& b) const { Ball r; arb_div(r.get(), a.get(), b.get(), prec); return r; }
    Ball sqrt(const Ball& a) const { Ball r; arb_sqrt(r.get(), a.get(), prec); return r; }
    // The midpoint alone (Newton iterations of an oracle carry no radius).
    static Ball mid(const Ball& a) { Ball r; arb_get_mid_arb(r.get(), a.get()); return r; }
};

}  // namespace ellvor
