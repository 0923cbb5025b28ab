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

}  // namespace

Ellipse wrap_into_box(const Ellipse& e, const CellDomain& box) {
    const Rational lx = box.x1 - box.x0, ly = box.y1 - box.y0;
    const Rational i = floor_of((e.xc() - box.x0) / lx), j = floor_of((e.yc() - box.y0) / ly);
    if (i.is_zero() && j.is_zero()) return e;
    return shifted(e, -(i * lx), -(j * ly));
}

void require_apart_on_torus(const std::vector<Ellipse>& wrapped, const CellDomain& box) {
    const Rational lx = box.x1 - box.x0, ly = box.y1 - box.y0;
    const double dlx = lx.to_double(), dly = ly.to_double();
    for (SiteId p = 0; p < wrapped.size(); ++p) {
        const EllipseShape sp = EllipseShape::of(wrapped[p]);
        for (SiteId q = p; q < wrapped.size(); ++q) {
            const EllipseShape sq = EllipseShape::of(wrapped[q]);
            // Copies q + (i Lx, j Ly) whose bounding circle may meet p's: the
            // slack covers the doubles' rounding; the exact test decides.
            const double reach = (std::max(sp.a, sp.b) + std::max(sq.a, sq.b)) * (1 + 1e-9) + 1e-9 * (dlx + dly);
            const double dx = sq.xc - sp.xc, dy = sq.yc - sp.yc;
            const long i0 = static_cast<long>(std::floor((-reach - dx) / dlx)), i1 = static_cast<long>(std::ceil((reach - dx) / dlx));
            const long j0 = static_cast<long>(std::floor((-reach - dy) / dly)), j1 = static_cast<long>(std::ceil((reach - dy) / dly));
            for (long i = i0; i <= i1; ++i)
                for (long j = j0; j <= j1; ++j) {
                    if (p == q && i == 0 && j == 0) continue;
                    if (std::hypot(dx + i * dlx, dy + j * dly) > reach) continue;
                    const Ellipse copy = shifted(wrapped[q], Rational(i) * lx, Rational(j) * ly);
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
                                         " on the torus (site " + std::to_string(q) + " shifted by " + shift +
                                         " periods); cells of touching or crossing sites are not supported yet",
                                     InputError::SitePair{p, q});
                }
        }
    }
}

PeriodicCopies periodic_copies(const std::vector<Ellipse>& wrapped, const CellDomain& box, long rings) {
    const Rational lx = box.x1 - box.x0, ly = box.y1 - box.y0;
    PeriodicCopies out;
    out.originals = wrapped.size();
    out.rings = rings;
    out.sites = wrapped;
    out.shift.assign(wrapped.size(), {0, 0});
    for (long i = -rings; i <= rings; ++i)
        for (long j = -rings; j <= rings; ++j) {
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
    const Rational l = std::min(box.x1 - box.x0, box.y1 - box.y0);
    long k = 1;
    while (!(Rational(k) * l > Rational(2) * e_max)) ++k;
    return k;
}

Rational distance_to_missing_copies(const Ellipse& p, const CellDomain& box, long rings) {
    const Rational k(rings);
    const Rational dx = k * (box.x1 - box.x0) + std::min(box.x1 - p.xc(), p.xc() - box.x0);
    const Rational dy = k * (box.y1 - box.y0) + std::min(box.y1 - p.yc(), p.yc() - box.y0);
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

}  // namespace ellvor
