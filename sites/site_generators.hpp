// Deterministic site generators. Every random draw is an integer draw from a
// seeded std::mt19937_64 (whose output sequence is fixed by the C++ standard),
// turned into numbers by our own code: no std::uniform_*_distribution and no
// std::shuffle (their algorithms are implementation-defined), no floating
// point. Hence the same seed gives the same sites on every machine.
//
// Rationals "of bit size B": a value in [lo, hi] is drawn as p/q with q uniform
// in [1, 2^B] and p uniform among the integers with lo <= p/q <= hi, so the
// denominators are at most 2^B and |p| <= max(|lo|, |hi|) 2^B.
//
// Disjointness is decided by a conservative sufficient test that does not need
// the exact predicates: two sites are accepted as separated when their bounding
// circles (center, radius max(a, b)) are disjoint, and a site is accepted as
// nested in a host when its bounding circle lies strictly inside the host's
// inscribed circle (radius min(a, b)), hence strictly inside the host.
// Crossing sites (below) are decided exactly: circles by their centers and
// radii, ellipses by the real roots of their intersection quartic (the count
// of predicates/relative_position.hpp's boundary_meeting_points, which this
// layer cannot call, made here with FLINT's real-root count).
#pragma once

#include "sites/ellipse.hpp"

#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace ellvor {

// A uniform integer draw source on top of std::mt19937_64.
class SiteRandom {
public:
    explicit SiteRandom(std::uint64_t seed) : engine_(seed) {}
    std::uint64_t next() { return engine_(); }
    // Uniform in [0, n] (n >= 0), by rejection.
    Integer uniform_integer(const Integer& n);
    // Uniform in [0, n) for n >= 1.
    std::uint64_t below(std::uint64_t n);
    // Uniform p/q in [lo, hi] with q uniform in [1, 2^bits] (see above).
    Rational uniform_rational(const Rational& lo, const Rational& hi, long bits);
    // +1 or -1.
    int sign() { return (next() >> 63) ? 1 : -1; }

private:
    std::mt19937_64 engine_;
};

enum class SiteKind { ellipses, circles };

struct GeneratorOptions {
    SiteKind kind = SiteKind::ellipses;
    long count = 10;
    std::uint64_t seed = 1;
    long bits = 8;                    // denominators up to 2^bits; 1 <= bits <= kMaxGeneratorBits
    Rational box = Rational(100);     // centers of top-level sites lie in [-box, box]^2
    Rational nested_fraction = Rational(0);  // round(fraction * count) sites are nested in another
    Rational crossing_fraction = Rational(0);  // round(fraction * count) sites cross another
};

constexpr long kMaxGeneratorBits = 1000;

// Pairwise-disjoint (separated or nested) sites. Exactly round(nested_fraction
// * count) of them lie strictly inside another (one level deep); they are
// placed in random order among the others (so a hidden site may come before
// its host). Throws Error on bad options, or when rejection sampling fails to
// place the sites (too many for the box).
//
// crossing_fraction in [0, 1]: exactly K = round(crossing_fraction * count)
// of the sites cross at least one other site (sites_cross below: boundaries
// meeting in exactly two points, crossing at both), and the other sites cross
// none; no two boundaries meet in three or four points. K = 1 is an Error (a
// crossing needs two sites), and so is K > count - nested (nested sites never
// cross). The K sites come from ceil(K/2) *partners*, drawn after the
// separated and nested sites: each crosses a separated site that crossed
// nothing yet (its target); for odd K the last partner's target is a site that
// already crosses. A partner may also cross any number of sites that already
// cross; from every other site (nested ones included) it is apart. So no two
// sites are identical, tangent or nested except the nested ones in their
// hosts, and the nested count is as above. Half the partner ellipses are
// drawn like the separated ones, half thin (the minor semi-axis below the
// separated ones' smallest, down to a quarter of it: aspect ratios up to 16);
// at any angle, their centers inside the target (deep crossings) or not. The
// separated sites are count - nested - ceil(K/2) of the first draws, on the
// grid and size range of K = 0: with fraction 0 the sites are those the
// generator made before the option existed, and two fractions with the same
// seed share their first separated sites.
std::vector<Ellipse> generate_sites(const GeneratorOptions& options);

