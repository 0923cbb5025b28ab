#include "sites/site_generators.hpp"

#include "sites/ellipse_polynomials.hpp"
#include "util/error.hpp"

#include <map>
#include <utility>

namespace ellvor {

// ---- SiteRandom --------------------------------------------------------------

Integer SiteRandom::uniform_integer(const Integer& n) {
    if (n.sign() < 0) throw Error("uniform_integer: negative bound");
    if (n.is_zero()) return Integer(0);
    const ulong nbits = fmpz_bits(n.get());
    Integer r;
    for (;;) {
        fmpz_zero(r.get());
        for (ulong have = 0; have < nbits; have += 64) {
            fmpz_mul_2exp(r.get(), r.get(), 64);
            fmpz_add_ui(r.get(), r.get(), next());
        }
        fmpz_fdiv_r_2exp(r.get(), r.get(), nbits);  // keep nbits random bits
        if (fmpz_cmp(r.get(), n.get()) <= 0) return r;
    }
}

std::uint64_t SiteRandom::below(std::uint64_t n) {
    if (n == 0) throw Error("below: empty range");
    const std::uint64_t threshold = (0 - n) % n;  // 2^64 mod n
    for (;;) {
        std::uint64_t r = next();
        if (r >= threshold) return r % n;
    }
}

Rational SiteRandom::uniform_rational(const Rational& lo, const Rational& hi, long bits) {
    if (hi < lo) throw Error("uniform_rational: empty interval");
    Integer max_den;
    fmpz_one(max_den.get());
    fmpz_mul_2exp(max_den.get(), max_den.get(), static_cast<ulong>(bits));
    for (int attempt = 0; attempt < 256; ++attempt) {
        Integer q = uniform_integer(max_den - Integer(1)) + Integer(1);
        Rational lq = lo * Rational(q), hq = hi * Rational(q);
        Integer pmin, pmax;
        fmpz_cdiv_q(pmin.get(), fmpq_numref(lq.get()), fmpq_denref(lq.get()));
        fmpz_fdiv_q(pmax.get(), fmpq_numref(hq.get()), fmpq_denref(hq.get()));
        if (pmax < pmin) continue;
        Integer p = pmin + uniform_integer(pmax - pmin);
        return Rational(p, q);
    }
    throw Error("cannot draw a rational of bit size " + std::to_string(bits) + " in [" + lo.str() + ", " +
                hi.str() + "]: the interval is too narrow; use more bits");
}

// ---- conservative geometric tests -------------------------------------------

namespace {
const Rational& max_axis(const Ellipse& e) { return e.a() < e.b() ? e.b() : e.a(); }
const Rational& min_axis(const Ellipse& e) { return e.a() < e.b() ? e.a() : e.b(); }
Rational squared_distance(const Ellipse& e1, const Ellipse& e2) {
    Rational dx = e1.xc() - e2.xc(), dy = e1.yc() - e2.yc();
    return dx * dx + dy * dy;
}
}  // namespace

bool bounding_circles_separated(const Ellipse& e1, const Ellipse& e2) {
    Rational r = max_axis(e1) + max_axis(e2);
    return squared_distance(e1, e2) > r * r;
}

bool bounding_circle_inside_inscribed(const Ellipse& inner, const Ellipse& host) {
    Rational gap = min_axis(host) - max_axis(inner);
    if (gap.sign() <= 0) return false;
    return squared_distance(inner, host) < gap * gap;
}

namespace {
// How two sites lie, as far as the generator cares: apart (disjoint, neither
// inside the other), crossing (boundaries meeting in exactly two points, both
// crossings), or anything else (tangent, nested, identical, meeting in three
// or four points). Exact.
enum class SitePair { separated, crossing, other };

// Two circles: by their centers and radii.
SitePair circle_pair(const Ellipse& c1, const Ellipse& c2) {
    const Rational d2 = squared_distance(c1, c2);
    const Rational sum = c1.a() + c2.a(), diff = c1.a() - c2.a();
    if (d2 > sum * sum) return SitePair::separated;
    if (diff * diff < d2 && d2 < sum * sum) return SitePair::crossing;
    return SitePair::other;
}

// Any two sites: by the intersection quartic (the conic of E2 along the
// boundary of E1, negative inside E2). Its roots are the meeting points, t =
// infinity (the i-point of E1) with multiplicity 4 - degree, and a root's
// multiplicity is the intersection multiplicity there: 1 for a transversal
// crossing, more for a tangency or an osculating crossing. So the sites cross
// transversally in two points iff the quartic is squarefree, of degree 3 or 4,
// with two real roots counting infinity. predicates/ counts them in
// boundary_meeting_points, which this layer cannot call; FLINT's real-root
// count (Sturm sequences, for squarefree polynomials) does it here.
SitePair ellipse_pair(const Ellipse& e1, const Ellipse& e2) {
    if (bounding_circles_separated(e1, e2)) return SitePair::separated;
    const IntPolynomial quartic = intersection_quartic(e1, e2);
    // Degree below 3: a multiple root at infinity, or the same ellipse (zero).
    if (quartic.degree() < 3 || !fmpz_poly_is_squarefree(quartic.get())) return SitePair::other;
    const long meeting_points = fmpz_poly_num_real_roots(quartic.get()) + (quartic.degree() == 3 ? 1 : 0);
    if (meeting_points == 2) return SitePair::crossing;
    if (meeting_points != 0) return SitePair::other;
    // The boundaries do not meet, so each lies wholly inside or outside the
    // other site: one point of each decides.
    const Point p2 = e2.point_at(Rational(0));
    return quartic.sign_at(Rational(0)) > 0 && e1.side_of_point(p2.x, p2.y) > 0 ? SitePair::separated
                                                                                : SitePair::other;
}

SitePair site_pair(const Ellipse& e1, const Ellipse& e2) {
    return e1.is_circle() && e2.is_circle() ? circle_pair(e1, e2) : ellipse_pair(e1, e2);
}
}  // namespace

bool circles_cross(const Ellipse& c1, const Ellipse& c2) {
    if (!c1.is_circle() || !c2.is_circle()) throw Error("circles_cross: the sites must be circles");
    return circle_pair(c1, c2) == SitePair::crossing;
}

bool sites_cross(const Ellipse& e1, const Ellipse& e2) { return site_pair(e1, e2) == SitePair::crossing; }

// ---- random site sets --------------------------------------------------------

std::string describe(const GeneratorOptions& o) {
    return std::string("ellvor generate ") + (o.kind == SiteKind::circles ? "circles" : "ellipses") +
           " --count " + std::to_string(o.count) + " --seed " + std::to_string(o.seed) + " --bits " +
           std::to_string(o.bits) + " --box " + o.box.str() + " --nested-fraction " + o.nested_fraction.str() +
           // only when set, so that the headers of files made before the option stay the same
           (o.crossing_fraction.is_zero() ? std::string() : " --crossing " + o.crossing_fraction.str());
}

namespace {

long isqrt_ceil(long n) {
    long r = 0;
    while (r * r < n) ++r;
    return r;
}

// The semi-axes and rotation of a site, before it has a center.
struct SiteShape {
    Rational a, b, w;
    const Rational& largest_axis() const { return a < b ? b : a; }
};

long floor_to_long(const Rational& q) {
    Integer f;
    fmpz_fdiv_q(f.get(), fmpq_numref(q.get()), fmpq_denref(q.get()));
    return fmpz_get_si(f.get());
}

}  // namespace

namespace {

void check_generator_options(const GeneratorOptions& o) {
    if (o.count < 0 || o.count > 1'000'000) throw Error("count must be in [0, 1000000], got " + std::to_string(o.count));
    if (o.bits < 1 || o.bits > kMaxGeneratorBits)
        throw Error("bits must be in [1, " + std::to_string(kMaxGeneratorBits) + "], got " + std::to_string(o.bits));
    if (o.box.sign() <= 0) throw Error("box must be positive, got " + o.box.str());
    if (o.nested_fraction.sign() < 0 || o.nested_fraction >= Rational(1))
        throw Error("nested fraction must be in [0, 1), got " + o.nested_fraction.str());
    if (o.crossing_fraction.sign() < 0 || o.crossing_fraction > Rational(1))
        throw Error("crossing fraction must be in [0, 1], got " + o.crossing_fraction.str());
}

// How many sites of each kind: round(fraction * count), halves rounded up.
struct SiteCounts {
    long nested, top, crossing, partners, separated;

