// The fuzz targets' inputs replayed in the normal suite (fuzz/, `make fuzz`):
// the committed seeds, and every finding that is fixed, run the way the target
// runs them (fuzz/fuzz_checks.hpp) or through the real binary.
#include "fuzz/fuzz_checks.hpp"
#include "tests/support/command_runner.hpp"

#include <algorithm>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

namespace {

using ellvor::SiteFormat;
using ellvor::fuzz::Outcome;
using ellvor::test::contains;
using ellvor::test::ScratchDirectory;

std::vector<std::string> corpus_files(const std::string& name) {
    std::vector<std::string> files;
    for (const auto& entry : std::filesystem::directory_iterator(std::string(ELLVOR_SOURCE_DIR) + "/fuzz/corpus/" + name))
        files.push_back(entry.path().string());
    std::sort(files.begin(), files.end());
    return files;
}

// An input error names "fuzz:LINE:COLUMN: " (or "fuzz.ell:...") first.
bool names_location(const std::string& message) {
    std::size_t i = message.rfind("fuzz.ell:", 0) == 0 ? 9 : message.rfind("fuzz:", 0) == 0 ? 5 : 0;
    if (i == 0) return false;
    for (int field = 0; field < 2; ++field) {
        const std::size_t start = i;
        while (i < message.size() && message[i] >= '0' && message[i] <= '9') ++i;
        if (i == start || i >= message.size() || message[i] != ':') return false;
        ++i;
    }
    return message.compare(i, 1, " ") == 0;
}

}  // namespace

TEST_CASE("fuzz: every parser seed reads, or is an input error naming its line and column", "[fuzz]") {
    const auto files = corpus_files("parser");
    REQUIRE(files.size() >= 40);
    std::size_t accepted = 0, rejected = 0;
    for (const std::string& path : files) {
        const std::string text = ellvor::test::read_file(path);
        for (SiteFormat format : {SiteFormat::ell, SiteFormat::cin}) {
            INFO(path << (format == SiteFormat::cin ? " as .cin" : " as .ell"));
            const Outcome o = ellvor::fuzz::read_site_text(text, format);
            INFO(o.message);
            CHECK(o.kind != Outcome::finding);
            if (o.kind == Outcome::input_error) CHECK(names_location(o.message));
            (o.kind == Outcome::accepted ? accepted : rejected) += 1;
        }
    }
    CHECK(accepted > 0);
    CHECK(rejected > 0);
}

TEST_CASE("fuzz: numbers beyond the 4096-bit cap are input errors naming the line and the limit", "[fuzz]") {
    struct Case {
        const char* seed;
        const char* location;  // LINE:COLUMN
        const char* phrase;
    };
    const Case cases[] = {
        {"just-over-cap.ell", "1:7", "limited to 4096 bits"},
        {"over-cap-numerator.ell", "1:7", "limited to 4096 bits"},
        {"over-cap-denominator.ell", "1:3", "limited to 4096 bits"},
        {"long-token.ell", "1:9", "too long: at most 4096 characters"},
        {"exponent-huge.ell", "1:7", "exponent out of range"},
    };
    ScratchDirectory dir;
    for (const Case& c : cases) {
        const std::string path = std::string(ELLVOR_SOURCE_DIR) + "/fuzz/corpus/parser/" + c.seed;
        INFO(c.seed);
        const auto r = dir.ellvor("build '" + path + "'");
        INFO(r.err.substr(0, 300));
        CHECK(r.status == 2);
        CHECK(r.err.find("ellvor: " + path + ":" + c.location + ": ") == 0);
        CHECK(contains(r.err, c.phrase));
    }
    // The largest accepted numbers are not errors: 2^4096 - 1 over 2^4096 - 3.
    const auto r = dir.ellvor("check '" + std::string(ELLVOR_SOURCE_DIR) + "/fuzz/corpus/parser/cap-fraction.ell'");
    CHECK(r.status == 0);
}

TEST_CASE("fuzz: every build seed gives a valid graph or an input error", "[fuzz]") {
    std::size_t built = 0;
    for (const std::string& path : corpus_files("build")) {
        INFO(path);
        const Outcome o = ellvor::fuzz::build_site_text(ellvor::test::read_file(path));
        INFO(o.message);
        CHECK(o.kind != Outcome::finding);
        if (o.kind == Outcome::input_error) CHECK(names_location(o.message));
        built += o.kind == Outcome::accepted ? 1 : 0;
    }
    CHECK(built >= 20);
}

