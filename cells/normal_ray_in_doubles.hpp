// The cell densities of cells/normal_ray_bisector.hpp at one real angle
// theta, certified in double intervals (under the upward rounding mode:
// util/upward_interval.hpp; the .cpp is compiled with its flags).
// These are the quadrature nodes of the cell integrals: at a tolerance of
// 1e-9 they need about 40 bits, and Arb's complex balls cost ten times what
// the doubles do there.
//
// Same system and certificate as NormalRayBisector (docs/DESIGN.md §10), with
// real unknowns: the 2 x 2 Krawczyk test in x = (s, phi), p's boundary taken
// over the whole interval of theta, proves one real root in the box X for
// every theta in it; Re s > 0 and (V - Q) . n~q > 0 on X (with the signed
// tie of close sites: s > -r_p and t > -r_q) make that root the bisector
// point of p's normal line, as the header of normal_ray_bisector.hpp argues. Sines and cosines come from util/interval_trig.hpp. Anything it
// cannot prove is "not certified", and the caller asks the Arb solver
// instead.
//
// On a complex disk of theta the Krawczyk test runs about the root's Taylor
// polynomial x_model(theta) = x0 + x1 d + x2 d^2 (d = theta - mid, the
// coefficients from Newton in doubles), every quantity a Taylor model in d on
// the disk (util/complex_taylor_model.hpp: real coefficients; the residual
// F(x_model(theta), theta) of degree 4, the rest of degree 2), with its own
// preconditioner C(theta) = sum C_k d^k at each theta (the Taylor polynomial
// of J^-1 along x_model, which cancels I - C(theta) J to that degree; x2 by
// central differences of Newton's roots). Interval evaluations over the
// box (a first-order mean-value form, then second-order jets) enclosed H =
// F(x_model(theta), theta) and I - C J(X) ten to thirty times over their true
// ranges; with the models the certified pieces are two to three times wider.
#pragma once

#include "cells/normal_ray_bisector.hpp"
#include "util/interval.hpp"

#include <array>
#include <cmath>
#include <optional>

namespace ellvor {

// The measures of EdgeMeasure (cells/normal_ray_bisector.hpp) as intervals:
// their densities at an angle, or their integrals over an edge.
struct MeasureIntervals : EdgeMeasure {
    Interval m[count];
};

class NormalRayInDoubles {
public:
    // As NormalRayBisector (the sites must outlive this object): the first
    // form asks NormalRayBisector::uses_signed_tie.
    NormalRayInDoubles(const Ellipse& p, const Ellipse& q);
    NormalRayInDoubles(const Ellipse& p, const Ellipse& q, bool signed_tie);

    // The origin O of the densities (exact doubles); p's center rounded to
    // doubles unless set.
    void set_origin(double x, double y) { origin_[0] = x, origin_[1] = y; }
    // The densities at every angle in `theta` (a real interval); nothing when
    // the certificate fails there.
    std::optional<MeasureIntervals> densities(const Interval& theta);
    // The bisector point V = P + s n~ at every angle in `theta`; likewise.
    std::optional<std::array<Interval, 2>> point(const Interval& theta);
    // Newton's next start from a point of the bisector near p's angle theta
    // (a Voronoi vertex of the edge): s by projection on the normal, phi the
    // nearest point of q. Any start is sound (a wrong root fails the
    // certificates); without one, or when Newton fails from it, the start is
    // found along the normal ray (about twenty times the cost of Newton).
    void start_near(double theta, double x, double y);
    // The angles theta (two, pi apart, in [-pi, pi]) where p's normal is
    // perpendicular to the line of the centers: for sites far apart the
    // normal ray runs along the bisector there, s has a pole near it.
    std::array<double, 2> pole_angles() const;
    // The widest piece [start, start + w] whose disk about its middle, of
    // radius disk_over_width w, stays within `share` of the middle's distance
    // to every pole angle (a step size's guide: the disk certificate holds to
    // about a quarter of the distance to a pole, two circles 10 apart).
    double pole_limited_width(double start, double disk_over_width, double share) const;
    // Green's area density (X dY - Y dX) / 2 at theta by Newton in doubles,
    // not certified: a scale (cell_area.cpp's first estimate of an area).
    std::optional<double> area_density_estimate(double theta);
    // The degree of the disk certificate's Taylor models, of the root's
    // polynomial and of the preconditioner (3 to 6 certified wider pieces but
    // cost more than they saved: experiments/results/cells_timing.md).
    static constexpr int kDiskDegree = 2;
    // Upper bounds over the complex disk |theta - mid| <= R, where the same
    // certificate, on Taylor models about the root's polynomial in theta,
    // proves the densities holomorphic: of the densities' moduli
    // (MeasureIntervals' order, from their models on the disk), and of
    // |V - p's center| and |V - q's center| at the real angles mid +- half,
    // half <= R (how far the edge gets from either site's center). Nothing
    // when the certificate fails.
    // `beyond_polynomial`: for each density f, a polynomial p of degree
    // kDiskDegree in theta - mid (`polynomial`, complex coefficients from
    // the lowest) with |f - p| <= beyond_polynomial on the disk (infinite
    // where none was found); a Gauss rule exact for p errs on f as on f - p.
    // `contraction`: how near the Krawczyk test came to failing, the
    // largest ratio of the image's bound to the box's (between 1/2 and 1):
    // a step size's guide, not a bound.
    struct DiskBounds {
        std::array<double, MeasureIntervals::count> density, beyond_polynomial;
        std::array<std::array<std::array<double, 2>, kDiskDegree + 1>, MeasureIntervals::count> polynomial;
        std::array<double, 2> center_distance;
        double contraction;
    };
    std::optional<DiskBounds> bounds_on_disk(double mid, double R, double half);
    // The root's models on that disk, from the same certificate: for every
    // theta there s(theta) = s0 + s1 d + e(theta) = s0 + s1 d + s2 d^2 +
    // e2(theta) (d = theta - mid), e and e2 holomorphic with |e| <= remainder
    // and |e2| <= quadratic_remainder; and |n~| <= normal there.
    struct RootModel {
        double mid, s0, s1, s2, remainder, quadratic_remainder, normal;
    };
    std::optional<RootModel> root_model(double mid, double R);

