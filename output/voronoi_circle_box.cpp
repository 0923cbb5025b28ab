#include "output/voronoi_circle_box.hpp"

#include "exact/medial_axis_tangency.hpp"
#include "predicates/incircle.hpp"
#include "subdivision/voronoi_circle_enclosure.hpp"

#include <algorithm>
#include <cmath>

namespace ellvor {
namespace {

// 2^-40: the double certificate's boxes are ~2^-50 of the magnitude on
// well-conditioned circles; Arb's at 53 bits ~2^-53.
constexpr double kTightWidth = 0x1p-40;

double magnitude(const Interval& x) { return std::fmax(std::fabs(x.lo), std::fabs(x.hi)); }

}  // namespace

bool is_tight(const VoronoiCircleBox& c) {
    const double scale = magnitude(c.center_x) + magnitude(c.center_y) + magnitude(c.radius);
    for (const Interval* x : {&c.center_x, &c.center_y, &c.radius})
        if (!(x->hi - x->lo <= kTightWidth * scale)) return false;
    return true;
}

VoronoiCircleBox voronoi_circle_box(const std::vector<Ellipse>& sites, const std::array<SiteId, 3>& face) {
    const std::optional<DoubleVoronoiCircle> c = certify_voronoi_circle_in_doubles(sites[face[0]], sites[face[1]], sites[face[2]], nullptr,
                                                                                   DoubleCertificate::tritangent_only);
    return voronoi_circle_box(sites, face, c ? &*c : nullptr);
}

VoronoiCircleBox voronoi_circle_box(const std::vector<Ellipse>& sites, const std::array<SiteId, 3>& face,
                                    const DoubleVoronoiCircle* c) {
    if (c) {
        const VoronoiCircleBox doubles{c->center_x, c->center_y, c->radius};
        if (is_tight(doubles)) return doubles;
    }
    VoronoiCircleSolver solver(sites[face[0]], sites[face[1]], sites[face[2]], common_medial_axis_tangency);
    // The wide double box (a huge circle) holds the root: Newton and Krawczyk from its middle spare the
    // solver's guesses and tangent-line starts, milliseconds a huge circle (a tile's hull along its seam).
    if (c) {
        solver.certify_near(c->flipped, {c->parameter[0].mid(), c->parameter[1].mid(), c->parameter[2].mid(),
                                         c->radius.mid(), c->center_x.mid(), c->center_y.mid()});
    }
    solver.refine_existing(53);  // a face of a graph has its counter-clockwise circle
    const VoronoiCircleEnclosure& e = solver.enclosure();
    return {enclose(e.center_x), enclose(e.center_y), enclose(e.radius)};
}

VoronoiCircleBox voronoi_circle_box_any_width(const std::vector<Ellipse>& sites, const std::array<SiteId, 3>& face,
                                              const DoubleVoronoiCircle* doubles) {
    if (doubles) return {doubles->center_x, doubles->center_y, doubles->radius};
    return voronoi_circle_box(sites, face, nullptr);
}

bool circle_boxes_meet(const VoronoiCircleBox& a, const VoronoiCircleBox& b) {
    auto meet = [](const Interval& x, const Interval& y) { return x.lo <= y.hi && y.lo <= x.hi; };
    return meet(a.center_x, b.center_x) && meet(a.center_y, b.center_y) && meet(a.radius, b.radius);
}

bool circle_differs_by_site(const std::vector<Ellipse>& sites, const VoronoiCircleBox& box,
                            const std::array<SiteId, 3>& face, const std::array<SiteId, 3>& other) {
    for (SiteId q : other) {
        if (std::find(face.begin(), face.end(), q) != face.end()) continue;
        if (filtered_distance_minus_radius(box.center_x, box.center_y, box.radius, sites[q]) > 0) return true;
    }
    return false;
}

}  // namespace ellvor
