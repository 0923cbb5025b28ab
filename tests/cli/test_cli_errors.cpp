// Malformed inputs fed to the real `ellvor` binary: exit status 2 and
// "ellvor: FILE:LINE:COL: what" on stderr.
#include "tests/support/command_runner.hpp"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace {

using Run = ellvor::test::CommandResult;
using TempDir = ellvor::test::ScratchDirectory;
using ellvor::test::read_file;


struct Malformed {
    const char* kind;
    std::string content;
    const char* location;  // "LINE:COL"
    const char* phrase;
    bool cin = false;
};

}  // namespace

TEST_CASE("malformed site files exit 2 with file:line:column and what was expected", "[cli]") {
    const std::string huge_integer(2000, '7');  // about 6600 bits
    const std::vector<Malformed> cases = {
        {"missing fields", "1 1 0 0 0\n1 2 3\n", "2:6", "expected 5 fields a b w xc yc, found 3"},
        {"one field", "# c\n7\n", "2:2", "expected 5 fields a b w xc yc, found 1"},
        {"extra field", "1 1 0 0 0 9\n", "1:11", "expected 5 fields a b w xc yc, found 6"},
        {"not a number", "1 abc 0 0 0\n", "1:3", "field b: expected a rational number"},
        {"a is zero", "0 1 0 0 0\n", "1:1", "semi-axis a must be positive, found 0"},
        {"b negative", "\n1 -2 0 0 0\n", "2:3", "semi-axis b must be positive, found -2"},
        {"a negative fraction", "  -1/2 1 0 0 0\n", "1:3", "semi-axis a must be positive, found -1/2"},
        {"zero denominator", "1 1 0 1/0 0\n", "1:7", "zero denominator"},
        {"nan", "1 1 nan 0 0\n", "1:5", "not a finite number"},
        {"inf", "1 1 0 0 0\n2 2 0 10 -inf\n", "2:10", "not a finite number"},
        {"huge exponent", "1 1 0 1e99999999 0\n", "1:7", "too large"},
        {"huge integer", "1 1 0 0 " + huge_integer + "\n", "1:9", "too large"},
        {"too long token", "1 1 0 0 " + std::string(5000, '1') + "\n", "1:9", "too long"},
        {"two dots", "1 1.2.3 0 0 0\n", "1:3", "more than one '.'"},
        {"hexadecimal", "0x10 1 0 0 0\n", "1:1", "expected a rational number"},
        {"two signs", "1 1 0 +-1 0\n", "1:7", "expected a rational number"},
        {"signed denominator", "1 1 1/-2 0 0\n", "1:5", "denominator"},
        {"decimal over integer", "1 1 1.5/2 0 0\n", "1:5", "p/q takes integers only"},
        {"malformed exponent", "1 1 0 0 2e\n", "1:9", "malformed exponent"},
        {"comma decimal", "1,5 1 0 0 0\n", "1:1", "expected a rational number"},
        {"exact duplicate", "1 2 0 0 0\n3 3 0 9 9\n1 2 0 0 0\n", "3:1", "duplicate site: site 2 (line 3)"},
        {"duplicate point set", "2 1 0 5 5\n# same ellipse, axes swapped, quarter turn\n1 2 1 5 5\n", "3:1",
         "same point set as site 0 (line 1)"},
        {"duplicate written differently", "0.5 1 0 0 0\n1/2 1.0 0 0.0 0e3\n", "2:1", "duplicate site"},
        {"NUL byte", std::string("1 1 0 0 0\n1 1\0 0 0 0\n", 21), "2:4", "NUL byte"},
        {"line too long", std::string((1 << 20) + 5, ' ') + "1 1 0 0 0\n", "1:1048577", "line too long"},
        {"cin missing field", "1 2\n", "1:4", "expected 3 fields x y r, found 2", true},
        {"cin radius zero", "0 0 1\n5 5 0\n", "2:5", "radius r must be positive", true},
        {"cin duplicate", "0 0 1\n0 0 1.0\n", "2:1", "duplicate site", true},
        {"boundaries meeting in 4 points (a cross)", "# a cross\n3 1 0 0 0\n1 3 0 0 0\n", "3:1",
         "site 1 crosses site 0 (line 2): their boundaries meet in 4 points (sites may cross in at most two)"},
        {"boundaries meeting in 3 points (a tangency and two crossings)", "1 1 0 0 0\n1 3/2 0 0 -1/2\n", "2:1",
         "their boundaries meet in 3 points"},
    };
    REQUIRE(cases.size() >= 20);
    TempDir dir;
    int n = 0;
    for (const Malformed& m : cases) {
        INFO("case: " << m.kind);
        const std::string file = dir.write("case" + std::to_string(n++) + (m.cin ? ".cin" : ".ell"), m.content);
        const Run r = dir.ellvor("check '" + file + "'" + (m.cin ? " --cin" : ""));
        INFO("stderr: " << r.err.substr(0, 300));
        CHECK(r.status == 2);
        CHECK(r.err.find("ellvor: " + file + ":" + m.location + ": ") == 0);
        CHECK(r.err.find(m.phrase) != std::string::npos);
    }
}