    struct Site {
        Interval a, b, c, s, xc, yc;  // semi-axes, cosine and sine of the rotation, center
        EllipseShape shape;
    };
    // How many nodes the disks' proofs certified (the rest by their own
    // Krawczyk tests).
    std::size_t disk_nodes() const { return disk_nodes_; }
    // The densities at the real ball theta at precision prec, for goals
    // beyond the doubles' 44 bits (cells/edge_quadrature.hpp's nodes in
    // Arb), from the last disk's proof: Newton in doubles, then steps in
    // balls, the root's error bounded by the proof as a double node's is
    // (the .cpp's disk_offsets), the sites' exact parameters as balls.
    // About a tenth of the work of NormalRayBisector::densities, which
    // certifies each node by itself. False when theta is not on the disk's
    // real diameter or the proof does not cover the root: then nothing is
    // claimed.
    bool densities_in_balls(const Ball& theta, long prec, NormalRayBisector::Densities& out);
    // The root (s, phi) at theta on the last disk's real diameter, from any
    // point x of X(theta) (DiskProof) by the disk's proof, as its nodes take
    // it from Newton's point: x +- delta. Nothing off the disk, or when x is
    // not in X(theta).
    std::optional<std::array<Interval, 2>> root_from_disk(const Interval& theta, const double (&x)[2]);
    // What the last disk certificate proved, for the nodes on its real
    // diameter (the .cpp's certify_node_in_disk): with d = theta - mid, the
    // system has one root in X(theta) = x_model(d) + D(0, reach) (x_model(d)
    // = sum x[i][k] d^k), and the preconditioner C(theta) = sum C[k] d^k
    // bounds |I - C(theta) J(X(theta))|_ij <= coupling[i][j], with
    // sum_j coupling[i][j] reach_j < reach[i].
    struct DiskProof {
        double mid, R;
        double C[kDiskDegree + 1][2][2];
        double x[2][kDiskDegree + 1];
        double reach[2], coupling[2][2];
    };

private:
    // Newton on the system in doubles at the angle theta from `start`; false
    // unless it converges to a root with s > 0 (any root it finds is only a
    // start: the certificate judges it).
    // C: the inverse of the Jacobian at the last step.
    bool newton(double theta, const double (&start)[2], double (&x)[2], double (&C)[2][2]) const;
    // Newton's start from the bisector point on p's normal ray at theta.
    bool ray_start(double theta, double (&start)[2]) const;
    // Newton's start from the last disk's root polynomial, when theta lies
    // on its real diameter (else false, `start` unchanged).
    bool disk_start(double theta, double (&start)[2]) const;
    // What a node gives: the densities and the bisector point, each absent
    // where the certificate of the root holds but theirs does not.
    struct Node {
        std::optional<MeasureIntervals> densities;
        std::optional<std::array<Interval, 2>> point;
    };
    struct DiskRoot;
    std::optional<DiskRoot> disk_root(double mid, double R);
    // The certified node at theta, from the last root or from the ray; its
    // densities only when asked (point() does not need them).
    std::optional<Node> node(const Interval& theta, bool with_densities);
    // The certificate about the point x0 (Newton's root).
    std::optional<Node> certified(const Interval& theta, const double (&x0)[2], const double (&C)[2][2],
                                  bool with_densities);
    // Whether theta lies on the last disk's real diameter.
    bool on_disk(const Interval& theta) const;

    Site p_, q_;
    const Ellipse *p_ellipse_, *q_ellipse_;  // for densities_in_balls
    SiteBalls p_balls_, q_balls_;            // theirs, at balls_prec_
    long balls_prec_ = 0;
    bool signed_;
    Interval medial_p_, medial_q_;  // r_p, r_q of normal_ray_bisector.hpp
    double size_;  // scale of the pair, for the double start
    double origin_[2];
    // How far q's frame moves (x, dx, ny; y, dy, nx) per unit change of its
    // sine and cosine: |a||c| + |b||s| and |a||s| + |b||c|, rounded up.
    double q_slack_[2];
    // The root at the last node: the next node's start.
    double last_[2] = {NAN, NAN};
    // The last disk certificate's proof, while its nodes are integrated
    // (none after a failed one).
    std::optional<DiskProof> disk_;
    std::size_t disk_nodes_ = 0;
};

}  // namespace ellvor
