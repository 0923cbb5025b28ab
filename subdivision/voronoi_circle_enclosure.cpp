#include "subdivision/voronoi_circle_enclosure.hpp"

#include "subdivision/bisector_walk_start.hpp"
#include "subdivision/huge_circle_start.hpp"
#include "subdivision/inscribed_disk.hpp"
#include "subdivision/medial_axis_circle.hpp"
#include "subdivision/near_duplicate_pair.hpp"
#include "subdivision/needle_chain.hpp"
#include "subdivision/voronoi_circle_guess.hpp"
#include "sites/mirror_symmetry.hpp"
#include "util/error.hpp"
#include "util/precision.hpp"

#include <algorithm>
#include <climits>
#include <deque>
#include <cmath>
#include <optional>

namespace ellvor {

namespace {

constexpr int kUnknowns = 6;  // t1, t2, t3, rho, x, y
constexpr long kStartPrecision = precision::kStart;
constexpr long kGuardBits = precision::kSolverGuardBits;
// Guesses are tried at 5 precisions (64 .. 1024 bits for sites of moderate
// magnitude), 4 Newton steps each.
constexpr int kGuessLevels = 5;
constexpr int kGuessSteps = 4;
// Search attempts: 3 precisions from the box's, Newton converging within 6
// steps at each.
constexpr int kSearchLevels = 3;
constexpr int kSearchSteps = 6;
constexpr long kStalledNewtonBits = 16;
// Refinement of a certified circle: precision doublings before giving up.
constexpr int kRefineLevels = 4;
// The search for the circle of a nearly coincident pair moved apart
// (certify_near_duplicate): 165 boxes on the crossing triples that need it.
constexpr long kMovedSearchBoxes = 5000;
// Distances the pair is moved apart to: moved_apart_bits, then 2 and 4 bits
// farther.
constexpr int kMovedAttempts = 3;
constexpr long kMovedStepBits = 2;

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

const char* circle_start_name(CircleStart s) {
    switch (s) {
        case CircleStart::guess: return "guess";
        case CircleStart::tangent_line: return "tangent-line";
        case CircleStart::near_duplicate: return "near-duplicate";
        case CircleStart::needle_chain: return "needle-chain";
        case CircleStart::bisector_walk: return "bisector-walk";
        case CircleStart::search: return "search";
    }
    return "?";
}

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

VoronoiCircleSolver::VoronoiCircleSolver(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3,
                                         CommonAxisTangency common_axis_tangency)
    : sites_{&e1, &e2, &e3}, work_sites_{&e1, &e2, &e3}, common_axis_tangency_(common_axis_tangency) {}

void VoronoiCircleSolver::set_frame() {
    if (framed_) return;
    framed_ = true;
    frame_ = SimilarityFrame::for_sites({sites_[0], sites_[1], sites_[2]});
    if (frame_.is_identity()) return;
    framed_sites_.reserve(3);
    for (int i = 0; i < 3; ++i) {
        framed_sites_.push_back(frame_.apply(*sites_[i]));
        work_sites_[i] = &framed_sites_.back();
    }
}

const VoronoiCircleEnclosure& VoronoiCircleSolver::enclosure() const {
    if (frame_.is_identity()) return enclosure_;
    if (!original_) original_ = std::make_unique<VoronoiCircleEnclosure>();
    VoronoiCircleEnclosure& original = *original_;
    original = enclosure_;
    const long prec = std::max(enclosure_.precision, kStartPrecision);
    original.radius = frame_.length_to_original(enclosure_.radius, prec);
    original.center_x = frame_.x_to_original(enclosure_.center_x, prec);
    original.center_y = frame_.y_to_original(enclosure_.center_y, prec);
    return original;
}

std::array<const BoundaryChart*, 3> VoronoiCircleSolver::charts() {
    if (site_charts_.empty()) {
        site_charts_.reserve(6);
        for (const Ellipse* e : work_sites_)
            for (bool f : {false, true}) site_charts_.emplace_back(*e, f);
    }
    std::array<const BoundaryChart*, 3> out{};
    for (int i = 0; i < 3; ++i) out[i] = &site_charts_[2 * i + (enclosure_.flipped[i] ? 1 : 0)];
    return out;
}

namespace {

using Charts = std::array<const BoundaryChart*, 3>;

// F(X) and, when J is given, its Jacobian over the box X.
void tritangent_system(const Charts& charts, const BallMatrix& X, BallMatrix& F, BallMatrix* J, long prec) {
    const arb_struct* rho = X.at(3, 0);
    Ball tmp;
    for (int i = 0; i < 3; ++i) {
        Ball t;
        arb_set(t.get(), X.at(i, 0));
        const BoundaryChart::Local q = charts[i]->evaluate(t, prec, J != nullptr);
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

// det(P2 - P1, P3 - P1) at the chart parameters X(0..2): positive iff the
// tangency points are counter-clockwise. With `of_normals`, det(nu2 - nu1,
// nu3 - nu1) instead: the same sign for every rho != 0 (P_i = V - rho nu_i,
// and a scaling by -rho multiplies the orientation by rho^2), and the only
// one defined at rho = 0.
Ball orientation(const Charts& charts, const BallMatrix& X, long prec, bool of_normals = false) {
    std::array<BoundaryChart::Local, 3> p{};
    for (int i = 0; i < 3; ++i) {
        Ball t;
        arb_set(t.get(), X.at(i, 0));
        p[i] = charts[i]->evaluate(t, prec, false);
    }
    Ball BoundaryChart::Local::*x = of_normals ? &BoundaryChart::Local::nx : &BoundaryChart::Local::px;
    Ball BoundaryChart::Local::*y = of_normals ? &BoundaryChart::Local::ny : &BoundaryChart::Local::py;
    Ball ux, uy, vx, vy, orient;
    arb_sub(ux.get(), (p[1].*x).get(), (p[0].*x).get(), prec);
    arb_sub(uy.get(), (p[1].*y).get(), (p[0].*y).get(), prec);
    arb_sub(vx.get(), (p[2].*x).get(), (p[0].*x).get(), prec);
    arb_sub(vy.get(), (p[2].*y).get(), (p[0].*y).get(), prec);
    arb_mul(orient.get(), ux.get(), vy.get(), prec);
    arb_submul(orient.get(), uy.get(), vx.get(), prec);
    return orient;
}

// rho is the signed distance from V to each site, for rho <= 0 (an internal
// circle of overlapping sites, DESIGN.md §4.1): while -rho stays below the
// site's smallest radius of curvature min(a, b)^2 / max(a, b), the disk of
// radius -rho touching E_i at P_i from inside lies in E_i (Blaschke's rolling
// theorem), so P_i is the boundary point nearest to V; deeper, up to E_i's
// medial axis, disk_inside_ellipse proves the same over the box K.
//
// A center exactly on a site's medial axis touches it at two mirror points,
// and the test fails for that site. When the other two are mirror images
// across an axis-parallel line L that is exactly their bisector and the site
// is its own mirror image across L (symmetric inputs: a needle between two
// equal circles), the two proven signed distances put the true V on L, and
// the test may skip the mirror image of the first foot's neighbourhood
// (disk_inside_ellipse with a mirror, DESIGN.md §4.1). Without such a line,
// center_on_medial_axis may prove V on the site's own major axis (§4.2, "On a
// medial axis"; *on_axis reports it), and the same skip follows.
bool signed_distances(const std::array<const Ellipse*, 3>& sites, const std::array<bool, 3>& flipped,
                      const std::array<const BoundaryChart*, 3>& charts, const BallMatrix& K, long prec,
                      CommonAxisTangency common_axis_tangency, bool* on_axis) {
    *on_axis = false;
    const arb_struct* rho = K.at(3, 0);
    int unproven = -1;
    for (int i = 0; i < 3; ++i) {
        const Ellipse* e = sites[i];
        const bool a_small = e->a() < e->b();
        const Rational& small = a_small ? e->a() : e->b();
        const Rational& large = a_small ? e->b() : e->a();
        Ball limit;
        arb_set_fmpq(limit.get(), (small * small / large).get(), prec);
        arb_add(limit.get(), limit.get(), rho, prec);
        if (arb_is_positive(limit.get())) continue;
        Ball t, r, vx, vy;
        arb_set(t.get(), K.at(i, 0));
        arb_set(r.get(), rho);
        arb_set(vx.get(), K.at(4, 0));
        arb_set(vy.get(), K.at(5, 0));
        if (disk_inside_ellipse(*e, flipped[i], t, r, vx, vy, prec)) continue;
        if (unproven >= 0) return false;
        unproven = i;
    }
    if (unproven < 0) return true;
    const std::optional<AxisLine> line = bisector_line(*sites[(unproven + 1) % 3], *sites[(unproven + 2) % 3]);
    SelfMirror mirror = line ? self_mirror(*sites[unproven], *line) : SelfMirror::none;
    if (mirror == SelfMirror::none) {
        if (!center_on_medial_axis(sites, charts, K, unproven, prec, common_axis_tangency)) return false;
        // The reflection across the major axis: t -> -t for the a-axis, 1/t for the b-axis.
        *on_axis = true;
        mirror = sites[unproven]->b() < sites[unproven]->a() ? SelfMirror::negates_parameter
                                                              : SelfMirror::inverts_parameter;
    }
    Ball t, r, vx, vy;
    arb_set(t.get(), K.at(unproven, 0));
    arb_set(r.get(), rho);
    arb_set(vx.get(), K.at(4, 0));
    arb_set(vy.get(), K.at(5, 0));
    return disk_inside_ellipse(*sites[unproven], flipped[unproven], t, r, vx, vy, prec, nullptr,
                               mirror == SelfMirror::negates_parameter ? AxisMirror::same_chart : AxisMirror::other_chart);
}

// -rho exceeds some site's smaller semi-axis (by the midpoint): no point of
// that site lies so deep, so the root is no Voronoi circle.
bool deeper_than_some_site(const std::array<const Ellipse*, 3>& sites, const arb_t rho) {
    const double depth = -arf_get_d(arb_midref(rho), ARF_RND_NEAR);
    for (const Ellipse* e : sites)
        if (depth > std::min(e->a(), e->b()).to_double()) return true;
    return false;
}

// Precision of the Jacobian for a Newton step at precision prec: half is
// enough, since the step only needs half of the bits (quadratic convergence).
long jacobian_precision(long prec) { return std::max(kStartPrecision, prec / 2 + kGuardBits); }

}  // namespace

long VoronoiCircleSolver::newton_step(long prec) {
    const long jprec = jacobian_precision(prec);
    BallMatrix F(kUnknowns, 1), Fj(kUnknowns, 1), J(kUnknowns, kUnknowns), step(kUnknowns, 1);
    if (jprec >= prec) {
        tritangent_system(charts(), midpoint_, F, &J, prec);
    } else {
        tritangent_system(charts(), midpoint_, F, nullptr, prec);
        tritangent_system(charts(), midpoint_, Fj, &J, jprec);
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
// m - Y F(m) needs the full precision: Y is any fixed matrix (here an
// approximate inverse at a low precision), and the last term is of the order
// of the box radius times |I - Y J|, so it is computed in low-precision balls
// (rigorous, merely wider).
// The box radius is inflated from the Newton correction Y F(m) itself
// (epsilon-inflation), so ill-conditioned systems get a box that fits them.
bool VoronoiCircleSolver::krawczyk(long prec) {
    // The low precision must exceed the bits the system's condition eats:
    // a few times the unknowns' magnitude beyond moderate sizes (a circle R
    // times the sites' size has a Jacobian conditioned like R^2 or worse:
    // Newton stalls ~2 log2 R bits short); two limbs are plenty below that.
    constexpr long kLowPrecision = 128, kModerateBits = 16, kConditionFactor = 4;
    // A nearly coincident pair (certify_near_duplicate) makes |Y| about
    // 2^condition_bits_: Y J(X) needs that many bits more.
    const long low = std::min(prec, std::max(condition_bits_, kConditionFactor * std::max(0L, magnitude_bits(midpoint_) -
                                                                                                   kModerateBits)) +
                                        kLowPrecision);
    BallMatrix Fm(kUnknowns, 1), Flow(kUnknowns, 1), Jm(kUnknowns, kUnknowns), Y(kUnknowns, kUnknowns);
    if (low >= prec) {
        tritangent_system(charts(), midpoint_, Fm, &Jm, prec);
    } else {
        tritangent_system(charts(), midpoint_, Fm, nullptr, prec);
        tritangent_system(charts(), midpoint_, Flow, &Jm, low);
    }
    // Y at two limbs at least, even for a 64-bit certificate: a Y good to
    // 64 bits leaves K's midpoint a rounding off roots with short binary
    // representations (the paper's set (1): radius exactly 1), and every
    // later Newton step then works on full-length mantissas (1.4x slower).
    if (!arb_mat_approx_inv(Y.get(), Jm.get(), std::max(low, kLowPrecision))) return false;
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
    tritangent_system(charts(), X, F, &J, low);
    arb_mat_mul(YJ.get(), Y.get(), J.get(), low);
    arb_mat_one(M.get());
    arb_mat_sub(M.get(), M.get(), YJ.get(), low);
    arb_mat_sub(D.get(), X.get(), midpoint_.get(), low);
    arb_mat_mul(K.get(), M.get(), D.get(), low);
    arb_mat_sub(K.get(), K.get(), YF.get(), prec);
    arb_mat_add(K.get(), K.get(), midpoint_.get(), prec);
    for (int j = 0; j < kUnknowns; ++j)
        if (!arb_contains_interior(X.at(j, 0), K.at(j, 0))) return false;
    bool on_axis = false;
    // The root in K: a counter-clockwise circle of positive radius?
    if (arb_is_positive(K.at(3, 0))) {
        // The tangency points' coordinates cancel in the orientation: it needs
        // their magnitude's bits on top of the low precision.
        // (And, for a nearly coincident pair, the closeness of its points.)
        const long orientation_prec = std::min(prec, kLowPrecision + magnitude_bits(midpoint_) + condition_bits_);
        if (!arb_is_positive(orientation(charts(), K, orientation_prec).get())) return false;
    } else {
        // An internal circle of overlapping sites (rho < 0), or one of radius
        // 0 where three boundaries meet: rho must be the signed distance to
        // each site, and the tangency points, V + |rho| nu_i, are
        // counter-clockwise iff the normals are (at rho = 0 only the normals
        // tell).
        if (!signed_distances(work_sites_, enclosure_.flipped, charts(), K, prec, common_axis_tangency_, &on_axis))
            return false;
        if (!arb_is_positive(orientation(charts(), K, prec, true).get())) return false;
    }

    for (int i = 0; i < 3; ++i) arb_set(enclosure_.parameter[i].get(), K.at(i, 0));
    arb_set(enclosure_.radius.get(), K.at(3, 0));
    arb_set(enclosure_.center_x.get(), K.at(4, 0));
    arb_set(enclosure_.center_y.get(), K.at(5, 0));
    enclosure_.precision = prec;
    enclosure_.on_medial_axis = on_axis;
    for (int j = 0; j < kUnknowns; ++j) arb_get_mid_arb(midpoint_.at(j, 0), K.at(j, 0));
    return true;
}

long VoronoiCircleSolver::start_precision() {
    if (magnitude_bits_ < 0) magnitude_bits_ = site_magnitude_bits(*work_sites_[0], *work_sites_[1], *work_sites_[2]);
    return kStartPrecision + std::max(0L, magnitude_bits_ - kGuardBits);
}

bool VoronoiCircleSolver::certify() {
    if (certified_) return true;
    return certify_from_starts() || certify_by_search();
}

bool VoronoiCircleSolver::certify_from_starts() {
    if (certified_) return true;
    set_frame();
    for_each_voronoi_circle_guess(*work_sites_[0], *work_sites_[1], *work_sites_[2], [&](const VoronoiCircleGuess& guess) {
        return certified_ = certify_from(guess);
    });
    if (certified_) return true;
    for_each_huge_circle_start(*work_sites_[0], *work_sites_[1], *work_sites_[2], precision::kHugeCircleBits,
                               [&](const VoronoiCircleStart& start) { return certified_ = certify_from(start); });
    if (certified_) {
        enclosure_.found_by = CircleStart::tangent_line;
        return true;
    }
    if ((certified_ = certify_near_duplicate())) {
        enclosure_.found_by = CircleStart::near_duplicate;
        return true;
    }
    for_each_bisector_walk_circle(*work_sites_[0], *work_sites_[1], *work_sites_[2],
                                  [&](const VoronoiCircleGuess& guess) { return certified_ = certify_from(guess); });
    if (certified_) {
        enclosure_.found_by = CircleStart::bisector_walk;
        return true;
    }
    if ((certified_ = certify_from_needle_chains())) enclosure_.found_by = CircleStart::needle_chain;
    return certified_;
}

bool VoronoiCircleSolver::certify_by_needle_chains() {
    if (certified_) return true;
    set_frame();
    if ((certified_ = certify_from_needle_chains())) enclosure_.found_by = CircleStart::needle_chain;
    return certified_;
}

bool VoronoiCircleSolver::certify_from_needle_chains() {
    const std::optional<int> needle = thinnest_needle(*work_sites_[0], *work_sites_[1], *work_sites_[2]);
    return needle && (certify_along_needle_chain(*needle, NeedleChain::thicker) ||
                      certify_along_needle_chain(*needle, NeedleChain::shorter));
}

bool VoronoiCircleSolver::certify_along_needle_chain(int i, NeedleChain chain) {
    const Ellipse& site = *work_sites_[i];
    const long aspect = aspect_bits(site);
    // The stout end of the chain: its own starts, else a short search (a few
    // hundred boxes at aspect 2^4); no circle there, or the search's cap,
    // leaves the triple to the search. The links' sites are this solver's,
    // near the unit: their frame is the identity. (A deque: the solvers keep
    // pointers to their sites.)
    std::array<const Ellipse*, 3> sites = work_sites_;
    std::deque<Ellipse> links{needle_link(site, chain, kStoutNeedleBits)};
    sites[i] = &links.back();
    auto previous = std::make_unique<VoronoiCircleSolver>(*sites[0], *sites[1], *sites[2], common_axis_tangency_);
    previous->set_frame();
    if (!previous->frame().is_identity()) return false;
    if (!previous->certify_from_starts()) {
        VoronoiCircleSearchOptions capped;
        capped.max_boxes = kMovedSearchBoxes;
        try {
            if (!previous->certify_by_search(capped)) return false;
        } catch (const Error&) {
            return false;
        }
    }
    // Each link: the needle's contact carried over (needle_chain.hpp; the
    // second map if the first fails), the rest as the last circle has them.
    const long prec = start_precision();
    for (long bits = kStoutNeedleBits; bits < aspect;) {
        bits = std::min(aspect, std::max(bits + 2, bits * 3 / 2));
        const bool last = bits == aspect;
        const Ellipse& from = links.back();
        const Ellipse& to = last ? site : links.emplace_back(needle_link(site, chain, bits));
        sites[i] = &to;
        std::unique_ptr<VoronoiCircleSolver> next;
        if (!last) {
            next = std::make_unique<VoronoiCircleSolver>(*sites[0], *sites[1], *sites[2], common_axis_tangency_);
            next->set_frame();
            if (!next->frame().is_identity()) return false;
        }
        VoronoiCircleSolver& solver = last ? *this : *next;
        const VoronoiCircleEnclosure& c = previous->enclosure_;
        bool certified = false;
        for (ContactMap map : contact_maps(from, chain, c.flipped[i], c.parameter[i], prec)) {
            VoronoiCircleStart start;
            start.flipped = c.flipped;
            start.precision = prec;
            for (int k = 0; k < 3; ++k) arb_get_mid_arb(start.parameter[k].get(), c.parameter[k].get());
            carry_contact(from, to, map, start.flipped[i], start.parameter[i], prec);
            arb_get_mid_arb(start.radius.get(), c.radius.get());
            arb_get_mid_arb(start.center_x.get(), c.center_x.get());
            arb_get_mid_arb(start.center_y.get(), c.center_y.get());
            if ((certified = solver.certify_from(start))) break;
        }
        if (!certified) return false;
        if (last) return true;
        previous = std::move(next);
    }
    return false;
}

bool VoronoiCircleSolver::certify_near_duplicate() {
    const std::optional<NearDuplicatePair> pair =
        closest_near_duplicate_pair(*work_sites_[0], *work_sites_[1], *work_sites_[2], kNearDuplicateBits);
    if (!pair) return false;
    // A moved triple that the guesses do not certify may well be certified a
    // little farther apart (a pair at 2^-19: 2^-9 failed in one rotation, 2^-8
    // did); each try costs a solver of the moved triple.
    for (int attempt = 0; attempt < kMovedAttempts; ++attempt) {
        const long moved_bits = moved_apart_bits(pair->bits) - kMovedStepBits * attempt;
        if (moved_bits < kMovedGapBits / 2) break;
        if (certify_from_moved_pair(*pair, moved_bits)) return true;
    }
    return false;
}

bool VoronoiCircleSolver::certify_from_moved_pair(const NearDuplicatePair& pair, long moved_bits) {
    const int i = pair.first, j = pair.second;
    // The pair moved apart to about 2^-moved_bits of its size: E_i + mu (E_j - E_i).
    Rational mu(1);
    fmpq_mul_2exp(mu.get(), mu.get(), static_cast<unsigned long>(pair.bits - moved_bits));
    const Ellipse moved = ellipse_moved_apart(*work_sites_[i], *work_sites_[j], mu);
    std::array<const Ellipse*, 3> sites = work_sites_;
    sites[j] = &moved;
    VoronoiCircleSolver apart(*sites[0], *sites[1], *sites[2], common_axis_tangency_);
    if (!apart.certify_from_starts()) {
        // Internal circles of a crossing third site are often found by the
        // search only; moved apart, it takes a few hundred boxes. A search that
        // proves no circle, or stops at this cap, leaves the triple to ours.
        VoronoiCircleSearchOptions capped;
        capped.max_boxes = kMovedSearchBoxes;
        try {
            if (!apart.certify_by_search(capped)) return false;
        } catch (const Error&) {
            return false;
        }
    }
    const VoronoiCircleEnclosure& c = apart.enclosure();  // in this solver's frame
    // Two kinds of circle. Contacts on E_i and E_j that nearly coincide (all
    // external circles): the blown-up unknowns, t_j = t_i + mu^-1 (t_j(mu) -
    // t_i(mu)) in E_i's chart, the others as they are (all O(2^-moved_bits)
    // off). Contacts apart (an internal circle centered near E_i's medial
    // axis, touching E_i and E_j at nearly mirror points): a regular root,
    // which moves by O(2^-moved_bits) only; the moved circle is the start.
    // Newton and Krawczyk need twice the pair's closeness, and a circle R
    // times the sites' size (about 1 in this frame) is conditioned like R^2
    // on top (fuzz F9: the pair 2^-66 apart and R ~ 2^130 failed at 250 bits).
    const long radius_bits = std::max(0L, static_cast<long>(arf_abs_bound_lt_2exp_si(arb_midref(c.radius.get()))));
    const long prec = start_precision() + 2 * pair.bits + 2 * radius_bits;
    std::array<Ball, 3> parameter;
    std::array<bool, 3> flipped = c.flipped;
    for (int k = 0; k < 3; ++k) arb_get_mid_arb(parameter[k].get(), c.parameter[k].get());
    Ball other(parameter[j]), offset, mu_ball;
    if (flipped[j] != flipped[i]) {  // t = -1/u
        arb_inv(other.get(), other.get(), prec);
        arb_neg(other.get(), other.get());
    }
    arb_sub(offset.get(), other.get(), parameter[i].get(), prec);
    const long same_contact_bits = moved_bits / 2;
    if (arf_cmpabs_2exp_si(arb_midref(offset.get()), -same_contact_bits) < 0) {
        arb_set_fmpq(mu_ball.get(), mu.get(), prec);
        arb_div(offset.get(), offset.get(), mu_ball.get(), prec);
        arb_add(parameter[j].get(), parameter[i].get(), offset.get(), prec);
        arb_get_mid_arb(parameter[j].get(), parameter[j].get());
        flipped[j] = flipped[i];
    }
    Ball radius, center_x, center_y;
    arb_get_mid_arb(radius.get(), c.radius.get());
    arb_get_mid_arb(center_x.get(), c.center_x.get());
    arb_get_mid_arb(center_y.get(), c.center_y.get());
    start_at(flipped, parameter, radius, center_x, center_y);
    condition_bits_ = pair.bits;
    // Newton from 2^-moved_bits doubles the correct bits a step: a handful of
    // steps reach the box width the certificate needs (below 2^-bits).
    constexpr int kLevels = 2, kSteps = 8;
    if (certify_here(prec, kLevels, kSteps)) return true;
    condition_bits_ = 0;
    return false;
}

bool VoronoiCircleSolver::certify_near(const std::array<bool, 3>& flipped, const std::array<double, 6>& x) {
    if (certified_) return true;
    set_frame();
    // In a similarity frame the point would have to be mapped: rare, the
    // guesses do it then.
    if (frame_.is_identity()) {
        std::array<Ball, 3> parameter;
        for (int i = 0; i < 3; ++i) arb_set_d(parameter[i].get(), x[i]);
        Ball radius, center_x, center_y;
        arb_set_d(radius.get(), x[3]);
        arb_set_d(center_x.get(), x[4]);
        arb_set_d(center_y.get(), x[5]);
        start_at(flipped, parameter, radius, center_x, center_y);
        if ((certified_ = certify_here(start_precision(), kGuessLevels, kGuessSteps))) return true;
    }
    return certify();
}

bool VoronoiCircleSolver::certify_from_tangent_lines() {
    if (certified_) return true;
    set_frame();
    for_each_huge_circle_start(*work_sites_[0], *work_sites_[1], *work_sites_[2], precision::kHugeCircleBits,
                               [&](const VoronoiCircleStart& start) { return certified_ = certify_from(start); });
    if (certified_) enclosure_.found_by = CircleStart::tangent_line;
    return certified_;
}

bool VoronoiCircleSolver::certify_by_search(const VoronoiCircleSearchOptions& options) {
    set_frame();
    const VoronoiCircleSearchResult result = search_voronoi_circle(
        *work_sites_[0], *work_sites_[1], *work_sites_[2], [&](const VoronoiCircleStart& start) { return certify_from(start); },
        options);
    certified_ = result.found;
    if (!certified_) enclosure_ = VoronoiCircleEnclosure{};
    enclosure_.found_by = CircleStart::search;
    enclosure_.search_boxes = result.boxes;
    return certified_;
}

void VoronoiCircleSolver::start_at(const std::array<bool, 3>& flipped, const std::array<Ball, 3>& parameter,
                                   const Ball& radius, const Ball& center_x, const Ball& center_y) {
    enclosure_ = VoronoiCircleEnclosure{};
    enclosure_.flipped = flipped;
    for (int i = 0; i < 3; ++i) arb_set(midpoint_.at(i, 0), parameter[i].get());
    arb_set(midpoint_.at(3, 0), radius.get());
    arb_set(midpoint_.at(4, 0), center_x.get());
    arb_set(midpoint_.at(5, 0), center_y.get());
}

bool VoronoiCircleSolver::certify_here(long first, int levels, int steps) {
    long prec = first;
    for (int level = 0; level < levels; ++level, prec *= 2)
        for (int it = 0; it < steps; ++it) {
            if (newton_step(prec) < 0) break;  // singular here: try a higher precision
            if (krawczyk(prec)) return true;
        }
    return false;
}

bool VoronoiCircleSolver::certify_from(const VoronoiCircleGuess& guess) {
    // Chart: t = tan(theta/2) for |theta| <= pi/2, else u = -1/t = -cot(theta/2).
    std::array<bool, 3> flipped{};
    std::array<Ball, 3> parameter;
    for (int i = 0; i < 3; ++i) {
        const double theta = guess.theta[i];
        flipped[i] = std::fabs(theta) > M_PI / 2;
        arb_set_d(parameter[i].get(), flipped[i] ? -1 / std::tan(theta / 2) : std::tan(theta / 2));
    }
    // The guess's center is relative to E1's center: add it back exactly
    // (then round to the start precision, which covers the sites' magnitude).
    const long first = start_precision();
    Ball radius, center_x(work_sites_[0]->xc(), first), center_y(work_sites_[0]->yc(), first), offset;
    arb_set_d(radius.get(), guess.radius);
    arb_set_d(offset.get(), guess.x);
    arb_add(center_x.get(), center_x.get(), offset.get(), first);
    arb_get_mid_arb(center_x.get(), center_x.get());
    arb_set_d(offset.get(), guess.y);
    arb_add(center_y.get(), center_y.get(), offset.get(), first);
    arb_get_mid_arb(center_y.get(), center_y.get());
    start_at(flipped, parameter, radius, center_x, center_y);
    // Ill-conditioned triples (huge circles of nearly collinear sites) need
    // more than the start precision before the Krawczyk test can pass. The
    // floating-point guess is good to about 50 bits: one step reaches the
    // start precision; more only when the certificate fails.
    return certify_here(first, kGuessLevels, kGuessSteps);
}

bool VoronoiCircleSolver::certify_from(const VoronoiCircleStart& start) {
    start_at(start.flipped, start.parameter, start.radius, start.center_x, start.center_y);
    long prec = std::max(start.precision, start_precision());
    for (int level = 0; level < kSearchLevels; ++level, prec *= 2) {
        // Near a regular root every Newton step gains bits until rounding
        // stops it (an ill-conditioned root: below prec - kGuardBits); far
        // from one Newton wanders: give up rather than spend a certificate.
        long step = 0;
        for (int it = 0; it < kSearchSteps && step < prec - kGuardBits; ++it) {
            const long previous = step;
            if ((step = newton_step(prec)) < 0) return false;
            if (it > 0 && step <= previous) break;
        }
        // Converged to some bits and then stalled: rounding, not distance, stopped
        // Newton (an ill-conditioned root: a huge circle of nearly collinear
        // sites); the next level's precision resolves it.
        if (step < prec / 2) {
            if (step >= kStalledNewtonBits) continue;
            return false;
        }
        // A root of the wrong kind (clockwise, or deeper than any point of a
        // site, its smaller semi-axis) would fail Krawczyk's final test: skip
        // it cheaply. Near rho = 0 the points' orientation is rho^2 times the
        // normals' and drowns in rounding: either one positive lets it through.
        if (arf_sgn(arb_midref(midpoint_.at(3, 0))) > 0) {
            if (arf_sgn(arb_midref(orientation(charts(), midpoint_, prec).get())) <= 0 &&
                arf_sgn(arb_midref(orientation(charts(), midpoint_, prec, true).get())) <= 0)
                return false;
        } else if (deeper_than_some_site(work_sites_, midpoint_.at(3, 0)) ||
                   arf_sgn(arb_midref(orientation(charts(), midpoint_, prec, true).get())) <= 0) {
            return false;
        }
        if (krawczyk(prec)) return true;
    }
    return false;
}

bool VoronoiCircleSolver::refine(long bits) {
    if (!certify()) return false;
    if (enclosure_.correct_bits() >= bits) return true;
    // Newton converges quadratically: one uncertified step per doubling of
    // the precision, then a certificate at the target precision; should that
    // fail, again from the certified midpoint at twice the target.
    const BallMatrix certified_midpoint = midpoint_;
    // A nearly coincident pair needs twice its closeness for a certificate.
    long target = std::max(bits + 2 * kGuardBits + magnitude_bits(midpoint_), 2 * condition_bits_ + kStartPrecision);
    for (int level = 0; level < kRefineLevels; ++level, target *= 2) {
        midpoint_ = certified_midpoint;
        bool singular = false;
        for (long prec = 2 * enclosure_.precision; prec < target && !singular; prec *= 2)
            singular = newton_step(prec) < 0;
        for (int attempt = 0; attempt < 3 && !singular; ++attempt) {
            singular = newton_step(target) < 0;
            if (!singular && krawczyk(target) && enclosure_.correct_bits() >= bits) return true;
        }
    }
    throw Error("VoronoiCircleSolver: a certified Voronoi circle could not be refined to " + std::to_string(bits) +
                " bits (internal error)");
}

void VoronoiCircleSolver::release_charts() {
    std::vector<BoundaryChart>().swap(site_charts_);
}

void VoronoiCircleSolver::refine_existing(long bits) {
    if (!refine(bits))
        throw Error("VoronoiCircleSolver: the search proved that a triple known to have a counter-clockwise Voronoi "
                    "circle has none (internal error)");
}

}  // namespace ellvor
