// Deterministic generators: reproducibility, disjointness (conservative and by exact
// boundary sampling), nested fraction, crossing circles and ellipses (checked against the
// predicates' exact relative positions), bit sizes, and the paper's datasets.
#include <catch2/catch.hpp>

#include "predicates/relative_position.hpp"
#include "sites/site_generators.hpp"
#include "sites/site_io.hpp"
#include "util/error.hpp"

#include <algorithm>
#include <set>
#include <sstream>
#include <tuple>

using namespace ellvor;

namespace {

std::string text(const std::vector<Ellipse>& sites) {
    std::ostringstream out;
    write_ell(out, sites);
    return out.str();
}

// Exact boundary points of e: P(t) for t = k/3, |k| <= 12, and the i-point.
std::vector<Point> boundary_samples(const Ellipse& e) {
    std::vector<Point> pts;
    for (long k = -12; k <= 12; ++k) pts.push_back(e.point_at(Rational(k, 3)));
    pts.push_back(e.i_point());
    return pts;
}

// Independent of the generator's own test: sampled boundary points of each ellipse
// are strictly outside the other (separated pairs), or strictly inside (nested).
void check_pair_by_sampling(const Ellipse& e1, const Ellipse& e2, bool nested_1_in_2) {
    for (const Point& p : boundary_samples(e1)) {
        const int side = e2.side_of_point(p.x, p.y);
        if (nested_1_in_2) REQUIRE(side < 0);
        else REQUIRE(side > 0);
    }
    if (!nested_1_in_2)
        for (const Point& p : boundary_samples(e2)) REQUIRE(e1.side_of_point(p.x, p.y) > 0);
}

long nested_count(const std::vector<Ellipse>& s) {
    long n = 0;
    for (std::size_t i = 0; i < s.size(); ++i)
        for (std::size_t j = 0; j < s.size(); ++j)
            if (i != j && bounding_circle_inside_inscribed(s[i], s[j])) {
                ++n;
                break;
            }
    return n;
}

// Crossing circles written out here, independently of the generator's test.
bool cross(const Ellipse& c1, const Ellipse& c2) {
    const Rational dx = c1.xc() - c2.xc(), dy = c1.yc() - c2.yc(), d2 = dx * dx + dy * dy;
    const Rational sum = c1.a() + c2.a(), diff = c1.a() - c2.a();
    return diff * diff < d2 && d2 < sum * sum;
}

// How many sites cross at least one other (circles).
long crossing_count(const std::vector<Ellipse>& s) {
    std::vector<char> crosses(s.size(), 0);
    for (std::size_t i = 0; i < s.size(); ++i)
        for (std::size_t j = i + 1; j < s.size(); ++j)
            if (cross(s[i], s[j])) crosses[i] = crosses[j] = 1;
    return static_cast<long>(std::count(crosses.begin(), crosses.end(), 1));
}

long rounded(const Rational& fraction, long count) {
    Rational q = fraction * Rational(count) + Rational(1, 2);  // round half up
    return fmpz_get_si(fmpq_numref(q.get())) / fmpz_get_si(fmpq_denref(q.get()));
}

// Every pair separated or nested (bounding-circle tests, and boundary sampling
// if `sample`); with `crossing_circles`, pairs of crossing circles are skipped.
void check_disjoint(const std::vector<Ellipse>& s, bool sample, bool crossing_circles = false) {
    for (std::size_t i = 0; i < s.size(); ++i)
        for (std::size_t j = i + 1; j < s.size(); ++j) {
            if (crossing_circles && cross(s[i], s[j])) continue;
            const bool in_ij = bounding_circle_inside_inscribed(s[i], s[j]);
            const bool in_ji = bounding_circle_inside_inscribed(s[j], s[i]);
            INFO("sites " << i << " and " << j << ": " << s[i].str() << " | " << s[j].str());
            REQUIRE((in_ij || in_ji || bounding_circles_separated(s[i], s[j])));
            if (!sample) continue;
            if (in_ij) check_pair_by_sampling(s[i], s[j], true);
            else if (in_ji) check_pair_by_sampling(s[j], s[i], true);
            else check_pair_by_sampling(s[i], s[j], false);
        }
}

// A generated set judged by the predicates alone (relative_position and
// boundary_meeting_points, exact), over all pairs: every pair is separated,
// strictly nested, or crosses meeting in exactly two points; nothing else.
struct CrossingCensus {
    std::vector<char> crosses, nested;  // per site: crosses another, lies inside another
    long crossing_pairs = 0;
    long deep_pairs = 0;  // a center inside the other site
    long crossing_sites() const { return static_cast<long>(std::count(crosses.begin(), crosses.end(), 1)); }
    long nested_sites() const { return static_cast<long>(std::count(nested.begin(), nested.end(), 1)); }
};

CrossingCensus crossing_census(const std::vector<Ellipse>& s) {
    CrossingCensus census;
    census.crosses.assign(s.size(), 0);
    census.nested.assign(s.size(), 0);
    for (std::size_t i = 0; i < s.size(); ++i)
        for (std::size_t j = i + 1; j < s.size(); ++j) {
            const RelativePosition position = *relative_position(s[i], s[j]);
            if (position == RelativePosition::separated) continue;
            if (position == RelativePosition::first_inside) census.nested[i] = 1;
            else if (position == RelativePosition::second_inside) census.nested[j] = 1;
            else {
                INFO("sites " << i << " and " << j << ": " << s[i].str() << " | " << s[j].str() << ": "
                              << relative_position_name(position));
                REQUIRE(position == RelativePosition::intersecting);
                REQUIRE(boundary_meeting_points(s[i], s[j]) == 2);
                census.crosses[i] = census.crosses[j] = 1;
                ++census.crossing_pairs;
                if (s[i].side_of_point(s[j].xc(), s[j].yc()) < 0 || s[j].side_of_point(s[i].xc(), s[i].yc()) < 0)
                    ++census.deep_pairs;
            }
        }
    return census;
}

// The generator's own crossing test against the predicates, both orders.
void check_sites_cross(const Ellipse& e1, const Ellipse& e2) {
    const bool expected = *relative_position(e1, e2) == RelativePosition::intersecting &&
                          boundary_meeting_points(e1, e2) == 2;
    INFO(e1.str() << " | " << e2.str());
    CHECK(sites_cross(e1, e2) == expected);
    CHECK(sites_cross(e2, e1) == expected);
}

}  // namespace

