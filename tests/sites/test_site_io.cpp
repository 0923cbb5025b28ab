// Site files: exact rational tokens, the .ell / .cin readers, their errors, writers, round trips.
#include <catch2/catch.hpp>

#include "sites/rational_parse.hpp"
#include "sites/site_generators.hpp"
#include "sites/site_io.hpp"
#include "util/error.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <random>
#include <sstream>
#include <unistd.h>

using namespace ellvor;

namespace {

Rational q(long p, unsigned long d = 1) { return Rational(p, d); }

std::string parse_error(const std::string& token) {
    Rational r;
    std::string error;
    if (parse_rational(token, r, error)) return "(accepted: " + r.str() + ")";
    return error;
}

std::string read_error(const std::string& text, SiteFormat format = SiteFormat::ell) {
    std::istringstream in(text);
    try {
        read_sites(in, "t.ell", format);
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

}  // namespace

TEST_CASE("parse_rational reads integers, fractions and decimals exactly", "[sites][io]") {
    CHECK(parse_rational("0.1") == q(1, 10));
    CHECK(parse_rational("-12") == q(-12));
    CHECK(parse_rational("+7") == q(7));
    CHECK(parse_rational("007") == q(7));
    CHECK(parse_rational("3/4") == q(3, 4));
    CHECK(parse_rational("-10/6") == q(-5, 3));
    CHECK(parse_rational("0/5") == q(0));
    CHECK(parse_rational(".5") == q(1, 2));
    CHECK(parse_rational("5.") == q(5));
    CHECK(parse_rational("-1.25e-3") == q(-1, 800));
    CHECK(parse_rational("1.5E2") == q(150));
    CHECK(parse_rational("2e+3") == q(2000));
    CHECK(parse_rational("0.333") == q(333, 1000));
    CHECK(parse_rational("12.50") == q(25, 2));
    CHECK(parse_rational("0e5") == q(0));
    CHECK(parse_rational("1000e-3") == q(1));
    CHECK(parse_rational("0.1") + parse_rational("0.2") == parse_rational("0.3"));  // exact, unlike doubles
}

TEST_CASE("parse_rational rejects malformed and oversized tokens with what was expected", "[sites][io]") {
    for (const char* bad : {"", "abc", "1.2.3", "0x10", "+-1", "--1", "1/-2", "1/+2", "1.5/2", "1/2/3", "1/", "/2",
                            ".", "-", "e5", "1e", "1e+", "1.2e3.4", "1,5", "1 2", "½", "1/2e3"}) {
        INFO("token '" << bad << "'");
        Rational r;
        std::string error;
        CHECK_FALSE(parse_rational(bad, r, error));
        CHECK(error.find("expected") != std::string::npos);
    }
    CHECK(parse_error("1/0").find("zero denominator") != std::string::npos);
    CHECK(parse_error("-7/000").find("zero denominator") != std::string::npos);
    for (const char* nonfinite : {"nan", "NaN", "-nan", "inf", "-Inf", "+infinity", "INFINITY"})
        CHECK(parse_error(nonfinite).find("not a finite number") != std::string::npos);
    CHECK(parse_error("1.2.3").find("more than one '.'") != std::string::npos);
    CHECK(parse_error("1/-2").find("denominator") != std::string::npos);
    CHECK_THROWS_AS(parse_rational("x"), Error);
}

TEST_CASE("parse_rational enforces the size limit before computing", "[sites][io]") {
    // 2^4096 - 1 has exactly 4096 bits: accepted; 2^4096 is one bit too many.
    Integer p;
    fmpz_one(p.get());
    fmpz_mul_2exp(p.get(), p.get(), kMaxRationalBits);
    const std::string limit = (p - Integer(1)).str(), over = p.str();
    CHECK(parse_rational(limit).bits() == kMaxRationalBits);
    CHECK(parse_error(over).find("too large") != std::string::npos);
    CHECK(parse_error("1/" + over).find("too large") != std::string::npos);
    CHECK(parse_error("1/" + limit) == "(accepted: 1/" + limit + ")");

    const auto start = std::chrono::steady_clock::now();
    for (const char* huge : {"1e99999999", "1e-99999999", "1e9999999999999999999999", "5e2000", "1e-1300", "3.5e1234"})
        CHECK(parse_error(huge).find("too large") != std::string::npos);
    CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(1));
    CHECK(parse_rational("1e1000") == Rational(parse_rational("1" + std::string(1000, '0'))));
    // trailing zeros of the mantissa cancel a negative exponent
    CHECK(parse_rational("1" + std::string(1500, '0') + "e-1500") == q(1));
    CHECK(parse_error(std::string(kMaxTokenLength + 1, '1')).find("too long") != std::string::npos);
}

TEST_CASE("read_sites: comments, blank lines, tabs, CRLF, 0-based ids", "[sites][io]") {
    std::istringstream in(
        "# header comment\n"
        "\n"
        "   \t  \n"
        "4 2 0 0 0   # first\n"
        "\t3/2\t1.5\t-1/3\t10\t0.25\r\n"
        "#1 1 0 0 0 (commented out)\n"
        "1e0 2 0 -10 -1e1# no space before the comment\n");
    SiteFile f = read_site_file(in, "mem.ell");
    REQUIRE(f.sites.size() == 3);
    CHECK(f.sites[0] == Ellipse(q(4), q(2), q(0), q(0), q(0)));
    CHECK(f.sites[1] == Ellipse(q(3, 2), q(3, 2), q(-1, 3), q(10), q(1, 4)));
    CHECK(f.sites[2] == Ellipse(q(1), q(2), q(0), q(-10), q(-10)));
    CHECK(f.lines == std::vector<long>{4, 5, 7});
    CHECK(f.name == "mem.ell");

    std::istringstream circles("1 2 3\n-1/2 0.5 1/4 # c\n");
    auto cs = read_sites(circles, "c.cin", SiteFormat::cin);
    REQUIRE(cs.size() == 2);
    CHECK(cs[0] == Ellipse::circle(q(1), q(2), q(3)));
    CHECK(cs[1] == Ellipse::circle(q(-1, 2), q(1, 2), q(1, 4)));

    std::istringstream empty("# nothing\n\n");
    CHECK(read_sites(empty, "e.ell").empty());
    std::istringstream no_newline("1 1 0 0 0");
    CHECK(read_sites(no_newline, "n.ell").size() == 1);
}

TEST_CASE("read_sites errors carry file:line:column and what was expected", "[sites][io]") {
    CHECK(read_error("1 1 0 0 0\n1 2 3\n") == "t.ell:2:6: expected 5 fields a b w xc yc, found 3 (missing field xc)");
    CHECK(read_error("1 1 0 0 0 9\n") == "t.ell:1:11: expected 5 fields a b w xc yc, found 6 (extra field '9')");
    CHECK(read_error("\n\n  1 zz 0 0 0\n").rfind("t.ell:3:5: field b: expected a rational", 0) == 0);
    CHECK(read_error("0 1 0 0 0\n") == "t.ell:1:1: semi-axis a must be positive, found 0");
    CHECK(read_error("1 -1/2 0 0 0\n") == "t.ell:1:3: semi-axis b must be positive, found -1/2");
    CHECK(read_error("1 1 0 1/0 0\n").rfind("t.ell:1:7: field xc: zero denominator", 0) == 0);
    CHECK(read_error("1 1 0 0 nan\n").rfind("t.ell:1:9: field yc: not a finite number", 0) == 0);
    CHECK(read_error("1 1 0 0 1e99999999\n").find("t.ell:1:9: field yc: number '1e99999999' is too large") == 0);
    CHECK(read_error("1 2\n", SiteFormat::cin) == "t.ell:1:4: expected 3 fields x y r, found 2 (missing field r)");
    CHECK(read_error("1 2 -3\n", SiteFormat::cin) == "t.ell:1:5: radius r must be positive, found -3");
    CHECK(read_error(std::string("1 1 0 0 0\n1 1\0 0 0 0\n", 21)) == "t.ell:2:4: unexpected NUL byte; expected a text file");
    CHECK(read_error(std::string(kMaxLineLength + 10, ' ') + "1 1 0 0 0\n").rfind("t.ell:1:", 0) == 0);
    CHECK(read_error(std::string(kMaxLineLength + 10, ' ')).find("line too long") != std::string::npos);
}

TEST_CASE("read_sites rejects duplicates, naming both lines and ids", "[sites][io]") {
    const std::string same = read_error("1 2 0 0 0\n\n3 3 0 5 5\n1 2 0 0 0\n");
    CHECK(same == "t.ell:4:1: duplicate site: site 2 (line 4) is the same ellipse as site 0 (line 1); sites must be distinct");
    // decimals and fractions denote the same numbers
    CHECK(read_error("0.5 1 0 0 0\n1/2 1.0 0 0 0\n").find("t.ell:2:1: duplicate site") == 0);
    // the same point set: a circle with another rotation; swapped axes with a quarter turn (w = 1)
    CHECK(read_error("1 1 0 0 0\n1 1 1/2 0 0\n").find("same point set as site 0 (line 1)") != std::string::npos);
    CHECK(read_error("2 1 0 5 5\n1 2 1 5 5\n").find("t.ell:2:1: duplicate site") == 0);
    CHECK(read_error("1 1 1\n", SiteFormat::cin) == "(no error)");
    CHECK(read_error("0 0 1\n0 0 1.0\n", SiteFormat::cin).find("t.ell:2:1: duplicate site") == 0);
    // same center, different shape: not a duplicate
    CHECK(read_error("2 1 0 0 0\n1 2 0 0 0\n") == "(no error)");
}

TEST_CASE("read_sites: many concentric sites are read without comparing every pair", "[sites][io][fuzz]") {
    // Nested concentric circles and ellipses are valid; the duplicate test used
    // to compare each site with every earlier one at the same center (20000
    // sites: about 50 s). Now a lookup of the point set.
    std::ostringstream text;
    const int n = 20000;
    for (int i = 1; i <= n; ++i) text << (i % 2 ? i : i + 1) << ' ' << i << " 0 0 0\n";
    std::istringstream in(text.str());
    const auto start = std::chrono::steady_clock::now();
    CHECK(read_sites(in, "c.ell").size() == n);
    CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(10));
    // A duplicate far down the file is still found (site 1 is "3 2 0 0 0": the same
    // ellipse with swapped axes and a quarter turn).
    CHECK(read_error(text.str() + "2 3 1 0 0\n").find("t.ell:20001:1: duplicate site: site 20000 (line 20001) is "
                                                      "the same point set as site 1 (line 2)") == 0);
}