    explicit SiteCounts(const GeneratorOptions& o) {
        auto rounded_count = [&](const Rational& fraction) {
            return floor_to_long(fraction * Rational(o.count) + Rational(1, 2));
        };
        nested = rounded_count(o.nested_fraction);
        top = o.count - nested;
        if (top < 1) throw Error("nested fraction leaves no site to nest into");
        crossing = rounded_count(o.crossing_fraction);
        if (crossing == 1)
            throw Error("crossing fraction " + o.crossing_fraction.str() + " of " + std::to_string(o.count) +
                        " sites is 1 crossing site; a crossing needs two sites");
        if (crossing > top)
            throw Error("crossing fraction " + o.crossing_fraction.str() + " asks for " + std::to_string(crossing) +
                        " crossing sites, but only " + std::to_string(top) +
                        " are not nested (nested sites never cross)");
        partners = (crossing + 1) / 2;
        separated = top - partners;
    }
};

// Places the sites of one set in three passes -- separated sites, nested
// ones, crossing partners -- drawing from one generator in a fixed order, so
// that the same options give the same file everywhere.
class SitePlacer {
public:
    SitePlacer(const GeneratorOptions& o, const SiteCounts& counts)
        : o_(o), counts_(counts), rng_(o.seed), circles_(o.kind == SiteKind::circles),
          // The scale depends on the non-nested sites, not on how many cross,
          // so that sets differing only in the crossing fraction are alike.
          rmax_(o.box / Rational(4 * isqrt_ceil(counts.top))),  // bounding radii in [rmax/4, rmax]
          rmin_(rmax_ / Rational(4)),
          center_extent_(o.box - rmax_),  // keeps every site inside [-box, box]^2
          cell_(Rational(2) * rmax_),     // grid for the neighbour search
          max_attempts_(1000 + 200 * o.count) {}