TEST_CASE("generators are deterministic: same seed, same sites; other seed, other sites", "[sites][generators]") {
    for (SiteKind kind : {SiteKind::ellipses, SiteKind::circles}) {
        GeneratorOptions o;
        o.kind = kind;
        o.count = 30;
        o.seed = 42;
        o.nested_fraction = Rational(1, 3);
        const std::string a = text(generate_sites(o)), b = text(generate_sites(o));
        CHECK(a == b);
        o.seed = 43;
        CHECK(text(generate_sites(o)) != a);
    }
    // A fixed sequence (guards against accidental changes of the draw algorithm,
    // which would change every generated file).
    SiteRandom r(7);
    std::ostringstream s;
    for (int i = 0; i < 4; ++i) s << r.uniform_rational(Rational(-10), Rational(10), 8).str() << ' ';
    SiteRandom r2(7);
    std::ostringstream s2;
    for (int i = 0; i < 4; ++i) s2 << r2.uniform_rational(Rational(-10), Rational(10), 8).str() << ' ';
    CHECK(s.str() == s2.str());
    CHECK(s.str() == "-221/28 -1685/207 283/71 -436/229 ");  // fixed by the algorithm, on every machine
}

TEST_CASE("random ellipses and circles are pairwise disjoint, nested fraction honoured", "[sites][generators]") {
    struct Case { SiteKind kind; long count; Rational fraction; long bits; };
    for (const Case& c : {Case{SiteKind::ellipses, 25, Rational(0), 8}, Case{SiteKind::ellipses, 24, Rational(1, 4), 12},
                          Case{SiteKind::circles, 20, Rational(1, 2), 6}, Case{SiteKind::ellipses, 9, Rational(1, 3), 3}}) {
        GeneratorOptions o;
        o.kind = c.kind;
        o.count = c.count;
        o.seed = 5;
        o.bits = c.bits;
        o.box = Rational(50);
        o.nested_fraction = c.fraction;
        auto s = generate_sites(o);
        REQUIRE(static_cast<long>(s.size()) == c.count);
        check_disjoint(s, true);
        CHECK(nested_count(s) == rounded(c.fraction, c.count));
        for (const Ellipse& e : s) {
            if (c.kind == SiteKind::circles) CHECK((e.is_circle() && e.w().is_zero()));
            for (const Rational* v : {&e.a(), &e.b(), &e.w(), &e.xc(), &e.yc()}) {
                CHECK(fmpz_bits(fmpq_denref(v->get())) <= static_cast<ulong>(c.bits) + 1);  // q <= 2^bits
                CHECK(v->to_double() >= -50);
                CHECK(v->to_double() <= 50);
            }
        }
    }
    // more sites: conservative test only (sampling is quadratic times 26 points)
    GeneratorOptions big;
    big.count = 300;
    big.seed = 9;
    big.nested_fraction = Rational(1, 10);
    auto s = generate_sites(big);
    check_disjoint(s, false);
    CHECK(nested_count(s) == 30);
}