TEST_CASE("read_sites from a path: cannot open, directories", "[sites][io]") {
    try {
        read_sites("/nonexistent/dir/x.ell");
        FAIL("no error");
    } catch (const InputError& e) {
        CHECK(std::string(e.what()).find("/nonexistent/dir/x.ell:1:1: cannot open file") == 0);
    }
    CHECK_THROWS_AS(read_sites("/tmp"), InputError);
}

TEST_CASE("write_ell / write_cin round-trip exactly", "[sites][io]") {
    for (std::uint64_t seed : {1u, 2u, 3u}) {
        GeneratorOptions o;
        o.count = 40;
        o.seed = seed;
        o.bits = 30 * static_cast<long>(seed);
        o.nested_fraction = Rational(1, 5);
        auto sites = generate_sites(o);
        std::ostringstream out;
        write_ell(out, sites, "round trip\nsecond header line");
        CHECK(out.str().rfind("# round trip\n# second header line\n", 0) == 0);
        std::istringstream in(out.str());
        CHECK(read_sites(in, "rt.ell") == sites);

        o.kind = SiteKind::circles;
        auto circles = generate_sites(o);
        std::ostringstream cout_;
        write_cin(cout_, circles);
        std::istringstream cin_(cout_.str());
        CHECK(read_sites(cin_, "rt.cin", SiteFormat::cin) == circles);
    }
    // every token form reads back to itself after writing
    std::istringstream in("0.1 1e-3 -0.75 123456789012345678901234567890.5 -1/3\n");
    auto one = read_sites(in, "x.ell");
    std::ostringstream out;
    write_ell(out, one);
    CHECK(out.str() == "1/10 1/1000 -3/4 246913578024691357802469135781/2 -1/3\n");
    std::istringstream back(out.str());
    CHECK(read_sites(back, "y.ell") == one);
    std::ostringstream bad;
    CHECK_THROWS_AS(write_cin(bad, one), Error);
}

