#include "cells/cell_vertex_angles.hpp"

#include "util/error.hpp"
#include "exact/medial_axis_tangency.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace ellvor {

namespace {
constexpr double kTwoPi = 6.28318530717958647692;
// Angles of up to this many bits are first asked of the circle certified in
// doubles (its boxes are some 2^-48 wide; Arb's solver costs tens of times
// more).
constexpr long kBitsInDoubles = 44;

// theta = 2 atan(t), plus pi in the flipped chart, for t in the ball.
Ball angle_of_parameter(const Ball& t, bool flipped, long prec) {
    Ball theta;
    arb_atan(theta.get(), t.get(), prec);
    arb_mul_2exp_si(theta.get(), theta.get(), 1);
    if (flipped) {
        Ball pi;
        arb_const_pi(pi.get(), prec);
        arb_add(theta.get(), theta.get(), pi.get(), prec);
    }
    return theta;
}
}  // namespace

CellVertexAngles::CellVertexAngles(const DelaunayGraph& graph, const std::vector<Ellipse>& sites)
    : CellVertexAngles(std::make_shared<const Faces>(graph.faces()), sites) {}

CellVertexAngles::CellVertexAngles(std::shared_ptr<const Faces> faces, const std::vector<Ellipse>& sites)
    : sites_(sites),
      faces_(std::move(faces)),
      solvers_(faces_->size()),
      circles_in_doubles_(faces_->size()),
      tried_in_doubles_(faces_->size(), 0) {}

const DoubleVoronoiCircle* CellVertexAngles::circle_in_doubles(long face) {
    const auto f = static_cast<std::size_t>(face);
    if (!tried_in_doubles_[f]) {
        tried_in_doubles_[f] = 1;
        circles_in_doubles_[f] =
            certify_voronoi_circle_in_doubles(sites_[(*faces_)[f][0]], sites_[(*faces_)[f][1]], sites_[(*faces_)[f][2]],
                                              nullptr, DoubleCertificate::tritangent_only);
    }
    return circles_in_doubles_[f] ? &*circles_in_doubles_[f] : nullptr;
}

int CellVertexAngles::position(long face, SiteId site) const {
    const auto& triple = faces_->at(static_cast<std::size_t>(face));
    const int i = static_cast<int>(std::find(triple.begin(), triple.end(), site) - triple.begin());
    if (i == 3) throw Error("CellVertexAngles: a cell's vertex misses its site");
    return i;
}

VoronoiCircleSolver& CellVertexAngles::solver(long face, long prec) {
    const auto f = static_cast<std::size_t>(face);
    if (face < 0 || f >= faces_->size()) throw Error("CellVertexAngles: no face " + std::to_string(face));
    if (!solvers_[f])
        solvers_[f] = std::make_unique<VoronoiCircleSolver>(sites_[(*faces_)[f][0]], sites_[(*faces_)[f][1]], sites_[(*faces_)[f][2]],
                                                               common_medial_axis_tangency);
    solvers_[f]->refine_existing(prec - 24);
    return *solvers_[f];
}

Ball CellVertexAngles::angle(long face, SiteId site, long prec) {
    const int i = position(face, site);
    if (prec - 24 <= kBitsInDoubles)
        if (const DoubleVoronoiCircle* d = circle_in_doubles(face)) {
            Ball theta = angle_of_parameter(ball_of(d->parameter[i], prec), d->flipped[i], prec);
            if (mag_cmp_2exp_si(arb_radref(theta.get()), 24 - prec) <= 0) {
                ++angles_from_doubles_;
                return theta;
            }
        }
    VoronoiCircleSolver& s = solver(face, prec);
    const VoronoiCircleEnclosure& c = s.enclosure();
    Ball theta = angle_of_parameter(c.parameter[i], c.flipped[i], prec);
    s.release_charts();
    return theta;
}

BallPoint CellVertexAngles::vertex(long face, long prec) {
    if (prec - 24 <= kBitsInDoubles)
        if (const DoubleVoronoiCircle* d = circle_in_doubles(face)) {
            BallPoint v{ball_of(d->center_x, prec), ball_of(d->center_y, prec)};
            // As the solver's refine(prec - 24): that many correct bits in each.
            if (arb_rel_accuracy_bits(v.x.get()) >= prec - 24 && arb_rel_accuracy_bits(v.y.get()) >= prec - 24) {
                ++vertices_from_doubles_;
                return v;
            }
        }
    VoronoiCircleSolver& s = solver(face, prec);
    BallPoint v{s.enclosure().center_x, s.enclosure().center_y};
    s.release_charts();
    return v;
}

std::vector<Ball> CellVertexAngles::lifted(const VoronoiCell& cell, long prec) {
    const std::size_t m = cell.edges.size();
    if (!cell.bounded()) throw Error("CellVertexAngles: cell " + std::to_string(cell.site) + " is not bounded");
    for (std::size_t k = 0; k < m; ++k)
        if (cell.edges[k].to != cell.edges[(k + 1) % m].from) throw Error("CellVertexAngles: cell edges do not chain");
    Ball two_pi;
    arb_const_pi(two_pi.get(), prec);
    arb_mul_2exp_si(two_pi.get(), two_pi.get(), 1);
    std::vector<Ball> out(m + 1);
    out[0] = angle(cell.edges[0].from, cell.site, prec);
    for (std::size_t k = 0; k < m; ++k) {
        const Ball next = angle(cell.edges[k].to, cell.site, prec);
        const double d = next.mid_double() - out[k].mid_double();
        const double eps = next.radius_double() + out[k].radius_double() + 1e-9;
        Ball shift;
        arb_mul_si(shift.get(), two_pi.get(), static_cast<slong>(std::floor((d + eps) / kTwoPi)), prec);
        arb_sub(out[k + 1].get(), next.get(), shift.get(), prec);
    }
    // The lifts telescope to the first angle plus 2 pi times an integer, which
    // must be one turn (then each difference is its true value).
    if (std::lround((out[m].mid_double() - out[0].mid_double()) / kTwoPi) != 1)
        throw Error("CellVertexAngles: the vertex angles of cell " + std::to_string(cell.site) + " do not make one turn");
    return out;
}

}  // namespace ellvor
