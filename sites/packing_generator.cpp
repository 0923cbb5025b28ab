#include "sites/packing_generator.hpp"

#include "sites/separating_slab.hpp"
#include "sites/site_generators.hpp"
#include "util/error.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace ellvor {

namespace {

// The dyadic grids of the parameters (see the header): every value is an
// exact double, and a b = k m^2 / 2^60 is an exact integer multiple of 2^-60.
constexpr int kAxisBits = 24;     // b = m / 2^24
constexpr int kAspectBits = 12;   // a = (k / 2^12) b
constexpr int kAngleBits = 20;    // w = j / 2^20
constexpr int kCenterBits = 40;   // xc = x / 2^40
constexpr long kMaxAspect = 16;
constexpr long kMaxGrowth = 3;                // a site's linear size at most 3 times its start
constexpr long kPassGrowthNum = 129, kPassGrowthDen = 128;  // at most 1 + 1/128 per pass
constexpr long kMaxPasses = 2000;
constexpr double kStartFraction = 0.55;        // of the RSA phase (at most)
constexpr double kSizeRatio = 6;              // of the largest start size to the smallest
constexpr long kPlacementAttempts = 100000;   // per site, in the RSA phase
constexpr int kStarts = 6;                    // RSA starts, each at kStartFractionStep times the last's fraction
constexpr double kStartFractionStep = 0.8;
// pi bracketed by rationals, for the certified packing fraction.
const Rational& pi_lower() { static const Rational p(Integer(314159265358979L), Integer(100000000000000L)); return p; }
const Rational& pi_upper() { static const Rational p(Integer(314159265358980L), Integer(100000000000000L)); return p; }

double dyadic(std::int64_t numerator, int bits) { return std::ldexp(static_cast<double>(numerator), -bits); }

// A site during the generation: integer numerators on the grids above (its
// SlabSite holds their exact doubles).
struct PackSite {
    std::int64_t m = 0, k = 0, j = 0, x = 0, y = 0;
    std::int64_t m_cap = 0;  // kMaxGrowth times the start
    bool frozen = false;
};

// cos and sin of the rotation for w = j / 2^20: w^2, 1 - w^2, 1 + w^2 and 2w
// are exact doubles, so one outward-rounded division each.
std::pair<Interval, Interval> rotation(std::int64_t j) {
    const double w = dyadic(j, kAngleBits);
    const Interval den(1 + w * w);
    return {Interval(1 - w * w) / den, Interval(2 * w) / den};
}

// A certified lower bound of the largest scale of p keeping it inside [0, L]^2.
double wall_scale(const SlabSite& p, double side) {
    const Interval hx = support_enclosure(p, 1, 0), hy = support_enclosure(p, 0, 1), L(side);
    return std::min({(p.xc / hx).lo, ((L - p.xc) / hx).lo, (p.yc / hy).lo, ((L - p.yc) / hy).lo});
}

std::int64_t floor_to_int64(const Rational& q) {
    Integer f;
    fmpz_fdiv_q(f.get(), fmpq_numref(q.get()), fmpq_denref(q.get()));
    if (!fmpz_fits_si(f.get())) throw Error("packing: a number out of range");
    return fmpz_get_si(f.get());
}
std::int64_t ceil_to_int64(const Rational& q) {
    Integer f;
    fmpz_cdiv_q(f.get(), fmpq_numref(q.get()), fmpq_denref(q.get()));
    if (!fmpz_fits_si(f.get())) throw Error("packing: a number out of range");
    return fmpz_get_si(f.get());
}

Integer power_of_two(int bits) {
    Integer p(1);
    fmpz_mul_2exp(p.get(), p.get(), static_cast<ulong>(bits));
    return p;
}

// The sum of a b over the sites, in units of 2^-60: exact (k m^2 < 2^84 and
// at most 10^6 sites).
using AreaSum = __int128;
AreaSum area_term(const PackSite& s) { return static_cast<AreaSum>(s.k) * s.m * s.m; }

Integer to_integer(AreaSum v) {
    // v >= 0 here
    const auto high = static_cast<std::uint64_t>(v >> 64), low = static_cast<std::uint64_t>(v);
    Integer r;
    fmpz_set_ui(r.get(), high);
    fmpz_mul_2exp(r.get(), r.get(), 64);
    fmpz_add_ui(r.get(), r.get(), low);
    return r;
}

// pi sum(a b) / L^2 with pi replaced by `pi`.
Rational fraction_of(AreaSum sum, long side, const Rational& pi) {
    return pi * Rational(to_integer(sum), power_of_two(2 * kAxisBits + kAspectBits) * Integer(side) * Integer(side));
}

// A nonnegative rational rounded down (or up) to `digits` decimals.
std::string decimals(const Rational& q, int digits, bool up) {
    Integer scale(1);
    fmpz_pow_ui(scale.get(), Integer(10).get(), static_cast<ulong>(digits));
    const Rational scaled = q * Rational(scale);
    Integer t;
    if (up) fmpz_cdiv_q(t.get(), fmpq_numref(scaled.get()), fmpq_denref(scaled.get()));
    else fmpz_fdiv_q(t.get(), fmpq_numref(scaled.get()), fmpq_denref(scaled.get()));
    Integer whole, part;
    fmpz_fdiv_qr(whole.get(), part.get(), t.get(), scale.get());
    std::string f = part.str();
    return whole.str() + "." + std::string(static_cast<std::size_t>(digits) - f.size(), '0') + f;
}

}  // namespace