TEST_CASE("write_file_atomically leaves either the whole file or nothing", "[sites][io]") {
    char dir_template[] = "/tmp/ellvor_io_XXXXXX";
    REQUIRE(::mkdtemp(dir_template) != nullptr);
    const std::string dir = dir_template, path = dir + "/out.ell";
    write_file_atomically(path, [](std::ostream& o) { o << "1 1 0 0 0\n"; });
    CHECK(read_sites(path).size() == 1);
    CHECK_THROWS_AS(write_file_atomically(path,
                                          [](std::ostream& o) {
                                              o << "2 2 0 0 0\n";
                                              throw Error("failure in the middle");
                                          }),
                    Error);
    CHECK(read_sites(path).front() == Ellipse::circle(q(0), q(0), q(1)));  // old content intact
    CHECK_THROWS_AS(write_file_atomically(dir + "/missing/sub/x.ell", [](std::ostream&) {}), Error);
    std::string listing;
    {
        std::string cmd = "ls -A " + dir;
        FILE* p = ::popen(cmd.c_str(), "r");
        char buf[256];
        while (p && std::fgets(buf, sizeof buf, p)) listing += buf;
        if (p) ::pclose(p);
    }
    CHECK(listing == "out.ell\n");  // no temporary left behind
    std::remove(path.c_str());
    ::rmdir(dir.c_str());
}