TEST_CASE("sites made before the crossing option are unchanged", "[sites][generators]") {
    // Output of the generator before crossing_fraction existed (commit edffa80).
    GeneratorOptions o;
    o.kind = SiteKind::circles;
    o.count = 4;
    o.seed = 11;
    o.nested_fraction = Rational(1, 4);
    const std::string circles = "133/12 133/12 0 -3595/87 655/237\n41/6 41/6 0 -2759/78 -9331/197\n"
                                "268/61 268/61 0 13329/254 -279/7\n111/94 111/94 0 360/7 -892/23\n";
    CHECK(text(generate_sites(o)).find(circles) != std::string::npos);
    o.crossing_fraction = Rational(0);
    CHECK(text(generate_sites(o)).find(circles) != std::string::npos);
    CHECK(describe(o) == "ellvor generate circles --count 4 --seed 11 --bits 8 --box 100 --nested-fraction 1/4");
    o.kind = SiteKind::ellipses;
    o.count = 3;
    o.nested_fraction = Rational(0);
    CHECK(text(generate_sites(o)).find("268/61 1091/254 -67/210 -1852/41 9749/178\n"
                                       "787/145 2089/234 29/167 -9600/143 -11194/227\n"
                                       "484/47 10/3 55/92 7460/127 1038/23\n") != std::string::npos);
}

TEST_CASE("crossing circles: exactly round(fraction * count) cross another, checked exactly", "[sites][generators]") {
    struct Case { long count; Rational crossing, nested; long bits; Rational box; };
    for (const Case& c : {Case{40, Rational(3, 10), Rational(0), 8, Rational(100)},       // K = 12
                          Case{60, Rational(1, 3), Rational(1, 10), 6, Rational(50)},     // K = 20, 6 nested
                          Case{31, Rational(1, 2), Rational(0), 8, Rational(100)},        // K = 16 (15.5 rounded up)
                          Case{25, Rational(1), Rational(0), 8, Rational(100)},           // every circle, K odd
                          Case{30, Rational(1, 10), Rational(1, 5), 8, Rational(100)},    // K = 3: last partner alone
                          Case{200, Rational(3, 10), Rational(0), 1, Rational(256 * 15)}}) {  // benchmark-like, dyadic
        GeneratorOptions o;
        o.kind = SiteKind::circles;
        o.count = c.count;
        o.seed = 17;
        o.bits = c.bits;
        o.box = c.box;
        o.nested_fraction = c.nested;
        o.crossing_fraction = c.crossing;
        INFO("count " << c.count << ", crossing " << c.crossing.str() << ", nested " << c.nested.str());
        const auto s = generate_sites(o);
        REQUIRE(static_cast<long>(s.size()) == c.count);
        CHECK(crossing_count(s) == rounded(c.crossing, c.count));
        CHECK(nested_count(s) == rounded(c.nested, c.count));
        // the rest: separated or nested, no tangency, no identical sites
        check_disjoint(s, c.count <= 60, true);
        for (std::size_t i = 0; i < s.size(); ++i) {
            CHECK((s[i].is_circle() && s[i].w().is_zero()));
            for (const Rational* v : {&s[i].xc(), &s[i].yc()}) CHECK((-c.box <= *v && *v <= c.box));
            for (std::size_t j = i + 1; j < s.size(); ++j) CHECK(circles_cross(s[i], s[j]) == cross(s[i], s[j]));
        }
        CHECK(text(generate_sites(o)) == text(s));
        o.seed = 18;
        CHECK(text(generate_sites(o)) != text(s));
        CHECK(describe(o).find(" --crossing " + c.crossing.str()) != std::string::npos);
    }
    // Without nested sites, the separated circles are those of fraction 0: all
    // but the ceil(K/2) partners of the crossing set are in the disjoint set.
    GeneratorOptions o;
    o.kind = SiteKind::circles;
    o.count = 300;
    o.seed = 2;
    const auto disjoint = generate_sites(o);
    o.crossing_fraction = Rational(3, 10);  // K = 90, 45 partners
    const auto crossing = generate_sites(o);
    CHECK(crossing_count(crossing) == 90);
    std::set<std::string> in_disjoint;
    for (const Ellipse& e : disjoint) in_disjoint.insert(e.str());
    long common = 0;
    for (const Ellipse& e : crossing) common += in_disjoint.count(e.str());
    CHECK(common == 300 - 45);
}

