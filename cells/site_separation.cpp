#include "cells/site_separation.hpp"

#include "decision/site_id.hpp"
#include "predicates/relative_position.hpp"
#include "sites/meeting_pair_candidates.hpp"
#include "subdivision/ellipse_shape.hpp"
#include "util/error.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace ellvor {

void require_sites_apart(const std::vector<Ellipse>& wrapped, const CellDomain& box) {
    const bool periodic = box.kind == CellDomain::Kind::periodic;
    // In the plane and a box only the shift (0, 0); the period is then unused.
    const Rational lx = periodic ? box.x1 - box.x0 : Rational(1), ly = periodic ? box.y1 - box.y0 : Rational(1);
    const double dlx = lx.to_double(), dly = ly.to_double();
    std::vector<EllipseShape> shapes;
    for (const Ellipse& e : wrapped) shapes.push_back(EllipseShape::of(e));
    // One pair (p, q), q >= p, with every copy of q whose bounding circle may meet p's.
    auto check_pair = [&](SiteId p, SiteId q) {
        const EllipseShape& sp = shapes[p];
        const EllipseShape& sq = shapes[q];
        // Copies q + (i Lx, j Ly) whose bounding circle may meet p's: the
        // slack covers the doubles' rounding; the exact test decides.
        const double reach = (std::max(sp.a, sp.b) + std::max(sq.a, sq.b)) * (1 + 1e-9) + 1e-9 * (dlx + dly);
        const double dx = sq.xc - sp.xc, dy = sq.yc - sp.yc;
        long i0 = 0, i1 = 0, j0 = 0, j1 = 0;
        if (periodic) {
            i0 = static_cast<long>(std::floor((-reach - dx) / dlx));
            i1 = static_cast<long>(std::ceil((reach - dx) / dlx));
            j0 = static_cast<long>(std::floor((-reach - dy) / dly));
            j1 = static_cast<long>(std::ceil((reach - dy) / dly));
        }
        for (long i = i0; i <= i1; ++i)
            for (long j = j0; j <= j1; ++j) {
                if (p == q && i == 0 && j == 0) continue;
                if (std::hypot(dx + i * dlx, dy + j * dly) > reach) continue;
                const Ellipse copy(wrapped[q].a(), wrapped[q].b(), wrapped[q].w(), wrapped[q].xc() + Rational(i) * lx,
                                   wrapped[q].yc() + Rational(j) * ly);
                const RelativePosition rp = *relative_position(wrapped[p], copy);
                if (rp != RelativePosition::intersecting && rp != RelativePosition::externally_tangent) continue;
                const std::string shift = "(" + std::to_string(i) + ", " + std::to_string(j) + ")";
                if (p == q)
                    throw InputError("cells: site " + std::to_string(p) +
                                         " meets its own periodic image shifted by " + shift +
                                         " periods: the periodic box is too small for it",
                                     InputError::SitePair{p, p});
                throw InputError("cells: sites " + std::to_string(p) + " and " + std::to_string(q) + " " +
                                     (rp == RelativePosition::intersecting ? "cross" : "touch") +
                                     (periodic ? " on the torus (site " + std::to_string(q) + " shifted by " + shift +
                                                     " periods)"
                                               : std::string()) +
                                     "; cells of touching or crossing sites are not supported yet",
                                 InputError::SitePair{p, q});
            }
    };
    if (!periodic) {
        // Only the pairs whose circumscribed disks may meet, in the order of (p, q).
        std::vector<std::pair<std::size_t, std::size_t>> pairs = pairs_that_may_meet(wrapped);
        std::sort(pairs.begin(), pairs.end());
        for (const auto& [p, q] : pairs) check_pair(p, q);
        return;
    }
    // On the torus every pair and every site with its own images, in doubles first.
    for (SiteId p = 0; p < wrapped.size(); ++p)
        for (SiteId q = p; q < wrapped.size(); ++q) check_pair(p, q);
}

}  // namespace ellvor