// The conservative tests used above (exact).
bool bounding_circles_separated(const Ellipse& e1, const Ellipse& e2);
bool bounding_circle_inside_inscribed(const Ellipse& inner, const Ellipse& host);

// The crossing tests (exact).
// Two circles' boundaries cross (meet in two points), exactly:
// (r1 - r2)^2 < |c1 - c2|^2 < (r1 + r2)^2. Throws Error unless both are circles.
bool circles_cross(const Ellipse& c1, const Ellipse& c2);
// Two sites' boundaries meet in exactly two points and cross transversally at
// both (intersection multiplicity 1), exactly; symmetric; for two circles
// circles_cross. False for every other pair: apart, tangent, nested,
// identical, meeting in three or four points, and the rare crossing that also
// osculates (multiplicity 3), which the generator does not make.
bool sites_cross(const Ellipse& e1, const Ellipse& e2);

// A one-line description of the options, for file headers.
std::string describe(const GeneratorOptions& options);

// ---- Nearly coincident copies (docs/DESIGN.md §4.2, item 3) ------------------------------------------------

// How near_copy moves a site by about 10^-k of its size.
enum class NearCopyMotion { shift_x, shift_xy, rotation, scale_up, scale_down };
const char* near_copy_motion_name(NearCopyMotion m);

// e moved by about 10^-k: translated by 10^-k (along x, or by (1, -3) 10^-k),
// rotated by about 10^-k about the point three semi-axes a from its center
// (to first order, exactly rational: w by the half-angle formula, the center
// along the rotation's tangent), or scaled by 1 +- 10^-k about that point. A
// copy of an ellipse (or circle) of moderate aspect crosses it in two points;
// a rotated copy of an elongated ellipse can meet it in four (an input error).
Ellipse near_copy(const Ellipse& e, NearCopyMotion motion, long k);

// ---- The circle datasets of the paper (Emiris, Tsigaridas, Tzoumas 2007), section 5.1 ---------------------
//
// family   kappa1:   sites E1 E2, query point q       (side_of_bisector)
//          kappa2:   sites E1 E2, query site Q        (vertex_conflict with the infinite vertex)
//          incircle: sites E1 E2 E3, query site Q     (vertex_conflict, InCircle)
// set "1"  the degenerate family:
//   kappa1   circles (-2,0) and (2,0) of radius 1; q = (s, s - 100) for s = 0, 1/2, ..., 100
//            (the segment from (0,-100) to (100,0), each coordinate moving by 1/2): 201 instances.
//   kappa2   the same circles; Q the circle of radius 1 (the paper does not give it; our choice)
//            centered at (s, s - 100), s as above: 201 instances.
//   incircle circles (-3,0) r 2, (3/2,0) r 1/2, (0,-2) r 1; Q of radius 1 centered at (0, y),
//            y = 1, 9/8, ..., 50: 393 instances.
// sets "2a", "2b", "2c": set 1 perturbed by 10^-2, 10^-4, 10^-6: our reading is that every
//   coordinate of every center, every radius and the query point's coordinates each get
//   + or - 10^-k with an independent random sign.
// set "3": 500 random instances in [-10,10]^2 with rationals of bit size `bits`:
//   kappa1 two circles with radii in (0, 2] and a point outside both; kappa2 three circles with
//   radii in (0, 2]; incircle four circles with radii in [1/3, 5/2]. Circles of one instance are
//   made pairwise separated (rejection), since the predicates need disjoint sites.
enum class PaperFamily { kappa1, kappa2, incircle };

struct PaperInstance {
    std::vector<Ellipse> sites;          // E1 E2 (E3)
    std::optional<Point> query_point;    // kappa1
    std::optional<Ellipse> query_site;   // kappa2, incircle
};

struct PaperDataset {
    PaperFamily family;
    std::string set;  // "1", "2a", "2b", "2c", "3"
    std::vector<PaperInstance> instances;
};

const char* paper_family_name(PaperFamily family);
// Throws Error for an unknown set name.
PaperDataset generate_paper_dataset(PaperFamily family, const std::string& set, std::uint64_t seed,
                                    long bits = 16);

}  // namespace ellvor
