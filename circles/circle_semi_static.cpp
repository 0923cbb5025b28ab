#include "circles/circle_semi_static.hpp"

#include "circles/semi_static.hpp"

#include <cmath>
#include <optional>
#include <utility>

namespace ellvor {

namespace {

using namespace semi_static;

// A circle site in doubles. Index 0: every parameter an exact double
// (Rational::is_small_dyadic). Index 1: each parameter the double nearest to it
// (rounded_input), x = x^ (1 + t) with |t| <= u, which the lemma of
// semi_static.hpp counts like a rounding.
template <int K>
struct Circle {
    Rounded<K> x, y, r;
};

// The doubles are read off the enclosures: enclose(q) is [down(x^),
// up(x^)] around the nearest double x^ (util/interval.hpp), which is q itself
// for a small dyadic q, so x^ = up(lo).
std::optional<Circle<0>> exact_circle(const Ellipse& e) {
    if (!e.is_dyadic_circle()) return std::nullopt;
    const Ellipse::Enclosure& k = e.enclosure();
    return Circle<0>{exact(Interval::up(k.xc.lo)), exact(Interval::up(k.yc.lo)), exact(Interval::up(k.a.lo))};
}

std::optional<Circle<1>> rounded_circle(const Ellipse& e) {
    if (!e.is_circle()) return std::nullopt;
    const Ellipse::Enclosure& k = e.enclosure();
    Circle<1> c;
    if (!rounded_input(k.xc, c.x) || !rounded_input(k.yc, c.y) || !rounded_input(k.a, c.r)) return std::nullopt;
    return c;
}

// Site c in the lifted space of site o (circle_predicates.hpp): (C - C_o, r - r_o).
// Of exact doubles, a rounded difference (index 1, magnitude |a - b|); of
// rounded ones, a sum of two rounded inputs (index 2, magnitude |a| + |b|).
template <int K>
struct Lifted {
    Rounded<K + 1> x, y, s;
};
Lifted<0> lift(const Circle<0>& c, const Circle<0>& o) {
    return {difference(c.x.value, o.x.value), difference(c.y.value, o.y.value), difference(c.r.value, o.r.value)};
}
Lifted<1> lift(const Circle<1>& c, const Circle<1>& o) { return {c.x - o.x, c.y - o.y, c.r - o.r}; }

// <a, b> = a_x b_x + a_y b_y - a_s b_s; <a, a> is the power |D|^2 - rho^2 of
// the pair, positive iff neither site contains the other.
template <int K>
auto lorentz(const Lifted<K>& a, const Lifted<K>& b) {
    return a.x * b.x + a.y * b.y - a.s * b.s;
}

// The circles tangent to three sites, as TangentCircles of
// circle_predicates.cpp computes them: C1 at the origin, a_i the lifted
// sites, p_i = <a_i, a_i>, g = <a_2, a_3>, p_23 the power of (C2, C3) (from
// their own difference: a smaller index and magnitude than p_2 + p_3 - 2 g),
// k = a_2 x a_3. The lifted circle of orientation o (+1 counter-clockwise) is
//   w = (m + sqrt(rad) n) / (2 <k, k>),   rad = p_2 p_3 p_23,   n = -o k,
//   m = (-M_x, -M_y, M_s),   M = (p_2 - g) p_3 a_2 + (p_3 - g) p_2 a_3,
// and <k, k> = g^2 - p_2 p_3. The indices of semi_static.hpp are in the types
// (at most 54, for the squared InCircle form of rounded inputs); the largest
// magnitude at inputs of 1, that of the squared InCircle form below, is 27216
// < 2^20 (the range of semi_static.hpp).
template <int K>
class TangentCircles {
public:
    // Nothing when the bounds cannot prove the premises of the closed form:
    // every power positive (so rad > 0) and <k, k> != 0 (no common tangent line).
    static std::optional<TangentCircles> of(const Circle<K>& c1, const Circle<K>& c2, const Circle<K>& c3) {
        TangentCircles t(c1, c2, c3);
        if (certain_sign(t.p2_) <= 0 || certain_sign(t.p3_) <= 0 || certain_sign(t.p23_) <= 0) return std::nullopt;
        t.kk_sign_ = certain_sign(t.kk_);
        if (t.kk_sign_ == 0) return std::nullopt;
        return t;
    }