TEST_CASE("the bundled example is valid by the conservative tests", "[sites][io]") {
    SiteFile f = read_site_file(std::string(ELLVOR_SOURCE_DIR) + "/data/example.ell");
    REQUIRE(f.sites.size() == 20);
    int circles = 0, nested = 0;
    for (std::size_t i = 0; i < f.sites.size(); ++i) {
        circles += f.sites[i].is_circle();
        bool inside_some = false;
        for (std::size_t j = 0; j < f.sites.size(); ++j) {
            if (i == j) continue;
            if (bounding_circle_inside_inscribed(f.sites[i], f.sites[j])) inside_some = true;
            else if (!bounding_circle_inside_inscribed(f.sites[j], f.sites[i]))
                CHECK(bounding_circles_separated(f.sites[i], f.sites[j]));
        }
        nested += inside_some;
    }
    CHECK(circles == 3);
    CHECK(nested == 4);
}

namespace {

// The error that reading `text` as t.ell throws.
InputError reading_error(const std::string& text) {
    std::istringstream in(text);
    try {
        read_sites(in, "t.ell");
    } catch (const InputError& e) {
        return e;
    }
    throw std::logic_error("no error reading: " + text);
}

}  // namespace

TEST_CASE("InputError keeps its location, reason and site pair as fields", "[sites][io]") {
    const InputError zero = reading_error("1 1 0 0 0\n\n1 2 0 0 0/0\n");
    CHECK(zero.has_location());
    CHECK(zero.file() == "t.ell");
    CHECK(zero.line() == 3);
    CHECK(zero.column() == 9);
    CHECK(std::string(zero.what()) == "t.ell:3:9: " + zero.reason());
    CHECK(!zero.sites());
    const InputError dup = reading_error("1 1 0 0 0\n2 1 0 9 0\n1 1 0 0 0\n");
    REQUIRE(dup.sites());
    CHECK(*dup.sites() == InputError::SitePair{0, 2});
    CHECK(dup.line() == 3);
    const IntersectingSites crossing(3, 7, "their boundaries meet in 4 points");
    CHECK(!crossing.has_location());
    CHECK(crossing.file().empty());
    CHECK(*crossing.sites() == InputError::SitePair{3, 7});
    CHECK(crossing.reason() == crossing.what());
    CHECK(crossing.why() == "their boundaries meet in 4 points");
    SiteFile file{"c.ell", {Ellipse::circle(0, 0, 1), Ellipse::circle(5, 0, 1)}, {2, 4}};
    const InputError e = crossing_sites_error(file, 1, 0, "why");
    CHECK(std::string(e.what()) == "c.ell:4:1: site 1 crosses site 0 (line 2): why");
    CHECK(*e.sites() == InputError::SitePair{0, 1});
}

