#include "subdivision/voronoi_circle_in_doubles.hpp"

#include "subdivision/bisector_walk_start.hpp"
#include "subdivision/huge_circle_start.hpp"
#include "subdivision/voronoi_circle_guess.hpp"
#include "util/precision.hpp"
#include "util/upward_ball.hpp"
#include "util/upward_interval.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <vector>

namespace ellvor {
namespace {

using Matrix6 = Eigen::Matrix<double, 6, 6>;
using Vector6 = Eigen::Matrix<double, 6, 1>;

// Newton has converged when its step is below this, relative to |x| + unit
// (1 for the chart parameters, the length scale for rho and V).
constexpr double kConvergedStep = 1e-13;

// The same formulas in doubles (Newton on the midpoint), in intervals (the
// 6 x 6 certificate) and in balls (the certificate by distances), both
// computed under the upward rounding mode (util/upward_interval.hpp,
// util/upward_ball.hpp; which is why this file is compiled with the
// Makefile's ROUNDING_MATH flags): N is double, UpwardInterval or UpwardBall.
double constant(double c, double) { return c; }
UpwardInterval constant(double c, const UpwardInterval&) { return UpwardInterval(c); }
UpwardBall constant(double c, const UpwardBall&) { return UpwardBall(c); }
double root(double x) { return std::sqrt(x); }
UpwardInterval root(const UpwardInterval& x) { return x.sqrt(); }
UpwardBall root(const UpwardBall& x) { return x.sqrt(); }
// x^2, 2 x, -x and 1/x: in intervals the square is nonnegative, doubling and
// negation are exact (below the overflow range), and a positive divisor needs
// two quotients, not four and their ordering.
double square(double x) { return x * x; }
UpwardInterval square(const UpwardInterval& x) { return x.square(); }
UpwardBall square(const UpwardBall& x) { return x.square(); }
double twice(double x) { return 2 * x; }
UpwardInterval twice(const UpwardInterval& x) { return x.twice(); }
UpwardBall twice(const UpwardBall& x) { return x.twice(); }
double negated_if(bool negate, double x) { return negate ? -x : x; }
UpwardInterval negated_if(bool negate, const UpwardInterval& x) { return negate ? -x : x; }
UpwardBall negated_if(bool negate, const UpwardBall& x) { return negate ? -x : x; }
double reciprocal(double x) { return 1 / x; }
UpwardInterval reciprocal(const UpwardInterval& x) { return x.reciprocal(); }
UpwardBall reciprocal(const UpwardBall& x) { return x.reciprocal(); }

// An ellipse: semi-axes, rotation (cos, sin), center, and the product a b.
template <class N>
struct Shape {
    N a, b, cos, sin, xc, yc, ab;
};

// The enclosures as they are (the cosine and sine computed before, in
// round-to-nearest: util/interval_trig.hpp); a b by Interval's product, whose
// outward steps make it an enclosure in round-to-nearest, the mode in which
// this is called.
Shape<UpwardInterval> interval_shape(const Ellipse& e) {
    const Ellipse::Enclosure& k = e.enclosure();
    using U = UpwardInterval;
    return {U(k.a), U(k.b), U(k.cos), U(k.sin), U(k.xc), U(k.yc), U(k.a * k.b)};
}

Shape<double> double_shape(const Ellipse& e) {
    const Ellipse::Enclosure& k = e.enclosure();
    const double a = k.a.mid(), b = k.b.mid();
    return {a, b, k.cos.mid(), k.sin.mid(), k.xc.mid(), k.yc.mid(), a * b};
}

// Boundary point P and outward unit normal nu at chart parameter t, and
// their derivatives in t when asked for. Both derivatives lie along the
// counter-clockwise tangent nu^perp = (-nu_y, nu_x): dP/dt = speed nu^perp
// and dnu/dt = turning nu^perp (boundary_at says why).
template <class N>
struct BoundaryPoint {
    N px, py, nx, ny, speed, turning;
};

// In the ellipse's frame the boundary is (a cos, b sin) with
// cos = (1 - t^2)/(1 + t^2), sin = 2t/(1 + t^2) (sites/ellipse.hpp); the
// flipped chart u = -1/t gives the opposite point, (cos, sin) -> -(cos, sin)
// at the same formula in u. The outward normal is along g = (b cos, a sin),
// of length at least min(a, b). Derivatives: d/dt = w d/dtheta with
// w = 2/(1 + t^2), and d(cos, sin)/dtheta = (-sin, cos). In the ellipse's
// frame, with m = g/|g| and m^perp = (-a sin, b cos)/|g|:
//   dP/dtheta = (-a sin, b cos) = |g| m^perp,
//   dm/dtheta = (g' - m (m . g'))/|g| with g' = (-b sin, a cos), and
//     g' = m (m . g') + m^perp (m^perp . g'), m^perp . g' = a b/|g|, so
//   dm/dtheta = (a b/|g|^2) m^perp;
// the rotation to the plane maps m^perp to nu^perp. Hence speed = w |g|
// and turning = w a b/|g|^2: identities of the exact functions, so their
// interval evaluation encloses the derivatives as the componentwise formulas
// did (with fewer operations, and no cancellation in g' - m (m . g')).
// What a caller needs: Newton the point, the normal and their derivatives;
// F(m) the point and the normal; Krawczyk's box the normal and the
// derivatives only (J(X); F over the box is never read).
enum class Parts { point, derivatives, all };

// Into `p` (written in place: it is 6 intervals, and a returned copy was
// 1 % of a build's instructions).
template <class N>
void boundary_at(const Shape<N>& k, bool flipped, const N& t, Parts parts, BoundaryPoint<N>& p) {
    const N one = constant(1, t), t2 = square(t);
    const N inverse_den = reciprocal(one + t2);
    const N c = negated_if(flipped, (one - t2) * inverse_den), s = negated_if(flipped, twice(t) * inverse_den);
    const N gx = k.b * c, gy = k.a * s;
    const N norm = root(square(gx) + square(gy)), inverse_norm = reciprocal(norm);
    const N mx = gx * inverse_norm, my = gy * inverse_norm;  // the unit normal in the ellipse's frame
    if (parts != Parts::derivatives) {
        const N lx = k.a * c, ly = k.b * s;
        p.px = k.xc + (k.cos * lx - k.sin * ly);
        p.py = k.yc + (k.sin * lx + k.cos * ly);
    }
    p.nx = k.cos * mx - k.sin * my;
    p.ny = k.sin * mx + k.cos * my;
    if (parts == Parts::point) return;
    const N w = twice(inverse_den);
    p.speed = w * norm;
    p.turning = (k.ab * w) * square(inverse_norm);
}

// The tritangent system at x = (t_1, t_2, t_3, rho, V_x, V_y): `at`
// receives the three boundary points (the parts asked for), and F when `F`
// is given (then the points are computed; without F, only the normals and
// derivatives).
//
// Its Jacobian J is used by its structure, not as a matrix: rows 2i, 2i + 1
// hold dP_i/dt + rho dnu_i/dt = scale_i nu_i^perp in column t_i (scale_i =
// speed_i + rho turning_i, t_column_scale), nu_i in column rho, -I in the
// columns V, and zeros elsewhere.
template <class N>
void tritangent_system(const std::array<Shape<N>, 3>& k, const std::array<bool, 3>& flipped,
                       const std::array<N, 6>& x, std::array<N, 6>* F, bool derivatives,
                       std::array<BoundaryPoint<N>, 3>& at) {
    const N& rho = x[3];
    const Parts parts = !derivatives ? Parts::point : F ? Parts::all : Parts::derivatives;
    for (int i = 0; i < 3; ++i) {
        BoundaryPoint<N>& p = at[i];
        boundary_at(k[i], flipped[i], x[i], parts, p);
        if (!F) continue;
        (*F)[2 * i] = p.px + rho * p.nx - x[4];
        (*F)[2 * i + 1] = p.py + rho * p.ny - x[5];
    }
}

template <class N>
N t_column_scale(const BoundaryPoint<N>& p, const N& rho) {
    return p.speed + rho * p.turning;
}

// Interval::max is std::fmax inlined (the library call was 1% of a build).
double magnitude(const UpwardInterval& x) { return Interval::max(std::fabs(x.lo), std::fabs(x.hi)); }

// Krawczyk's products of Y (doubles, exact) with intervals, without the sign
// cases of an interval product (Y's signs are a coin toss for the branch
// predictor), under the upward rounding mode. An interval [lo, hi] is the
// pair (-lo, hi) in one SSE register: one vector addition, rounded up, gives
// (-lo_a - lo_b, hi_a + hi_b) rounded up, upper bounds of -(lo_a + lo_b) and
// of hi_a + hi_b. With y = y+ - y- (y+ = max(y, 0), y- = max(-y, 0), one of
// them 0), y [lo, hi] is [y lo, y hi] or [y hi, y lo] by y's sign, i.e.
//   y+ (-lo, hi) + y- (hi, -lo),
// each product rounded up and the exact 0 of the other term added exactly.
// An infinite bound times the 0 gives NaN, which fails K's finiteness test.
using NegatedLowHigh = double __attribute__((vector_size(16)));
NegatedLowHigh negated_low_high(const UpwardInterval& v) { return NegatedLowHigh{-v.lo, v.hi}; }
// y+ and y- of an entry of Y, each in both lanes.
struct SplitEntry {
    NegatedLowHigh plus, minus;
};
NegatedLowHigh times(const SplitEntry& y, NegatedLowHigh v) {
    return y.plus * v + y.minus * NegatedLowHigh{v[1], v[0]};
}

// The tangency points are counter-clockwise on the circle iff the normals
// are: P_i = V - rho nu_i, and a translation followed by the scaling by
// -rho multiplies the orientation of three points by rho^2 > 0.
bool counterclockwise(const std::array<BoundaryPoint<UpwardInterval>, 3>& p) {
    const UpwardInterval orientation =
        (p[1].nx - p[0].nx) * (p[2].ny - p[0].ny) - (p[1].ny - p[0].ny) * (p[2].nx - p[0].nx);
    return orientation.positive();
}

// The solution's rho is the signed distance from V to each site (DESIGN.md
// §4.1): rho > 0, or -rho below every site's smallest radius of curvature
// b^2 / a, so that the disk of radius -rho touching E_i at P_i from inside
// lies in E_i (Blaschke's rolling theorem) and P_i is V's nearest boundary
// point.
bool signed_distances(const std::array<Shape<UpwardInterval>, 3>& k, const UpwardInterval& rho) {
    if (rho.positive()) return true;
    for (const Shape<UpwardInterval>& e : k) {
        // min(a, b)^2 / max(a, b) = min(a^2 / b, b^2 / a), bounded below.
        const UpwardInterval curvature_radius(Interval::min((e.a.square() / e.b).lo, (e.b.square() / e.a).lo));
        if (!(rho + curvature_radius).positive()) return false;
    }
    return true;
}

// The Krawczyk test with epsilon-inflation: boxes m +- r, r from the size of
// the Newton correction, grown a few times when K(X) is not inside X.
// Returns K(X), which holds the unique solution in X, once it has also
// proved that rho is the signed distance to the sites and the
// counter-clockwise order (on X, which contains K(X)).
// With `converged_step_only` (m one Newton step before convergence, Y F(m)
// being that step), the test runs only if Y F(m) is a converged step, below
// kConvergedStep (|m| + unit); else it returns nullopt. (K(X) encloses the
// solution for any m and Y; this only keeps X as small as Newton's next
// step would.)
// All of it runs under the upward rounding mode: every double computed here
// is rounded up, so sums and products of nonnegative upper bounds (the
// spread, the box's reach) are upper bounds as they stand. The scope is the
// first thing done and the last undone, and every input is read through a
// reference after it (with ELLVOR_UPWARD_ROUNDING_FUNCTION: no double
// computed in round-to-nearest by the caller is taken for one computed here,
// nor the reverse).
ELLVOR_UPWARD_ROUNDING_FUNCTION std::optional<std::array<Interval, 6>> krawczyk(
    const std::array<Shape<UpwardInterval>, 3>& k, const std::array<bool, 3>& flipped, const Vector6& m,
    const Matrix6& Y, double length_scale, bool converged_step_only = false) {
    const UpwardRoundingScope upward;
    std::array<UpwardInterval, 6> point, F;
    std::array<BoundaryPoint<UpwardInterval>, 3> at;
    for (int j = 0; j < 6; ++j) point[j] = UpwardInterval(m[j]);
    tritangent_system<UpwardInterval>(k, flipped, point, &F, false, at);
    // Y = Y+ - Y- for times() (Y is finite: newton_then_certify checks).
    // Two rows at a time: y = (Y_ij, Y_i+1,j), and the lane masks of y > 0
    // and y < 0 (all ones or zeros) select y+ and y- (or +0) in each lane.
    using Mask = long long __attribute__((vector_size(16)));
    SplitEntry split[6][6];
    for (int j = 0; j < 6; ++j)
        for (int i = 0; i < 6; i += 2) {
            const NegatedLowHigh y{Y(i, j), Y(i + 1, j)}, zero{0, 0};
            const NegatedLowHigh plus = NegatedLowHigh(Mask(y) & (y > zero)), minus = NegatedLowHigh(Mask(-y) & (y < zero));
            split[i][j] = {NegatedLowHigh{plus[0], plus[0]}, NegatedLowHigh{minus[0], minus[0]}};
            split[i + 1][j] = {NegatedLowHigh{plus[1], plus[1]}, NegatedLowHigh{minus[1], minus[1]}};
        }
    // Y's products with J(X)'s columns V_x and V_y (-1 in the even, in the
    // odd rows), independent of X: P = -(Y_i0 + Y_i2 + Y_i4) and -(Y_i1 +
    // Y_i3 + Y_i5), as (-lo, hi) pairs, i.e. (RU(-P), RU(P)), the sums of the
    // y's and of the -y's rounded up; two rows at a time (rows i, i + 1 in
    // the lanes).
    std::array<NegatedLowHigh, 6> times_V_x, times_V_y;
    for (int i = 0; i < 6; i += 2)
        for (int axis = 0; axis < 2; ++axis) {
            NegatedLowHigh sum{0, 0}, negated_sum{0, 0};
            for (int c = 0; c < 3; ++c) {
                const NegatedLowHigh y{Y(i, 2 * c + axis), Y(i + 1, 2 * c + axis)};
                sum += y, negated_sum += -y;
            }
            std::array<NegatedLowHigh, 6>& products = axis == 0 ? times_V_x : times_V_y;
            products[i] = NegatedLowHigh{sum[0], negated_sum[0]};
            products[i + 1] = NegatedLowHigh{sum[1], negated_sum[1]};
        }
    std::array<NegatedLowHigh, 6> F_pair;
    for (int j = 0; j < 6; ++j) F_pair[j] = negated_low_high(F[j]);
    std::array<UpwardInterval, 6> correction;  // Y F(m)
    std::array<double, 6> r;
    for (int i = 0; i < 6; ++i) {
        NegatedLowHigh product{0, 0};
        for (int j = 0; j < 6; ++j) product += times(split[i][j], F_pair[j]);
        const UpwardInterval sum(-product[0], product[1]);
        if (!sum.finite()) return std::nullopt;
        correction[i] = sum;
        const double unit = i < 3 ? 1.0 : length_scale;
        if (converged_step_only && !(magnitude(sum) <= kConvergedStep * (std::fabs(m[i]) + unit))) return std::nullopt;
        r[i] = 2 * magnitude(sum) + 1e-15 * (std::fabs(m[i]) + unit);
    }
    for (int attempt = 0; attempt < 3; ++attempt) {
        std::array<UpwardInterval, 6> X, K;
        std::array<double, 6> reach_of_box;  // |X - m| bound: the rounding widened X beyond m +- r
        for (int j = 0; j < 6; ++j) {
            X[j] = UpwardInterval(-(r[j] - m[j]), m[j] + r[j]);
            reach_of_box[j] = Interval::max(m[j] - X[j].lo, X[j].hi - m[j]);
        }
        tritangent_system<UpwardInterval>(k, flipped, X, nullptr, true, at);
        // J(X)'s nonzero entries (tritangent_system) but V's: in rows 2c,
        // 2c + 1, column t_c holds scale_c nu_c^perp and column rho nu_c.
        std::array<NegatedLowHigh, 3> t_column_x, t_column_y, normal_x, normal_y;
        for (int c = 0; c < 3; ++c) {
            const UpwardInterval scale = t_column_scale(at[c], X[3]);
            t_column_x[c] = negated_low_high(-(scale * at[c].ny)), t_column_y[c] = negated_low_high(scale * at[c].nx);
            normal_x[c] = negated_low_high(at[c].nx), normal_y[c] = negated_low_high(at[c].ny);
        }
        bool inside = true;
        std::array<double, 6> reach{};
        for (int i = 0; i < 6; ++i) {
            // Row i of Y J(X), as (-lo, hi) pairs.
            std::array<NegatedLowHigh, 6> row;
            const SplitEntry* y = split[i];
            row[3] = NegatedLowHigh{0, 0};
            for (int c = 0; c < 3; ++c) {
                row[c] = times(y[2 * c], t_column_x[c]) + times(y[2 * c + 1], t_column_y[c]);
                row[3] += times(y[2 * c], normal_x[c]) + times(y[2 * c + 1], normal_y[c]);
            }
            row[4] = times_V_x[i], row[5] = times_V_y[i];
            // Row i of I - Y J(X) times X - m, within [-reach_of_box,
            // reach_of_box]: the entries' magnitudes times that. With
            // delta - [lo, hi] as the pair row[c] + (delta, -delta) =
            // (delta - lo, hi - delta) rounded up, the magnitude is at most
            // the larger lane; two entries at a time (their first lanes and
            // their second lanes side by side).
            row[i] += NegatedLowHigh{1, -1};
            NegatedLowHigh spread_pair{0, 0}, lanes_sum{0, 0};
            for (int c = 0; c < 6; c += 2) {
                const NegatedLowHigh first{row[c][0], row[c + 1][0]}, second{row[c][1], row[c + 1][1]};
                spread_pair += (first > second ? first : second) * NegatedLowHigh{reach_of_box[c], reach_of_box[c + 1]};
                lanes_sum += first + second;
            }
            // The selection may drop a NaN lane (0 * inf in times()); the
            // plain sum of all lanes keeps it (and an infinite bound): then
            // nothing is proved.
            if (!std::isfinite(lanes_sum[0] + lanes_sum[1])) return std::nullopt;
            const double spread = spread_pair[0] + spread_pair[1];
            K[i] = UpwardInterval(m[i]) - correction[i] + UpwardInterval(-spread, spread);
            if (!K[i].finite()) return std::nullopt;
            if (!(K[i].lo > X[i].lo && K[i].hi < X[i].hi)) inside = false;
            reach[i] = Interval::max(std::fabs(K[i].lo - m[i]), std::fabs(K[i].hi - m[i]));
        }
        if (inside) {
            if (!signed_distances(k, K[3]) || !counterclockwise(at)) return std::nullopt;
            std::array<Interval, 6> box;
            for (int i = 0; i < 6; ++i) box[i] = K[i].interval();
            return box;
        }
        for (int i = 0; i < 6; ++i) r[i] = 2 * Interval::max(r[i], reach[i]);
    }
    return std::nullopt;
}

// The center alone, when the circle touches every site from outside
// (docs/DESIGN.md §4.1a, "by distances"). Then V is a root of the plane system
//     G(V) = (d_1(V) - d_2(V), d_1(V) - d_3(V)) = 0,
// d_i the distance to E_i, and Krawczyk's test on G needs three boundary
// points at the point m, none over a box:
// - At a point c and an exact boundary point P (at the double parameter
//   m_i) with outward unit normal n: E_i lies in the half-plane
//   n . (y - P) <= 0, so n . (c - P) <= d_i(c) <= |c - P| (c is outside E_i
//   when the left side is positive). E_i's nearest point Q to c lies in that
//   half-plane no farther from c than P, so n . (c - Q)/|c - Q| >=
//   n . (c - P)/|c - P| = cos delta: grad d_i(c) = (c - Q)/|c - Q| is within
//   the angle delta of n, and tan delta = |n x (c - P)| / n . (c - P) (the
//   `slope` below) bounds delta and |grad d_i(c) - n| = 2 sin(angle / 2).
// - Over a box: c - Q(c) is 1-Lipschitz (the identity minus the projection
//   on a convex set is nonexpansive), and unit vectors obey
//   |u/|u| - v/|v|| <= 2 |u - v| / (|u| + |v|) (Dunkl-Williams, in an inner
//   product space), so |grad d_i(y) - grad d_i(c)| <= |y - c| / (d_i(c) - |y - c|).
// So J(X)'s rows grad d_1 - grad d_k are enclosed from the normals at m, and
// K(X) inside X proves one root V of G in X: a point at the same distance
// rho > 0 from the three sites, i.e. a circle touching each from outside at
// its nearest point; with those points counter-clockwise (the normals
// grad d_i(V) are: P_i = V - rho grad d_i(V)), THE Voronoi circle, as in
// voronoi_circle_enclosure.hpp. rho = d_i(V) is within |V - c| of d_i(c).
// The tangency parameters follow from the normals' directions: the normal's
// angle grows with the ellipse angle theta at the rate a b / |g|^2 >=
// a b / max(a, b)^2 (boundary_at), and dt/dtheta = (1 + t^2)/2 (either chart).
// Under the upward rounding mode as krawczyk(), whose arguments this takes
// (`converged_step_only` the same rule, on G's Newton step), in
// midpoint-radius balls (util/upward_ball.hpp: its operands are a few ulps
// wide, and a ball's operations do not branch on signs); it fails where a
// center is not proven outside a site (crossing sites, rho <= 0), and
// krawczyk() runs.
ELLVOR_UPWARD_ROUNDING_FUNCTION std::optional<std::array<Interval, 6>> distance_krawczyk(
    const std::array<Shape<UpwardInterval>, 3>& k, const std::array<bool, 3>& flipped, const Vector6& m,
    double length_scale, bool converged_step_only = false) {
    const UpwardRoundingScope upward;
    using B = UpwardBall;
    const double c[2] = {m[4], m[5]};
    std::array<BoundaryPoint<B>, 3> at;
    double near[3], far[3], slope[3];  // d_i(c) in [near, far]; tan delta_i <= slope
    for (int i = 0; i < 3; ++i) {
        const Shape<UpwardInterval>& e = k[i];
        const Shape<B> shape{B::around(e.a),  B::around(e.b),  B::around(e.cos), B::around(e.sin),
                             B::around(e.xc), B::around(e.yc), B::around(e.ab)};
        boundary_at(shape, flipped[i], B(m[i]), Parts::point, at[i]);
        const B wx = B(c[0]) - at[i].px, wy = B(c[1]) - at[i].py;
        const B along = at[i].nx * wx + at[i].ny * wy, across = at[i].nx * wy - at[i].ny * wx;
        const B distance = (wx.square() + wy.square()).sqrt();
        near[i] = along.lower();
        // c not proven outside E_i (or an overflow: NaN fails too).
        if (!(near[i] > 0) || !across.finite() || !distance.finite()) return std::nullopt;
        far[i] = distance.upper();
        slope[i] = across.magnitude() / near[i];
    }
    const B G[2] = {B::around(UpwardInterval(near[0], far[0]) - UpwardInterval(near[1], far[1])),
                    B::around(UpwardInterval(near[0], far[0]) - UpwardInterval(near[2], far[2]))};
    // Y ~ J(c)^-1 from the normals' midpoints (any Y is sound).
    const double j00 = at[0].nx.mid - at[1].nx.mid, j01 = at[0].ny.mid - at[1].ny.mid;
    const double j10 = at[0].nx.mid - at[2].nx.mid, j11 = at[0].ny.mid - at[2].ny.mid;
    const double det = j00 * j11 - j01 * j10;
    const double Y[2][2] = {{j11 / det, -j01 / det}, {-j10 / det, j00 / det}};
    if (!std::isfinite(Y[0][0] + Y[0][1] + Y[1][0] + Y[1][1])) return std::nullopt;  // finite only if each is
    B correction[2];  // Y G(c)
    double r[2];
    for (int j = 0; j < 2; ++j) {
        correction[j] = Y[j][0] * G[0] + Y[j][1] * G[1];
        if (!correction[j].finite()) return std::nullopt;
        const double unit = std::fabs(c[j]) + length_scale;
        // Converged: Newton's step from c (the midpoint) is; the radius is
        // the rounding of G(c), which no further step removes.
        if (converged_step_only && !(std::fabs(correction[j].mid) <= kConvergedStep * unit)) return std::nullopt;
        r[j] = 2 * correction[j].magnitude() + 1e-15 * unit;
    }
    for (int attempt = 0; attempt < 3; ++attempt) {
        double X_lo[2], X_hi[2];
        double reach_of_box[2];  // |y - c| bound per axis: the rounding widened X beyond c +- r
        for (int j = 0; j < 2; ++j) {
            X_lo[j] = -(r[j] - c[j]), X_hi[j] = c[j] + r[j];
            reach_of_box[j] = Interval::max(c[j] - X_lo[j], X_hi[j] - c[j]);
        }
        const double reach = std::sqrt(reach_of_box[0] * reach_of_box[0] + reach_of_box[1] * reach_of_box[1]);
        B gradient_x[3], gradient_y[3];  // grad d_i over X
        for (int i = 0; i < 3; ++i) {
            const double room = -(reach - near[i]);  // d_i(y) >= near - reach, rounded down
            if (!(room > 0)) return std::nullopt;
            const double spread = slope[i] + reach / room;
            gradient_x[i] = {at[i].nx.mid, at[i].nx.rad + spread}, gradient_y[i] = {at[i].ny.mid, at[i].ny.rad + spread};
        }
        const B J[2][2] = {{gradient_x[0] - gradient_x[1], gradient_y[0] - gradient_y[1]},
                           {gradient_x[0] - gradient_x[2], gradient_y[0] - gradient_y[2]}};
        bool inside = true;
        double K_lo[2], K_hi[2], reach_of_K[2];
        for (int j = 0; j < 2; ++j) {
            double spread = 0;  // |(I - Y J(X)) (X - c)| bound, row j
            for (int l = 0; l < 2; ++l) {
                const B entry = B(j == l ? 1.0 : 0.0) - (Y[j][0] * J[0][l] + Y[j][1] * J[1][l]);
                spread += entry.magnitude() * reach_of_box[l];
            }
            const B K = B(c[j]) - correction[j] + B(0, spread);
            if (!K.finite()) return std::nullopt;
            K_lo[j] = K.lower(), K_hi[j] = K.upper();
            if (!(K_lo[j] > X_lo[j] && K_hi[j] < X_hi[j])) inside = false;
            reach_of_K[j] = Interval::max(c[j] - K_lo[j], K_hi[j] - c[j]);
        }
        if (!inside) {
            for (int j = 0; j < 2; ++j) r[j] = 2 * Interval::max(r[j], reach_of_K[j]);
            continue;
        }
        // The root V in K: rho, the normals grad d_i(V) and the tangency parameters.
        const double reach_V = std::sqrt(reach_of_K[0] * reach_of_K[0] + reach_of_K[1] * reach_of_K[1]);
        double rho_lo = 0, rho_hi = HUGE_VAL;
        B normal_x[3], normal_y[3];
        std::array<Interval, 6> box;
        for (int i = 0; i < 3; ++i) {
            const double room = -(reach_V - near[i]);  // positive: reach_V <= reach
            rho_lo = Interval::max(rho_lo, room), rho_hi = Interval::min(rho_hi, far[i] + reach_V);
            const double chord = reach_V / room;  // |grad d_i(V) - grad d_i(c)|
            if (!(chord <= 1)) return std::nullopt;
            const double spread = slope[i] + chord;
            normal_x[i] = {at[i].nx.mid, at[i].nx.rad + spread}, normal_y[i] = {at[i].ny.mid, at[i].ny.rad + spread};
            // The angle from n_i to grad d_i(V): delta_i + 2 arcsin(chord / 2),
            // and arcsin x <= (pi / 2) x on [0, 1].
            const double angle = slope[i] + 1.5708 * chord;
            // |theta_i - theta(m_i)| <= angle max(a, b)^2 / (a b); t moves at
            // most 1 while (1 + t^2)/2 <= (1 + (|m_i| + 1)^2)/2.
            const double major = Interval::max(k[i].a.hi, k[i].b.hi), t_bound = std::fabs(m[i]) + 1;
            const double step = angle * (major * major) / k[i].ab.lo * (1 + t_bound * t_bound) / 2;
            if (!(step <= 1)) return std::nullopt;
            box[i] = Interval(-(step - m[i]), m[i] + step);
        }
        if (!(rho_lo > 0 && rho_lo <= rho_hi)) return std::nullopt;
        const B orientation = (normal_x[1] - normal_x[0]) * (normal_y[2] - normal_y[0]) -
                              (normal_y[1] - normal_y[0]) * (normal_x[2] - normal_x[0]);
        if (!(orientation.lower() > 0)) return std::nullopt;
        box[3] = Interval(rho_lo, rho_hi), box[4] = Interval(K_lo[0], K_hi[0]), box[5] = Interval(K_lo[1], K_hi[1]);
        return box;
    }
    return std::nullopt;
}

// The circle of a certified box (t_1, t_2, t_3, rho, V_x, V_y).
DoubleVoronoiCircle circle_of(const std::array<Interval, 6>& box, const std::array<bool, 3>& flipped,
                              bool by_distances) {
    DoubleVoronoiCircle circle;
    circle.by_distances = by_distances;
    for (int i = 0; i < 3; ++i) circle.parameter[i] = box[i];
    circle.flipped = flipped;
    circle.radius = box[3], circle.center_x = box[4], circle.center_y = box[5];
    return circle;
}

// J d = f for the Jacobian of the tritangent system, by its structure
// (tritangent_system): rows 2i, 2i + 1 read
//     scale_i nu_i^perp d_ti + nu_i d_rho - d_V = f_i.
// Their dot products with nu_i (nu_i . nu_i^perp = 0, |nu_i| = 1) leave
//     d_rho - nu_i . d_V = nu_i . f_i,   i = 1, 2, 3,
// three equations in (d_rho, d_V), solved with the inverse of their matrix M;
// those with nu_i^perp give d_ti = nu_i^perp . (f_i + d_V) / scale_i.
class TritangentNewtonSolver {
public:
    TritangentNewtonSolver(const std::array<BoundaryPoint<double>, 3>& at, double rho) {
        for (int i = 0; i < 3; ++i) nx_[i] = at[i].nx, ny_[i] = at[i].ny, scale_[i] = t_column_scale(at[i], rho);
        // M's rows are m_i = (1, -nu_i), and M^-1 = adj(M) / det, where
        // adj(M)'s column c is m_u x m_v, (u, v) = (c + 1, c + 2) mod 3:
        //   (nu_u x nu_v, ny_v - ny_u, nx_u - nx_v),
        // and det = m_0 . (m_1 x m_2), the sum of the three nu_u x nu_v.
        constexpr int kNext[3] = {1, 2, 0}, kAfterNext[3] = {2, 0, 1};
        det_ = 0;
        for (int c = 0; c < 3; ++c) {
            const int u = kNext[c], v = kAfterNext[c];
            adjugate_[0][c] = nx_[u] * ny_[v] - ny_[u] * nx_[v];
            adjugate_[1][c] = ny_[v] - ny_[u];
            adjugate_[2][c] = nx_[u] - nx_[v];
            det_ += adjugate_[0][c];
        }
        usable_ = det_ != 0 && scale_[0] != 0 && scale_[1] != 0 && scale_[2] != 0;
    }
    // False when J is singular (then nothing is certified from it).
    bool usable() const { return usable_; }

