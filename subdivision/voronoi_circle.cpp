#include "subdivision/voronoi_circle.hpp"

namespace ellvor {

const DoubleVoronoiCircle* VoronoiCircle::in_doubles() {
    if (doubles_tried_ == Tried::not_yet) {
        const std::optional<DoubleVoronoiCircle> c = certify_voronoi_circle_in_doubles(*sites_[0], *sites_[1], *sites_[2]);
        doubles_tried_ = c ? Tried::certified : Tried::failed;
        if (c) doubles_ = *c;
    }
    return doubles_tried_ == Tried::certified ? &doubles_ : nullptr;
}

VoronoiCircleSolver& VoronoiCircle::solver() {
    if (!solver_) {
        solver_ = std::make_unique<VoronoiCircleSolver>(*sites_[0], *sites_[1], *sites_[2], common_axis_tangency_);
        // A certified double circle is a start right at the root.
        if (doubles_tried_ == Tried::certified)
            solver_->certify_near(doubles_.flipped, {doubles_.parameter[0].mid(), doubles_.parameter[1].mid(),
                                                     doubles_.parameter[2].mid(), doubles_.radius.mid(),
                                                     doubles_.center_x.mid(), doubles_.center_y.mid()});
    }
    return *solver_;
}

void VoronoiCircle::release_charts() {
    if (solver_) solver_->release_charts();
}

}  // namespace ellvor