TEST_CASE("check_site_set: the first duplicate in order, as comparing every pair finds it (randomized)", "[sites][io]") {
    // Few centers (a 3 x 3 grid), few shapes and rotations: centers meet often (the index's collisions and
    // growth), point sets repeat (a circle at any rotation, swapped axes a quarter turn apart).
    std::mt19937_64 random(11);
    auto pick = [&](int n) { return static_cast<long>(random() % static_cast<unsigned>(n)); };
    const Rational rotations[] = {q(0), q(1), q(-1), q(1, 3)};
    int duplicates = 0;
    for (int trial = 0; trial < 300; ++trial) {
        SiteFile file;
        const long count = 2 + pick(40);
        for (long k = 0; k < count; ++k) {
            const long a = 1 + pick(3), b = 1 + pick(3);
            file.sites.push_back(Ellipse(q(a), q(b), rotations[pick(4)], q(10 * pick(3)), q(10 * pick(3))));
        }
        std::optional<InputError::SitePair> expected;
        for (std::size_t j = 0; j < file.sites.size() && !expected; ++j)
            for (std::size_t i = 0; i < j && !expected; ++i)
                if (file.sites[i].point_set_key() == file.sites[j].point_set_key()) expected = InputError::SitePair{i, j};
        INFO("trial " << trial);
        try {
            check_site_set(file);
            CHECK(!expected);
        } catch (const InputError& e) {
            REQUIRE(expected);
            CHECK(*e.sites() == *expected);
            ++duplicates;
        }
    }
    CHECK(duplicates > 100);
    CHECK(duplicates < 300);
}

TEST_CASE("check_site_set: the reader's set checks for sites without a file", "[sites][io]") {
    SiteFile file;
    file.sites = {Ellipse(q(2), q(1), q(0), q(0), q(0)), Ellipse::circle(q(9), q(0), q(1)),
                  Ellipse(q(1), q(2), q(1), q(0), q(0))};
    try {
        check_site_set(file);
        FAIL("no error");
    } catch (const InputError& e) {
        CHECK(std::string(e.what()) == "duplicate site: site 2 is the same point set as site 0; sites must be distinct");
        CHECK(!e.has_location());
        CHECK(*e.sites() == InputError::SitePair{0, 2});
    }
    file.sites.pop_back();
    CHECK_NOTHROW(check_site_set(file));
    // The dynamic range: a site 2^260 times its size away.
    Rational far(1);
    fmpq_mul_2exp(far.get(), far.get(), 260);
    file.sites.push_back(Ellipse::circle(far, q(0), q(1)));
    CHECK_THROWS_WITH(check_site_set(file), Catch::Contains("times the smallest semi-axis, site 0's"));
    // With lines, the same errors as the reader's.
    file.name = "f.ell";
    file.lines = {1, 2, 5};
    CHECK_THROWS_WITH(check_site_set(file), Catch::StartsWith("f.ell:1:1: the site set spans about 2^"));
}
