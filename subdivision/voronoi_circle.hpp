// The Voronoi circle of an ordered triple (E1, E2, E3) as the predicates ask
// about it, stage by stage: first the double-interval certificate
// (voronoi_circle_in_doubles.hpp), tried once and kept (a few doubles); the
// Arb solver (voronoi_circle_enclosure.hpp) is made only when a question
// needs more than doubles, and its charts can be freed between questions. A
// cache of one per face (traits/voronoi_circle_cache.hpp) stays small.
#pragma once

#include "sites/ellipse.hpp"
#include "subdivision/voronoi_circle_enclosure.hpp"
#include "subdivision/voronoi_circle_in_doubles.hpp"

#include <array>
#include <memory>

namespace ellvor {

class VoronoiCircle {
public:
    // The sites must outlive this object.
    // common_axis_tangency: passed to the solver (VoronoiCircleSolver).
    VoronoiCircle(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3,
                  CommonAxisTangency common_axis_tangency = nullptr)
        : sites_{&e1, &e2, &e3}, common_axis_tangency_(common_axis_tangency) {}

    // The certified double enclosure, computed on the first call; nullptr
    // when the doubles could not certify it (which proves nothing: the
    // solver decides).
    const DoubleVoronoiCircle* in_doubles();
    // The Arb solver, made on first use; when the doubles certified the
    // circle, already certified from their box (VoronoiCircleSolver::certify_near),
    // and when they only reached a root stalled at the rounding noise (a huge
    // circle, StalledDoubleRoot), first tried from it; when they reached no
    // root, first tried from the tangent lines of a huge circle
    // (VoronoiCircleSolver::certify_from_tangent_lines).
    VoronoiCircleSolver& solver();
    bool has_solver() const { return solver_ != nullptr; }
    // VoronoiCircleSolver::release_charts, if there is a solver.
    void release_charts();
    const std::array<const Ellipse*, 3>& sites() const { return sites_; }

private:
    std::array<const Ellipse*, 3> sites_;
    enum class Tried : unsigned char { not_yet, certified, stalled, failed };
    Tried doubles_tried_ = Tried::not_yet;
    DoubleVoronoiCircle doubles_;  // certified: the enclosure; stalled: the root's point intervals
    std::unique_ptr<VoronoiCircleSolver> solver_;
    CommonAxisTangency common_axis_tangency_ = nullptr;
};

}  // namespace ellvor