TEST_CASE("crossing option errors", "[sites][generators]") {
    GeneratorOptions o;
    o.kind = SiteKind::circles;
    o.count = 20;
    o.crossing_fraction = Rational(-1, 4);
    CHECK_THROWS_WITH(generate_sites(o), Catch::Contains("crossing fraction must be in [0, 1]"));
    o.crossing_fraction = Rational(5, 4);
    CHECK_THROWS_WITH(generate_sites(o), Catch::Contains("crossing fraction must be in [0, 1]"));
    o.crossing_fraction = Rational(1, 20);  // K = 1
    CHECK_THROWS_WITH(generate_sites(o), Catch::Contains("a crossing needs two sites"));
    o.crossing_fraction = Rational(1, 40);  // K = round(1/2) = 1
    CHECK_THROWS_WITH(generate_sites(o), Catch::Contains("a crossing needs two sites"));
    o.crossing_fraction = Rational(1, 100);  // K = 0: no crossing
    CHECK(crossing_count(generate_sites(o)) == 0);
    o.nested_fraction = Rational(1, 2);
    o.crossing_fraction = Rational(11, 20);  // K = 11 > 10 not nested
    CHECK_THROWS_WITH(generate_sites(o), Catch::Contains("nested sites never cross"));
    o.crossing_fraction = Rational(1, 2);  // K = 10: every non-nested circle crosses
    const auto s = generate_sites(o);
    CHECK(crossing_count(s) == 10);
    CHECK(nested_count(s) == 10);
    const Ellipse e1 = Ellipse::circle(Rational(0), Rational(0), Rational(1));
    const Ellipse e2(Rational(2), Rational(1), Rational(0), Rational(1), Rational(0));
    CHECK_THROWS_AS(circles_cross(e1, e2), Error);
    CHECK(circles_cross(e1, Ellipse::circle(Rational(1), Rational(0), Rational(1))));
    CHECK(!circles_cross(e1, Ellipse::circle(Rational(2), Rational(0), Rational(1))));  // tangent
    CHECK(!circles_cross(e1, Ellipse::circle(Rational(1, 2), Rational(0), Rational(1, 2))));  // internally tangent
    CHECK(!circles_cross(e1, e1));
}

