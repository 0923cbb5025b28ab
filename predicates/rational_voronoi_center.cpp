#include "predicates/rational_voronoi_center.hpp"

#include "exact/algebraic_real.hpp"
#include "exact/real_roots.hpp"
#include "sites/ellipse_polynomials.hpp"
#include "util/error.hpp"
#include "util/precision.hpp"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace ellvor {

// One site seen from v.
class RationalCenter::Site {
public:
    // The foot points of v on E (boundary points whose normal passes through
    // v): the real roots of the foot-point quartic, and the i-point when the
    // quartic loses degree. For v outside E the nearest point is one of them,
    // strictly nearer than the others (a convex set has a unique nearest
    // point from outside, and v, outside, is no circle's center: finitely many
    // foot points).
    Site(const Ellipse& e, const Point& v) : e_(e), v_(v), outside_(e.side_of_point(v.x, v.y) > 0) {
        if (!outside_) return;
        const IntPolynomial f = foot_point_quartic(e, v);
        feet_ = real_roots(f);
        i_point_ = f.degree() < 4;
    }

    const Ellipse& ellipse() const { return e_; }
    bool outside() const { return outside_; }

    // The nearest point and its squared distance, enclosed at precision prec;
    // nullopt when that distance is not yet separated from the other foot
    // points'. v outside only.
    struct Nearest {
        BallPoint point;
        Ball squared_distance;
    };
    std::optional<Nearest> nearest(long prec) {
        std::vector<Nearest> candidates;
        for (AlgebraicReal& t : feet_) candidates.push_back({e_.point_at(t.to_ball(prec), prec), Ball()});
        if (i_point_) {
            const Point p = e_.i_point();
            candidates.push_back({{Ball(p.x, prec), Ball(p.y, prec)}, Ball()});
        }
        const Ball vx(v_.x, prec), vy(v_.y, prec);
        for (Nearest& c : candidates) {
            Ball dx, dy;
            arb_sub(dx.get(), c.point.x.get(), vx.get(), prec);
            arb_sub(dy.get(), c.point.y.get(), vy.get(), prec);
            arb_sqr(dx.get(), dx.get(), prec);
            arb_sqr(dy.get(), dy.get(), prec);
            arb_add(c.squared_distance.get(), dx.get(), dy.get(), prec);
        }
        for (const Nearest& c : candidates) {
            bool nearest = true;
            for (const Nearest& other : candidates)
                nearest = nearest && (&other == &c || arb_lt(c.squared_distance.get(), other.squared_distance.get()));
            if (nearest) return c;
        }
        return std::nullopt;
    }

    // d(v, E)^2 exactly: the root of the squared-distance quartic that the
    // nearest point's enclosure isolates (it shrinks to the simple root of the
    // squarefree part, so isolation succeeds; the limit is an internal error).
    AlgebraicReal& squared_distance() {
        if (squared_distance_) return *squared_distance_;
        const IntPolynomial delta = squarefree_part(squared_distance_quartic(e_, v_));
        for (long prec = precision::kStart; prec <= precision::kExactIsolationLimit; prec *= 2) {
            const std::optional<Nearest> n = nearest(prec);
            if (!n) continue;
            Rational lo, hi;
            ball_endpoints(n->squared_distance, lo, hi);
            if (lo == hi) {
                if (sign_at_rational(delta, lo) == 0) return *(squared_distance_ = AlgebraicReal::from_rational(lo));
            } else if (sign_at_rational(delta, lo) != 0 && sign_at_rational(delta, hi) != 0 &&
                       count_real_roots(delta, lo, hi) == 1) {
                return *(squared_distance_ = AlgebraicReal::from_interval(delta, lo, hi));
            }
        }
        throw Error("rational Voronoi center: squared distance not isolated within " +
                    std::to_string(precision::kExactIsolationLimit) + " bits (internal error)");
    }

private:
    const Ellipse& e_;
    const Point& v_;
    const bool outside_;
    std::vector<AlgebraicReal> feet_;
    bool i_point_ = false;
    std::optional<AlgebraicReal> squared_distance_;
};

RationalCenter::RationalCenter(Point v) : v_(std::move(v)) {}
RationalCenter::~RationalCenter() = default;

RationalCenter::Site& RationalCenter::site(const Ellipse& e) {
    for (const std::unique_ptr<Site>& s : sites_)
        if (&s->ellipse() == &e) return *s;
    sites_.push_back(std::make_unique<Site>(e, v_));
    return *sites_.back();
}

bool RationalCenter::is_center_of(const std::array<const Ellipse*, 3>& triple) {
    std::array<Site*, 3> s{};
    for (int i = 0; i < 3; ++i) {
        s[i] = &site(*triple[i]);
        if (!s[i]->outside()) return false;
    }
    for (int i = 1; i < 3; ++i)
        if (compare(s[0]->squared_distance(), s[i]->squared_distance()) != 0) return false;
    // Orientation of the nearest points: nonzero unless two coincide
    // (distinct points of one circle are never collinear), so Arb decides.
    for (long prec = precision::kStart; prec <= precision::kExactIsolationLimit; prec *= 2) {
        std::array<std::optional<Site::Nearest>, 3> n;
        for (int i = 0; i < 3; ++i) n[i] = s[i]->nearest(prec);
        if (!n[0] || !n[1] || !n[2]) continue;
        const BallPoint &p0 = n[0]->point, &p1 = n[1]->point, &p2 = n[2]->point;
        Ball ux, uy, wx, wy, det, cross;
        arb_sub(ux.get(), p1.x.get(), p0.x.get(), prec);
        arb_sub(uy.get(), p1.y.get(), p0.y.get(), prec);
        arb_sub(wx.get(), p2.x.get(), p0.x.get(), prec);
        arb_sub(wy.get(), p2.y.get(), p0.y.get(), prec);
        arb_mul(det.get(), ux.get(), wy.get(), prec);
        arb_mul(cross.get(), uy.get(), wx.get(), prec);
        arb_sub(det.get(), det.get(), cross.get(), prec);
        if (const int sign = det.certain_sign()) return sign > 0;
    }
    return false;
}

std::optional<Rational> simplest_rational_in(const Ball& ball, long max_bits) {
    if (!arb_is_finite(ball.get())) return std::nullopt;
    Rational lo, hi, simplest;
    ball_endpoints(ball, lo, hi);
    fmpq_simplest_between(simplest.get(), lo.get(), hi.get());
    if (simplest.bits() > max_bits) return std::nullopt;
    return simplest;
}

}  // namespace ellvor