    Vector6 solve(const std::array<double, 6>& f) const {
        double rhs[3], d[6];
        for (int i = 0; i < 3; ++i) rhs[i] = nx_[i] * f[2 * i] + ny_[i] * f[2 * i + 1];
        for (int r = 0; r < 3; ++r)
            d[3 + r] = (adjugate_[r][0] * rhs[0] + adjugate_[r][1] * rhs[1] + adjugate_[r][2] * rhs[2]) / det_;
        for (int i = 0; i < 3; ++i) d[i] = tangential(i, f[2 * i], f[2 * i + 1], d) / scale_[i];
        return Eigen::Map<const Vector6>(d);
    }
    // J^-1 (to rounding: Krawczyk's Y need not be exact), column by column:
    // solve() of the unit vector of row 2k + axis, whose only nonzero
    // nu_i . f_i is nu_k's component on the axis; divisions as products with
    // reciprocals made once.
    Matrix6 inverse() const {
        const double inverse_det = 1 / det_;
        const double inverse_scale[3] = {1 / scale_[0], 1 / scale_[1], 1 / scale_[2]};
        Matrix6 Y;
        for (int k = 0; k < 3; ++k)
            for (int axis = 0; axis < 2; ++axis) {
                const double component = (axis == 0 ? nx_[k] : ny_[k]) * inverse_det;
                double d[6];
                for (int r = 0; r < 3; ++r) d[3 + r] = adjugate_[r][k] * component;
                for (int i = 0; i < 3; ++i) d[i] = tangential(i, 0, 0, d) * inverse_scale[i];
                d[k] += (axis == 0 ? -ny_[k] : nx_[k]) * inverse_scale[k];  // f_k's own term
                Y.col(2 * k + axis) = Eigen::Map<const Vector6>(d);
            }
        return Y;
    }

private:
    // nu_i^perp . (f_i + d_V) for f_i = (fx, fy), d_V = (d[4], d[5]): d_ti
    // times scale_i.
    double tangential(int i, double fx, double fy, const double* d) const {
        return nx_[i] * (fy + d[5]) - ny_[i] * (fx + d[4]);
    }

