// Order of Voronoi vertices along the bisector of two sites (research digest
// 2.4): every circle externally tangent to E1 and E2 touches E1 on the arc
// facing E2, and along the bisector the tangency point moves monotonically,
// counter-clockwise, from E1's "departure" external bitangent point (the end
// at the infinite vertex (E2, E1, infinity)) to its "arrival" point (the end
// at (E1, E2, infinity)). A vertex's position is that counter-clockwise angle.
#pragma once

#include "predicates/external_bitangent.hpp"
#include "sites/ellipse.hpp"
#include "subdivision/voronoi_circle_enclosure.hpp"

#include <optional>

namespace ellvor {

class BisectorFrame {
public:
    // E1, E2 separated (throws Error otherwise).
    BisectorFrame(const Ellipse& e1, const Ellipse& e2);
    // Position (radians in (0, 2 pi)) of the circle whose tangency point on E1
    // is at chart parameter `parameter` (flipped: u = -1/t). The ball may
    // straddle 0 only for circles at the departure end (never for finite ones).
    Ball position(const Ball& parameter, bool flipped, long prec);

private:
    BoundaryParameter departure_;
};

// Angle theta of E's parametrization (t = tan(theta/2)) for a chart
// parameter: 2 atan(t), or 2 atan2(1, -u) in the flipped chart (continuous
// through the i-point, theta = pi).
Ball parameter_angle(const Ball& parameter, bool flipped, long prec);

}  // namespace ellvor
