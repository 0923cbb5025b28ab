#include "subdivision/voronoi_circle_enclosure.hpp"

#include "subdivision/voronoi_circle_guess.hpp"

#include <algorithm>
#include <climits>
#include <cmath>

namespace ellvor {

namespace {

constexpr int kUnknowns = 6;  // t1, t2, t3, rho, x, y
constexpr long kStartPrecision = 64;
constexpr long kGuardBits = 32;
constexpr long kCertifyPrecisionLimit = 1024;

// Bits of accuracy of a ball: relative for |mid| >= 1, absolute below.
long ball_bits(const arb_t x) {
    if (arb_is_exact(x)) return LONG_MAX;
    if (!arb_is_finite(x)) return LONG_MIN;
    if (arf_cmpabs_2exp_si(arb_midref(x), 0) >= 0) return arb_rel_accuracy_bits(x);  // |mid| >= 1
    // rad = m 2^e with m < 1: at least -e correct bits.
    return -fmpz_get_si(MAG_EXPREF(arb_radref(x)));
}

// Largest |entry| exponent of a vector, as bits (0 for entries below 1).
long magnitude_bits(const BallMatrix& v) {
    long m = 0;
    for (long i = 0; i < v.rows(); ++i)
        if (!arb_is_zero(v.at(i, 0))) m = std::max(m, static_cast<long>(arf_abs_bound_lt_2exp_si(arb_midref(v.at(i, 0)))));
    return m;
}

}  // namespace

Ball VoronoiCircleEnclosure::tangency_parameter(int i, long prec) const {
    if (!flipped[i]) return parameter[i];
    Ball t;
    arb_inv(t.get(), parameter[i].get(), prec);
    arb_neg(t.get(), t.get());
    return t;
}

long VoronoiCircleEnclosure::correct_bits() const {
    long bits = LONG_MAX;
    for (const Ball& b : parameter) bits = std::min(bits, ball_bits(b.get()));
    for (const Ball* b : {&radius, &center_x, &center_y}) bits = std::min(bits, ball_bits(b->get()));
    return bits;
}

VoronoiCircleSolver::VoronoiCircleSolver(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3)
    : sites_{&e1, &e2, &e3} {}

namespace {

// F(X) and, when J is given, its Jacobian over the box X.
void tritangent_system(const std::vector<BoundaryChart>& charts, const BallMatrix& X, BallMatrix& F, BallMatrix* J,
                       long prec) {
    const arb_struct* rho = X.at(3, 0);
    Ball tmp;
    for (int i = 0; i < 3; ++i) {
        Ball t;
        arb_set(t.get(), X.at(i, 0));
        const BoundaryChart::Local q = charts[i].evaluate(t, prec, J != nullptr);
        // F = P + rho nu - V
        arb_mul(tmp.get(), rho, q.nx.get(), prec);
        arb_add(F.at(2 * i, 0), q.px.get(), tmp.get(), prec);
        arb_sub(F.at(2 * i, 0), F.at(2 * i, 0), X.at(4, 0), prec);
        arb_mul(tmp.get(), rho, q.ny.get(), prec);
        arb_add(F.at(2 * i + 1, 0), q.py.get(), tmp.get(), prec);
        arb_sub(F.at(2 * i + 1, 0), F.at(2 * i + 1, 0), X.at(5, 0), prec);
        if (!J) continue;
        arb_mul(tmp.get(), rho, q.dnx.get(), prec);
        arb_add(J->at(2 * i, i), q.dpx.get(), tmp.get(), prec);
        arb_mul(tmp.get(), rho, q.dny.get(), prec);
        arb_add(J->at(2 * i + 1, i), q.dpy.get(), tmp.get(), prec);
        arb_set(J->at(2 * i, 3), q.nx.get());
        arb_set(J->at(2 * i + 1, 3), q.ny.get());
        arb_set_si(J->at(2 * i, 4), -1);
        arb_set_si(J->at(2 * i + 1, 5), -1);
    }
}

}  // namespace

// Precision of the Jacobian for a Newton step at precision prec: half is
// enough, since the step only needs half of the bits (quadratic convergence).
long jacobian_precision(long prec) { return std::max(kStartPrecision, prec / 2 + kGuardBits); }

long VoronoiCircleSolver::newton_step(long prec) {
    const long jprec = jacobian_precision(prec);
    BallMatrix F(kUnknowns, 1), Fj(kUnknowns, 1), J(kUnknowns, kUnknowns), step(kUnknowns, 1);
    if (jprec >= prec) {
        tritangent_system(charts_, midpoint_, F, &J, prec);
    } else {
        tritangent_system(charts_, midpoint_, F, nullptr, prec);
        tritangent_system(charts_, midpoint_, Fj, &J, jprec);
    }
    if (!arb_mat_approx_solve(step.get(), J.get(), F.get(), jprec)) return -1;
    for (int j = 0; j < kUnknowns; ++j) {
        arb_sub(midpoint_.at(j, 0), midpoint_.at(j, 0), step.at(j, 0), prec);
        mag_zero(arb_radref(midpoint_.at(j, 0)));
    }
    ++enclosure_.newton_steps;
    // How far below the unknowns' magnitude the step is.
    long step_size = LONG_MIN;
    for (int j = 0; j < kUnknowns; ++j)
        if (!arf_is_zero(arb_midref(step.at(j, 0))))
            step_size = std::max(step_size, static_cast<long>(arf_abs_bound_lt_2exp_si(arb_midref(step.at(j, 0)))));
    if (step_size == LONG_MIN) return prec;
    return magnitude_bits(midpoint_) - step_size;
}

// Krawczyk: K = m - Y F(m) + (I - Y J(X)) (X - m) with Y ~ J(m)^-1. If K lies
// in the interior of X, X holds exactly one root, and it lies in K. Only
// m - Y F(m) needs the full precision: Y is any fixed matrix (here a 128-bit
// approximate inverse), and the last term is of the order of the box radius
// times |I - Y J|, so it is computed in 128-bit balls (rigorous, merely wider).
// The box radius is inflated from the Newton correction Y F(m) itself
// (epsilon-inflation), so ill-conditioned systems get a box that fits them.
bool VoronoiCircleSolver::krawczyk(long prec) {
    constexpr long kLowPrecision = 128;
    const long low = std::min(prec, kLowPrecision);
    BallMatrix Fm(kUnknowns, 1), Flow(kUnknowns, 1), Jm(kUnknowns, kUnknowns), Y(kUnknowns, kUnknowns);
    if (low >= prec) {
        tritangent_system(charts_, midpoint_, Fm, &Jm, prec);
    } else {
        tritangent_system(charts_, midpoint_, Fm, nullptr, prec);
        tritangent_system(charts_, midpoint_, Flow, &Jm, low);
    }
    if (!arb_mat_approx_inv(Y.get(), Jm.get(), kLowPrecision)) return false;
    BallMatrix YF(kUnknowns, 1);
    arb_mat_mul(YF.get(), Y.get(), Fm.get(), prec);

    BallMatrix X = midpoint_;
    for (int j = 0; j < kUnknowns; ++j) {
        Mag r, floor;
        arb_get_mag(r.get(), YF.at(j, 0));
        mag_mul_2exp_si(r.get(), r.get(), 2);
        const long size = arf_is_zero(arb_midref(midpoint_.at(j, 0)))
                              ? 0
                              : std::max(0L, static_cast<long>(arf_abs_bound_lt_2exp_si(arb_midref(midpoint_.at(j, 0)))));
        mag_set_ui_2exp_si(floor.get(), 1, size - prec + kGuardBits / 4);
        mag_add(arb_radref(X.at(j, 0)), r.get(), floor.get());
    }
    BallMatrix F(kUnknowns, 1), J(kUnknowns, kUnknowns), YJ(kUnknowns, kUnknowns), M(kUnknowns, kUnknowns),
        D(kUnknowns, 1), K(kUnknowns, 1);
    tritangent_system(charts_, X, F, &J, low);
    arb_mat_mul(YJ.get(), Y.get(), J.get(), kLowPrecision);
    arb_mat_one(M.get());
    arb_mat_sub(M.get(), M.get(), YJ.get(), kLowPrecision);
    arb_mat_sub(D.get(), X.get(), midpoint_.get(), kLowPrecision);
    arb_mat_mul(K.get(), M.get(), D.get(), kLowPrecision);
    arb_mat_sub(K.get(), K.get(), YF.get(), prec);
    arb_mat_add(K.get(), K.get(), midpoint_.get(), prec);
    for (int j = 0; j < kUnknowns; ++j)
        if (!arb_contains_interior(X.at(j, 0), K.at(j, 0))) return false;
    // The root in K: a counter-clockwise circle of positive radius?
    if (!arb_is_positive(K.at(3, 0))) return false;
    std::array<BoundaryChart::Local, 3> p{};
    for (int i = 0; i < 3; ++i) {
        Ball t;
        arb_set(t.get(), K.at(i, 0));
        p[i] = charts_[i].evaluate(t, kLowPrecision, false);
    }
    Ball ux, uy, vx, vy, orient, tmp;
    arb_sub(ux.get(), p[1].px.get(), p[0].px.get(), kLowPrecision);
    arb_sub(uy.get(), p[1].py.get(), p[0].py.get(), kLowPrecision);
    arb_sub(vx.get(), p[2].px.get(), p[0].px.get(), kLowPrecision);
    arb_sub(vy.get(), p[2].py.get(), p[0].py.get(), kLowPrecision);
    arb_mul(orient.get(), ux.get(), vy.get(), kLowPrecision);
    arb_mul(tmp.get(), uy.get(), vx.get(), kLowPrecision);
    arb_sub(orient.get(), orient.get(), tmp.get(), kLowPrecision);
    if (!arb_is_positive(orient.get())) return false;

    for (int i = 0; i < 3; ++i) arb_set(enclosure_.parameter[i].get(), K.at(i, 0));
    arb_set(enclosure_.radius.get(), K.at(3, 0));
    arb_set(enclosure_.center_x.get(), K.at(4, 0));
    arb_set(enclosure_.center_y.get(), K.at(5, 0));
    enclosure_.precision = prec;
    for (int j = 0; j < kUnknowns; ++j) arb_get_mid_arb(midpoint_.at(j, 0), K.at(j, 0));
    return true;
}

bool VoronoiCircleSolver::certify() {
    if (certified_) return true;
    for_each_voronoi_circle_guess(*sites_[0], *sites_[1], *sites_[2], [&](const VoronoiCircleGuess& guess) {
        return certified_ = certify_from(guess);
    });
    return certified_;
}

bool VoronoiCircleSolver::certify_from(const VoronoiCircleGuess& guess) {
    // Chart: t = tan(theta/2) for |theta| <= pi/2, else u = -1/t = -cot(theta/2).
    charts_.clear();
    enclosure_ = VoronoiCircleEnclosure{};
    for (int i = 0; i < 3; ++i) {
        const double theta = guess.theta[i];
        const bool flipped = std::fabs(theta) > M_PI / 2;
        charts_.emplace_back(*sites_[i], flipped);
        enclosure_.flipped[i] = flipped;
        arb_set_d(midpoint_.at(i, 0), flipped ? -1 / std::tan(theta / 2) : std::tan(theta / 2));
    }
    arb_set_d(midpoint_.at(3, 0), guess.radius);
    arb_set_d(midpoint_.at(4, 0), guess.x);
    arb_set_d(midpoint_.at(5, 0), guess.y);
    // Ill-conditioned triples (huge circles of nearly collinear sites) need
    // more than the start precision before the Krawczyk test can pass.
    for (long prec = kStartPrecision; prec <= kCertifyPrecisionLimit; prec *= 2) {
        // The floating-point guess is good to about 50 bits: one step reaches
        // the start precision; more only when the certificate fails.
        bool singular = false;
        for (int it = 0; it < 4 && !singular; ++it) {
            singular = newton_step(prec) < 0;
            if (!singular && krawczyk(prec)) return true;
        }
    }
    return false;
}

bool VoronoiCircleSolver::refine(long bits) {
    if (!certify()) return false;
    if (enclosure_.correct_bits() >= bits) return true;
    // Newton converges quadratically: one uncertified step per doubling of
    // the precision, then a certificate at the target precision.
    const long target = bits + 2 * kGuardBits + magnitude_bits(midpoint_);
    for (long prec = 2 * enclosure_.precision; prec < target; prec *= 2)
        if (newton_step(prec) < 0) return certified_ = false;
    for (int attempt = 0; attempt < 3; ++attempt) {
        if (newton_step(target) < 0) return certified_ = false;
        if (krawczyk(target) && enclosure_.correct_bits() >= bits) return true;
    }
    return certified_ = false;
}

}  // namespace ellvor