TEST_CASE("crossing pairs are all listed by id, the invalid ones with their reason", "[cli]") {
    TempDir dir;
    const std::string file = dir.write("x.ell",
                                       "1 1 0 0 0\n"
                                       "1 1 0 10 0\n"
                                       "1 1 0 1 0\n"       // crosses 0
                                       "1 1 0 11 0\n"      // crosses 1
                                       "3 1 0 30 0\n"      // a cross with the next:
                                       "1 3 0 30 0\n");    // 4 points
    const Run r = dir.ellvor("check " + file + " --describe");
    CHECK(r.status == 2);
    CHECK(r.out.find("crossing: 0 2\n") != std::string::npos);
    CHECK(r.out.find("crossing: 1 3\n") != std::string::npos);
    CHECK(r.out.find("invalid: 4 5 their boundaries meet in 4 points") != std::string::npos);
    CHECK(r.out.find("  crossing pairs: 2 (0 x 2, 1 x 3)\n") != std::string::npos);
    CHECK(r.out.find("6 sites (4 circles), 0 hidden, 2 crossing pairs, 1 invalid pair, INVALID") != std::string::npos);
    CHECK(r.err.find(":6:1: site 5 crosses site 4 (line 5): their boundaries meet in 4 points") != std::string::npos);
    // Crossing circles alone are a valid file.
    const std::string circles = dir.write("c.ell", "1 1 0 0 0\n1 1 0 10 0\n1 1 0 1 0\n1 1 0 11 0\n");
    const Run ok = dir.ellvor("check " + circles);
    CHECK(ok.status == 0);
    CHECK(ok.out.find("4 sites (4 circles), 0 hidden, 2 crossing pairs, OK") != std::string::npos);
}

TEST_CASE("every predicate command rejects crossing sites at the later site's line", "[cli]") {
    // E2 crosses E1 in four points (fuzzing found `incircle` answering
    // "no-circle" on a crossing pair before crossings were checked).
    TempDir dir;
    const std::string crossing = "3 1 0 0 0\n1 3 0 0 0\n1 1 0 9 9\n1 1 0 -9 9\n";
    const struct {
        const char* command;
        int sites;
        const char* extra;
    } commands[] = {{"incircle", 4, ""},           {"voronoi-circle", 3, " --bits 20"}, {"resultant", 3, ""},
                    {"bitangent", 3, ""},          {"side-of-bisector", 2, " 5 5"}};
    for (const auto& c : commands) {
        std::string content;
        std::istringstream lines(crossing);
        std::string line;
        for (int i = 0; i < c.sites && std::getline(lines, line); ++i) content += line + "\n";
        const std::string file = dir.write(std::string(c.command) + ".ell", content);
        const Run r = dir.ellvor(std::string(c.command) + " " + file + c.extra);
        INFO(c.command << "\nstdout: " << r.out << "\nstderr: " << r.err);
        CHECK(r.status == 2);
        CHECK(r.out.empty());
        CHECK(r.err.find(c.command + std::string(".ell:2:1: site 1 crosses site 0 (line 1): their boundaries meet in 4 "
                                                 "points")) != std::string::npos);
    }
}