TEST_CASE("fuzz: sites with equal center coordinates build a valid graph", "[fuzz]") {
    // Any two centers on a horizontal or vertical line once made SiteGrid
    // convert ~1e150 to long (undefined behaviour, seen by clang's UBSan).
    for (const char* text : {"1 1 0 0 0\n1 1 0 3 0\n", "1 1 0 0 0\n1 1 0 0 3\n1 1 0 0 7\n",
                             "1 1 0 0 0\n2 1 0 6 0\n1 2 0 12 0\n1 1 0 20 0\n"}) {
        INFO(text);
        const Outcome o = ellvor::fuzz::build_site_text(text);
        INFO(o.message);
        CHECK(o.kind == Outcome::accepted);
    }
}

TEST_CASE("fuzz findings: inputs that crashed, failed or hung now build or are input errors naming the limit",
          "[fuzz]") {
    // The minimized findings of experiments/results/fuzz.md ('/' separates lines there).
    struct Finding {
        const char* what;
        const char* text;
        const char* limit;  // nullptr: a valid graph
    };
    const Finding findings[] = {
        // B1: a negative refinement bit count reached fmpq_mul_2exp (gmp abort, SIGSEGV).
        {"B1 gmp abort", "1 1 0 0 0\n1 1 0 0 2\n1 1 0 1e201 0\n1 2 0 2 0\n", "spans about 2^"},
        {"B1 at 4e30", "4e30 2 1 4 0\n1 2 0 7 7\n1 1 0 0 6\n2 2 2 12 31\n", "differ by more than a factor 2^40"},
        {"B1 SIGSEGV", "1 1 1 0 0\n2 27 0 7 7\n1 1 0 1e201 4\n2 3 880 3 3\n", "spans about 2^"},
        {"B1 center 1e300", "1 1 0 0 0\n1 1 0 5 1\n1 1 0 1e300 3\n2 1 0 -7 2\n", "spans about 2^"},
        // B2: InCircle 10^20 away from the origin ("internal error").
        {"B2 translated 1e20",
         "1 1 0 100000000000000000000 0\n1 1 0 100000000000000000005 1\n1 1 0 100000000000000000002 6\n"
         "2 1 1/3 100000000000000000003 -5\n",
         nullptr},
        {"B2 refinement", "1 1 0 5 1\n1 1 0 10000002 6\n2 1 1/3 10000000000000000002 6\n2 1 1/3 100000000000000000003 -5\n",
         nullptr},
        // B3: the exhaustive search gave up or ran for minutes.
        {"B3 gap 1e-81", "1 1 0 0 0\n2 1 0 1 71\n1 1 0 1e-40 2\n1 1 0 0 5\n", nullptr},
        {"B3 tangent pair", "1 1 0 0 0\n1 1 0 0 2\n1 1 0 0 3655555555555555555555555555555555555555555555555555555555555\n1 1 0 1 5\n",
         nullptr},
        {"B3 needle 1e17", "1 1 0 0 0\n2 100000000000000000 0 6 .7\n2 2 0 1e4 1e+4\n2 2 0 32 35e20\n",
         "differ by more than a factor 2^40"},
        {"B3 1e-404", "1 1 0 0 0\n2 2 0 7 7\n1 1000000000000000000001 10 1e-404 14\n2 2 0 35 35\n",
         "differ by more than a factor 2^40"},
        // B4: right but slow (1e999 axes).
        {"B4 axis 1e999", "1 1 0 0 0\n1 1 0 5 1\n1e999 1 0 0 1e1000\n", "differ by more than a factor 2^40"},
        {"B4 center 7e999", "9 1 0 0 0\n2 2 0 7e999 74\n2 2 20 35 35\n", "spans about 2^"},
        // B6: an invalid graph (order on a bisector near its departure end).
        {"B6 order near departure",
         "1 1 0 1000000010000000000280 0\n1 1 280 10000000000000.410000002 6\n2 1 1/3 050000000000000000002 6\n"
         "22222 1 1/3 05000000/2 -5\n",
         nullptr},
        // B7: the search gave up after 20 s (a far site past a needle's tip).
        {"B7 needle and far site",
         "1 1 0 1000000000000000000200 0\n1 1000000000 0 100000000000000000005 1\n1 1 0 100000000000000000002 6\n"
         "2 1 1/1 030000003 -5\n",
         nullptr},
        // B8: validation gave up after 45 s (the far site first in the triple).
        {"B8 far site first",
         "4 2 0 0 0\n1.5 3025 0 133333333333333333333333333330 10\n4 325 0 10 10\n4 3 -0.2 20 10\n1 1 0 0 0\n"
         "1.2 0.8 1/5 2075 10.25\n",
         nullptr},
        // F4 (campaign 7): validation asked a hidden circle against a face with a Voronoi circle of
        // radius 0 on its host's boundary; the exact stage paired it with its host ("internal error").
        {"F4 hidden query through a vertex of radius 0", "5 5 0 -5 0\n5 5 0 0 -5\n5  5 0 5 0\n5 55 0 5 0\n5 5 0 0 5\n",
         nullptr},
        // F5 (campaign 7): an ellipse and a copy 10^-6 thinner, shifted by 6e-30: the search stopped
        // at its cap (an Error after 20 s). The pair, 2^-19 apart, now gets the near-duplicate start
        // (test_near_duplicate_sites.cpp: "fuzz F5"); 0.5 s.
        {"F5 copy 10^-6 thinner",
         "2 1 1/3 0 0\n1.9999999999999999999999999999999999999999999999999998 0.9999990000000000 1/3 6e-30 0\n"
         "1 1 0 6 1\n1 1 0 -5 6\n3/2 1/2 1 5 3\n3/2 1/2 1 1 -6\n",
         nullptr},
        // F6 (campaign 7): a needle (minor semi-axis 10^-6) and its copy with the minor semi-axis
        // 10/37, sharing the tips to 10^-35, both crossing a third site that holds the one tip where
        // the needle pokes out of its copy: the needle lies in the union of the two, its cell is
        // empty, and the count's complete search could not prove that the triple has no circle
        // (circles through the tip nearly solve: its cap in all six orders). Now the union cover is
        // proven (covered_without_circle, test_crossing_ellipse_predicates.cpp); 0.8 s.
        {"F6 needle and its fat copy sharing tips",
         "345/127 10e-7 -6/35 17909/230 11267/144\n2 363/161 -43/82 9731/121 2128/27\n345/127 10/37 -6/35 "
         "77.8652173913043478260869565217391304000000000000000000000000000000000000000000004010161755154250351 "
         "11267/144\n",
         nullptr},
        // F7, F8 (campaign 8): a needle 10^8 : 1 (a = 47/1444446440, b = 24/5) among three sites;
        // the circle past its tip had no start (the guesses and the search do not resolve a contact
        // whose normal turns over 10^-8 radians) and the search's cap ended the validation. Now the
        // circle of the triple with the needle thickened to aspect 16, carried to the needle
        // through thinner copies, is the start (needle_chain.hpp, test_needle_chain.cpp); 0.1 s.
        {"F7 needle 10^8 : 1 past a long ellipse",
         "47/1444446440 24/5 -47/50 91/5 058/5\n9/54 49/5 1/50 5 137/5\n92/5 09 -13/50 2080/1 58/5\n"
         "3 6310. -7/10 24/2 41/29",
         nullptr},
        {"F8 needle 10^9 : 1 beside crossing ellipses",
         "47/14444442880 23/5 -47/50 91/5 116/5\n8/54 49/5 20/5 5 137/5\n92/5 10 -7/10 24/25  58/5\n"
         "3 63/10 -7/10 24/25  41/2\n",
         nullptr},
        // F10 (campaign 8): a band 8.4e6 x 9.8 crossing three small sites. A thin site covered by
        // the band and another is now proven to leave its triple without a circle
        // (covered_without_circle's depth test about a piece's midpoint,
        // test_crossing_ellipse_predicates.cpp), where the count's search hit its cap; 0.01 s. (A
        // circle beside the band, no longer asked, is certified from the band shortened to aspect
        // 16: needle_chain.hpp, test_needle_chain.cpp.)
        {"F10 band 8.4e6 x 9.8 among small crossing sites",
         "47/10 03/74 -47/49 91/5 116/5\n84E5 49/5 1/05 5 137/5\n92/5 10 -13/50 206/11 58/5\n"
         "3 63/95 -7/10 25/2 41/2\n",
         nullptr},
        // F9 (campaign 8): an ellipse and its copy moved by 10^-20 at x = 10^20, a circle 10^20 to
        // its left: the pair's bitangent (parallel to the move) was lost to rounding in doubles,
        // so the huge circle (R ~ 10^39) had no tangent-line start, and the near-copy start's
        // circle of the pair 2^-20 apart is another circle at that radius. Now the pair's
        // bitangent is resolved (huge_circle_start.cpp, test_huge_circle_start.cpp); 0.03 s.
        {"F9 copy moved by 10^-20 at 10^20, a far circle",
         "2 1 1/3 1e20 0\n2 1 1/3 100000000000000000000.00000000000000000001 0\n1 1 0 1000000000000000000000001 0\n"
         "1 1 0 1000000000000000 3\n",
         nullptr},
        // F11 (campaign 9): F8's needle (10^8 : 1) beside a band 9.2e6 x 10; after the removal of
        // the odd sites, the small graph that replaces a star asks the circle of (needle, band,
        // small site), which the guesses and the needle chains missed (the search's cap, 10 s).
        // The bisector walk's start certifies it (test_bisector_walk_start.cpp); 0.08 s.
        {"F11 two needles after a removal",
         "47/1444446440 23/5 -47/50 91/5 116/5\n8/54 49/5 10/5 5 137/5\n92E5 10 -13/85 20/1 58/5\n"
         "3 63/10 -7/18 24/2 41/2\n",
         nullptr},
    };
    for (const Finding& f : findings) {
        INFO(f.what << "\n" << f.text);
        const Outcome o = ellvor::fuzz::build_site_text(f.text);
        INFO(o.message);
        if (f.limit) {
            REQUIRE(o.kind == Outcome::input_error);
            CHECK(names_location(o.message));
            CHECK(contains(o.message, f.limit));
        } else {
            CHECK(o.kind == Outcome::accepted);
        }
    }
}