TEST_CASE("crossing ellipses: exactly round(fraction * count) cross another, by the predicates", "[sites][generators]") {
    struct Case { long count; Rational crossing, nested; long bits; Rational box; std::uint64_t seed; };
    long deep_pairs = 0, shallow_pairs = 0, thin_crossing = 0, turned_left = 0, turned_right = 0;
    for (const Case& c : {Case{40, Rational(3, 10), Rational(0), 8, Rational(100), 1},        // K = 12
                          Case{150, Rational(0), Rational(0), 8, Rational(100), 2},           // no crossing
                          Case{300, Rational(3, 10), Rational(0), 8, Rational(100), 3},       // K = 90
                          Case{201, Rational(1), Rational(0), 8, Rational(100), 4},           // every site, K odd
                          Case{400, Rational(1, 3), Rational(1, 10), 12, Rational(50), 5},    // K = 133, 40 nested
                          Case{30, Rational(1, 10), Rational(1, 5), 6, Rational(100), 6},     // K = 3: last partner alone
                          Case{200, Rational(3, 10), Rational(0), 1, Rational(256 * 15), 7},  // dyadic, as benchmarks
                          Case{1000, Rational(3, 10), Rational(0), 8, Rational(100), 8}}) {   // K = 300
        GeneratorOptions o;
        o.count = c.count;
        o.seed = c.seed;
        o.bits = c.bits;
        o.box = c.box;
        o.nested_fraction = c.nested;
        o.crossing_fraction = c.crossing;
        INFO("count " << c.count << ", crossing " << c.crossing.str() << ", nested " << c.nested.str() << ", seed "
                      << c.seed);
        const auto s = generate_sites(o);
        REQUIRE(static_cast<long>(s.size()) == c.count);
        const CrossingCensus census = crossing_census(s);
        CHECK(census.crossing_sites() == rounded(c.crossing, c.count));
        CHECK(census.nested_sites() == rounded(c.nested, c.count));
        for (std::size_t i = 0; i < s.size(); ++i) {
            CHECK(!(census.crosses[i] && census.nested[i]));  // nested sites never cross
            for (const Rational* v : {&s[i].xc(), &s[i].yc()}) CHECK((-c.box <= *v && *v <= c.box));
            if (!census.crosses[i]) continue;
            const Rational ratio = s[i].a() < s[i].b() ? s[i].b() / s[i].a() : s[i].a() / s[i].b();
            thin_crossing += ratio > Rational(4);  // beyond the separated sites' shapes
            (s[i].w().sign() < 0 ? turned_right : turned_left) += 1;
        }
        deep_pairs += census.deep_pairs;
        shallow_pairs += census.crossing_pairs - census.deep_pairs;
        // deterministic: the same options give the same file, another seed another
        CHECK(text(generate_sites(o)) == text(s));
        o.seed = c.seed + 100;
        CHECK(text(generate_sites(o)) != text(s));
        CHECK((describe(o).find(" --crossing ") != std::string::npos) == !c.crossing.is_zero());
    }
    // varied crossings: deep and shallow, thin partners, turned both ways
    CHECK(deep_pairs >= 50);
    CHECK(shallow_pairs >= 100);
    CHECK(thin_crossing >= 30);
    CHECK(turned_left >= 100);
    CHECK(turned_right >= 100);

    // A fixed set (guards against accidental changes of the partners' draws).
    GeneratorOptions o;
    o.count = 4;
    o.seed = 11;
    o.crossing_fraction = Rational(1, 2);
    CHECK(text(generate_sites(o)).find("1319/200 727/116 44/61 56 409/12\n"
                                       "484/47 10/3 55/92 7460/127 1038/23\n"
                                       "787/145 2089/234 29/167 -9600/143 -11194/227\n"
                                       "268/61 1091/254 -67/210 -1852/41 9749/178\n") != std::string::npos);
    // Without nested sites, all but the ceil(K/2) partners are the disjoint set's.
    o.count = 300;
    o.seed = 2;
    o.crossing_fraction = Rational(0);
    std::set<std::string> disjoint;
    for (const Ellipse& e : generate_sites(o)) disjoint.insert(e.str());
    o.crossing_fraction = Rational(3, 10);  // K = 90, 45 partners
    long common = 0;
    for (const Ellipse& e : generate_sites(o)) common += static_cast<long>(disjoint.count(e.str()));
    CHECK(common == 300 - 45);
    // errors as for circles
    o.count = 20;
    o.crossing_fraction = Rational(1, 20);  // K = 1
    CHECK_THROWS_WITH(generate_sites(o), Catch::Contains("a crossing needs two sites"));
    o.nested_fraction = Rational(1, 2);
    o.crossing_fraction = Rational(11, 20);  // K = 11 > 10 not nested
    CHECK_THROWS_WITH(generate_sites(o), Catch::Contains("nested sites never cross"));
}

