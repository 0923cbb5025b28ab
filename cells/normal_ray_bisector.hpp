// The Voronoi edge of two sites p, q seen from p, certified on complex balls
// of p's boundary angle theta (docs/DESIGN.md §10).
//
// With P(theta) = C + a cos(theta) u + b sin(theta) v and the unnormalized
// outward normal n~(theta) = b cos(theta) u + a sin(theta) v (length N(theta),
// N^2 = a^2 sin^2 + b^2 cos^2 = |P'|^2), the bisector point on p's normal
// line is V = P(theta) + s n~(theta), at signed distance rho = s N(theta)
// from p. With Q(phi) a boundary point of q, the system in x = (s, phi)
//     F0 = (V - Q(phi)) . Q'(phi)          = 0   (Q is a foot point of V on q)
//     F1 = |V - Q(phi)|^2 - s^2 N(theta)^2 = 0   (V as far from q as from p)
// is polynomial in the cosines and sines: holomorphic in theta, s, phi, with
// no square root. (dF1/dphi = -2 F0 vanishes at a root: the distance to q is
// stationary in the foot point, which keeps the system well conditioned far
// along the edge, where the ray meets the bisector at a small angle.)
//
// Sites that meet (cross or touch, docs/DESIGN.md §9) have edge points with
// s = 0 on both boundaries, where F1 has a double root and the Jacobian is
// singular; sites a gap g apart have a nearly double root where the edge
// passes between them, and the certified pieces there shrink with g (a
// packing's neighbours 10^-6 apart: some 26,000 pieces a cell). For both, and
// for every pair whose bounding circles overlap (uses_signed_tie), F1 is the
// signed tie
//     F1 = (V - Q) . n~q(phi) - s N(theta) Nq(phi)   (Nq = |n~q|),
// which says V = Q + t n~q with t Nq = s N: equal signed distances. Its
// Jacobian in (s, phi) is nonsingular wherever the two boundaries are not
// tangent with the same normal; N and Nq are square roots, holomorphic near
// the reals (N^2 > 0 there). (About 300 pieces a cell on that packing.)
//
// Certificate: with x0 a Newton point at the (real) middle m of the ball and
// x' its slope there, the root is sought as x = x0 + x' (theta - m) + y; the
// 2 x 2 Krawczyk operator in y, over a complex box Y and the whole
// theta-ball (its constant term in the mean-value form around m), lies in
// the interior of Y. Then for every theta in the ball the system has exactly
// one root in X(theta) = x0 + x' (theta - m) + Y, a holomorphic function of
// theta (the Jacobian is nonsingular there). If moreover Re s > 0 and
// Re (V - Q) . n~q(phi) > 0 on X, then for a real theta the root is real
// (X(theta) is symmetric about the reals and conjugation maps roots to
// roots), s > 0, and V - Q lies along q's outward normal at Q,
// so Q is the nearest point of the convex q to V and dist(V, q) = |V - Q| =
// s N = dist(V, p): V is the one point of p's normal ray equidistant from p
// and q (docs/DESIGN.md §10). With the signed tie the conditions are Re s >
// -r_p and Re ((V - Q) . n~q + r_q Nq^2) > 0 (t > -r_q), r = min(a, b) /
// max(a, b): the inward normal of an ellipse at P(theta) meets its medial axis
// at s = -r, and up to there P(theta) is the nearest boundary point, so the
// signed distances of V to p and q are s N and t Nq, equal by F1.
#pragma once

#include "sites/ellipse.hpp"
#include "subdivision/ellipse_shape.hpp"
#include "util/complex_ball.hpp"

#include <array>