    void place_separated_sites() {
        while (static_cast<long>(placed_.size()) < counts_.separated) {
            count_attempt();
            const SiteShape shape = draw_shape(rmin_, rmax_, rmin_, rmax_);
            Rational xc = rng_.uniform_rational(-center_extent_, center_extent_, o_.bits);
            Rational yc = rng_.uniform_rational(-center_extent_, center_extent_, o_.bits);
            Ellipse e(shape.a, shape.b, shape.w, xc, yc);
            const auto [cx, cy] = grid_cell(xc, yc);
            bool ok = true;
            for (long i = cx - 1; i <= cx + 1 && ok; ++i)
                for (long j = cy - 1; j <= cy + 1 && ok; ++j) {
                    auto it = grid_.find({i, j});
                    if (it == grid_.end()) continue;
                    for (std::size_t k : it->second)
                        if (!bounding_circles_separated(e, placed_[k])) { ok = false; break; }
                }
            if (!ok) continue;
            grid_[{cx, cy}].push_back(placed_.size());
            placed_.push_back(std::move(e));
        }
        hosts_ = placed_.size();
        inside_.assign(hosts_, {});
    }

    void place_nested_sites() {
        for (long n = 0; n < counts_.nested;) {
            count_attempt();
            const std::size_t h = rng_.below(hosts_);
            const Ellipse& host = placed_[h];
            const Rational m = min_axis(host);
            const SiteShape shape = draw_shape(m / Rational(8), m / Rational(2), m / Rational(8), m / Rational(2));
            const Rational off = m / Rational(4);
            Rational xc = rng_.uniform_rational(host.xc() - off, host.xc() + off, o_.bits);
            Rational yc = rng_.uniform_rational(host.yc() - off, host.yc() + off, o_.bits);
            Ellipse e(shape.a, shape.b, shape.w, xc, yc);
            if (!bounding_circle_inside_inscribed(e, host)) continue;
            bool ok = true;
            for (std::size_t k : inside_[h])
                if (!bounding_circles_separated(e, placed_[k])) { ok = false; break; }
            if (!ok) continue;
            inside_[h].push_back(placed_.size());
            placed_.push_back(std::move(e));
            ++n;
        }
    }