TEST_CASE("sites_cross: two transversal crossings, as the predicates count them", "[sites][generators]") {
    // Random pairs near each other: apart, crossing in two or four points, nested.
    SiteRandom rng(23);
    long crossing = 0, four_points = 0, nested = 0, separated = 0;
    for (int k = 0; k < 1500; ++k) {
        auto shape = [&](const Rational& x, const Rational& y) {
            return Ellipse(rng.uniform_rational(Rational(1, 4), Rational(4), 8),
                           rng.uniform_rational(Rational(1, 4), Rational(4), 8),
                           rng.uniform_rational(Rational(-1), Rational(1), 8), x, y);
        };
        const Ellipse e1 = shape(Rational(0), Rational(0));
        const Ellipse e2 = shape(rng.uniform_rational(Rational(-5), Rational(5), 8),
                                 rng.uniform_rational(Rational(-5), Rational(5), 8));
        check_sites_cross(e1, e2);
        const RelativePosition position = *relative_position(e1, e2);
        if (position == RelativePosition::intersecting)
            ++(boundary_meeting_points(e1, e2) == 2 ? crossing : four_points);
        else if (position == RelativePosition::separated) ++separated;
        else ++nested;
    }
    CHECK(crossing >= 100);
    CHECK(four_points >= 20);
    CHECK(nested >= 10);
    CHECK(separated >= 100);
    // Special pairs: tangent, identical, three meeting points, a crossing at
    // E1's i-point (t = infinity: (-2, 0) for the first ellipse), circles.
    const Ellipse wide(Rational(2), Rational(1), Rational(0), Rational(0), Rational(0));
    const Ellipse unit = Ellipse::circle(Rational(0), Rational(0), Rational(1));
    for (const auto& [e1, e2, crosses] : std::vector<std::tuple<Ellipse, Ellipse, bool>>{
             {wide, Ellipse::circle(Rational(3), Rational(0), Rational(1)), false},                   // tangent outside
             {wide, unit, false},                                                                     // tangent inside, twice
             {wide, wide, false},                                                                     // identical
             {unit, Ellipse(Rational(1), Rational(3, 2), Rational(0), Rational(0), Rational(-1, 2)), false},  // 3 points
             {wide, Ellipse::circle(Rational(-2), Rational(1, 2), Rational(1, 2)), true},             // through the i-point
             {wide, Ellipse(Rational(1), Rational(2), Rational(0), Rational(0), Rational(0)), false},  // 4 points
             {wide, Ellipse(Rational(1), Rational(2), Rational(0), Rational(0), Rational(5, 2)), true},
             {unit, Ellipse::circle(Rational(1), Rational(0), Rational(1)), true}}) {
        check_sites_cross(e1, e2);
        CHECK(sites_cross(e1, e2) == crosses);
    }
}

TEST_CASE("generator option errors", "[sites][generators]") {
    GeneratorOptions o;
    o.count = -1;
    CHECK_THROWS_AS(generate_sites(o), Error);
    o.count = 5;
    o.bits = 0;
    CHECK_THROWS_AS(generate_sites(o), Error);
    o.bits = 8;
    o.nested_fraction = Rational(1);
    CHECK_THROWS_AS(generate_sites(o), Error);
    o.nested_fraction = Rational(0);
    o.count = 0;
    CHECK(generate_sites(o).empty());
}