TEST_CASE("fuzz findings, slow: pairs nearly internally tangent at two points", "[.][fuzz-slow]") {
    // Campaign 7 (experiments/results/fuzz.md, F1-F3; F5 and F6 are fixed, above): mutations of the
    // near-copy seeds in which one site lies in another touching it at two points (concentric, one
    // semi-axis shared), then moved by about 10^-30 so that the two cross. Near the tangency points
    // the pair nearly coincides, the Voronoi circles there defeat the guesses, and the exhaustive
    // search decides in seconds (F1-F3: 2.6-17 s release, over 10 s under ASan; 35 s together;
    // F12 below, a nearly coincident nested pair, 2.2 s; F13 and F14 below, 74 s and 36 s).
    // Hidden from the default run for their time only (docs/DESIGN.md §4.2, "What still ends at the
    // box cap", (4)); the graph must be valid.
    const char* findings[] = {
        // F1: (2, 1) inside (4, 1), touching at the ends of the minor axis, moved by 6e-30.
        "2 1 1/3 0 0\n4 1 3000000000000000000000000000005/9000000000000000000000000000000 0 -6e-30\n1 1 0 6 1\n"
        "1 1 0 -2 3\n3/2 1/2 1 1 -6\n",
        // F2: a nearly round ellipse and one nearly touching it inside at two points.
        "2 1.99999999999999999991 1/3 0 0\n1.999999999999999999999999999998 0.9999999999999999 1/3 6e-30 0\n"
        "1 1 0 6 1\n1 1 0 -5 3\n3/2 1/2 1 5 3\n3/2 1/2 1 1 -6\n",
        // F3: the unit circle in the ellipse (2, 1), touching at (0, +-1), moved by 1e-30.
        "1 1 1/3 0 0\n2 1 1/3 1e-30 0\n1 1 0 6 1\n1 1 0 -5 3\n3/2 1/2 5.1 1 -6e20\n",
        // F12 (campaign 12): a copy of site 0 with its minor semi-axis 11/37 for 10/37 and its
        // center moved by about 10^-100 (site 0 is hidden in it): 2.2 s release (the exact
        // stages' Voronoi circle search), over 10 s under ASan; the same at c9f49c1.
        "345/127 10/37 -6/35 17909/230 11267/144\n2 363/161 -43/82 9731/121 2128/27\n345/127 11/37 -6/35 "
        "77.865217391304347826086956521739130434782608695652173913043478260869565217391000910611639059937618"
        "4 11267/144\n",
        // F13 (campaign 13): F12 with both copies' minor semi-axis 10/37 (the two touch at the ends of the
        // minor axis, then the center moves by about 10^-100): 74 s release, the same before session 7.
        "365/127 10/37 -6/35 17909/230 11267/144\n2 363/161 -43/82 9731/121 2128/27\n345/127 10/37 -6/35 "
        "77.865217391304347826086956521739130434782608695652173913043478260869565217391304347826086956521739"
        "2 11267/144\n",
        // F14 (campaign 13): an ellipse of semi-axes 10 and 1000000001 centred 6e-30 from a circle of
        // radius 10, beside two unit circles: 36 s release.
        "10 10 0 0 0\n10 10 0 12 0\n10 01000000001 1/3 -6e-30 0\n1 1 0 6 1\n1 1 0 0.1   64\n",
    };
    for (const char* text : findings) {
        INFO(text);
        const Outcome o = ellvor::fuzz::build_site_text(text);
        INFO(o.message);
        CHECK(o.kind == Outcome::accepted);
    }
}