std::string fraction_bounds_text(const Packing& p) {
    return "[" + decimals(p.fraction_lower, 8, false) + ", " + decimals(p.fraction_upper, 8, true) + "]";
}

std::string describe(const PackingOptions& o) {
    return "ellvor generate packing --count " + std::to_string(o.count) + " --packing-fraction " + o.fraction.str() +
           " --gap " + o.gap.str() + " --aspect " + o.aspect_lo.str() + ".." + o.aspect_hi.str() + " --seed " +
           std::to_string(o.seed);
}

bool packing_pair_certified(const Ellipse& e1, const Ellipse& e2, const Rational& gap) {
    const SlabSite p = SlabSite::of(e1), q = SlabSite::of(e2);
    const Interval g = enclose(gap);
    return certified_separating_scale(p, q, g.mid(), g.hi, 1) >= 1;
}

Packing generate_packing(const PackingOptions& o) {
    if (o.count < kMinPackingCount || o.count > 1'000'000)
        throw Error("count must be in [" + std::to_string(kMinPackingCount) + ", 1000000], got " +
                    std::to_string(o.count));
    if (o.fraction.sign() <= 0 || o.fraction > max_packing_fraction())
        throw Error("packing fraction must be in (0, " + max_packing_fraction().str() + "], got " + o.fraction.str());
    if (o.gap.sign() < 0 || o.gap > Rational(1, 10)) throw Error("gap must be in [0, 1/10], got " + o.gap.str());
    if (o.aspect_lo < Rational(1) || o.aspect_hi < o.aspect_lo || o.aspect_hi > Rational(kMaxAspect))
        throw Error("aspect range must be LO..HI with 1 <= LO <= HI <= " + std::to_string(kMaxAspect) + ", got " +
                    o.aspect_lo.str() + ".." + o.aspect_hi.str());
    const Rational aspect_unit = Rational(Integer(1), power_of_two(kAspectBits));
    const std::int64_t k_lo = ceil_to_int64(o.aspect_lo / aspect_unit), k_hi = floor_to_int64(o.aspect_hi / aspect_unit);
    if (k_hi < k_lo)
        throw Error("aspect range " + o.aspect_lo.str() + ".." + o.aspect_hi.str() + " holds no multiple of 1/" +
                    std::to_string(1L << kAspectBits));

    Packing out;
    long side = 0;
    while (side * side < o.count) ++side;
    out.box_side = side;

    const Interval gap_enclosure = enclose(o.gap);
    const double gap = gap_enclosure.mid(), gap_upper = gap_enclosure.hi;
    // The area sum that proves the fraction: pi_lower sum / (2^60 L^2) >= F.
    const Rational needed = o.fraction * Rational(side) * Rational(side) *
                            Rational(power_of_two(2 * kAxisBits + kAspectBits)) / pi_lower();
    const AreaSum target = [&] {
        Integer t;
        fmpz_cdiv_q(t.get(), fmpq_numref(needed.get()), fmpq_denref(needed.get()));
        AreaSum v = 0;
        Integer high, low;
        fmpz_fdiv_q_2exp(high.get(), t.get(), 64);
        fmpz_fdiv_r_2exp(low.get(), t.get(), 64);
        v = static_cast<AreaSum>(fmpz_get_ui(high.get())) << 64;
        return v + fmpz_get_ui(low.get());
    }();

    // RSA in decreasing order of size at a start fraction phi0 (the asked
    // fraction when lower): site n has area A0 s_n^2 with the harmonic sizes
    // s_n = 1 / (1 + (rho - 1) n / (N - 1)), from 1 down to 1/rho, A0 such that
    // the areas sum to phi0 L^2; b = sqrt(area / (pi r)), a = r b. A few large
    // sites in a small box can jam RSA early (40 sites at 0.55): then RSA starts
    // again, from the same seed, at a lower phi0, and the growth makes up the rest.
    const double pi = 3.141592653589793;
    auto relative_size = [&](long n) {
        return o.count > 1 ? 1 / (1 + (kSizeRatio - 1) * static_cast<double>(n) / static_cast<double>(o.count - 1))
                           : 1.0;
    };
    double size_sum = 0;
    for (long n = 0; n < o.count; ++n) size_sum += relative_size(n) * relative_size(n);

    // The RSA state, set by `restart` for each start fraction. A grid of cells
    // about twice the smallest site; queries look as far as the largest site
    // can reach.
    SiteRandom rng(o.seed);
    double largest_area = 0, cell_width = 1;
    long cells = 1;
    std::vector<std::vector<std::int32_t>> grid;
    double largest_axis = 0;  // of the sites placed, an upper bound
    std::vector<PackSite> sites;
    std::vector<SlabSite> frames;
    auto restart = [&](double start_fraction) {
        rng = SiteRandom(o.seed);
        largest_area = start_fraction * static_cast<double>(side) * static_cast<double>(side) / size_sum;
        const double smallest_axis = std::sqrt(largest_area * dyadic(k_lo, kAspectBits) / pi) / kSizeRatio;
        cells = std::max(1L, std::min(4096L, static_cast<long>(static_cast<double>(side) / (4 * smallest_axis))));
        cell_width = static_cast<double>(side) / static_cast<double>(cells);
        grid.assign(static_cast<std::size_t>(cells * cells), {});
        largest_axis = 0;
        sites.clear();
        frames.clear();
        sites.reserve(static_cast<std::size_t>(o.count));
        frames.reserve(static_cast<std::size_t>(o.count));
    };
    auto cell_of = [&](double v) { return std::min(cells - 1, std::max(0L, static_cast<long>(v / cell_width))); };
    auto make_frame = [&](const PackSite& s) {
        const auto rot = rotation(s.j);
        const double b = dyadic(s.m, kAxisBits), a = dyadic(s.k * s.m, kAxisBits + kAspectBits);
        return SlabSite::of(Interval(a), Interval(b), rot.first, rot.second, Interval(dyadic(s.x, kCenterBits)),
                        Interval(dyadic(s.y, kCenterBits)));
    };
    // The sites that may come within the gap of p when p is scaled by at most
    // `scale` (the others' bounding circles stay apart: certified).
    auto for_each_near = [&](const SlabSite& p, double scale, std::size_t self, auto&& visit) {
        const Interval reach_p = scale * p.a;
        const double reach_all = Interval::up(Interval::up(reach_p.hi + largest_axis) + gap_upper);
        const long x0 = cell_of(p.xd - reach_all), x1 = cell_of(p.xd + reach_all);
        const long y0 = cell_of(p.yd - reach_all), y1 = cell_of(p.yd + reach_all);
        for (long i = x0; i <= x1; ++i)
            for (long j = y0; j <= y1; ++j)
                for (std::int32_t id : grid[static_cast<std::size_t>(i * cells + j)]) {
                    if (static_cast<std::size_t>(id) == self) continue;
                    const SlabSite& q = frames[static_cast<std::size_t>(id)];
                    const Interval d2 = (q.xc - p.xc).square() + (q.yc - p.yc).square();
                    const Interval reach = reach_p + q.a + Interval(gap_upper);
                    if (d2.lo > reach.square().hi) continue;
                    if (!visit(static_cast<std::size_t>(id), q)) return false;
                }
        return true;
    };

    // Places site n at a random free center; false when none of
    // kPlacementAttempts centers is free.
    const std::int64_t center_unit = std::int64_t(1) << kCenterBits;
    auto place = [&](long n) {
        PackSite s;
        s.k = k_lo + static_cast<std::int64_t>(rng.below(static_cast<std::uint64_t>(k_hi - k_lo + 1)));
        s.j = static_cast<std::int64_t>(rng.below(std::uint64_t(2) << kAngleBits)) - (std::int64_t(1) << kAngleBits);
        const double r = dyadic(s.k, kAspectBits);
        const double area = largest_area * relative_size(n) * relative_size(n);
        s.m = static_cast<std::int64_t>(std::floor(std::ldexp(std::sqrt(area / (pi * r)), kAxisBits)));
        if (s.m < 1) throw Error("packing: sites too small for the grid of the axes");
        s.m_cap = kMaxGrowth * s.m;
        // the center at least a (the bounding radius) from the walls, on the grid
        const std::int64_t margin = s.k * s.m * (std::int64_t(1) << (kCenterBits - kAxisBits - kAspectBits));
        const std::int64_t span = side * center_unit - 2 * margin;
        if (span <= 0) throw Error("packing: a site does not fit in the box");
        for (long attempt = 0; attempt < kPlacementAttempts; ++attempt) {
            s.x = margin + static_cast<std::int64_t>(rng.below(static_cast<std::uint64_t>(span) + 1));
            s.y = margin + static_cast<std::int64_t>(rng.below(static_cast<std::uint64_t>(span) + 1));
            const SlabSite f = make_frame(s);
            const bool free = wall_scale(f, static_cast<double>(side)) >= 1 &&
                              for_each_near(f, 1.0, sites.size(), [&](std::size_t, const SlabSite& q) {
                                  return certified_separating_scale(f, q, gap, gap_upper, 1) >= 1;
                              });
            if (free) {
                grid[static_cast<std::size_t>(cell_of(f.xd) * cells + cell_of(f.yd))].push_back(
                    static_cast<std::int32_t>(sites.size()));
                sites.push_back(s);
                frames.push_back(f);
                largest_axis = std::max(largest_axis, f.ad);
                return true;
            }
        }
        return false;
    };

    double start_fraction = std::min(kStartFraction, o.fraction.to_double());
    for (int start = 1;; ++start) {
        restart(start_fraction);
        long n = 0;
        while (n < o.count && place(n)) ++n;
        if (n == o.count) break;
        if (start == kStarts) {
            AreaSum sum = 0;
            for (const PackSite& t : sites) sum += area_term(t);
            throw Error("packing fraction " + o.fraction.str() + " not reached: site " + std::to_string(n + 1) + " of " +
                        std::to_string(o.count) + " found no room after " + std::to_string(kPlacementAttempts) +
                        " random centers, at packing fraction " + decimals(fraction_of(sum, side, pi_lower()), 4, false) +
                        " (random sequential addition started " + std::to_string(kStarts) + " times, last at " +
                        decimals(Rational(static_cast<long>(std::floor(start_fraction * 10000)), 10000UL), 4, false) + ")");
        }
        start_fraction *= kStartFractionStep;
    }

    AreaSum sum = 0;
    for (const PackSite& s : sites) sum += area_term(s);
    for (long pass = 0; pass < kMaxPasses && sum < target; ++pass) {
        bool grew = false;
        for (std::size_t i = 0; i < sites.size() && sum < target; ++i) {
            PackSite& s = sites[i];
            if (s.frozen) continue;
            const std::int64_t wanted = std::min(s.m_cap, s.m * kPassGrowthNum / kPassGrowthDen);
            if (wanted <= s.m) { s.frozen = true; continue; }
            const double want_scale = static_cast<double>(wanted) / static_cast<double>(s.m);
            const SlabSite& p = frames[i];
            double scale = std::min(want_scale, wall_scale(p, static_cast<double>(side)));
            for_each_near(p, want_scale, i, [&](std::size_t, const SlabSite& q) {
                scale = std::min(scale, certified_separating_scale(p, q, gap, gap_upper, scale));
                return true;
            });
            // m' <= scale m exactly: the product rounded down.
            const std::int64_t m_new =
                std::min(wanted, static_cast<std::int64_t>(std::floor(Interval::down(scale * static_cast<double>(s.m)))));
            if (m_new <= s.m) { s.frozen = true; continue; }
            sum -= area_term(s);
            s.m = m_new;
            sum += area_term(s);
            frames[i] = make_frame(s);
            largest_axis = std::max(largest_axis, frames[i].ad);
            grew = true;
        }
        if (!grew) break;
    }

    out.fraction_lower = fraction_of(sum, side, pi_lower());
    out.fraction_upper = fraction_of(sum, side, pi_upper());
    if (sum < target)
        throw Error("packing fraction " + o.fraction.str() + " not reached: the sites jammed at " +
                    decimals(out.fraction_lower, 4, false) + " (" + std::to_string(o.count) + " sites, aspect " +
                    o.aspect_lo.str() + ".." + o.aspect_hi.str() + ", gap " + o.gap.str() + ")");

    // Every pair and wall again, from the final sizes alone: the guarantee does
    // not rest on the bookkeeping of the passes.
    for (std::size_t i = 0; i < sites.size(); ++i) {
        const SlabSite& p = frames[i];
        bool ok = wall_scale(p, static_cast<double>(side)) >= 1 &&
                  for_each_near(p, 1.0, i, [&](std::size_t, const SlabSite& q) {
                      return certified_separating_scale(p, q, gap, gap_upper, 1) >= 1;
                  });
        if (!ok) throw Error("packing: internal error: site " + std::to_string(i) + " not certified at the end");
    }

    out.sites.reserve(sites.size());
    const Integer axis_den = power_of_two(kAxisBits), a_den = power_of_two(kAxisBits + kAspectBits),
                  w_den = power_of_two(kAngleBits), c_den = power_of_two(kCenterBits);
    for (const PackSite& s : sites)
        out.sites.emplace_back(Rational(Integer(s.k * s.m), a_den), Rational(Integer(s.m), axis_den),
                               Rational(Integer(s.j), w_den), Rational(Integer(s.x), c_den),
                               Rational(Integer(s.y), c_den));
    return out;
}

}  // namespace ellvor
