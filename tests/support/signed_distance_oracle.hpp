// An independent checker of a built Voronoi diagram of ellipses, for tests: its
// own signed distance (docs/DESIGN.md §2: dist(x, ∂E) outside E, -dist(x, ∂E)
// inside) in MPFR at kOracleBits bits, and brute-force checks of a graph's
// claims with it. It calls none of ellvor's predicates or solvers, so a bug
// there cannot hide itself here.
#pragma once

#include "graph/delaunay_graph.hpp"
#include "output/graph_json.hpp"
#include "sites/ellipse.hpp"

#include <mpfr.h>

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace ellvor::test {

// Far beyond the doubles the checks compare (their tolerances are 1e-9 of the
// scene): the distance of a point within 2^-100 of a boundary, or of a needle's
// tip, still has most of its digits.
constexpr mpfr_prec_t kOracleBits = 192;

// An MPFR number of kOracleBits bits (RAII); every operation rounds to nearest.
class Real {
public:
    Real() { mpfr_init2(v_, kOracleBits); mpfr_set_zero(v_, 1); }
    Real(double x) { mpfr_init2(v_, kOracleBits); mpfr_set_d(v_, x, MPFR_RNDN); }  // NOLINT: exact, implicit is intended
    // Rounded to nearest (a point at 2^-192 of its scale from a rational point).
    explicit Real(const Rational& q) { mpfr_init2(v_, kOracleBits); fmpq_get_mpfr(v_, q.get(), MPFR_RNDN); }
    Real(const Real& o) { mpfr_init2(v_, kOracleBits); mpfr_set(v_, o.v_, MPFR_RNDN); }
    Real(Real&& o) noexcept { mpfr_init2(v_, kOracleBits); mpfr_swap(v_, o.v_); }
    Real& operator=(const Real& o) { mpfr_set(v_, o.v_, MPFR_RNDN); return *this; }
    Real& operator=(Real&& o) noexcept { mpfr_swap(v_, o.v_); return *this; }
    ~Real() { mpfr_clear(v_); }

    mpfr_ptr get() { return v_; }
    mpfr_srcptr get() const { return v_; }
    double to_double() const { return mpfr_get_d(v_, MPFR_RNDN); }
    int sign() const { return mpfr_sgn(v_); }
    static Real pi() { Real r; mpfr_const_pi(r.v_, MPFR_RNDN); return r; }

    friend Real operator+(const Real& a, const Real& b) { return apply(mpfr_add, a, b); }
    friend Real operator-(const Real& a, const Real& b) { return apply(mpfr_sub, a, b); }
    friend Real operator*(const Real& a, const Real& b) { return apply(mpfr_mul, a, b); }
    friend Real operator/(const Real& a, const Real& b) { return apply(mpfr_div, a, b); }
    Real operator-() const { Real r; mpfr_neg(r.v_, v_, MPFR_RNDN); return r; }
    friend Real sqrt(const Real& a) { Real r; mpfr_sqrt(r.v_, a.v_, MPFR_RNDN); return r; }
    friend Real abs(const Real& a) { Real r; mpfr_abs(r.v_, a.v_, MPFR_RNDN); return r; }
    friend Real cos(const Real& a) { Real r; mpfr_cos(r.v_, a.v_, MPFR_RNDN); return r; }
    friend Real sin(const Real& a) { Real r; mpfr_sin(r.v_, a.v_, MPFR_RNDN); return r; }
    friend Real hypot(const Real& a, const Real& b) { return apply(mpfr_hypot, a, b); }
    friend bool operator<(const Real& a, const Real& b) { return mpfr_less_p(a.v_, b.v_); }
    friend bool operator>(const Real& a, const Real& b) { return mpfr_greater_p(a.v_, b.v_); }
    friend bool operator<=(const Real& a, const Real& b) { return mpfr_lessequal_p(a.v_, b.v_); }
    friend bool operator>=(const Real& a, const Real& b) { return mpfr_greaterequal_p(a.v_, b.v_); }
    friend bool operator==(const Real& a, const Real& b) { return mpfr_equal_p(a.v_, b.v_); }

private:
    using BinaryOp = int (*)(mpfr_ptr, mpfr_srcptr, mpfr_srcptr, mpfr_rnd_t);
    static Real apply(BinaryOp op, const Real& a, const Real& b) { Real r; op(r.v_, a.v_, b.v_, MPFR_RNDN); return r; }
    mpfr_t v_;
};

struct RealPoint {
    Real x, y;
};

struct SignedDistance {
    Real value;         // δ(x, E)
    RealPoint foot;     // a nearest point of ∂E
    // Where the inward normal at the foot meets E's medial axis: along the
    // segment from it to the foot (and on past it) δ(·, E) grows at rate 1.
    RealPoint medial;
    RealPoint normal;   // the outward unit normal of ∂E at the foot
};

// One site, held in MPFR in the frame of its longer axis (A >= B).
class OracleEllipse {
public:
    explicit OracleEllipse(const Ellipse& e);

    SignedDistance signed_distance(const RealPoint& x) const;
    Real signed_distance_value(const RealPoint& x) const { return signed_distance(x).value; }
    // |x - C| - A <= δ(x, E): E lies in the disk of radius A about C (cheap, to
    // skip sites that are far away).
    Real distance_lower_bound(const RealPoint& x) const;

    // The medial axis: the segment of the long axis between the centres of
    // curvature of its two vertices, C + s (A² - B²)/A U for s in [-1, 1] (the
    // centre for a circle).
    RealPoint medial_axis_point(const Real& s) const;
    // C + A cos θ U + B sin θ V.
    RealPoint boundary_point(const Real& theta) const;
    // Where the inward normal at boundary_point(θ) meets the medial axis.
    RealPoint medial_point_below(const Real& theta) const;

private:
    RealPoint to_world(const Real& xi, const Real& eta) const;
    Real A_, B_;           // semi-axes, A >= B
    RealPoint center_;
    RealPoint U_, V_;      // unit directions of the A-axis and the B-axis
    bool circle_;
};

// What a built graph claims (docs/DESIGN.md §2): the visible sites, the hidden
// ones with the sites that hide them, the finite faces (counter-clockwise
// triples) and the Voronoi vertex of each face, one per face in that order.
struct DiagramClaim {
    std::vector<SiteId> visible;
    std::vector<std::pair<SiteId, SiteId>> hidden;  // [hidden, hiding]
    std::vector<std::array<SiteId, 3>> faces;
    std::vector<VoronoiVertexValue> vertices;
};

// The graph's claim, with the vertices as output/graph_json.hpp prints them.
DiagramClaim claim_of(const DelaunayGraph& graph, const std::vector<Ellipse>& sites);

// The claim's problems ("" if none), one a line, naming sites and numbers. The
// inserted sites are the visible and the hidden ones. Tolerances: `tol` = 2.5
// error + 1e-12 scale for a vertex (V and ρ are each within `error`, δ is
// 1-Lipschitz), and a margin of 1e-9 scale for owning a point; the scale is the
// largest |coordinate| the inserted sites reach (doubles round relative to it).
//  - structure: each site at most once among visible and hidden, hosts visible,
//    face sites visible, one vertex per face;
//  - faces: |δ(V, E) - ρ| <= tol for the face's three sites, whose feet are
//    counter-clockwise in the face's order, and δ(V, E) >= ρ - tol for every
//    other inserted site, hidden ones included;
//  - visible sites own a point: some x with δ(x, E) < δ(x, E') - margin for every
//    other E' (tried: where the normal from each of E's Voronoi vertices through
//    its foot meets E's medial axis, then points along the medial axis); E's
//    twins (a site whose boundary is provably within margin/2 of E's: a
//    nearly coincident copy, which no point separates by the margin) are
//    left out of that comparison;
//  - hidden sites own none of 200 points of their medial axis (a non-empty cell
//    reaches it: inward along a normal δ(·, H) falls at rate 1, any other δ at
//    rate <= 1), nor points of their boundary and between it and the medial axis.
std::string check_diagram(const std::vector<Ellipse>& sites, const DiagramClaim& claim);
// claim_of(graph, sites) checked, and every site the graph contains listed in it.
std::string check_diagram(const std::vector<Ellipse>& sites, const DelaunayGraph& graph);

}  // namespace ellvor::test
