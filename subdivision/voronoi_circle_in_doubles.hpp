// The Voronoi circle of an ordered triple (E1, E2, E3) certified in double
// intervals: the floating-point stage in front of the Arb solver
// (voronoi_circle_enclosure.hpp), with the same certificate.
//
// The Krawczyk operator of the tritangent system
//     F(x) = P_i(t_i) + rho nu_i(t_i) - V = 0,   i = 1, 2, 3,
//     x = (t_1, t_2, t_3, rho, V_x, V_y)
// (docs/DESIGN.md §4.1, §4.1a) is evaluated in double intervals computed under
// the upward rounding mode (util/upward_interval.hpp; returned as Interval) on a
// small box X around a floating-point solution m:
//     K(X) = m - Y F(m) + (I - Y J(X)) (X - m),   Y ~ J(m)^-1 in doubles.
// K(X) inside the interior of X proves exactly one solution in X, and it lies
// in K(X). With rho > 0 and the tangency points counter-clockwise on the box,
// that solution is THE counter-clockwise Voronoi circle, for the reason given
// in voronoi_circle_enclosure.hpp. First, where the center lies outside the
// three sites (rho > 0), a cheaper test proves the same from the center's
// distances to the sites alone (the .cpp's distance_krawczyk, DESIGN.md
// §4.1a "By distances first"). Anything the doubles cannot prove
// (no convergence, a box that does not contract, an overflow, rho or the
// orientation not of certain sign) is "not certified", and the Arb solver
// runs; it never answers "no circle".
#pragma once

#include "sites/ellipse.hpp"
#include "util/interval.hpp"

#include <array>
#include <optional>

namespace ellvor {

struct DoubleVoronoiCircle {
    Interval center_x, center_y, radius;
    // Chart parameter of each tangency point, as in VoronoiCircleEnclosure:
    // t_i, or u_i = -1/t_i when flipped (the chart in which |parameter| <= 1).
    std::array<Interval, 3> parameter;
    std::array<bool, 3> flipped{};
    bool from_tangent_line = false;  // certified from a huge circle's tangent-line start
    // Certified by the center's distances to the sites (rho > 0), not by the
    // whole tritangent system.
    bool by_distances = false;
};

// A root of the tritangent system that Newton in doubles reached only to the
// rounding noise (its steps stalled above 1e-13; a circle about 2^20 times
// its sites' size or more, conditioned beyond what the double Krawczyk test
// proves), in the form of DoubleVoronoiCircle's midpoints: chart flags and
// (parameters, rho, V_x, V_y). A start for the Arb solver
// (VoronoiCircleSolver::certify_near), which proves or rejects it; no proof
// of anything.
struct StalledDoubleRoot {
    std::array<bool, 3> flipped{};
    std::array<double, 6> x{};
};

// Which certificates may prove the circle: the center's distances first
// (the build's), or the 6 x 6 test only, whose tangency parameters are some
// ten times narrower (callers that read the tangency angles or the vertex to
// ~2^-44: the cells' vertex angles, the Voronoi vertices written out).
enum class DoubleCertificate { distances_first, tritangent_only };

// Starts from the Apollonius circles of circle models of the sites
// (voronoi_circle_guess.hpp), Newton in doubles; nullopt when none certifies.
// Then, if `stalled` is given, the first stalled root met (nullopt if none).
std::optional<DoubleVoronoiCircle> certify_voronoi_circle_in_doubles(
    const Ellipse& e1, const Ellipse& e2, const Ellipse& e3, std::optional<StalledDoubleRoot>* stalled = nullptr,
    DoubleCertificate which = DoubleCertificate::distances_first);

// The certificate by distances alone about the point m = (chart parameters
// of the tangency points, rho, V_x, V_y), any point: a circle it returns is
// THE counter-clockwise one, whatever m (the tests move m off Newton's
// root, where the angle between a site's normal at m_i and the direction
// to the center counts).
std::optional<DoubleVoronoiCircle> certify_voronoi_circle_by_distances_at(const Ellipse& e1, const Ellipse& e2,
                                                                          const Ellipse& e3,
                                                                          const std::array<bool, 3>& flipped,
                                                                          const std::array<double, 6>& m);

}  // namespace ellvor
