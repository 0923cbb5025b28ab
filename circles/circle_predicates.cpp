#include "circles/circle_predicates.hpp"

#include "util/error.hpp"

#include <initializer_list>
#include <string>

namespace ellvor {

namespace {

// Every predicate here is invariant under translation and under scaling by a
// positive factor, so the sites are scaled by the least common multiple of
// their denominators and everything runs in integers: no fraction is ever
// reduced (FLINT's gcds dominated the cost of the rational version).

// A vector (x, y, s) of the lifted space (circle_predicates.hpp).
using Lifted = std::array<Integer, 3>;

void require_circle(const Ellipse& e, const char* who) {
    if (!e.is_circle()) throw Error(std::string(who) + ": site " + e.str() + " is not a circle");
}

bool same_circle(const Ellipse& p, const Ellipse& q) {
    return &p == &q || (p.xc() == q.xc() && p.yc() == q.yc() && p.a() == q.a());
}

// l = the least common multiple of the denominators of the sites' centers
// and radii (1 for integer sites).
void common_denominator(Integer& l, std::initializer_list<const Ellipse*> sites) {
    fmpz_one(l.get());
    for (const Ellipse* e : sites)
        for (const Rational* q : {&e->xc(), &e->yc(), &e->a()})
            if (!q->is_integer()) fmpz_lcm(l.get(), l.get(), fmpq_denref(q->get()));
}

// out = q l, an integer because l is a multiple of q's denominator.
void scale_exactly(Integer& out, const Rational& q, const Integer& l) {
    if (q.is_integer()) {
        fmpz_mul(out.get(), fmpq_numref(q.get()), l.get());
        return;
    }
    fmpz_divexact(out.get(), l.get(), fmpq_denref(q.get()));
    fmpz_mul(out.get(), out.get(), fmpq_numref(q.get()));
}

// The circle c scaled by l: (l x, l y, l r).
void scale_circle(Lifted& out, const Ellipse& c, const Integer& l) {
    scale_exactly(out[0], c.xc(), l);
    scale_exactly(out[1], c.yc(), l);
    scale_exactly(out[2], c.a(), l);
}

// a = l c - origin: the scaled site in the lifted frame of the scaled origin.
void lift_site(Lifted& a, const Ellipse& c, const Integer& l, const Lifted& origin) {
    scale_circle(a, c, l);
    for (int i = 0; i < 3; ++i) fmpz_sub(a[i].get(), a[i].get(), origin[i].get());
}

// r = x . y (Euclidean).
void dot(Integer& r, const Lifted& x, const Lifted& y) {
    fmpz_mul(r.get(), x[0].get(), y[0].get());
    fmpz_addmul(r.get(), x[1].get(), y[1].get());
    fmpz_addmul(r.get(), x[2].get(), y[2].get());
}
// r = <b_x, b_y> for b = (a_x, a_y, -a_s): a_x . a_y in the plane minus the
// product of the radius differences. <b, b> = |D|^2 - rho^2 is the power p
// = 2 h of the site (circle_predicates.hpp).
void lorentz_of_sites(Integer& r, const Lifted& x, const Lifted& y) {
    fmpz_mul(r.get(), x[0].get(), y[0].get());
    fmpz_addmul(r.get(), x[1].get(), y[1].get());
    fmpz_submul(r.get(), x[2].get(), y[2].get());
}
// r = u v - w z
void det2(Integer& r, const Integer& u, const Integer& v, const Integer& w, const Integer& z) {
    fmpz_mul(r.get(), u.get(), v.get());
    fmpz_submul(r.get(), w.get(), z.get());
}

// sign(s + rho / f) for the lifted circle s = (m_s + sqrt(radicand) n_s) /
// denominator: the sign of R + r for a site of lifted radius rho = r - r1,
// scaled like s times f (f > 0), i.e. whether V lies on that site's nappe of
// the cone.
int lifted_height_sign(const Lifted& m, const Lifted& n, const Integer& denominator, const Integer& radicand,
                       const Integer& rho, const Integer& f) {
    Integer base, root;
    fmpz_mul(base.get(), rho.get(), denominator.get());
    fmpz_addmul(base.get(), m[2].get(), f.get());
    fmpz_mul(root.get(), n[2].get(), f.get());
    return sign_of_quadratic(base, root, radicand) * denominator.sign();
}

// The lifted circles tangent to three sites, in the scaled frame of C1: the
// points w of the line {a_2 . w = h_2, a_3 . w = h_3} on the cone <w, w> = 0
// (circle_predicates.hpp), given as w = (m + sqrt(radicand) n) / denominator.
//
// Main case, <k, k> != 0: b_2 = (D_2, -rho_2), b_3 and k = a_2 x a_3 are a
// basis with k Lorentz-orthogonal to b_2, b_3 (<b_i, k> = a_i . k = 0). In
// w = alpha b_2 + beta b_3 + t k the two equations fix (alpha, beta) through
// the Gram matrix [[p_2, g], [g, p_3]] (p_i = <b_i, b_i> = 2 h_i, g = <b_2,
// b_3>) and the cone fixes t^2. With p_23 = p_2 + p_3 - 2 g (the power of
// C3 seen from C2) and <k, k> = g^2 - p_2 p_3 (Lagrange's identity with the
// Lorentz sign) this is
//   w = -(p_3 (p_2 - g) b_2 + p_2 (p_3 - g) b_3 +- sqrt(p_2 p_3 p_23) k) / (2 <k, k>),
// symmetric, without any pivot, and the radicand is positive for every
// valid triple. <w, k> = t <k, k>: the counter-clockwise circle takes t <k,
// k> < 0, the "+" above.
//
// <k, k> = 0 (a common tangent line): the quadratic in t along w = p + t k
// is linear, 2 <p, k> t + <p, p> = 0, one root (the other circle became the
// line), of orientation -sign <p, k>. The pivot of the linear system that
// gives p is s: <k, k> = 0 with k_s = 0 forces k = 0 (rank 1), which leaves
// no circle.
class TangentCircles {
public:
    TangentCircles(const Ellipse& c1, const Ellipse& c2, const Ellipse& c3) {
        common_denominator(scale, {&c1, &c2, &c3});
        scale_circle(origin, c1, scale);
        lift_site(a2_, c2, scale, origin);
        lift_site(a3_, c3, scale, origin);
        lorentz_of_sites(p2_, a2_, a2_);
        lorentz_of_sites(p3_, a3_, a3_);
        lorentz_of_sites(g_, a2_, a3_);
        fmpz_add(p23_.get(), p2_.get(), p3_.get());
        fmpz_submul_ui(p23_.get(), g_.get(), 2);
        if (p2_.sign() <= 0 || p3_.sign() <= 0 || p23_.sign() <= 0)
            throw Error("circle predicates: one site lies inside another (" + c1.str() + " / " + c2.str() + " / " +
                        c3.str() + ")");
        det2(k_[0], a2_[1], a3_[2], a2_[2], a3_[1]);
        det2(k_[1], a2_[2], a3_[0], a2_[0], a3_[2]);
        det2(k_[2], a2_[0], a3_[1], a2_[1], a3_[0]);
        det2(kk_, g_, g_, p2_, p3_);
    }