    // Crossing partners (see the header). `crosses_` marks the sites that
    // cross another; `free_targets` the separated sites that do not yet.
    void place_crossing_partners() {
        crosses_.assign(placed_.size(), 0);
        std::vector<std::size_t> crossing_ids, free_targets;
        for (std::size_t k = 0; k < hosts_; ++k) free_targets.push_back(k);
        for (long p = 0; p < counts_.partners;) {
            count_attempt();
            // Two new crossing sites (the partner and its target) while two or
            // more are missing; for odd K the last partner adds only itself.
            const bool pair = counts_.crossing - static_cast<long>(crossing_ids.size()) >= 2;
            const std::size_t slot = rng_.below(pair ? free_targets.size() : crossing_ids.size());
            const std::size_t t = pair ? free_targets[slot] : crossing_ids[slot];
            const Ellipse& target = placed_[t];
            // Half the partner ellipses thin: the minor semi-axis in [rmin/4, rmin],
            // an aspect ratio up to 16 (no draw for circles, whose sets stay as they were).
            const bool thin = !circles_ && rng_.below(2) == 0;
            const SiteShape shape = draw_shape(rmin_, rmax_, thin ? rmin_ / Rational(4) : rmin_, thin ? rmin_ : rmax_);
            // Centers up to the sum of the largest semi-axes away in each coordinate:
            // deep crossings (a center inside the other site) and shallow ones.
            const Rational reach = max_axis(target) + shape.largest_axis();
            Rational xc = rng_.uniform_rational(target.xc() - reach, target.xc() + reach, o_.bits);
            Rational yc = rng_.uniform_rational(target.yc() - reach, target.yc() + reach, o_.bits);
            if (xc < -center_extent_ || xc > center_extent_ || yc < -center_extent_ || yc > center_extent_) continue;
            Ellipse e(shape.a, shape.b, shape.w, xc, yc);
            if (site_pair(e, target) != SitePair::crossing) continue;
            const auto [cx, cy] = grid_cell(xc, yc);
            if (!crosses_only_crossing_sites(e, t, cx, cy)) continue;
            if (pair) {
                crosses_[t] = 1;
                crossing_ids.push_back(t);
                free_targets[slot] = free_targets.back();
                free_targets.pop_back();
            }
            grid_[{cx, cy}].push_back(placed_.size());
            crosses_.push_back(1);
            crossing_ids.push_back(placed_.size());
            placed_.push_back(std::move(e));
            ++p;
        }
    }

    // Fisher-Yates with our own uniform draws.
    std::vector<Ellipse> shuffled() {
        for (std::size_t i = placed_.size(); i > 1; --i) {
            std::size_t j = rng_.below(i);
            std::swap(placed_[i - 1], placed_[j]);
        }
        // The separation tests made the exact parameters of the circles they
        // read; a compact circle does not keep them (sites/ellipse.hpp).
        for (Ellipse& e : placed_) e.make_own();
        return std::move(placed_);
    }

private:
    void count_attempt() {
        if (++attempts_ <= max_attempts_) return;
        throw Error("could not place " + std::to_string(o_.count) + (counts_.crossing ? " sites" : " disjoint sites") +
                    " after " + std::to_string(max_attempts_) + " attempts; use a larger --box or more --bits");
    }

    // a in [a_lo, a_hi]; for ellipses b in [b_lo, b_hi] and w in [-1, 1]
    // (every direction of the a-axis: the rotation in [-pi/2, pi/2]).
    SiteShape draw_shape(const Rational& a_lo, const Rational& a_hi, const Rational& b_lo, const Rational& b_hi) {
        SiteShape shape;
        shape.a = rng_.uniform_rational(a_lo, a_hi, o_.bits);
        if (circles_) {
            shape.b = shape.a;
        } else {
            shape.b = rng_.uniform_rational(b_lo, b_hi, o_.bits);
            shape.w = rng_.uniform_rational(Rational(-1), Rational(1), o_.bits);
        }
        return shape;
    }

    std::pair<long, long> grid_cell(const Rational& xc, const Rational& yc) const {
        return {floor_to_long((xc + o_.box) / cell_), floor_to_long((yc + o_.box) / cell_)};
    }

    // e (crossing its target t) is apart from every other site or crosses
    // only sites that cross already, and meets no nested site. Every site
    // near enough to meet e is in a neighbouring cell (largest semi-axes <=
    // rmax); nested sites lie inside their hosts, so only the hosts e meets
    // need their nested sites checked.
    bool crosses_only_crossing_sites(const Ellipse& e, std::size_t t, long cx, long cy) const {
        for (long i = cx - 1; i <= cx + 1; ++i)
            for (long j = cy - 1; j <= cy + 1; ++j) {
                auto it = grid_.find({i, j});
                if (it == grid_.end()) continue;
                for (std::size_t k : it->second) {
                    if (k != t) {  // the target crosses e
                        const SitePair rel = site_pair(e, placed_[k]);
                        if (rel == SitePair::separated) continue;
                        if (rel == SitePair::other || !crosses_[k]) return false;
                    }
                    if (k < hosts_)
                        for (std::size_t m : inside_[k])
                            if (site_pair(e, placed_[m]) != SitePair::separated) return false;
                }
            }
        return true;
    }