namespace ellvor {

// An ellipse's parameters as balls at one precision: semi-axes, cosine and
// sine of the rotation, center.
struct SiteBalls {
    Ball a, b, cos, sin, xc, yc;
    SiteBalls() = default;
    SiteBalls(const Ellipse& e, long prec);
};

// The measures of an edge that a cell's Green integrals need (docs/DESIGN.md
// §10), as densities per unit of p's angle theta, with (X, Y) = V - O for an
// origin O the caller chooses and dX, dY their theta-derivatives: X dY, Y dX,
// the edge's length |V'|, X^2 dY, Y^2 dX, X Y dY, X^3 dY, Y^3 dX and X^2 Y
// dY. A cell's area and moments about any point follow from them
// (cells/edge_integrals.hpp).
struct EdgeMeasure {
    enum Index { x_dy, y_dx, length, x2_dy, y2_dx, xy_dy, x3_dy, y3_dx, x2y_dy, count };
};

class NormalRayBisector {
public:
    // The sites must outlive this object. The first form asks
    // uses_signed_tie(p, q).
    NormalRayBisector(const Ellipse& p, const Ellipse& q);
    NormalRayBisector(const Ellipse& p, const Ellipse& q, bool signed_tie);

    // Whether two sites cross or touch from outside (exact,
    // predicates/relative_position.hpp, after the bounding circles' filter).
    static bool meet(const Ellipse& p, const Ellipse& q);
    // Whether the system is the signed one above: unless the sites' bounding
    // circles are apart (in doubles, certified), so for every pair that
    // meets. Either system is sound for any pair; the squared one is cheaper
    // a node where the sites are not close.
    static bool uses_signed_tie(const Ellipse& p, const Ellipse& q);

    // Encloses s(theta) for every theta in the complex ball `theta`, at
    // precision prec; false when the certificate fails there (the ball is too
    // large, or has no bisector point: then nothing is claimed).
    bool solve(const ComplexBall& theta, long prec, ComplexBall& s);

    // The root's linear model on the ball: for every theta in it,
    // s(theta) = s0 + s1 (theta - mid) + e(theta), e holomorphic there with
    // |e| <= remainder (the certificate's own form, see above). False when
    // solve() is.
    struct LinearModel {
        ComplexBall mid, s0, s1;
        Mag remainder;
    };
    bool solve(const ComplexBall& theta, long prec, LinearModel& model);

    // The origin O of the densities (exact doubles); p's center rounded to
    // doubles unless set.
    void set_origin(double x, double y) { origin_[0] = x, origin_[1] = y; }
    // The densities of EdgeMeasure on the edge, V' = P' + s' n~ + s n~', with
    // s' = -dg/dtheta / dg/ds from the tie function (its foot point drops
    // out). False when solve() is, or when |V'|^2 may touch the square root's
    // cut.
    struct Densities : EdgeMeasure {
        ComplexBall m[count];
    };
    bool densities(const ComplexBall& theta, long prec, Densities& out);
    // The bisector point V = P + s n~ for every theta in the ball; false when
    // solve() is.
    bool point(const ComplexBall& theta, long prec, ComplexBall& vx, ComplexBall& vy);

    const Ellipse& first() const { return *p_; }
    const Ellipse& second() const { return *q_; }
    bool signed_tie() const { return signed_; }

    struct Boundary;  // p's or q's boundary at a complex angle (the .cpp)

private:
    void set_precision(long prec);
    // solve(), and what densities() needs besides: the tie derivatives at the
    // root, (P - Q) . n~ and (P - Q) . (P' + s n~') (for s'), and p's boundary
    // on the theta-ball.
    bool solve(const ComplexBall& theta, long prec, ComplexBall& s, ComplexBall* tie_ds, ComplexBall* tie_dtheta,
               Boundary* p_boundary, LinearModel* model = nullptr);

    const Ellipse* p_;
    const Ellipse* q_;
    EllipseShape p_shape_, q_shape_;
    double size_;  // scale of the pair, for the double guesses
    bool signed_;  // the signed tie (see above)
    long prec_ = 0;
    SiteBalls pb_, qb_;
    Ball medial_p_, medial_q_;  // r_p, r_q (see above)
    double origin_[2];
};

}  // namespace ellvor
