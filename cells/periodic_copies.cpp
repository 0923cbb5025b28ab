#include "cells/periodic_copies.hpp"

#include "predicates/relative_position.hpp"
#include "subdivision/ellipse_shape.hpp"
#include "util/error.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace ellvor {
namespace {

Rational floor_of(const Rational& q) {
    Integer f;
    fmpz_fdiv_q(f.get(), fmpq_numref(q.get()), fmpq_denref(q.get()));
    return Rational(f);
}

Rational larger_semi_axis(const Ellipse& e) { return std::max(e.a(), e.b()); }

Ellipse shifted(const Ellipse& e, const Rational& dx, const Rational& dy) {
    return Ellipse(e.a(), e.b(), e.w(), e.xc() + dx, e.yc() + dy);
}

// The rings in each direction at level k: k, times the ratio of the periods
// (rounded up) along the shorter period, so that the copies reach about as
// far both ways.
std::array<long, 2> rings_along_axes(const CellDomain& box, long level) {
    const Rational lx = box.x1 - box.x0, ly = box.y1 - box.y0;
    auto ratio = [](const Rational& longer, const Rational& shorter) {
        const Rational q = longer / shorter;
        Integer c;
        fmpz_cdiv_q(c.get(), fmpq_numref(q.get()), fmpq_denref(q.get()));
        return std::max(1L, fmpz_get_si(c.get()));
    };
    return {level * (ly > lx ? ratio(ly, lx) : 1L), level * (lx > ly ? ratio(lx, ly) : 1L)};
}

}  // namespace

Ellipse wrap_into_box(const Ellipse& e, const CellDomain& box) {
    const Rational lx = box.x1 - box.x0, ly = box.y1 - box.y0;
    const Rational i = floor_of((e.xc() - box.x0) / lx), j = floor_of((e.yc() - box.y0) / ly);
    if (i.is_zero() && j.is_zero()) return e;
    return shifted(e, -(i * lx), -(j * ly));
}

PeriodicCopies periodic_copies(const std::vector<Ellipse>& wrapped, const CellDomain& box, long rings) {
    const Rational lx = box.x1 - box.x0, ly = box.y1 - box.y0;
    PeriodicCopies out;
    out.originals = wrapped.size();
    out.rings = rings;
    out.sites = wrapped;
    out.shift.assign(wrapped.size(), {0, 0});
    const std::array<long, 2> k = rings_along_axes(box, rings);
    for (long i = -k[0]; i <= k[0]; ++i)
        for (long j = -k[1]; j <= k[1]; ++j) {
            if (i == 0 && j == 0) continue;
            for (const Ellipse& e : wrapped) {
                out.sites.push_back(shifted(e, Rational(i) * lx, Rational(j) * ly));
                out.shift.push_back({i, j});
            }
        }
    return out;
}

long starting_rings(const std::vector<Ellipse>& wrapped, const CellDomain& box) {
    Rational e_max(0);
    for (const Ellipse& e : wrapped) e_max = std::max(e_max, larger_semi_axis(e));
    for (long level = 1;; ++level) {
        const std::array<long, 2> k = rings_along_axes(box, level);
        if (Rational(k[0]) * (box.x1 - box.x0) > Rational(2) * e_max &&
            Rational(k[1]) * (box.y1 - box.y0) > Rational(2) * e_max)
            return level;
    }
}

Rational distance_to_missing_copies(const Ellipse& p, const CellDomain& box, long rings) {
    const std::array<long, 2> k = rings_along_axes(box, rings);
    const Rational dx = Rational(k[0]) * (box.x1 - box.x0) + std::min(box.x1 - p.xc(), p.xc() - box.x0);
    const Rational dy = Rational(k[1]) * (box.y1 - box.y0) + std::min(box.y1 - p.yc(), p.yc() - box.y0);
    return std::min(dx, dy);
}

bool periodic_cell_is_proven(double reach, const Ellipse& p, const Rational& d_out, const Rational& e_max) {
    if (!std::isfinite(reach)) return false;
    // reach is a double, hence an exact rational: the comparison is exact.
    Arf a;
    arf_set_d(a.get(), reach);
    Rational r;
    arf_get_fmpq(r.get(), a.get());
    return Rational(2) * r < d_out + std::min(p.a(), p.b()) - e_max;
}

void require_sites_fit_periodic_box(const std::vector<Ellipse>& wrapped, const CellDomain& box) {
    const Rational lx = box.x1 - box.x0, ly = box.y1 - box.y0;
    const double dlx = lx.to_double(), dly = ly.to_double();
    for (SiteId p = 0; p < wrapped.size(); ++p) {
        const EllipseShape e = EllipseShape::of(wrapped[p]);
        // The shifts whose copy's bounding circle may meet p's: the slack
        // covers the doubles' rounding; the exact test decides.
        const double reach = 2 * std::max(e.a, e.b) * (1 + 1e-9) + 1e-9 * (dlx + dly);
        const long ki = static_cast<long>(std::ceil(reach / dlx)), kj = static_cast<long>(std::ceil(reach / dly));
        for (long i = -ki; i <= ki; ++i)
            for (long j = -kj; j <= kj; ++j) {
                if ((i == 0 && j == 0) || std::hypot(i * dlx, j * dly) > reach) continue;
                const RelativePosition rp = *relative_position(wrapped[p], shifted(wrapped[p], Rational(i) * lx, Rational(j) * ly));
                if (rp != RelativePosition::intersecting && rp != RelativePosition::externally_tangent) continue;
                throw InputError("cells: site " + std::to_string(p) + " meets its own periodic image shifted by (" +
                                     std::to_string(i) + ", " + std::to_string(j) +
                                     ") periods: the periodic box is too small for it",
                                 InputError::SitePair{p, p});
            }
    }
}

}  // namespace ellvor