TEST_CASE("paper datasets of section 5.1", "[sites][generators]") {
    const Rational half(1, 2);
    auto k1 = generate_paper_dataset(PaperFamily::kappa1, "1", 1);
    REQUIRE(k1.instances.size() == 201);
    CHECK(k1.instances[0].sites[0] == Ellipse::circle(Rational(-2), Rational(0), Rational(1)));
    CHECK(k1.instances[0].sites[1] == Ellipse::circle(Rational(2), Rational(0), Rational(1)));
    CHECK(k1.instances[0].query_point->x == Rational(0));
    CHECK(k1.instances[0].query_point->y == Rational(-100));
    CHECK(k1.instances[1].query_point->x == half);
    CHECK(k1.instances[200].query_point->x == Rational(100));
    CHECK(k1.instances[200].query_point->y == Rational(0));
    CHECK(!k1.instances[0].query_site);

    auto k2 = generate_paper_dataset(PaperFamily::kappa2, "1", 1);
    REQUIRE(k2.instances.size() == 201);
    CHECK(*k2.instances[3].query_site == Ellipse::circle(Rational(3, 2), Rational(-197, 2), Rational(1)));

    auto ic = generate_paper_dataset(PaperFamily::incircle, "1", 1);
    REQUIRE(ic.instances.size() == 393);
    CHECK(ic.instances[0].sites[1] == Ellipse::circle(Rational(3, 2), Rational(0), half));
    CHECK(*ic.instances[392].query_site == Ellipse::circle(Rational(0), Rational(50), Rational(1)));
    CHECK(*ic.instances[1].query_site == Ellipse::circle(Rational(0), Rational(9, 8), Rational(1)));

    // perturbations: each coordinate moves by exactly +-10^-k, with both signs occurring
    for (auto [set, den] : {std::pair<const char*, long>{"2a", 100}, {"2b", 10000}, {"2c", 1000000}}) {
        auto p = generate_paper_dataset(PaperFamily::incircle, set, 3);
        REQUIRE(p.instances.size() == 393);
        const Rational eps(1, static_cast<unsigned long>(den));
        std::set<int> signs;
        for (std::size_t k = 0; k < p.instances.size(); ++k) {
            for (std::size_t s = 0; s < 4; ++s) {
                const Ellipse& a = s < 3 ? p.instances[k].sites[s] : *p.instances[k].query_site;
                const Ellipse& b = s < 3 ? ic.instances[k].sites[s] : *ic.instances[k].query_site;
                for (auto d : {a.xc() - b.xc(), a.yc() - b.yc(), a.a() - b.a()}) {
                    REQUIRE((d == eps || d == -eps));
                    signs.insert(d.sign());
                }
                CHECK(a.is_circle());
            }
        }
        CHECK(signs.size() == 2);
        CHECK(text(generate_paper_dataset(PaperFamily::incircle, set, 3).instances[7].sites) ==
              text(p.instances[7].sites));
        CHECK(text(generate_paper_dataset(PaperFamily::incircle, set, 4).instances[7].sites) !=
              text(p.instances[7].sites));
    }
    auto p1 = generate_paper_dataset(PaperFamily::kappa1, "2b", 1);
    CHECK(p1.instances[0].query_point->x.sign() != 0);  // the query point is perturbed too

    // random sets: 500 instances, disjoint circles in the box, kappa1 point outside both
    for (PaperFamily f : {PaperFamily::kappa1, PaperFamily::kappa2, PaperFamily::incircle}) {
        auto r = generate_paper_dataset(f, "3", 11);
        REQUIRE(r.instances.size() == 500);
        for (const PaperInstance& inst : r.instances) {
            std::vector<Ellipse> all = inst.sites;
            if (inst.query_site) all.push_back(*inst.query_site);
            CHECK(all.size() == (f == PaperFamily::kappa1 ? 2u : f == PaperFamily::kappa2 ? 3u : 4u));
            check_disjoint(all, false);
            for (const Ellipse& c : all) {
                CHECK(c.a() <= (f == PaperFamily::incircle ? Rational(5, 2) : Rational(2)));
                CHECK(c.a() >= (f == PaperFamily::incircle ? Rational(1, 3) : Rational(0)));
                CHECK(c.xc() >= Rational(-10));
                CHECK(c.xc() <= Rational(10));
            }
            if (inst.query_point)
                for (const Ellipse& c : inst.sites) CHECK(c.side_of_point(inst.query_point->x, inst.query_point->y) > 0);
        }
    }
    CHECK_THROWS_AS(generate_paper_dataset(PaperFamily::kappa1, "4", 1), Error);
}
