#include "sites/similarity_frame.hpp"

#include <algorithm>
#include <climits>

namespace ellvor {

namespace {

// e with 2^(e-1) < |q| < 2^(e+1) (q != 0): cheap, from the bit lengths.
long exponent_of(const Rational& q) {
    return static_cast<long>(fmpz_bits(fmpq_numref(q.get()))) - static_cast<long>(fmpz_bits(fmpq_denref(q.get())));
}

// q * 2^shift, exactly.
Rational times_power_of_two(const Rational& q, long shift) {
    Rational r;
    if (shift >= 0)
        fmpq_mul_2exp(r.get(), q.get(), static_cast<ulong>(shift));
    else
        fmpq_div_2exp(r.get(), q.get(), static_cast<ulong>(-shift));
    return r;
}

// floor(q / 2^k) 2^k: a dyadic within 2^k of q.
Rational dyadic_floor(const Rational& q, long k) {
    Integer n;
    const Rational scaled = times_power_of_two(q, -k);
    fmpz_fdiv_q(n.get(), fmpq_numref(scaled.get()), fmpq_denref(scaled.get()));
    return times_power_of_two(Rational(n), k);
}

}  // namespace

SimilarityFrame SimilarityFrame::for_sites(std::initializer_list<const Ellipse*> sites) {
    long size = LONG_MIN, offset = LONG_MIN;
    for (const Ellipse* e : sites) {
        size = std::max({size, exponent_of(e->a()), exponent_of(e->b())});
        for (const Rational* c : {&e->xc(), &e->yc()})
            if (!c->is_zero()) offset = std::max(offset, exponent_of(*c));
    }
    SimilarityFrame f;
    if (std::abs(size) <= kNearUnitBits && offset <= size + kNearUnitBits) return f;
    f.identity_ = false;
    f.exponent_ = size;
    const Ellipse& first = **sites.begin();
    f.origin_ = {dyadic_floor(first.xc(), size - kOriginBits), dyadic_floor(first.yc(), size - kOriginBits)};
    f.origin_bits_ = std::max(0L, offset - size);
    return f;
}

Ellipse SimilarityFrame::apply(const Ellipse& e) const {
    if (identity_) return e;
    return Ellipse(times_power_of_two(e.a(), -exponent_), times_power_of_two(e.b(), -exponent_), e.w(),
                   times_power_of_two(e.xc() - origin_.x, -exponent_), times_power_of_two(e.yc() - origin_.y, -exponent_));
}

Point SimilarityFrame::apply(const Point& p) const {
    if (identity_) return p;
    return {times_power_of_two(p.x - origin_.x, -exponent_), times_power_of_two(p.y - origin_.y, -exponent_)};
}

Ball SimilarityFrame::length_to_original(const Ball& length, long prec) const {
    Ball r = length;
    arb_mul_2exp_si(r.get(), r.get(), exponent_);
    return r;
}

Ball SimilarityFrame::coordinate_to_original(const Ball& c, const Rational& origin, long prec) const {
    Ball r = length_to_original(c, prec);
    const long wide = prec + origin_bits_ + 2;
    arb_add(r.get(), r.get(), Ball(origin, wide).get(), wide);
    return r;
}

Ball SimilarityFrame::x_to_original(const Ball& x, long prec) const { return coordinate_to_original(x, origin_.x, prec); }
Ball SimilarityFrame::y_to_original(const Ball& y, long prec) const { return coordinate_to_original(y, origin_.y, prec); }

}  // namespace ellvor
