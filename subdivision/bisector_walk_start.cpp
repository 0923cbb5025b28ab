#include "subdivision/bisector_walk_start.hpp"

#include <cmath>

#include "subdivision/nearest_point.hpp"
#include "subdivision/shape_in_doubles.hpp"

namespace ellvor {
namespace {

// Distance from (px, py) to the site and, if asked, the angle of its nearest
// point and the unit vector from there to (px, py); NaN inside (or on) the
// site, where no external circle has its center.
double distance(const ShapeInDoubles& k, double px, double py, double* angle, double* ux = nullptr,
                double* uy = nullptr) {
    const double dx = px - k.x, dy = py - k.y;
    const double x = k.c * dx + k.s * dy, y = k.c * dy - k.s * dx;
    if (!((x / k.a) * (x / k.a) + (y / k.b) * (y / k.b) > 1)) return NAN;
    const double theta = approximate_nearest_angle(k.a, k.b, x, y);
    if (angle) *angle = theta;
    const double lx = x - k.a * std::cos(theta), ly = y - k.b * std::sin(theta), d = std::hypot(lx, ly);
    if (ux) *ux = (k.c * lx - k.s * ly) / d, *uy = (k.s * lx + k.c * ly) / d;
    return d;
}

// The circle tangent to site p at angle theta and to site q, and its gap to
// site k: g = d(V, k) - rho (-rho when V lies in k); NaN when there is none
// (the normal faces away from q, or the circle is huge: huge_circle_start.hpp).
struct Sample {
    double theta, rho, vx, vy, g;
};

// rho solves h(rho) = d(P + rho n, q) - rho = 0, h(0) > 0, h nonincreasing
// (h' = n . u - 1, u the unit vector from q's nearest point): Newton from
// `hint` (the neighbouring sample's rho), kept in the bracket [lo, hi] that
// it narrows, bisecting when a step leaves it.
Sample sample(const ShapeInDoubles& p, const ShapeInDoubles& q, const ShapeInDoubles& k, double theta, double size,
              double hint) {
    Sample out{theta, NAN, NAN, NAN, NAN};
    const double ct = std::cos(theta), st = std::sin(theta);
    const double px = p.x + p.c * p.a * ct - p.s * p.b * st, py = p.y + p.s * p.a * ct + p.c * p.b * st;
    double nx = p.c * p.b * ct - p.s * p.a * st, ny = p.s * p.b * ct + p.c * p.a * st;
    const double norm = std::hypot(nx, ny);
    nx /= norm, ny /= norm;
    const double limit = 1e6 * size;
    double lo = 0, hi = INFINITY;
    double rho = std::isfinite(hint) && hint > 0 ? hint : distance(q, px, py, nullptr);
    bool converged = false;
    for (int it = 0; it < 60 && !converged; ++it) {
        if (!(rho < limit)) return out;
        double ux, uy;
        const double d = distance(q, px + rho * nx, py + rho * ny, nullptr, &ux, &uy);
        if (!std::isfinite(d)) {  // inside q: past the root
            hi = rho;
            rho = 0.5 * (lo + hi);
            continue;
        }
        const double h = d - rho, slope = nx * ux + ny * uy - 1;
        (h > 0 ? lo : hi) = rho;
        double next = slope < 0 ? rho - h / slope : INFINITY;
        if (!(next > lo && next < hi)) next = std::isfinite(hi) ? 0.5 * (lo + hi) : 2 * std::fmax(rho, lo) + size;
        converged = std::fabs(next - rho) <= 1e-13 * (rho + size);
        rho = next;
    }
    if (!converged) return out;
    out.rho = rho;
    out.vx = px + rho * nx, out.vy = py + rho * ny;
    // A center inside k: the circle meets k, as when g < 0 (its size only
    // weights the regula falsi).
    const double d = distance(k, out.vx, out.vy, nullptr);
    out.g = std::isfinite(d) ? d - rho : -rho;
    return out;
}

// The walk along the bisector of (p, q) with k; sites[3] in argument order,
// i, j, m the indices of p, q, k there; (x0, y0) the reference point. A sign
// change of g between two samples is refined by regula falsi (Illinois).
bool walk(const std::array<ShapeInDoubles, 3>& sites, int i, int j, int m, double size, double x0, double y0,
          const std::function<bool(const VoronoiCircleGuess&)>& try_guess) {
    constexpr int kSamples = 32, kRefinements = 40;
    const ShapeInDoubles &p = sites[i], &q = sites[j], &k = sites[m];
    Sample previous = sample(p, q, k, -M_PI, size, NAN);
    for (int n = 1; n <= kSamples; ++n) {
        const Sample next = sample(p, q, k, -M_PI + 2 * M_PI * n / kSamples, size, previous.rho);
        if (std::isfinite(previous.g) && std::isfinite(next.g) && (previous.g > 0) != (next.g > 0)) {
            Sample lo = previous, hi = next, mid = previous;
            int kept = 0;  // which end the last steps kept (Illinois: halve its g after two)
            bool lost = false;
            for (int it = 0; it < kRefinements; ++it) {
                const double theta = (lo.theta * hi.g - hi.theta * lo.g) / (hi.g - lo.g);
                mid = sample(p, q, k, theta, size, mid.rho);
                if ((lost = !std::isfinite(mid.g))) break;
                if (std::fabs(hi.theta - lo.theta) <= 1e-13 || mid.g == 0) break;
                if ((mid.g > 0) == (lo.g > 0)) {
                    lo = mid;
                    if (kept == -1) hi.g *= 0.5;
                    kept = -1;
                } else {
                    hi = mid;
                    if (kept == 1) lo.g *= 0.5;
                    kept = 1;
                }
                if (std::fabs(mid.g) <= 1e-13 * (mid.rho + size)) break;
            }
            if (!lost && mid.g > -mid.rho) {  // a center outside k
                VoronoiCircleGuess c;
                c.radius = mid.rho, c.x = x0 + mid.vx, c.y = y0 + mid.vy;
                c.theta[i] = mid.theta;
                if (std::isfinite(distance(q, mid.vx, mid.vy, &c.theta[j])) &&
                    std::isfinite(distance(k, mid.vx, mid.vy, &c.theta[m])) && try_guess(c))
                    return true;
            }
        }
        previous = next;
    }
    return false;
}

}  // namespace

bool for_each_bisector_walk_circle(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3,
                                   const std::function<bool(const VoronoiCircleGuess&)>& try_guess) {
    const std::array<ShapeInDoubles, 3> sites = {shape_relative_to(e1, e1), shape_relative_to(e2, e1),
                                                 shape_relative_to(e3, e1)};
    double size = 0;
    for (const ShapeInDoubles& s : sites) size = std::fmax(size, std::fmax(s.a, s.b) + std::hypot(s.x, s.y));
    const double x0 = e1.enclosure().xc.mid(), y0 = e1.enclosure().yc.mid();
    return walk(sites, 0, 1, 2, size, x0, y0, try_guess) || walk(sites, 1, 2, 0, size, x0, y0, try_guess) ||
           walk(sites, 2, 0, 1, size, x0, y0, try_guess);
}

}  // namespace ellvor