    // The circle of this orientation (+1 counter-clockwise, -1 clockwise)
    // if it has R > 0; false when there is none.
    bool circle(int orientation, Lifted& m, Lifted& n, Integer& denominator, Integer& radicand) const {
        if (!kk_.is_zero()) {
            Integer c2, c3;
            fmpz_sub(c2.get(), p2_.get(), g_.get());
            fmpz_mul(c2.get(), c2.get(), p3_.get());
            fmpz_sub(c3.get(), p3_.get(), g_.get());
            fmpz_mul(c3.get(), c3.get(), p2_.get());
            for (int i = 0; i < 3; ++i) {
                fmpz_mul(m[i].get(), c2.get(), a2_[i].get());
                fmpz_addmul(m[i].get(), c3.get(), a3_[i].get());
                if (i < 2) fmpz_neg(m[i].get(), m[i].get());  // b = (a_x, a_y, -a_s)
                if (orientation > 0) fmpz_neg(n[i].get(), k_[i].get());
                else fmpz_set(n[i].get(), k_[i].get());
            }
            fmpz_mul_2exp(denominator.get(), kk_.get(), 1);
            fmpz_mul(radicand.get(), p2_.get(), p3_.get());
            fmpz_mul(radicand.get(), radicand.get(), p23_.get());
        } else if (!on_tangent_line(orientation, m, n, denominator, radicand)) {
            return false;
        }
        // A circle of signed distances: |V - C_i| = R + r_i needs R + r_i > 0
        // for every site, i.e. for the smallest, s + min(0, rho_2, rho_3) > 0
        // (for sites that do not overlap R > 0 follows: V outside all three).
        const Integer& lowest = fmpz_cmp(a2_[2].get(), a3_[2].get()) < 0 ? a2_[2] : a3_[2];
        return lifted_height_sign(m, n, denominator, radicand, lowest.sign() < 0 ? lowest : Integer(0), Integer(1)) > 0;
    }