    std::array<double, 3> nx_, ny_, scale_;
    double adjugate_[3][3], det_;
    bool usable_ = false;
};

// The fraction of the Newton correction to take from x: 1, halved (at most
// 5 times) while the step does not lower the residual |F|^2. Far from the
// circle a full step can overshoot around elongated sites that nearly touch
// (dense packings) and cycle; near it the full step is taken.
double damped_step(const std::array<Shape<double>, 3>& shape, const std::array<bool, 3>& flipped,
                   const std::array<double, 6>& x, const std::array<double, 6>& F, const Vector6& correction) {
    constexpr int kHalvings = 6;
    double residual = 0;
    for (double f : F) residual += f * f;
    double step = 1;
    for (int halvings = 1; halvings < kHalvings; ++halvings, step /= 2) {
        std::array<double, 6> trial = x, trial_F;
        std::array<bool, 3> trial_flipped = flipped;
        for (int i = 0; i < 6; ++i) trial[i] -= step * correction[i];
        for (int i = 0; i < 3; ++i)
            if (std::fabs(trial[i]) > 1) trial[i] = -1 / trial[i], trial_flipped[i] = !trial_flipped[i];
        std::array<BoundaryPoint<double>, 3> at;
        tritangent_system<double>(shape, trial_flipped, trial, &trial_F, false, at);
        double trial_residual = 0;
        for (double f : trial_F) trial_residual += f * f;
        if (trial_residual < residual) break;
    }
    return step;
}

// Newton in doubles in the charts from x, then the certificates (by
// distances, else the 6 x 6 Krawczyk test);
// `shape` and `enclosed` are the sites in doubles and enclosed. Keeps each
// parameter in the chart where it is at most 1 in magnitude. `damped`: steps
// by damped_step, and more of them (the retry of a start that did not
// converge); `diverged` (if given) says whether Newton failed to converge.
// A root Newton reached only to the rounding noise becomes the Arb solver's
// start if it looks like the counter-clockwise circle in doubles: rho > 0
// and the normals (p: at Newton's last point, a stalled step before x)
// counter-clockwise; the system's other roots would cost Arb a failed
// attempt. Out of line: rare, and kept out of Newton's code.
[[gnu::noinline]] void offer_stalled_root(const std::array<BoundaryPoint<double>, 3>& p,
                                          const std::array<bool, 3>& flipped, const std::array<double, 6>& x,
                                          std::optional<StalledDoubleRoot>& stalled) {
    if (!(x[3] > 0)) return;
    const double orientation = (p[1].nx - p[0].nx) * (p[2].ny - p[0].ny) - (p[1].ny - p[0].ny) * (p[2].nx - p[0].nx);
    if (orientation > 0) stalled = StalledDoubleRoot{flipped, x};
}

std::optional<DoubleVoronoiCircle> newton_then_certify(const std::array<Shape<double>, 3>& shape,
                                                       const std::array<Shape<UpwardInterval>, 3>& enclosed,
                                                       DoubleCertificate which,
                                                       std::array<bool, 3> flipped, std::array<double, 6> x,
                                                       double length_scale, bool damped = false,
                                                       bool* diverged = nullptr,
                                                       std::optional<StalledDoubleRoot>* stalled = nullptr) {
    if (diverged) *diverged = true;
    const int kSteps = damped ? 30 : 12;
    // An ill-conditioned root (a circle 10^4 times the sites' size or more)
    // stops Newton at the rounding noise, far above kConvergedStep: a step that
    // no longer shrinks, below kStalled, is offered to Krawczyk (which decides).
    constexpr double kStalled = 1e-6;
    // Newton converges quadratically: after a step below kNearlyConverged the
    // next one is expected below kConvergedStep. Krawczyk's F(m) is that step's
    // evaluation, so the test is tried at once (the first time only),
    // provided that Y F(m) is that small (`converged_step_only`); when not,
    // or when it fails, Newton goes on as if it had not been tried. (Y from
    // the step before: any nonsingular Y is sound.)
    constexpr double kNearlyConverged = 1e-7;
    bool tried_early = false;
    const auto certified = [&](const std::array<Interval, 6>& box, bool by_distances) {
        if (diverged) *diverged = false;
        return circle_of(box, flipped, by_distances);
    };
    std::array<double, 6> F;
    std::array<BoundaryPoint<double>, 3> at;
    Matrix6 Y;
    bool converged = false;
    double previous = HUGE_VAL;  // the last relative step size
    for (int step = 0; step < kSteps && !converged; ++step) {
        for (int i = 0; i < 3; ++i)
            if (std::fabs(x[i]) > 1) x[i] = -1 / x[i], flipped[i] = !flipped[i];
        tritangent_system<double>(shape, flipped, x, &F, true, at);
        const TritangentNewtonSolver newton(at, x[3]);
        if (!newton.usable()) return std::nullopt;
        const Vector6 correction = newton.solve(F);
        if (!std::isfinite(correction.sum())) return std::nullopt;  // a sum is finite only if each term is
        double relative = 0;
        const double fraction = damped ? damped_step(shape, flipped, x, F, correction) : 1.0;
        for (int i = 0; i < 6; ++i) {
            x[i] -= fraction * correction[i];
            const double unit = i < 3 ? 1.0 : length_scale;
            // Never NaN: the correction is finite and the divisor positive.
            relative = std::max(relative, std::fabs(correction[i]) / (std::fabs(x[i]) + unit));
        }
        converged = relative <= kConvergedStep || (relative <= kStalled && relative > previous / 4);
        previous = relative;
        // Y: the inverse Jacobian one tiny step before the midpoint (any
        // nonsingular Y is sound; a close one contracts).
        if (converged) Y = newton.inverse();
        if (!converged && relative <= kNearlyConverged && !tried_early) {
            tried_early = true;
            const Eigen::Map<const Vector6> m(x.data());
            if (which == DoubleCertificate::distances_first)
                if (const auto box = distance_krawczyk(enclosed, flipped, m, length_scale, true)) return certified(*box, true);
            Y = newton.inverse();
            if (!std::isfinite(Y.sum())) continue;  // a sum is finite only if each term is
            if (const auto box = krawczyk(enclosed, flipped, m, Y, length_scale, true)) return certified(*box, false);
        }
    }
    if (!converged) return std::nullopt;
    const Eigen::Map<const Vector6> m(x.data());
    if (which == DoubleCertificate::distances_first)
        if (const auto box = distance_krawczyk(enclosed, flipped, m, length_scale)) return certified(*box, true);
    if (!std::isfinite(Y.sum())) return std::nullopt;
    if (diverged) *diverged = false;
    const std::optional<std::array<Interval, 6>> box = krawczyk(enclosed, flipped, m, Y, length_scale);
    if (!box) {
        // Stalled at the rounding noise: a start for Arb (the first one met).
        if (stalled && !*stalled && previous > kConvergedStep) offer_stalled_root(at, flipped, x, *stalled);
        return std::nullopt;
    }
    return certified(*box, false);
}

}  // namespace

std::optional<DoubleVoronoiCircle> certify_voronoi_circle_in_doubles(const Ellipse& e1, const Ellipse& e2,
                                                                      const Ellipse& e3,
                                                                      std::optional<StalledDoubleRoot>* stalled,
                                                                      DoubleCertificate which) {
    if (stalled) stalled->reset();
    const std::array<const Ellipse*, 3> sites = {&e1, &e2, &e3};
    std::array<Shape<double>, 3> shape;
    std::array<Shape<UpwardInterval>, 3> enclosed;
    double size = 0;
    for (int i = 0; i < 3; ++i) {
        shape[i] = double_shape(*sites[i]);
        enclosed[i] = interval_shape(*sites[i]);
        size = std::max({size, shape[i].a, shape[i].b});
    }
    // Starts: the Apollonius circles of the circle models, each tangency at
    // the point of E_i whose outward normal points at the center (exact for
    // circles, close for a circle large or far against the site):
    // (cos theta, sin theta) = (a d_u, b d_v)/|(a d_u, b d_v)| for the
    // direction d from the site's center in its frame.
    struct Retry {
        std::array<bool, 3> flipped;
        std::array<double, 6> x;
        double length_scale;
    };
    std::vector<Retry> retries;
    for (CircleModel model : kCircleModels)
        for (const std::array<double, 3>& circle : model_apollonius_circles(e1, e2, e3, model)) {
            std::array<double, 6> x;
            std::array<bool, 3> flipped;
            x[3] = circle[0], x[4] = shape[0].xc + circle[1], x[5] = shape[0].yc + circle[2];
            for (int i = 0; i < 3; ++i) {
                const Shape<double>& k = shape[i];
                const double dx = x[4] - k.xc, dy = x[5] - k.yc;
                const double du = k.a * (k.cos * dx + k.sin * dy), dv = k.b * (k.cos * dy - k.sin * dx);
                const double norm = std::hypot(du, dv), c = du / norm, s = dv / norm;
                // t = tan(theta/2) = s/(1 + c); flipped, u = -1/t = -s/(1 - c).
                flipped[i] = c < 0;
                x[i] = flipped[i] ? -s / (1 - c) : s / (1 + c);
            }
            if (!std::all_of(x.begin(), x.end(), [](double v) { return std::isfinite(v); })) continue;
            bool diverged = false;
            if (auto certified = newton_then_certify(shape, enclosed, which, flipped, x, std::max(size, circle[0]), false,
                                                     &diverged, stalled))
                return certified;
            if (diverged) retries.push_back({flipped, x, std::max(size, circle[0])});
        }
    // The starts where plain Newton did not converge, again with damped steps
    // (elongated sites that nearly touch, as in dense packings: the full
    // step overshoots and cycles). Only after every plain start failed, so
    // the inputs those decide cost the same as before.
    for (const Retry& r : retries)
        if (auto certified = newton_then_certify(shape, enclosed, which, r.flipped, r.x, r.length_scale, true, nullptr, stalled))
            return certified;
    // Circles far larger than the sites (three sites nearly on a line): the
    // models' circles may lead Newton to the clockwise one, or not exist; the
    // tangent-line starts of huge_circle_start.hpp lead to the right one.
    // Their doubles first (most such circles are below 2^20 sizes); the Arb
    // pass only when those fail (a gap the doubles do not resolve).
    std::optional<DoubleVoronoiCircle> certified;
    const auto try_start = [&](const std::array<bool, 3>& flipped, const std::array<double, 6>& x) {
        if (!std::all_of(x.begin(), x.end(), [](double v) { return std::isfinite(v); })) return false;
        certified = newton_then_certify(shape, enclosed, which, flipped, x, std::max(size, x[3]), false, nullptr, stalled);
        if (certified) certified->from_tangent_line = true;
        return certified.has_value();
    };
    if (for_each_huge_circle_start_in_doubles(e1, e2, e3, precision::kHugeCircleBitsInDoubles,
                                              [&](const DoubleCircleStart& start) {
                                                  return try_start(start.flipped, start.x);
                                              }))
        return certified;
    // The circles met along the bisectors (bisector_walk_start.hpp): sites
    // close against their sizes, where the models' circles lead Newton to the
    // other circle or nowhere; before the Arb pass, which costs more.
    const auto try_walked = [&](const VoronoiCircleGuess& c) {
        std::array<bool, 3> flipped;
        std::array<double, 6> x = {0, 0, 0, c.radius, c.x, c.y};
        for (int i = 0; i < 3; ++i) {
            // t = tan(theta/2) = sin/(1 + cos); flipped, u = -1/t = -sin/(1 - cos).
            const double cos = std::cos(c.theta[i]), sin = std::sin(c.theta[i]);
            flipped[i] = cos < 0;
            x[i] = flipped[i] ? -sin / (1 - cos) : sin / (1 + cos);
        }
        certified = newton_then_certify(shape, enclosed, which, flipped, x, std::max(size, c.radius), false, nullptr, stalled);
        return certified.has_value();
    };
    if (for_each_bisector_walk_circle(e1, e2, e3, try_walked)) return certified;
    for_each_huge_circle_start(e1, e2, e3, precision::kHugeCircleBitsInDoubles, [&](const VoronoiCircleStart& start) {
        std::array<double, 6> x;
        for (int i = 0; i < 3; ++i) x[i] = arf_get_d(arb_midref(start.parameter[i].get()), ARF_RND_NEAR);
        x[3] = arf_get_d(arb_midref(start.radius.get()), ARF_RND_NEAR);
        x[4] = arf_get_d(arb_midref(start.center_x.get()), ARF_RND_NEAR);
        x[5] = arf_get_d(arb_midref(start.center_y.get()), ARF_RND_NEAR);
        return try_start(start.flipped, x);
    });
    return certified;
}

std::optional<DoubleVoronoiCircle> certify_voronoi_circle_by_distances_at(const Ellipse& e1, const Ellipse& e2,
                                                                          const Ellipse& e3,
                                                                          const std::array<bool, 3>& flipped,
                                                                          const std::array<double, 6>& m) {
    const std::array<const Ellipse*, 3> sites = {&e1, &e2, &e3};
    std::array<Shape<UpwardInterval>, 3> enclosed;
    double size = m[3];
    for (int i = 0; i < 3; ++i) {
        enclosed[i] = interval_shape(*sites[i]);
        size = std::max({size, enclosed[i].a.hi, enclosed[i].b.hi});
    }
    const auto box = distance_krawczyk(enclosed, flipped, Eigen::Map<const Vector6>(m.data()), size);
    if (!box) return std::nullopt;
    return circle_of(*box, flipped, true);
}

}  // namespace ellvor
