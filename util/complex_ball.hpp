// An Arb complex ball (acb): a rectangle [re +/- r1] + i [im +/- r2]. The
// certified cell integrals (cells/) evaluate their integrands on complex
// balls, as Arb's quadrature asks. Copyable and movable, like Ball.
#pragma once

#include "util/flint_types.hpp"

#include <acb.h>

namespace ellvor {

class ComplexBall {
public:
    ComplexBall() { acb_init(v_); }
    explicit ComplexBall(const Ball& real) { acb_init(v_); acb_set_arb(v_, real.get()); }
    ComplexBall(const ComplexBall& o) { acb_init(v_); acb_set(v_, o.v_); }
    ComplexBall(ComplexBall&& o) noexcept { acb_init(v_); acb_swap(v_, o.v_); }
    ComplexBall& operator=(const ComplexBall& o) { acb_set(v_, o.v_); return *this; }
    ComplexBall& operator=(ComplexBall&& o) noexcept { acb_swap(v_, o.v_); return *this; }
    ~ComplexBall() { acb_clear(v_); }

    acb_struct* get() { return v_; }
    const acb_struct* get() const { return v_; }
    arb_struct* real() { return acb_realref(v_); }
    const arb_struct* real() const { return acb_realref(v_); }
    arb_struct* imag() { return acb_imagref(v_); }
    const arb_struct* imag() const { return acb_imagref(v_); }

private:
    acb_t v_;
};

}  // namespace ellvor