    // +1 when the circle of orientation o is one of signed distances, R +
    // r_i > 0 for the three sites, -1 when not, 0 when unproven (as
    // TangentCircles::circle in circle_predicates.cpp). The lifted s = R + r1
    // is (m_s + sqrt(rad) n_s) / (2 <k, k>); R + r_i = s + rho_i. R > 0, the
    // one sign sites that do not overlap need, proves it; else the site with
    // the smallest radius decides (the doubles of rounded inputs keep the order
    // of the radii except at ties, so every tied site is asked).
    int radius_sign(int o) {
        const auto n_s = o > 0 ? -k_s_ : k_s_;
        const bool positive = height_sign(-c1_.r, n_s) > 0;
        if (o > 0) ccw_radius_positive_ = positive;
        if (positive) return 1;
        const double smallest = std::fmin(c1_.r.value, std::fmin(c2_r_, c3_r_));
        int sign = 1;
        auto require = [&](int s) {
            if (s < 0) sign = -1;
            else if (s == 0 && sign > 0) sign = 0;
        };
        if (c1_.r.value == smallest) require(certain_sign_with_root(m_s_, n_s, rad_) * kk_sign_);
        if (c2_r_ == smallest) require(height_sign(a2_.s, n_s));
        if (c3_r_ == smallest) require(height_sign(a3_.s, n_s));
        return sign;
    }

    // For the counter-clockwise circle: -1 when Q meets its open disk, +1
    // when not, 0 when unproven. Q meets it iff h_Q - a_Q . w < 0, i.e.
    //   sign(p_Q <k, k> + <a_Q, M> + sqrt(rad) a_Q . k) sign(<k, k>) < 0
    // (circle_vertex_conflict in circle_predicates.cpp, divided by 2).
    int conflict_sign(const Circle<K>& q) const {
        const Lifted<K> a = lift(q, c1_);
        // R + r_Q < 0 (an internal circle deeper than Q's radius): no conflict
        // whatever the squares say. Not when R > 0 (radius_sign(1) proved it,
        // as it does for all sites that do not overlap), and R + r_Q > R +
        // r_min > 0 unless Q is smaller.
        if (!ccw_radius_positive_ && q.r.value <= std::fmin(c1_.r.value, std::fmin(c2_r_, c3_r_))) {
            const int height = height_sign(a.s, -k_s_);
            if (height <= 0) return height < 0 ? 1 : 0;
        }
        const auto rational_part = lorentz(a, a) * kk_ + (a.x * m_x_ + a.y * m_y_ - a.s * m_s_);
        const auto root_part = a.x * k_x_ + a.y * k_y_ + a.s * k_s_;
        return certain_sign_with_root(rational_part, root_part, rad_) * kk_sign_;
    }

private:
    // sign(s + rho) for a site of lifted radius rho, on the circle with root part n_s.
    template <class Rho, class RootPart>
    int height_sign(const Rho& rho, const RootPart& n_s) const {
        return certain_sign_with_root(m_s_ + twice(rho * kk_), n_s, rad_) * kk_sign_;
    }

    TangentCircles(const Circle<K>& c1, const Circle<K>& c2, const Circle<K>& c3)
        : c1_(c1), c2_r_(c2.r.value), c3_r_(c3.r.value), a2_(lift(c2, c1)), a3_(lift(c3, c1)), p2_(lorentz(a2_, a2_)), p3_(lorentz(a3_, a3_)),
          p23_(lorentz(lift(c3, c2), lift(c3, c2))), g_(lorentz(a2_, a3_)),
          k_x_(a2_.y * a3_.s - a2_.s * a3_.y), k_y_(a2_.s * a3_.x - a2_.x * a3_.s), k_s_(a2_.x * a3_.y - a2_.y * a3_.x),
          kk_(g_ * g_ - p2_ * p3_), m_x_(factor2() * a2_.x + factor3() * a3_.x),
          m_y_(factor2() * a2_.y + factor3() * a3_.y), m_s_(factor2() * a2_.s + factor3() * a3_.s),
          rad_(p2_ * p3_ * p23_) {}