    Integer scale;   // of the sites
    Lifted origin;   // C1 scaled

private:
    // <k, k> = 0: the one root, if it has this orientation.
    bool on_tangent_line(int orientation, Lifted& m, Lifted& n, Integer& denominator, Integer& radicand) const {
        // <k, k> = k_x^2 + k_y^2 - k_s^2 = 0 with k_s = 0 forces k = 0.
        if (k_[2].is_zero()) return false;  // rank 1: parallel planes (circle_predicates.hpp)
        // The point p of the line with p_s = 0, by Cramer's rule on
        // a_2 . p = p_2 / 2, a_3 . p = p_3 / 2 (determinant k_s): q = 2 k_s p
        // is an integer vector.
        Lifted q;
        det2(q[0], p2_, a3_[1], a2_[1], p3_);
        det2(q[1], a2_[0], p3_, p2_, a3_[0]);
        Integer qk, qq;  // <q, k>, <q, q>
        fmpz_mul(qk.get(), q[0].get(), k_[0].get());
        fmpz_addmul(qk.get(), q[1].get(), k_[1].get());
        fmpz_mul(qq.get(), q[0].get(), q[0].get());
        fmpz_addmul(qq.get(), q[1].get(), q[1].get());
        // <p, k> = 0 as well would make the line parallel to a generator in
        // the cone's tangent plane; writing b_2, b_3, p in a basis (k, e) of
        // that plane shows it forces p_23 = 0, which the constructor excludes.
        if (qk.is_zero()) throw Error("circle predicates: a tangent line without a root (internal error)");
        if (-qk.sign() * k_[2].sign() != orientation) return false;
        // t = -<q, q> / (2 <q, k>) along q / (2 k_s) + t k:
        //   w = (2 <q, k> q - <q, q> k) / (4 k_s <q, k>).
        for (int i = 0; i < 3; ++i) {
            fmpz_mul(m[i].get(), qk.get(), q[i].get());
            fmpz_mul_2exp(m[i].get(), m[i].get(), 1);
            fmpz_submul(m[i].get(), qq.get(), k_[i].get());
            fmpz_zero(n[i].get());
        }
        fmpz_mul(denominator.get(), k_[2].get(), qk.get());
        fmpz_mul_2exp(denominator.get(), denominator.get(), 2);
        fmpz_zero(radicand.get());
        return true;
    }

