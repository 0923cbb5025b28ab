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

PeriodicCopies periodic_copies(const std::vector<Ellipse>& wrapped, const CellDomain& box, const CopyMargin& margin) {
    const Rational lx = box.x1 - box.x0, ly = box.y1 - box.y0;
    PeriodicCopies out;
    out.originals = wrapped.size();
    out.sites = wrapped;
    for (SiteId s = 0; s < wrapped.size(); ++s) out.original.push_back(s);
    out.shift.assign(wrapped.size(), {0, 0});
    // Whole periods that may bring a center (in the box) within the margin.
    const auto periods = [](const Rational& d, const Rational& l) {
        Integer c;
        const Rational q = d / l;
        fmpz_cdiv_q(c.get(), fmpq_numref(q.get()), fmpq_denref(q.get()));
        return fmpz_get_si(c.get());
    };
    const long ki = periods(margin[0], lx), kj = periods(margin[1], ly);
    const Rational x_lo = box.x0 - margin[0], x_hi = box.x1 + margin[0];
    const Rational y_lo = box.y0 - margin[1], y_hi = box.y1 + margin[1];
    for (long i = -ki; i <= ki; ++i)
        for (long j = -kj; j <= kj; ++j) {
            if (i == 0 && j == 0) continue;
            const Rational dx = Rational(i) * lx, dy = Rational(j) * ly;
            for (SiteId s = 0; s < wrapped.size(); ++s) {
                const Rational x = wrapped[s].xc() + dx, y = wrapped[s].yc() + dy;
                if (x < x_lo || !(x < x_hi) || y < y_lo || !(y < y_hi)) continue;
                out.sites.push_back(shifted(wrapped[s], dx, dy));
                out.original.push_back(s);
                out.shift.push_back({i, j});
            }
        }
    return out;
}

CopyMargin ring_margin(const CellDomain& box, long rings) {
    const std::array<long, 2> k = rings_along_axes(box, rings);
    return {Rational(k[0]) * (box.x1 - box.x0), Rational(k[1]) * (box.y1 - box.y0)};
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

Rational distance_to_missing_copies(const Ellipse& p, const CellDomain& box, const CopyMargin& margin) {
    const Rational dx = margin[0] + std::min(box.x1 - p.xc(), p.xc() - box.x0);
    const Rational dy = margin[1] + std::min(box.y1 - p.yc(), p.yc() - box.y0);
    return std::min(dx, dy);
}

bool periodic_cell_is_proven(double reach, const Ellipse& p, const Rational& d_out, const Rational& e_max) {
    if (!std::isfinite(reach)) return false;
    // reach is a double, hence an exact rational: the comparison is exact.
    return Rational(2) * Rational::of_double(reach) < d_out + std::min(p.a(), p.b()) - e_max;
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