    using Power = decltype(lorentz(std::declval<Lifted<K>>(), std::declval<Lifted<K>>()));
    using Coordinate = decltype(std::declval<Lifted<K>>().x);
    using Cross = decltype(std::declval<Coordinate>() * std::declval<Coordinate>() -
                           std::declval<Coordinate>() * std::declval<Coordinate>());
    using Factor = decltype((std::declval<Power>() - std::declval<Power>()) * std::declval<Power>());
    auto factor2() const { return (p2_ - g_) * p3_; }
    auto factor3() const { return (p3_ - g_) * p2_; }

    Circle<K> c1_;
    double c2_r_, c3_r_;  // the radii's doubles, to find the smallest
    Lifted<K> a2_, a3_;
    Power p2_, p3_, p23_, g_;
    Cross k_x_, k_y_, k_s_;
    decltype(std::declval<Power>() * std::declval<Power>() - std::declval<Power>() * std::declval<Power>()) kk_;
    decltype(std::declval<Factor>() * std::declval<Coordinate>() + std::declval<Factor>() * std::declval<Coordinate>())
        m_x_, m_y_, m_s_;  // M (the sign of m_x, m_y is in the formulas)
    decltype(std::declval<Power>() * std::declval<Power>() * std::declval<Power>()) rad_;
    int kk_sign_ = 0;
    bool ccw_radius_positive_ = false;  // radius_sign(1) proved R > 0
};

// kappa3 from circles of index K.
template <int K>
Decision<InCircle> incircle_of(const Circle<K>& c1, const Circle<K>& c2, const Circle<K>& c3, const Circle<K>& q) {
    const Decision<InCircle> undecided = Decision<InCircle>::undecided(Stage::filter, 0);
    std::optional<TangentCircles<K>> circles = TangentCircles<K>::of(c1, c2, c3);
    if (!circles) return undecided;
    const int radius = circles->radius_sign(1);
    if (radius < 0) return Decision<InCircle>::decided(InCircle::no_circle, Stage::filter);
    if (radius == 0) return undecided;
    const int s = circles->conflict_sign(q);
    if (s == 0) return undecided;
    return Decision<InCircle>::decided(s < 0 ? InCircle::conflict : InCircle::no_conflict, Stage::filter);
}

}  // namespace

Decision<InCircle> circle_incircle_semi_static(const Ellipse& c1, const Ellipse& c2, const Ellipse& c3,
                                               const Ellipse& q) {
    // Exact doubles first (smaller indices: a tighter bound), else the
    // nearest doubles of the rationals.
    const auto e1 = exact_circle(c1), e2 = exact_circle(c2), e3 = exact_circle(c3), eq = exact_circle(q);
    if (e1 && e2 && e3 && eq) {
        const Decision<InCircle> d = incircle_of(*e1, *e2, *e3, *eq);
        if (d.is_decided()) return d;
    }
    const auto r1 = rounded_circle(c1), r2 = rounded_circle(c2), r3 = rounded_circle(c3), rq = rounded_circle(q);
    if (r1 && r2 && r3 && rq) return incircle_of(*r1, *r2, *r3, *rq);
    return Decision<InCircle>::undecided(Stage::filter, 0);
}

Decision<VoronoiCircles> circle_voronoi_circle_count_semi_static(const Ellipse& c1, const Ellipse& c2,
                                                                 const Ellipse& c3) {
    const Decision<VoronoiCircles> undecided = Decision<VoronoiCircles>::undecided(Stage::filter, 0);
    const auto e1 = exact_circle(c1), e2 = exact_circle(c2), e3 = exact_circle(c3);
    if (!e1 || !e2 || !e3) return undecided;
    std::optional<TangentCircles<0>> circles = TangentCircles<0>::of(*e1, *e2, *e3);
    if (!circles) return undecided;
    const int ccw = circles->radius_sign(1), cw = circles->radius_sign(-1);
    if (ccw == 0 || cw == 0) return undecided;
    const VoronoiCircles count = ccw > 0 ? (cw > 0 ? VoronoiCircles::both : VoronoiCircles::ccw_only)
                                         : (cw > 0 ? VoronoiCircles::cw_only : VoronoiCircles::none);
    return Decision<VoronoiCircles>::decided(count, Stage::filter);
}

Decision<Sign> circle_infinite_vertex_conflict_semi_static(const Ellipse& c1, const Ellipse& c2, const Ellipse& q) {
    const Decision<Sign> undecided = Decision<Sign>::undecided(Stage::filter, 0);
    const auto e1 = exact_circle(c1), e2 = exact_circle(c2), eq = exact_circle(q);
    if (!e1 || !e2 || !eq) return undecided;
    // circle_infinite_vertex_conflict (circle_predicates.cpp): with D = C2 -
    // C1, dr = r1 - r2, e = |D|^2 - dr^2 > 0, D_Q and rho_Q Q's lifted
    // coordinates, Q meets the half-plane iff
    //   dr D . D_Q + rho_Q |D|^2 + sqrt(e) D x D_Q > 0.
    const Lifted<0> d = lift(*e2, *e1), dq = lift(*eq, *e1);
    const auto e = lorentz(d, d);
    if (certain_sign(e) <= 0) return undecided;
    const auto rational_part = -d.s * (d.x * dq.x + d.y * dq.y) + dq.s * (d.x * d.x + d.y * d.y);
    const int side = certain_sign_with_root(rational_part, d.x * dq.y - d.y * dq.x, e);
    if (side == 0) return undecided;
    return Decision<Sign>::decided(side > 0 ? Sign::negative : Sign::positive, Stage::filter);
}

Decision<Sign> circle_side_of_bisector_at_center_semi_static(const Ellipse& c1, const Ellipse& c2,
                                                             const Ellipse& site) {
    const Decision<Sign> undecided = Decision<Sign>::undecided(Stage::filter, 0);
    auto decided = [](int s) { return Decision<Sign>::decided(s > 0 ? Sign::positive : Sign::negative, Stage::filter); };
    const auto e1 = exact_circle(c1), e2 = exact_circle(c2), p = exact_circle(site);
    if (!e1 || !e2 || !p) return undecided;
    // sign(d2 - d1), d_i = sqrt(A_i) - r_i, A_i = |p - C_i|^2, as
    // sign_of_root_difference (side_of_bisector.cpp) decides it exactly:
    // with delta = r2 - r1, sqrt(A_2) - sqrt(A_1) has the sign u of A_2 - A_1;
    // if u and delta have opposite signs, u; else u times the sign of
    // M - 2 sqrt(A_1 A_2), M = A_1 + A_2 - delta^2: -1 if M < 0, else that of
    // M^2 - 4 A_1 A_2. Each sign certain (semi_static.hpp) or undecided.
    auto squared_distance = [&](const Circle<0>& c) {
        const Rounded<1> dx = difference(p->x.value, c.x.value), dy = difference(p->y.value, c.y.value);
        return dx * dx + dy * dy;
    };
    const auto a1 = squared_distance(*e1), a2 = squared_distance(*e2);
    const Rounded<1> delta = difference(e2->r.value, e1->r.value);
    const int u = certain_sign(a2 - a1), d = certain_sign(delta);
    if (u == 0) return undecided;
    if (u != d) return decided(u);  // d = 0 (equal radii) included
    const auto m = a1 + a2 - delta * delta;
    const int sm = certain_sign(m);
    if (sm < 0) return decided(-u);
    if (sm == 0) return undecided;
    const int s = certain_sign(m * m - twice(twice(a1 * a2)));
    if (s == 0) return undecided;
    return decided(u * s);
}

}  // namespace ellvor
