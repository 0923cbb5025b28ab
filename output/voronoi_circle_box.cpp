#include "output/voronoi_circle_box.hpp"

#include "exact/medial_axis_tangency.hpp"
#include "subdivision/voronoi_circle_enclosure.hpp"

#include <cmath>

namespace ellvor {
namespace {

// 2^-40: the double certificate's boxes are ~2^-50 of the magnitude on
// well-conditioned circles; Arb's at 53 bits ~2^-53.
constexpr double kTightWidth = 0x1p-40;

double magnitude(const Interval& x) { return std::fmax(std::fabs(x.lo), std::fabs(x.hi)); }

bool tight(const DoubleVoronoiCircle& c) {
    const double scale = magnitude(c.center_x) + magnitude(c.center_y) + magnitude(c.radius);
    for (const Interval* x : {&c.center_x, &c.center_y, &c.radius})
        if (!(x->hi - x->lo <= kTightWidth * scale)) return false;
    return true;
}

}  // namespace

VoronoiCircleBox voronoi_circle_box(const std::vector<Ellipse>& sites, const std::array<SiteId, 3>& face) {
    const std::optional<DoubleVoronoiCircle> c = certify_voronoi_circle_in_doubles(sites[face[0]], sites[face[1]], sites[face[2]]);
    return voronoi_circle_box(sites, face, c ? &*c : nullptr);
}

VoronoiCircleBox voronoi_circle_box(const std::vector<Ellipse>& sites, const std::array<SiteId, 3>& face,
                                    const DoubleVoronoiCircle* c) {
    if (c && tight(*c)) return {c->center_x, c->center_y, c->radius};
    VoronoiCircleSolver solver(sites[face[0]], sites[face[1]], sites[face[2]], common_medial_axis_tangency);
    solver.refine_existing(53);  // a face of a graph has its counter-clockwise circle
    const VoronoiCircleEnclosure& e = solver.enclosure();
    return {enclose(e.center_x), enclose(e.center_y), enclose(e.radius)};
}

}  // namespace ellvor
