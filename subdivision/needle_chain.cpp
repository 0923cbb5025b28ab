#include "subdivision/needle_chain.hpp"

#include <cmath>

namespace ellvor {

namespace {

bool a_long(const Ellipse& e) { return !(e.a() < e.b()); }
const Rational& minor_axis(const Ellipse& e) { return a_long(e) ? e.b() : e.a(); }
const Rational& major_axis(const Ellipse& e) { return a_long(e) ? e.a() : e.b(); }

// (p, q) proportional to (cos theta, sin theta), by a positive factor, of the
// point at chart parameter x: t = tan(theta / 2) gives (1 - t^2, 2 t); the
// flipped chart's u = -1/t gives (u^2 - 1, -2 u).
void angle_of(bool flipped, const Ball& x, Ball& p, Ball& q, long prec) {
    arb_sqr(p.get(), x.get(), prec);
    if (flipped) {
        arb_sub_ui(p.get(), p.get(), 1, prec);
        arb_mul_si(q.get(), x.get(), -2, prec);
    } else {
        arb_neg(p.get(), p.get());
        arb_add_ui(p.get(), p.get(), 1, prec);
        arb_mul_2exp_si(q.get(), x.get(), 1);
    }
}

// The chart parameter of the angle of (p, q) != 0: t = q / (|(p, q)| + p)
// where p >= 0, else u = -1/t = -q / (|(p, q)| - p).
void chart_of(const Ball& p, const Ball& q, bool& flipped, Ball& parameter, long prec) {
    Ball norm, denominator;
    arb_hypot(norm.get(), p.get(), q.get(), prec);
    flipped = arf_sgn(arb_midref(p.get())) < 0;
    if (flipped) {
        arb_sub(denominator.get(), norm.get(), p.get(), prec);
        arb_div(parameter.get(), q.get(), denominator.get(), prec);
        arb_neg(parameter.get(), parameter.get());
    } else {
        arb_add(denominator.get(), norm.get(), p.get(), prec);
        arb_div(parameter.get(), q.get(), denominator.get(), prec);
    }
    arb_get_mid_arb(parameter.get(), parameter.get());
}

void scale(Ball& x, const Rational& factor, long prec) {
    Ball f;
    arb_set_fmpq(f.get(), factor.get(), prec);
    arb_mul(x.get(), x.get(), f.get(), prec);
}

}  // namespace

long aspect_bits(const Ellipse& e) {
    const Rational ratio = major_axis(e) / minor_axis(e);
    return static_cast<long>(fmpz_bits(fmpq_numref(ratio.get()))) -
           static_cast<long>(fmpz_bits(fmpq_denref(ratio.get())));
}

std::optional<int> thinnest_needle(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3) {
    std::optional<int> needle;
    long most = kNeedleBits - 1;
    const Ellipse* sites[3] = {&e1, &e2, &e3};
    for (int i = 0; i < 3; ++i) {
        const long bits = aspect_bits(*sites[i]);
        if (bits > most) most = bits, needle = i;
    }
    return needle;
}

Ellipse needle_link(const Ellipse& e, NeedleChain chain, long bits) {
    Rational axis = chain == NeedleChain::thicker ? major_axis(e) : minor_axis(e);
    if (chain == NeedleChain::thicker) {
        fmpq_div_2exp(axis.get(), axis.get(), static_cast<unsigned long>(bits));
        if (!(minor_axis(e) < axis)) return e;
    } else {
        fmpq_mul_2exp(axis.get(), axis.get(), static_cast<unsigned long>(bits));
        if (!(axis < major_axis(e))) return e;
    }
    // The axis that changes: the minor one for thicker, the major one for shorter.
    const bool change_a = (chain == NeedleChain::thicker) != a_long(e);
    return change_a ? Ellipse(axis, e.b(), e.w(), e.xc(), e.yc()) : Ellipse(e.a(), axis, e.w(), e.xc(), e.yc());
}

void carry_contact(const Ellipse& from, const Ellipse& to, ContactMap map, bool& flipped, Ball& parameter, long prec) {
    if (map == ContactMap::same_angle) return;  // the same chart parameter
    Ball p, q;
    angle_of(flipped, parameter, p, q, prec);
    if (map == ContactMap::same_normal) {
        // The outward normal at angle theta is along (b cos theta, a sin theta):
        // the same normal on `to` has (cos, sin) along (b_f cos / b_t, a_f sin / a_t).
        scale(p, from.b() / to.b(), prec);
        scale(q, from.a() / to.a(), prec);
    } else {
        // The same position along the major axis, M cos(psi) with psi the
        // angle from it: the cosine scaled by M_from / M_to, the other
        // coordinate's sign kept.
        Ball norm, other;
        arb_hypot(norm.get(), p.get(), q.get(), prec);
        Ball& along = a_long(from) ? p : q;
        Ball& across = a_long(from) ? q : p;
        arb_div(along.get(), along.get(), norm.get(), prec);
        scale(along, major_axis(from) / major_axis(to), prec);
        arb_sqr(other.get(), along.get(), prec);
        arb_neg(other.get(), other.get());
        arb_add_ui(other.get(), other.get(), 1, prec);
        arb_get_mid_arb(other.get(), other.get());
        if (arf_sgn(arb_midref(other.get())) < 0) arf_zero(arb_midref(other.get()));
        arb_sqrt(other.get(), other.get(), prec);
        if (arf_sgn(arb_midref(across.get())) < 0) arb_neg(other.get(), other.get());
        across = other;
    }
    chart_of(p, q, flipped, parameter, prec);
}

std::array<ContactMap, 2> contact_maps(const Ellipse& from, NeedleChain chain, bool flipped, const Ball& parameter,
                                       long prec) {
    if (chain == NeedleChain::shorter) return {ContactMap::same_position, ContactMap::same_angle};
    Ball p, q;
    angle_of(flipped, parameter, p, q, prec);
    const double along = std::fabs((a_long(from) ? p : q).mid_double());
    const double across = std::fabs((a_long(from) ? q : p).mid_double());
    const bool near_tip = across < std::sqrt((minor_axis(from) / major_axis(from)).to_double()) * along;
    return near_tip ? std::array<ContactMap, 2>{ContactMap::same_normal, ContactMap::same_angle}
                    : std::array<ContactMap, 2>{ContactMap::same_angle, ContactMap::same_normal};
}

}  // namespace ellvor
