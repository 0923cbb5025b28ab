#include "predicates/support_function.hpp"

#include "util/positive_divisor.hpp"

#include <cmath>

namespace ellvor {

namespace {

// A support function and its derivative in phi at n = (c, s) = (cos phi, sin
// phi), in doubles.
struct SupportDouble {
    double value, slope;
};

// About the center, from the mid-points of the site's enclosure: rho(n) =
// h(n) - n.C, and its derivative (S - C).(-s, c), S the support point.
SupportDouble radial_support_double(const Ellipse::Enclosure& k, double c, double s) {
    const double cw = k.cos.mid(), sw = k.sin.mid(), a2 = k.a.mid() * k.a.mid(), b2 = k.b.mid() * k.b.mid();
    const double nu = c * cw + s * sw, nv = s * cw - c * sw;
    const double norm = std::sqrt(a2 * nu * nu + b2 * nv * nv);
    const double lu = a2 * nu / norm, lv = b2 * nv / norm;
    const double x = cw * lu - sw * lv, y = sw * lu + cw * lv;
    return {norm, -x * s + y * c};
}

}  // namespace

SupportEnclosure support_enclosure(const Ellipse::Enclosure& k, Interval nx, Interval ny) {
    const Interval nu = nx * k.cos + ny * k.sin, nv = ny * k.cos - nx * k.sin;
    const Interval a2 = k.a.square(), b2 = k.b.square();
    const Interval norm = (a2 * nu.square() + b2 * nv.square()).sqrt();
    const Interval lu = a2 * nu / norm, lv = b2 * nv / norm;  // local support point
    const Interval x = k.xc + k.cos * lu - k.sin * lv, y = k.yc + k.sin * lu + k.cos * lv;
    return {nx * k.xc + ny * k.yc + norm, x, y};
}

Interval support_value(const Ellipse::Enclosure& k, Interval nx, Interval ny) {
    // The operations of support_enclosure's value, in its order: the same interval.
    const Interval nu = nx * k.cos + ny * k.sin, nv = ny * k.cos - nx * k.sin;
    const Interval norm = (k.a.square() * nu.square() + k.b.square() * nv.square()).sqrt();
    return nx * k.xc + ny * k.yc + norm;
}

namespace {

bool finite(const Ellipse::Enclosure& k) { return k.a.finite() && k.b.finite() && k.xc.finite() && k.yc.finite(); }

// C1 - C2 enclosed: h1(n) - h2(n) = n.(C1 - C2) + rho1(n) - rho2(n), rho the
// support function about the center. Differencing the centers first keeps
// their magnitude (a packing's coordinates reach 100 for sites of size 1)
// out of the rounding: the value of h1 - h2 near a common tangent, and so
// the Newton steps and the proven signs, are as accurate as the sites' sizes
// allow, not their position.
struct CenterOffset {
    Interval x, y;
};

// p - q for coordinates p, q and their enclosures kp, kq. Exact doubles (a
// packing's centers are, on the grid 2^-40) are read back from their
// enclosures (x = up(lo): util/interval.hpp's enclose) and only the
// difference is rounded; else the enclosures' widths, an ulp of the
// coordinates each, add up (at coordinates near 300 they exceed h1 - h2 over
// certify's first interval).
Interval coordinate_difference(const Rational& p, const Interval& kp, const Rational& q, const Interval& kq) {
    if (p.is_small_dyadic() && q.is_small_dyadic())
        return Interval(Interval::up(kp.lo)) - Interval(Interval::up(kq.lo));
    return kp - kq;
}

Interval radial_support(const Ellipse::Enclosure& k, Interval nx, Interval ny) {
    const Interval nu = nx * k.cos + ny * k.sin, nv = ny * k.cos - nx * k.sin;
    return (k.a.square() * nu.square() + k.b.square() * nv.square()).sqrt();
}

Interval support_difference(const Ellipse::Enclosure& k1, const Ellipse::Enclosure& k2, const CenterOffset& offset,
                            Interval nx, Interval ny) {
    return nx * offset.x + ny * offset.y + (radial_support(k1, nx, ny) - radial_support(k2, nx, ny));
}

// A proven sign change of h1 - h2 over a tiny interval of directions around phi.
std::optional<BitangentNormal> certify(const Ellipse::Enclosure& k1, const Ellipse::Enclosure& k2,
                                       const CenterOffset& offset, double phi) {
    NormalInterval n;
    if (std::cos(phi) < 0) {
        phi = phi > 0 ? phi - M_PI : phi + M_PI;
        n.sign = -1;
    }
    for (double width : {1e-13, 1e-10, 1e-7}) {
        n.tau_lo = std::tan(0.5 * (phi - width)), n.tau_hi = std::tan(0.5 * (phi + width));
        if (!(n.tau_lo < n.tau_hi)) continue;
        auto difference = [&](double tau) {
            NormalInterval at{n.sign, tau, tau};
            return support_difference(k1, k2, offset, at.nx(), at.ny());
        };
        const Interval lo = difference(n.tau_lo), hi = difference(n.tau_hi);
        if (lo.negative() && hi.positive()) return BitangentNormal{n, true};
        if (lo.positive() && hi.negative()) return BitangentNormal{n, false};
    }
    return std::nullopt;
}

}  // namespace

namespace {

// The proven tangents, stopping at the one `wanted` (arrival or not) if given.
std::vector<BitangentNormal> find_bitangent_normals(const Ellipse::Enclosure& k1, const Ellipse::Enclosure& k2,
                                                    const CenterOffset& offset, std::optional<bool> wanted) {
    std::vector<BitangentNormal> out;
    if (!finite(k1) || !finite(k2) || !offset.x.finite() || !offset.y.finite()) return out;
    auto done = [&] { return out.size() == 2 || (wanted && !out.empty() && out.back().arrival == *wanted); };
    // h1 - h2 and its derivative in phi, about the centers (CenterOffset).
    const double ox = offset.x.mid(), oy = offset.y.mid();
    auto f = [&](double phi) {
        const double c = std::cos(phi), s = std::sin(phi);
        const SupportDouble h1 = radial_support_double(k1, c, s), h2 = radial_support_double(k2, c, s);
        return SupportDouble{c * ox + s * oy + (h1.value - h2.value), -s * ox + c * oy + (h1.slope - h2.slope)};
    };
    // Newton refinement of a root of h1 - h2 inside [lo, hi] (bisection when a
    // step leaves the bracket; plain Newton when there is none).
    auto refine = [&](double x, double lo, double hi, bool bracketed, bool rising) {
        // Stops at a step of 1e-15 or, below 1e-13 (certify's first width),
        // at one no smaller than the last: rounding, no more convergence.
        double last_step = INFINITY;
        for (int it = 0; it < 40; ++it) {
            const SupportDouble v = f(x);
            if (bracketed) ((v.value < 0) == rising ? lo : hi) = x;
            double next = x - v.value / v.slope;
            if (bracketed && !(next > lo && next < hi)) next = 0.5 * (lo + hi);
            if (!std::isfinite(next)) return x;
            const double step = std::fabs(next - x);
            if (step <= 1e-15 * (1 + std::fabs(x)) || (step < 1e-13 && step >= last_step)) return next;
            last_step = step;
            x = next;
        }
        return x;
    };
    auto add = [&](double phi) {
        if (const auto b = certify(k1, k2, offset, phi))
            if (out.empty() || out[0].arrival != b->arrival) out.push_back(*b);
    };
    // First guesses: the common tangents of the circles with the sites'
    // centers and mean radii, n.(C2 - C1) = r1 - r2, in closed form (side +1:
    // where the hull arrives on E1).
    const double dx = -ox, dy = -oy, length = std::hypot(dx, dy);
    const double r1 = 0.5 * (k1.a.mid() + k1.b.mid()), r2 = 0.5 * (k2.a.mid() + k2.b.mid());
    const double c = (r1 - r2) / length;
    if (length > 0 && std::fabs(c) < 1) {
        const double ex = dx / length, ey = dy / length, root = std::sqrt(1 - c * c);
        const bool departure_first = wanted && !*wanted;
        for (double side : {departure_first ? -1.0 : 1.0, departure_first ? 1.0 : -1.0}) {
            add(refine(std::atan2(c * ey + side * root * ex, c * ex - side * root * ey), 0, 0, false, false));
            if (done()) return out;
        }
    }
    // Otherwise bracket the roots of h1 - h2 by sampling.
    constexpr int kSamples = 16;
    double prev_phi = -M_PI, prev = f(prev_phi).value;
    for (int i = 1; i <= kSamples && !done(); ++i) {
        const double phi = -M_PI + 2 * M_PI * i / kSamples, value = f(phi).value;
        if ((prev < 0) != (value < 0)) add(refine(0.5 * (prev_phi + phi), prev_phi, phi, true, prev < 0));
        prev_phi = phi, prev = value;
    }
    return out;
}

}  // namespace

std::optional<ArrivalNormalBox> ArrivalNormalBox::of(const Ellipse::Enclosure& k1, const Ellipse::Enclosure& k2) {
    if (!finite(k1) || !finite(k2)) return std::nullopt;
    // Outer radii rounded up, inner ones down: R >= max(a, b), r <= min(a, b).
    const double R1 = Interval::max(k1.a.hi, k1.b.hi), r1 = Interval::min(k1.a.lo, k1.b.lo);
    const double R2 = Interval::max(k2.a.hi, k2.b.hi), r2 = Interval::min(k2.a.lo, k2.b.lo);
    if (!(r1 > 0 && r2 > 0)) return std::nullopt;
    ArrivalNormalBox box(k1, k2);
    const Interval dx = k2.xc - k1.xc, dy = k2.yc - k1.yc;
    box.d_ = (dx.square() + dy.square()).sqrt();
    if (!(box.d_.lo > (Interval(R1) + Interval(R2)).hi)) return std::nullopt;
    box.ex_ = divide_by_positive(dx, box.d_), box.ey_ = divide_by_positive(dy, box.d_);
    // s = n.e between (r1 - R2)/d and (R1 - r2)/d, for every d in its enclosure.
    box.s_ = Interval(divide_by_positive(Interval(r1) - Interval(R2), box.d_).lo,
                      divide_by_positive(Interval(R1) - Interval(r2), box.d_).hi);
    if (!(box.s_.lo > -1 && box.s_.hi < 1)) return std::nullopt;
    box.set_box();
    return box;
}

void ArrivalNormalBox::set_box() {
    const Interval c = (Interval(1.0) - s_.square()).sqrt();
    nx_ = s_ * ex_ - c * ey_, ny_ = s_ * ey_ + c * ex_;
}

bool ArrivalNormalBox::contract() {
    // The box holds n, so the enclosure over it holds rho_i(n) = sqrt(a^2
    // (n.u)^2 + b^2 (n.v)^2), and s = (rho1(n) - rho2(n))/d.
    auto rho = [&](const Ellipse::Enclosure& k) {
        const Interval nu = nx_ * k.cos + ny_ * k.sin, nv = ny_ * k.cos - nx_ * k.sin;
        return (k.a.square() * nu.square() + k.b.square() * nv.square()).sqrt();
    };
    const Interval again = divide_by_positive(rho(*k1_) - rho(*k2_), d_);
    const Interval narrower(std::fmax(s_.lo, again.lo), std::fmin(s_.hi, again.hi));
    if (!(narrower.lo <= narrower.hi)) return false;
    s_ = narrower;
    set_box();
    return true;
}

std::vector<BitangentNormal> certified_bitangent_normals(const Ellipse::Enclosure& k1, const Ellipse::Enclosure& k2) {
    return find_bitangent_normals(k1, k2, CenterOffset{k1.xc - k2.xc, k1.yc - k2.yc}, std::nullopt);
}

std::optional<NormalInterval> certified_bitangent_normal(const Ellipse& e1, const Ellipse& e2, bool arrival) {
    const Ellipse::Enclosure &k1 = e1.enclosure(), &k2 = e2.enclosure();
    const CenterOffset offset{coordinate_difference(e1.xc(), k1.xc, e2.xc(), k2.xc),
                              coordinate_difference(e1.yc(), k1.yc, e2.yc(), k2.yc)};
    for (const BitangentNormal& b : find_bitangent_normals(k1, k2, offset, arrival))
        if (b.arrival == arrival) return b.normal;
    return std::nullopt;
}

std::optional<int> compare_normals(const NormalInterval& a, const NormalInterval& b) {
    if (a.sign == b.sign) {
        if (a.tau_hi < b.tau_lo) return -1;
        if (b.tau_hi < a.tau_lo) return 1;
        return std::nullopt;
    }
    // Different half circles: the +1 chart (phi in [-pi/2, pi/2]) comes first,
    // unless both touch a seam they share (phi = pi/2: tau = 1 in the +1
    // chart, -1 in the other; phi = -pi/2: tau = -1, +1).
    constexpr double kSeam = 1e-6;
    const NormalInterval& plus = a.sign > 0 ? a : b;
    const NormalInterval& minus = a.sign > 0 ? b : a;
    auto near = [](const NormalInterval& n, double end) { return n.tau_lo <= end + kSeam && n.tau_hi >= end - kSeam; };
    if ((near(plus, 1) && near(minus, -1)) || (near(plus, -1) && near(minus, 1))) return std::nullopt;
    return a.sign > 0 ? -1 : 1;
}

std::optional<int> normal_in_arc(const NormalInterval& from, const NormalInterval& to, const NormalInterval& x) {
    const auto from_to = compare_normals(from, to), after_from = compare_normals(x, from), before_to = compare_normals(to, x);
    if (!from_to || !after_from || !before_to) return std::nullopt;
    const bool inside = *from_to < 0 ? (*after_from > 0 && *before_to > 0)   // from < x < to
                                     : (*after_from > 0 || *before_to > 0);  // wraps through the cut
    return inside ? 1 : -1;
}

}  // namespace ellvor