    const GeneratorOptions& o_;
    const SiteCounts& counts_;
    SiteRandom rng_;
    const bool circles_;
    const Rational rmax_, rmin_, center_extent_, cell_;
    const long max_attempts_;
    long attempts_ = 0;
    std::vector<Ellipse> placed_;
    std::map<std::pair<long, long>, std::vector<std::size_t>> grid_;
    std::size_t hosts_ = 0;                         // the separated sites, placed first
    std::vector<std::vector<std::size_t>> inside_;  // nested sites per host
    std::vector<char> crosses_;
};

}  // namespace

std::vector<Ellipse> generate_sites(const GeneratorOptions& o) {
    check_generator_options(o);
    if (o.count == 0) return {};
    const SiteCounts counts(o);
    SitePlacer placer(o, counts);
    placer.place_separated_sites();
    placer.place_nested_sites();
    placer.place_crossing_partners();
    return placer.shuffled();
}

// ---- paper datasets ----------------------------------------------------------

const char* paper_family_name(PaperFamily family) {
    switch (family) {
        case PaperFamily::kappa1: return "kappa1";
        case PaperFamily::kappa2: return "kappa2";
        case PaperFamily::incircle: return "incircle";
    }
    return "?";
}

namespace {

Rational power_of_ten_inverse(int k) {
    Integer p;
    fmpz_ui_pow_ui(p.get(), 10, static_cast<ulong>(k));
    return Rational(Integer(1), p);
}

Rational perturbed(SiteRandom& rng, const Rational& x, const Rational& eps) {
    return rng.sign() > 0 ? x + eps : x - eps;
}

Ellipse perturbed_circle(SiteRandom& rng, const Ellipse& c, const Rational& eps) {
    Rational x = perturbed(rng, c.xc(), eps);
    Rational y = perturbed(rng, c.yc(), eps);
    Rational r = perturbed(rng, c.a(), eps);
    return Ellipse::circle(x, y, r);
}

std::vector<PaperInstance> degenerate_family(PaperFamily family) {
    std::vector<PaperInstance> out;
    const Rational half(1, 2);
    if (family == PaperFamily::incircle) {
        std::vector<Ellipse> base = {Ellipse::circle(Rational(-3), Rational(0), Rational(2)),
                                     Ellipse::circle(Rational(3, 2), Rational(0), Rational(1, 2)),
                                     Ellipse::circle(Rational(0), Rational(-2), Rational(1))};
        for (long j = 0; j <= 49 * 8; ++j) {  // y = 1 + j/8, 1 <= y <= 50
            PaperInstance inst;
            inst.sites = base;
            inst.query_site = Ellipse::circle(Rational(0), Rational(1) + Rational(j, 8), Rational(1));
            out.push_back(std::move(inst));
        }
        return out;
    }
    std::vector<Ellipse> base = {Ellipse::circle(Rational(-2), Rational(0), Rational(1)),
                                 Ellipse::circle(Rational(2), Rational(0), Rational(1))};
    for (long j = 0; j <= 200; ++j) {  // s = j/2: (s, s - 100) from (0,-100) to (100,0)
        PaperInstance inst;
        inst.sites = base;
        Rational s = Rational(j, 2), t = Rational(j, 2) - Rational(100);
        if (family == PaperFamily::kappa1)
            inst.query_point = Point{s, t};
        else
            inst.query_site = Ellipse::circle(s, t, Rational(1));
        out.push_back(std::move(inst));
    }
    return out;
}

bool all_separated(const std::vector<Ellipse>& cs) {
    for (std::size_t i = 0; i < cs.size(); ++i)
        for (std::size_t j = i + 1; j < cs.size(); ++j)
            if (!bounding_circles_separated(cs[i], cs[j])) return false;
    return true;
}

PaperInstance random_instance(PaperFamily family, SiteRandom& rng, long bits) {
    const Rational lo(-10), hi(10);
    const Rational rlo = family == PaperFamily::incircle ? Rational(1, 3) : Rational(0);
    const Rational rhi = family == PaperFamily::incircle ? Rational(5, 2) : Rational(2);
    const int n = family == PaperFamily::kappa1 ? 2 : family == PaperFamily::kappa2 ? 3 : 4;
    for (int attempt = 0; attempt < 100000; ++attempt) {
        std::vector<Ellipse> cs;
        for (int i = 0; i < n; ++i) {
            Rational x = rng.uniform_rational(lo, hi, bits), y = rng.uniform_rational(lo, hi, bits);
            Rational r = rng.uniform_rational(rlo, rhi, bits);
            while (r.is_zero()) r = rng.uniform_rational(rlo, rhi, bits);
            cs.push_back(Ellipse::circle(x, y, r));
        }
        if (!all_separated(cs)) continue;
        PaperInstance inst;
        if (family == PaperFamily::kappa1) {
            Rational x = rng.uniform_rational(lo, hi, bits), y = rng.uniform_rational(lo, hi, bits);
            if (cs[0].side_of_point(x, y) <= 0 || cs[1].side_of_point(x, y) <= 0) continue;
            inst.query_point = Point{x, y};
            inst.sites = cs;
        } else {
            inst.query_site = cs.back();
            cs.pop_back();
            inst.sites = cs;
        }
        return inst;
    }
    throw Error("could not draw a random paper instance");
}

}  // namespace

PaperDataset generate_paper_dataset(PaperFamily family, const std::string& set, std::uint64_t seed, long bits) {
    if (bits < 1 || bits > kMaxGeneratorBits)
        throw Error("bits must be in [1, " + std::to_string(kMaxGeneratorBits) + "], got " + std::to_string(bits));
    PaperDataset ds{family, set, {}};
    SiteRandom rng(seed);
    if (set == "1") {
        ds.instances = degenerate_family(family);
    } else if (set == "2a" || set == "2b" || set == "2c") {
        const int k = set == "2a" ? 2 : set == "2b" ? 4 : 6;
        const Rational eps = power_of_ten_inverse(k);
        for (PaperInstance inst : degenerate_family(family)) {
            for (Ellipse& c : inst.sites) c = perturbed_circle(rng, c, eps);
            if (inst.query_site) inst.query_site = perturbed_circle(rng, *inst.query_site, eps);
            if (inst.query_point)
                inst.query_point = Point{perturbed(rng, inst.query_point->x, eps), perturbed(rng, inst.query_point->y, eps)};
            ds.instances.push_back(std::move(inst));
        }
    } else if (set == "3") {
        for (int i = 0; i < 500; ++i) ds.instances.push_back(random_instance(family, rng, bits));
    } else {
        throw Error("unknown dataset set '" + set + "'; expected 1, 2a, 2b, 2c or 3");
    }
    return ds;
}

const char* near_copy_motion_name(NearCopyMotion m) {
    switch (m) {
        case NearCopyMotion::shift_x: return "shift x";
        case NearCopyMotion::shift_xy: return "shift (1,-3)";
        case NearCopyMotion::rotation: return "rotation";
        case NearCopyMotion::scale_up: return "scale 1+";
        case NearCopyMotion::scale_down: return "scale 1-";
    }
    return "?";
}

Ellipse near_copy(const Ellipse& e, NearCopyMotion motion, long k) {
    const Rational d = power_of_ten(-k);
    const Rational px = e.xc() + Rational(3) * e.a(), py = e.yc();  // the pivot
    switch (motion) {
        case NearCopyMotion::shift_x: return Ellipse(e.a(), e.b(), e.w(), e.xc() + d, e.yc());
        case NearCopyMotion::shift_xy: return Ellipse(e.a(), e.b(), e.w(), e.xc() + d, e.yc() - Rational(3) * d);
        case NearCopyMotion::rotation:
            return Ellipse(e.a(), e.b(), e.w() + d * (Rational(1) + e.w() * e.w()) / Rational(2), e.xc() - d * (e.yc() - py),
                           e.yc() + d * (e.xc() - px));
        case NearCopyMotion::scale_up:
        case NearCopyMotion::scale_down: {
            const Rational s = motion == NearCopyMotion::scale_up ? Rational(1) + d : Rational(1) - d;
            return Ellipse(e.a() * s, e.b() * s, e.w(), px + s * (e.xc() - px), py + s * (e.yc() - py));
        }
    }
    return e;
}

}  // namespace ellvor
