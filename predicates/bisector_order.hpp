// Order of Voronoi vertices along the bisector of two sites (docs/DESIGN.md
// §2): every circle externally tangent to E1 and E2 touches E1 on the arc
// facing E2, and along the bisector the tangency point moves monotonically,
// counter-clockwise, from E1's "departure" external bitangent point (the end
// at the infinite vertex (E2, E1, infinity)) to its "arrival" point (the end
// at (E1, E2, infinity)). A vertex's position is that counter-clockwise angle.
#pragma once

#include "predicates/external_bitangent.hpp"
#include "decision/staged_refinement.hpp"
#include "sites/ellipse.hpp"
#include "subdivision/voronoi_circle_enclosure.hpp"
#include "subdivision/voronoi_circle_in_doubles.hpp"
#include "util/interval.hpp"

#include <optional>

namespace ellvor {

class BisectorFrame {
public:
    // E1, E2 separated (throws Error otherwise).
    BisectorFrame(const Ellipse& e1, const Ellipse& e2);
    // Position (radians in (0, 2 pi)) of the circle whose tangency point on E1
    // is at chart parameter `parameter` (flipped: u = -1/t): a ball inside
    // (0, 2 pi), or the whole [0, 2 pi] when this precision cannot tell a
    // position near the departure end from one near the arrival end.
    Ball position(const Ball& parameter, bool flipped, long prec);

private:
    BoundaryParameter departure_;
};

// Position along the bisector frame of the Voronoi vertex of `solver`'s
// triple (which must have a counter-clockwise circle), whose triple has the
// frame's E1 at `index`: refines the solver to about prec bits first.
Ball vertex_position(BisectorFrame& frame, VoronoiCircleSolver& solver, int index, long prec);

// Order of two Voronoi vertices along the bisector of (E1, E2) (both circles
// touch E1 and E2; `index` is E1's place in each triple): NEGATIVE if `a`
// comes first from the departure end, POSITIVE if after, ZERO if they are the
// same vertex. The staged refinement of staged_refinement.hpp: the positions
// in Arb up to the cap; then the exact stage decides whether they touch E1 at
// the same point (voronoi_vertex_equality.hpp), and if not, the subdivision
// resumes until it separates them. Both triples must have a counter-clockwise
// circle (certification is complete: a triple without one throws Error).
// Undecided only with options.exact_stage = false.
Decision<Sign> order_on_bisector(BisectorFrame& frame, VoronoiCircleSolver& a, int index_a, VoronoiCircleSolver& b,
                                 int index_b, const RefinementOptions& options);

// The filter stage of order_on_bisector, on the double certificates of the
// two vertices: positions as pseudo-angles, exact about what they know.
// Instead of theta, P = t on the chart |t| <= 1 (theta in [-pi/2, pi/2])
// and P = 2 + u on the flipped one (u = -1/t, theta in [pi/2, 3 pi/2]):
// increasing with theta, continuous through both seams, period 4, so it
// orders points of E1 counter-clockwise as theta does, with no arctangent.
// The departure point comes from the proven departure normal of
// support_function.hpp (the boundary point with that outward normal).
class BisectorFrameInDoubles {
public:
    BisectorFrameInDoubles(const Ellipse& e1, const Ellipse& e2);
    // Position in (0, 4) of the vertex whose tangency point on E1 has this
    // chart parameter; nullopt when these intervals cannot tell (the
    // departure not proven, a parameter outside its chart's [-1, 1], a
    // position touching the departure end).
    std::optional<Interval> position(const Interval& parameter, bool flipped) const;

private:
    std::optional<Interval> departure_;  // the departure point's pseudo-angle
};

// NEGATIVE or POSITIVE when the double enclosures of the two vertices
// (E1 at `index_a`, `index_b` of their triples) order them along the
// bisector; nullopt otherwise (equal vertices included: the Arb and exact
// stages of order_on_bisector decide those).
std::optional<Sign> order_on_bisector_in_doubles(const BisectorFrameInDoubles& frame, const DoubleVoronoiCircle& a,
                                                 int index_a, const DoubleVoronoiCircle& b, int index_b);

// Angle theta of E's parametrization (t = tan(theta/2)) for a chart
// parameter: 2 atan(t), or 2 atan2(1, -u) in the flipped chart (continuous
// through the i-point, theta = pi).
Ball parameter_angle(const Ball& parameter, bool flipped, long prec);

}  // namespace ellvor
