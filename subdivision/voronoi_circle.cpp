#include "subdivision/voronoi_circle.hpp"

namespace ellvor {

const DoubleVoronoiCircle* VoronoiCircle::in_doubles() {
    if (doubles_tried_ == Tried::not_yet) {
        std::optional<StalledDoubleRoot> stalled;
        const std::optional<DoubleVoronoiCircle> c =
            certify_voronoi_circle_in_doubles(*sites_[0], *sites_[1], *sites_[2], &stalled);
        doubles_tried_ = c ? Tried::certified : stalled ? Tried::stalled : Tried::failed;
        if (c) doubles_ = *c;
        if (!c && stalled) {
            for (int i = 0; i < 3; ++i) doubles_.parameter[i] = Interval(stalled->x[i]);
            doubles_.radius = Interval(stalled->x[3]);
            doubles_.center_x = Interval(stalled->x[4]), doubles_.center_y = Interval(stalled->x[5]);
            doubles_.flipped = stalled->flipped;
        }
    }
    return doubles_tried_ == Tried::certified ? &doubles_ : nullptr;
}

VoronoiCircleSolver& VoronoiCircle::solver() {
    if (!solver_) {
        solver_ = std::make_unique<VoronoiCircleSolver>(*sites_[0], *sites_[1], *sites_[2], common_axis_tangency_);
        // A certified double circle is a start right at the root; a stalled
        // one (a huge circle) near it, which the guesses find only after
        // milliseconds.
        if (doubles_tried_ == Tried::certified || doubles_tried_ == Tried::stalled)
            solver_->certify_near(doubles_.flipped, {doubles_.parameter[0].mid(), doubles_.parameter[1].mid(),
                                                     doubles_.parameter[2].mid(), doubles_.radius.mid(),
                                                     doubles_.center_x.mid(), doubles_.center_y.mid()});
        // No root at all in doubles: mostly a circle beyond their reach (sites
        // in a row along a packing's wall), which the tangent lines start in
        // a millisecond and the guesses, tried first by certify(), in tens.
        if (doubles_tried_ == Tried::failed) solver_->certify_from_tangent_lines();
    }
    return *solver_;
}

void VoronoiCircle::release_charts() {
    if (solver_) solver_->release_charts();
}

}  // namespace ellvor