    Lifted a2_, a3_, k_;
    Integer p2_, p3_, p23_, g_, kk_;
};

}  // namespace

// ----------------------------------------------------- CircleVoronoiVertex --

CircleVoronoiVertex::CircleVoronoiVertex(const Ellipse& c1, const Ellipse& c2, const Ellipse& c3)
    : sites_{&c1, &c2, &c3} {
    for (const Ellipse* c : sites_) require_circle(*c, "CircleVoronoiVertex");
    TangentCircles circles(c1, c2, c3);
    exists_ = circles.circle(1, m_, n_, denominator_, radicand_);
    scale_ = std::move(circles.scale);
    origin_ = std::move(circles.origin);
}

void CircleVoronoiVertex::require_exists(const char* who) const {
    if (!exists_)
        throw Error(std::string(who) + ": the triple " + sites_[0]->str() + " / " + sites_[1]->str() + " / " +
                    sites_[2]->str() + " has no counter-clockwise Voronoi circle");
}

QuadraticNumber CircleVoronoiVertex::center_x() const {
    require_exists("CircleVoronoiVertex::center_x");
    const Integer d = scale_ * denominator_;
    return {sites_[0]->xc() + Rational(m_[0], d), Rational(n_[0], d), Rational(radicand_)};
}

QuadraticNumber CircleVoronoiVertex::center_y() const {
    require_exists("CircleVoronoiVertex::center_y");
    const Integer d = scale_ * denominator_;
    return {sites_[0]->yc() + Rational(m_[1], d), Rational(n_[1], d), Rational(radicand_)};
}

QuadraticNumber CircleVoronoiVertex::radius() const {
    require_exists("CircleVoronoiVertex::radius");
    const Integer d = scale_ * denominator_;
    return {Rational(m_[2], d) - sites_[0]->a(), Rational(n_[2], d), Rational(radicand_)};
}

// ------------------------------------------------------------- predicates --

int circle_vertex_conflict(const CircleVoronoiVertex& vertex, const Ellipse& q) {
    require_circle(q, "circle_vertex_conflict");
    if (!vertex.exists_) return -1;
    // Q in the vertex's frame, scaled once more by f (the part of Q's
    // denominators that the vertex's scale lacks) so that it is integral:
    // a = f (scale C_Q - origin). Then with p = <b, b> (f^2 times Q's power)
    //   sign(h_Q - a_Q . w) = sign(den) sign(p den - 2 f a . m - 2 f sqrt(rad) a . n).
    Integer f(1), scale;
    common_denominator(f, {&q});
    if (fmpz_is_one(f.get())) {
        scale = vertex.scale_;
    } else {
        Integer g;
        fmpz_gcd(g.get(), f.get(), vertex.scale_.get());
        fmpz_divexact(f.get(), f.get(), g.get());
        fmpz_mul(scale.get(), f.get(), vertex.scale_.get());
    }
    Lifted a;
    scale_circle(a, q, scale);
    for (int i = 0; i < 3; ++i) fmpz_submul(a[i].get(), f.get(), vertex.origin_[i].get());
    // R + r_Q < 0 (an internal circle deeper than Q's radius): Q's signed
    // distance at V is at least -r_Q > R, whatever the squares below say. In
    // the frame scaled by f the lifted circle is f w, so the sign of R + r_Q
    // is that of s + a_s / f.
    if (lifted_height_sign(vertex.m_, vertex.n_, vertex.denominator_, vertex.radicand_, a[2], f) < 0) return 1;
    Integer rational_part, root_part, t;
    lorentz_of_sites(rational_part, a, a);
    fmpz_mul(rational_part.get(), rational_part.get(), vertex.denominator_.get());
    dot(t, a, vertex.m_);
    fmpz_mul(t.get(), t.get(), f.get());
    fmpz_submul_ui(rational_part.get(), t.get(), 2);
    dot(root_part, a, vertex.n_);
    fmpz_mul(root_part.get(), root_part.get(), f.get());
    fmpz_mul_si(root_part.get(), root_part.get(), -2);
    return sign_of_quadratic(rational_part, root_part, vertex.radicand_) * vertex.denominator_.sign();
}

int circle_vertex_conflict(const Ellipse& c1, const Ellipse& c2, const Ellipse& c3, const Ellipse& q) {
    return circle_vertex_conflict(CircleVoronoiVertex(c1, c2, c3), q);
}

int circle_infinite_vertex_conflict(const Ellipse& c1, const Ellipse& c2, const Ellipse& q) {
    for (const Ellipse* c : {&c1, &c2, &q}) require_circle(*c, "circle_infinite_vertex_conflict");
    // With D = C2 - C1 and dr = r1 - r2, the unit normal of the bitangent L
    // pointing into H is n = (dr D + sqrt(e) J) / |D|^2, e = |D|^2 - dr^2,
    // J = D turned by +90 degrees (n . D = dr makes L tangent to both; J puts
    // H on the left of T1 -> T2). Q meets H iff its support value exceeds
    // C1's: n . D_Q + rho_Q > 0 (D_Q = C_Q - C1, rho_Q = r_Q - r1), and
    //   |D|^2 (n . D_Q + rho_Q) = dr D . D_Q + rho_Q |D|^2 + sqrt(e) D x D_Q.
    // Homogeneous in the sites (degree 3), so scaled to integers.
    Integer scale;
    common_denominator(scale, {&c1, &c2, &q});
    Lifted origin, d, dq;
    scale_circle(origin, c1, scale);
    lift_site(d, c2, scale, origin);
    lift_site(dq, q, scale, origin);
    Integer d2, e, along, across, dr, rational_part;
    fmpz_neg(dr.get(), d[2].get());
    fmpz_mul(d2.get(), d[0].get(), d[0].get());
    fmpz_addmul(d2.get(), d[1].get(), d[1].get());
    fmpz_set(e.get(), d2.get());
    fmpz_submul(e.get(), dr.get(), dr.get());
    if (e.sign() <= 0)
        throw Error("circle_infinite_vertex_conflict: no external bitangent (one site inside the other): " + c1.str() +
                    " / " + c2.str());
    fmpz_mul(along.get(), d[0].get(), dq[0].get());  // D . D_Q
    fmpz_addmul(along.get(), d[1].get(), dq[1].get());
    det2(across, d[0], dq[1], d[1], dq[0]);  // D x D_Q
    fmpz_mul(rational_part.get(), dr.get(), along.get());
    fmpz_addmul(rational_part.get(), dq[2].get(), d2.get());
    const int side = sign_of_quadratic(rational_part, across, e);
    if (side != 0) return -side;
    // Q touches L from the sites' side. Positions along L (n turned by -90
    // degrees) from T1: T2 at sqrt(e), Q's contact point at D_Q x n, and
    //   |D|^2 D_Q x n = -dr D x D_Q + sqrt(e) D . D_Q.
    // CGAL's tie-break: -1 iff strictly between.
    Integer offset, rest;
    fmpz_mul(offset.get(), dr.get(), across.get());
    fmpz_neg(offset.get(), offset.get());
    const bool after_first = sign_of_quadratic(offset, along, e) > 0;
    fmpz_neg(offset.get(), offset.get());
    fmpz_sub(rest.get(), d2.get(), along.get());
    const bool before_second = sign_of_quadratic(offset, rest, e) > 0;
    return after_first && before_second ? -1 : 1;
}

VoronoiCircles circle_voronoi_circle_count(const Ellipse& c1, const Ellipse& c2, const Ellipse& c3) {
    for (const Ellipse* c : {&c1, &c2, &c3}) require_circle(*c, "circle_voronoi_circle_count");
    const TangentCircles circles(c1, c2, c3);
    Lifted m, n;
    Integer denominator, radicand;
    const bool ccw = circles.circle(1, m, n, denominator, radicand);
    const bool cw = circles.circle(-1, m, n, denominator, radicand);
    return ccw ? (cw ? VoronoiCircles::both : VoronoiCircles::ccw_only)
               : (cw ? VoronoiCircles::cw_only : VoronoiCircles::none);
}

namespace {

// A unit direction P + sqrt(radicand) R (up to a positive factor), integers.
struct Direction {
    Lifted p, r;  // [2] unused
    Integer radicand;
};

// The contact direction on C (scaled frame, origin C) of the external
// bitangent with X (circle_predicates.hpp, circle_infinite_edge_interior_conflict).
Direction bitangent_direction(const Lifted& x, const Integer& radius_c, bool arrival, const char* who) {
    Direction n;
    Integer dr, d2;
    fmpz_sub(dr.get(), radius_c.get(), x[2].get());
    fmpz_mul(d2.get(), x[0].get(), x[0].get());
    fmpz_addmul(d2.get(), x[1].get(), x[1].get());
    fmpz_set(n.radicand.get(), d2.get());
    fmpz_submul(n.radicand.get(), dr.get(), dr.get());
    if (n.radicand.sign() <= 0)
        throw Error(std::string(who) + ": no external bitangent (one site inside the other)");
    for (int i = 0; i < 2; ++i) fmpz_mul(n.p[i].get(), dr.get(), x[i].get());
    // J = (-D_y, D_x); departure takes -J.
    fmpz_neg(n.r[0].get(), x[1].get());
    fmpz_set(n.r[1].get(), x[0].get());
    if (!arrival)
        for (int i = 0; i < 2; ++i) fmpz_neg(n.r[i].get(), n.r[i].get());
    return n;
}

// sign of cross(u, v) (cross) or dot(u, v) for directions in two fields.
int sign_of_product(const Direction& u, const Direction& v, bool cross) {
    auto form = [cross](Integer& out, const Lifted& a, const Lifted& b) {
        if (cross) det2(out, a[0], b[1], a[1], b[0]);
        else {
            fmpz_mul(out.get(), a[0].get(), b[0].get());
            fmpz_addmul(out.get(), a[1].get(), b[1].get());
        }
    };
    Integer a, b, c, e;
    form(a, u.p, v.p);
    form(b, u.r, v.p);
    form(c, u.p, v.r);
    form(e, u.r, v.r);
    return sign_of_biquadratic(a, b, c, e, u.radicand, v.radicand);
}

bool same_direction(const Direction& u, const Direction& v) {
    return sign_of_product(u, v, true) == 0 && sign_of_product(u, v, false) > 0;
}

// Which half-turn from `from` v lies in: 0 along it, 1 in (0, pi), 2 at pi,
// 3 in (pi, 2 pi).
int half_turn(const Direction& from, const Direction& v) {
    const int c = sign_of_product(from, v, true);
    if (c > 0) return 1;
    if (c < 0) return 3;
    return sign_of_product(from, v, false) > 0 ? 0 : 2;
}

// +1 strictly inside the counter-clockwise arc from `from` to `to`, 0 at an
// end, -1 outside (a single point when from == to).
int position_in_arc(const Direction& from, const Direction& to, const Direction& x) {
    if (same_direction(x, from) || same_direction(x, to)) return 0;
    const int hx = half_turn(from, x), ht = half_turn(from, to);
    if (ht == 0) return -1;
    if (hx != ht) return hx < ht ? 1 : -1;
    // Same open half-turn: x comes first iff the turn from x to `to` is counter-clockwise.
    return sign_of_product(x, to, true) > 0 ? 1 : -1;
}

}  // namespace

bool circle_infinite_edge_interior_conflict(const Ellipse& c2, const Ellipse& c3, const Ellipse& c4, const Ellipse& q,
                                            bool b) {
    const char* who = "circle_infinite_edge_interior_conflict";
    for (const Ellipse* c : {&c2, &c3, &c4, &q}) require_circle(*c, who);
    Integer scale;
    common_denominator(scale, {&c2, &c3, &c4, &q});
    Lifted origin, x3, x4, xq;
    scale_circle(origin, c2, scale);
    for (auto [site, x] : {std::pair{&c3, &x3}, {&c4, &x4}, {&q, &xq}}) {
        scale_circle(*x, *site, scale);
        for (int i = 0; i < 2; ++i) fmpz_sub((*x)[i].get(), (*x)[i].get(), origin[i].get());
    }
    const Integer& r2 = origin[2];
    const Direction from = bitangent_direction(x3, r2, true, who), to = bitangent_direction(x4, r2, false, who);
    int inside = position_in_arc(from, to, bitangent_direction(xq, r2, false, who));
    if (inside == 0) {  // Q's line coincides with an end: its other line decides
        inside = position_in_arc(from, to, bitangent_direction(xq, r2, true, who));
        if (inside == 0) return !b;
    }
    return b ? inside < 0 : inside > 0;
}

int circle_order_on_bisector(const Ellipse& c1, const Ellipse& c2, const CircleVoronoiVertex& a,
                             const CircleVoronoiVertex& b) {
    for (const CircleVoronoiVertex* v : {&a, &b}) {
        v->require_exists("circle_order_on_bisector");
        auto holds = [&](const Ellipse& c) {
            for (const Ellipse* s : v->sites_)
                if (same_circle(*s, c)) return true;
            return false;
        };
        if (!holds(c1) || !holds(c2))
            throw Error("circle_order_on_bisector: a vertex's triple does not contain both sites of the bisector");
    }
    // sign(J . (V_a - V_b)) with V = origin / scale + (m + sqrt(radicand) n)_xy
    // / (scale denominator) for each vertex. Only J's direction matters, so
    // it is taken from the sites scaled to integers; multiplied by T =
    // scale_a den_a scale_b den_b the difference is
    //   X + Y sqrt(radicand_a) + Z sqrt(radicand_b)
    // with integers X, Y, Z, and sign(T) = sign(den_a) sign(den_b).
    Integer delta;
    common_denominator(delta, {&c1, &c2});
    Lifted p1, p2;
    scale_circle(p1, c1, delta);
    scale_circle(p2, c2, delta);
    Integer jx, jy;
    fmpz_sub(jx.get(), p1[1].get(), p2[1].get());
    fmpz_sub(jy.get(), p2[0].get(), p1[0].get());
    auto j_dot = [&](Integer& r, const Lifted& v) {
        fmpz_mul(r.get(), jx.get(), v[0].get());
        fmpz_addmul(r.get(), jy.get(), v[1].get());
    };
    Integer factor_a, factor_b, x, y, z, t;
    fmpz_mul(factor_a.get(), b.scale_.get(), b.denominator_.get());
    fmpz_mul(factor_b.get(), a.scale_.get(), a.denominator_.get());
    // X: the origins' part, then the rational parts of the offsets.
    j_dot(x, a.origin_);
    fmpz_mul(x.get(), x.get(), b.scale_.get());
    j_dot(t, b.origin_);
    fmpz_submul(x.get(), t.get(), a.scale_.get());
    fmpz_mul(x.get(), x.get(), a.denominator_.get());
    fmpz_mul(x.get(), x.get(), b.denominator_.get());
    j_dot(t, a.m_);
    fmpz_addmul(x.get(), t.get(), factor_a.get());
    j_dot(t, b.m_);
    fmpz_submul(x.get(), t.get(), factor_b.get());
    j_dot(t, a.n_);
    fmpz_mul(y.get(), t.get(), factor_a.get());
    j_dot(t, b.n_);
    fmpz_mul(z.get(), t.get(), factor_b.get());
    fmpz_neg(z.get(), z.get());
    return sign_of_two_roots(x, y, a.radicand_, z, b.radicand_) * a.denominator_.sign() * b.denominator_.sign();
}

}  // namespace ellvor
