// `ellvor resultant` (the real binary, ELLVOR_BINARY): the coefficient
// listing of the InCircle resultant's wanted factor, its normalisation
// (primitive, positive leading coefficient), --stats, --help and bad input.
#include "tests/support/command_runner.hpp"

#include <flint/fmpz.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace {

using Run = ellvor::test::CommandResult;
using ellvor::test::read_file;

using Scratch = ellvor::test::ScratchDirectory;
using ellvor::test::contains;

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> v;
    std::istringstream in(text);
    for (std::string l; std::getline(in, l);) v.push_back(l);
    return v;
}

// Three pairwise disjoint ellipses in general position (different shapes,
// generic rotations): the wanted factor has degree 184.
const char* const kGenericTriple =
    "# E1 E2 E3\n"
    "2 1 1/3 0 0\n"
    "3/2 1 2 9 1\n"
    "1 5/2 -1/2 2 10\n";

}  // namespace

TEST_CASE("resultant command: 185 integer coefficients, primitive, positive leading coefficient", "[cli]") {
    Scratch s;
    const std::string path = s.write("triple.ell", kGenericTriple);
    const Run r = s.ellvor("resultant '" + path + "'");
    INFO("stderr: " << r.err);
    REQUIRE(r.status == 0);
    CHECK(r.err.empty());
    const std::vector<std::string> coeffs = lines(r.out);
    REQUIRE(coeffs.size() == 185);

    fmpz_t c, g;
    fmpz_init(c);
    fmpz_init(g);
    bool all_parsed = true;
    for (const std::string& text : coeffs) {
        // Optional '-' and decimal digits only.
        const std::size_t first = text.size() > 1 && text[0] == '-' ? 1 : 0;
        const bool digits = first < text.size() && text.find_first_not_of("0123456789", first) == std::string::npos;
        if (!digits || fmpz_set_str(c, text.c_str(), 10) != 0) {
            all_parsed = false;
            UNSCOPED_INFO("not an integer: '" << text << "'");
            continue;
        }
        fmpz_gcd(g, g, c);
    }
    CHECK(all_parsed);
    // Content 1.
    CHECK(fmpz_is_one(g));
    // Leading coefficient (last line) positive; constant term (first) nonzero
    // for this triple (t = 0 is not a root).
    REQUIRE(fmpz_set_str(c, coeffs.back().c_str(), 10) == 0);
    CHECK(fmpz_sgn(c) > 0);
    REQUIRE(fmpz_set_str(c, coeffs.front().c_str(), 10) == 0);
    CHECK(fmpz_sgn(c) != 0);
    // Big integers, not doubles.
    CHECK(fmpz_bits(c) > 64);
    fmpz_clear(c);
    fmpz_clear(g);

    // --stats: same stdout, the figures on stderr.
    const Run st = s.ellvor("resultant '" + path + "' --stats");
    INFO("stderr: " << st.err);
    REQUIRE(st.status == 0);
    CHECK(st.out == r.out);
    CHECK(contains(st.err, "degree: 184"));
    CHECK(contains(st.err, "expected degree: 184"));
    CHECK(contains(st.err, "seed exponents held: yes"));
    CHECK(contains(st.err, "removed factors: 3\n"));
    CHECK(contains(st.err, "  R2:1+t^2  exponent 52\n"));
    CHECK(contains(st.err, "  R2:parnorm13  exponent 6\n"));
    CHECK(contains(st.err, "  R2:parnorm12  exponent 6\n"));
    CHECK(contains(st.err, "coefficient bound: 2^"));
    CHECK(contains(st.err, "primes used: "));
    CHECK(contains(st.err, "coefficient bits: "));
    CHECK(contains(st.err, "seconds: "));
}

TEST_CASE("resultant command: circles give lower degrees, --cin is read", "[cli]") {
    Scratch s;
    // Three circles in CGAL's 'x y r' format: expected degree 8.
    const std::string path = s.write("circles.cin", "0 0 1\n7 1 2\n2 9 3/2\n");
    const Run r = s.ellvor("resultant --cin --stats '" + path + "'");
    INFO("stderr: " << r.err);
    REQUIRE(r.status == 0);
    const std::vector<std::string> coeffs = lines(r.out);
    CHECK(coeffs.size() >= 2);
    CHECK(coeffs.size() <= 9);
    CHECK(contains(r.err, "expected degree: 8"));
    REQUIRE(!coeffs.empty());
    CHECK(coeffs.back().rfind('-', 0) != 0);
}

TEST_CASE("resultant command: bad input and --help", "[cli]") {
    Scratch s;
    {
        const std::string path = s.write("two.ell", "2 1 0 0 0\n1 1 0 9 0\n");
        const Run r = s.ellvor("resultant '" + path + "'");
        INFO("stderr: " << r.err);
        CHECK(r.status == 2);
        CHECK(r.out.empty());
        CHECK(!r.err.empty());
    }
    {
        const std::string path = s.write("four.ell", std::string(kGenericTriple) + "1 1 0 -20 -20\n");
        const Run r = s.ellvor("resultant '" + path + "'");
        CHECK(r.status == 2);
        CHECK(r.out.empty());
    }
    {
        const Run r = s.ellvor("resultant");
        CHECK(r.status == 2);
    }
    {
        const Run r = s.ellvor("resultant '" + s.write("t.ell", kGenericTriple) + "' --no-such-option");
        CHECK(r.status == 2);
    }
    for (const char* form : {" --help", " -h"}) {
        const Run r = s.ellvor(std::string("resultant") + form);
        INFO(form << "\n" << r.err);
        CHECK(r.status == 0);
        CHECK(r.out.rfind("usage: ellvor resultant", 0) == 0);
        CHECK(contains(r.out, "--stats"));
        CHECK(r.err.empty());
    }
    // Listed in the program help.
    const Run all = s.ellvor("--help");
    CHECK(contains(all.out, "  resultant "));
}