TEST_CASE("unreadable files and bad command lines exit 2", "[cli]") {
    TempDir dir;
    Run r = dir.ellvor("check " + dir.path() + "/missing.ell");
    CHECK(r.status == 2);
    CHECK(r.err.find("ellvor: " + dir.path() + "/missing.ell:1:1: cannot open file") == 0);

    r = dir.ellvor("check " + dir.path());
    CHECK(r.status == 2);
    CHECK(r.err.find("is a directory") != std::string::npos);

    struct Usage { const char* args; const char* phrase; };
    for (const Usage& u : {Usage{"frobnicate", "unknown command 'frobnicate'"},
                           Usage{"", "usage: ellvor COMMAND"},
                           Usage{"check", "missing argument"},
                           Usage{"check a.ell b.ell", "unexpected argument 'b.ell'"},
                           Usage{"check --bogus a.ell", "unknown option '--bogus'"},
                           Usage{"check --describe=yes a.ell", "takes no value"},
                           Usage{"generate", "missing argument"},
                           Usage{"generate squares --count 3", "unknown kind 'squares'"},
                           Usage{"generate ellipses", "missing option --count"},
                           Usage{"generate ellipses --count", "needs a value"},
                           Usage{"generate ellipses --count ten", "option --count: expected an integer"},
                           Usage{"generate ellipses --count -3", "option --count: expected an integer"},
                           Usage{"generate ellipses --count 3 --seed -1", "option --seed"},
                           Usage{"generate ellipses --count 3 --bits 0", "option --bits"},
                           Usage{"generate ellipses --count 3 --box 0", "option --box"},
                           Usage{"generate ellipses --count 3 --box 1/0", "zero denominator"},
                           Usage{"generate ellipses --count 3 --nested-fraction 1", "option --nested-fraction"},
                           Usage{"generate ellipses --count 3 --cin", "--cin needs 'circles'"},
                           Usage{"generate ellipses --count 3 --count 4", "given twice"},
                           Usage{"generate ellipses --count 5000 --box 1/1000000 --bits 1", "use more bits"},
                           Usage{"generate nested --count 100 --nested-fraction 0.9", "could not place 100"},
                           Usage{"generate ellipses --count 10 --crossing 0.1", "a crossing needs two sites"},
                           Usage{"generate nested --count 10 --crossing 0.9", "nested sites never cross"},
                           Usage{"generate ellipses --count 10 --crossing 2", "option --crossing: expected a rational in [0, 1]"},
                           Usage{"generate circles --count 10 --crossing 1.5", "option --crossing: expected a rational in [0, 1]"},
                           Usage{"generate circles --count 10 --crossing -1/5", "option --crossing: expected a rational in [0, 1]"},
                           Usage{"generate circles --count 10 --crossing x", "option --crossing"},
                           Usage{"generate circles --count 10 --crossing 0.1", "a crossing needs two sites"},
                           Usage{"generate circles --count 10 --nested-fraction 1/2 --crossing 0.6", "nested sites never cross"},
                           Usage{"generate paper-dataset kappa1 --set 1 --crossing 0.3", "does not apply to paper-dataset"},
                           Usage{"generate paper-dataset kappa9 --set 1", "unknown family"},
                           Usage{"generate paper-dataset kappa1", "missing option --set"},
                           Usage{"generate paper-dataset kappa1 --set 4", "option --set"}}) {
        INFO("ellvor " << u.args);
        r = dir.ellvor(u.args);
        INFO("stderr: " << r.err);
        CHECK(r.status == 2);
        CHECK(r.err.find(u.phrase) != std::string::npos);
    }
}
