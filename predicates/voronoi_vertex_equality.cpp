#include "predicates/voronoi_vertex_equality.hpp"

#include "exact/incircle_resultant.hpp"
#include "exact/real_roots.hpp"
#include "predicates/rational_voronoi_center.hpp"
#include "sites/ellipse_polynomials.hpp"
#include "util/error.hpp"
#include "util/precision.hpp"

#include <algorithm>

namespace ellvor {

namespace {

// Whether the ball [lo, hi] holds exactly one root of the squarefree p,
// strictly inside.
bool isolates_one_root(const IntPolynomial& p, const Rational& lo, const Rational& hi) {
    return lo < hi && sign_at_rational(p, lo) != 0 && sign_at_rational(p, hi) != 0 && count_real_roots(p, lo, hi) == 1;
}

// E turned by a quarter turn with its axes swapped: the same point set. With
// omega'' = omega + pi/2 its angle is theta'' = theta - pi/2, with
// omega'' = omega - pi/2 it is theta + pi/2 (w = tan(omega/2) transforms by
// the matching Moebius map).
Ellipse quarter_turned_twin(const Ellipse& e, bool plus) {
    const Rational one(1), &w = e.w();
    const Rational w2 = plus ? (one + w) / (one - w) : (w - one) / (w + one);
    return Ellipse(e.b(), e.a(), w2, e.xc(), e.yc());
}

}  // namespace

// The contact parameter on the shared site, in the comparison's chart:
// t = tan(theta/2), or t'' = tan((theta -+ pi/2)/2) = (t -+ 1)/(1 +- t).
Ball ContactComparison::contact(const CertifiedVoronoiCircle& c) const {
    const VoronoiCircleEnclosure& e = c.solver->enclosure();
    const long prec = e.precision;
    Ball t = e.tangency_parameter(c.index, prec);
    if (*chart_ == Chart::t) return t;
    // From the chart parameter directly, so that t = infinity causes no harm:
    // with u = -1/t, (t - 1)/(1 + t) = (1 + u)/(1 - u) and (t + 1)/(1 - t) = (u - 1)/(u + 1).
    const bool minus = *chart_ == Chart::twin_minus;
    Ball num, den, one(Rational(1), prec), r;
    const Ball& p = e.parameter[c.index];
    if (e.flipped[c.index]) {
        minus ? arb_add(num.get(), one.get(), p.get(), prec) : arb_sub(num.get(), p.get(), one.get(), prec);
        minus ? arb_sub(den.get(), one.get(), p.get(), prec) : arb_add(den.get(), p.get(), one.get(), prec);
    } else {
        minus ? arb_sub(num.get(), p.get(), one.get(), prec) : arb_add(num.get(), p.get(), one.get(), prec);
        minus ? arb_add(den.get(), one.get(), p.get(), prec) : arb_sub(den.get(), one.get(), p.get(), prec);
    }
    arb_div(r.get(), num.get(), den.get(), prec);
    return r;
}

// The InCircle resultant of the triple rotated to start at the shared site
// (a rotation keeps the circle) -- or at its twin --, times the two
// parallel-normals polynomials that the resultant divides out (the paper's Lemma
// 3.1): a genuine contact can be a root of those (e.g. when the normals at two
// contact points are collinear), so they stay among the candidates. Squarefree.
IntPolynomial ContactComparison::polynomial(const CertifiedVoronoiCircle& c) const {
    const auto& t = c.triple;
    const int i = c.index;
    const Ellipse &next = *t[(i + 1) % 3], &last = *t[(i + 2) % 3];
    const Ellipse shared = *chart_ == Chart::t ? *t[i] : quarter_turned_twin(*t[i], *chart_ == Chart::twin_minus);
    IntPolynomial p = incircle_resultant(shared, next, last).polynomial, product;
    fmpz_poly_mul(product.get(), p.get(), parallel_normals_polynomial(shared, next).get());
    fmpz_poly_mul(product.get(), product.get(), parallel_normals_polynomial(shared, last).get());
    return squarefree_part(product);
}

// A short rational point in the finer center enclosure, proven the center of
// both circles: then they are one circle (both touch the shared site, so
// their radii are its distance). Short: at most a quarter of the enclosure's
// correct bits, so an irrational center (whose simplest rational in the ball
// has about half of them) almost never costs a check, while an exact center
// of h bits is the simplest rational of every ball narrower than 2^-2h
// around it.
bool ContactComparison::common_rational_center() const {
    const VoronoiCircleEnclosure &ea = a_.solver->enclosure(), &eb = b_.solver->enclosure();
    const VoronoiCircleEnclosure& finer = ea.correct_bits() >= eb.correct_bits() ? ea : eb;
    const long max_bits = finer.correct_bits() / 4;
    const std::optional<Rational> x = simplest_rational_in(finer.center_x, max_bits),
                                  y = simplest_rational_in(finer.center_y, max_bits);
    if (!x || !y) return false;
    for (const VoronoiCircleEnclosure* e : {&ea, &eb})
        if (!e->center_x.contains(*x) || !e->center_y.contains(*y)) return false;
    RationalCenter center({*x, *y});
    return center.is_center_of(a_.triple) && center.is_center_of(b_.triple);
}

bool ContactComparison::same_contact_point(long reached_precision) {
    const long limit = std::max(precision::kExactIsolationLimit, 4 * reached_precision);
    // From the start precision: a solver refined further already has these
    // bits, and the other one (often fresh) needs only what isolation needs.
    for (long p = precision::kStart; p <= limit; p *= 2) {
        // Both circles exist (the caller's premise), so refining cannot fail.
        a_.solver->refine_existing(p);
        b_.solver->refine_existing(p);
        if (const std::optional<bool> same = same_contact_point_at_current_precision()) return *same;
    }
    throw Error("the exact stage could not isolate the resultant roots of two Voronoi vertices within " +
                std::to_string(limit) + " bits (internal error)");
}

std::optional<bool> ContactComparison::same_contact_point_at_current_precision() {
    if (!chart_) {
        // A contact with |t| > 1 (flipped chart) may be at the i-point: use the
        // twin whose quarter turn brings it to |t''| <= 1.
        const VoronoiCircleEnclosure& e = a_.solver->enclosure();
        if (!e.flipped[a_.index] && !b_.solver->enclosure().flipped[b_.index]) {
            chart_ = Chart::t;
        } else {
            // flipped u = -1/t: u < 0 means theta in (pi/2, pi), turn by -pi/2.
            const bool theta_positive = e.flipped[a_.index] ? e.parameter[a_.index].mid_double() <= 0
                                                            : e.parameter[a_.index].mid_double() > 0;
            chart_ = theta_positive ? Chart::twin_minus : Chart::twin_plus;
            // twin_minus needs w != 1 and twin_plus w != -1 (quarter_turned_twin).
            const Rational& w = a_.triple[a_.index]->w();
            if (*chart_ == Chart::twin_minus && w == Rational(1)) chart_ = Chart::twin_plus;
            if (*chart_ == Chart::twin_plus && w == Rational(-1)) chart_ = Chart::twin_minus;
        }
    }
    const Ball ta = contact(a_), tb = contact(b_);
    if (!arb_is_finite(ta.get()) || !arb_is_finite(tb.get())) return std::nullopt;
    if (!arb_overlaps(ta.get(), tb.get())) {
        proof_ = Proof::enclosures;
        return false;
    }
    if (try_rational_center_) {
        try_rational_center_ = false;
        if (common_rational_center()) {
            proof_ = Proof::rational_center;
            return true;
        }
    }
    proof_ = Proof::resultants;
    if (!pa_) pa_ = polynomial(a_);
    if (!pb_) pb_ = polynomial(b_);
    // Isolation is tested on widened balls first (k bits): cheap, since exact
    // root counting on an interval with 4000-bit ends is slow, and enough as
    // soon as the widened balls isolate single roots.
    const long finest = std::min(a_.solver->enclosure().precision, b_.solver->enclosure().precision);
    for (long k = 32; k <= finest; k *= 2) {
        Ball wa = ta, wb = tb;
        for (Ball* w : {&wa, &wb}) {
            arb_set_round(w->get(), w->get(), k + 16);  // short ends, so exact counting stays cheap
            Mag r;
            mag_set_ui_2exp_si(r.get(), 1, -k);
            if (mag_cmp(r.get(), arb_radref(w->get())) > 0) mag_set(arb_radref(w->get()), r.get());
        }
        Rational alo, ahi, blo, bhi;
        ball_endpoints(wa, alo, ahi);
        ball_endpoints(wb, blo, bhi);
        if (!isolates_one_root(*pa_, alo, ahi) || !isolates_one_root(*pb_, blo, bhi)) continue;
        // Equal iff the gcd has a root where the two enclosures meet (it
        // divides both, so it vanishes at none of the four ends).
        IntPolynomial g;
        fmpz_poly_gcd(g.get(), pa_->get(), pb_->get());
        if (g.degree() < 1) return false;
        const Rational lo = std::max(alo, blo), hi = std::min(ahi, bhi);
        return lo < hi && count_real_roots(g, lo, hi) > 0;
    }
    return std::nullopt;
}

}  // namespace ellvor
