// The predicate commands of the real ellvor binary (ELLVOR_BINARY) on files
// written to a temporary directory: side-of-bisector, bitangent, incircle,
// voronoi-circle -- their words, JSON, exit statuses and input errors.
#include "tests/support/command_runner.hpp"
#include <nlohmann/json.hpp>

#include <cctype>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace {

using nlohmann::json;

using Run = ellvor::test::CommandResult;
using ellvor::test::read_file;

using Scratch = ellvor::test::ScratchDirectory;
using ellvor::test::contains;

json parse(const Run& r) {
    INFO("stdout: " << r.out << "\nstderr: " << r.err);
    json j;
    REQUIRE_NOTHROW(j = json::parse(r.out));
    return j;
}

}  // namespace

TEST_CASE("predicate commands: --help exits 0 with the usage line", "[cli]") {
    Scratch s;
    for (const char* cmd : {"side-of-bisector", "bitangent", "incircle", "voronoi-circle"}) {
        for (const char* form : {" --help", " -h"}) {
            const Run r = s.ellvor(std::string(cmd) + form);
            INFO(cmd << form << "\n" << r.err);
            CHECK(r.status == 0);
            CHECK(r.out.rfind(std::string("usage: ellvor ") + cmd, 0) == 0);
            CHECK(r.err.empty());
        }
    }
    // The program's help lists them.
    const Run r = s.ellvor("--help");
    CHECK(r.status == 0);
    for (const char* cmd : {"side-of-bisector", "bitangent", "incircle", "voronoi-circle"}) CHECK(contains(r.out, cmd));
}

TEST_CASE("side-of-bisector: first, second and an exact tie", "[cli]") {
    Scratch s;
    // Circles (3, 4, r = 1) and (-6, 8, r = 6): the origin is at distance
    // 5 - 1 = 4 = 10 - 6 from both, an exact tie.
    const std::string ell = s.write("pair.ell", "1 1 0 3 4\n6 6 0 -6 8\n");
    const std::string cin = s.write("pair.cin", "3 4 1\n-6 8 6\n");
    struct Case {
        std::string args, word;
    };
    const Case cases[] = {
        {ell + " 0 0", "equidistant"},
        {cin + " 0 0 --cin", "equidistant"},
        {ell + " 0.0 0/7", "equidistant"},  // decimals and fractions are exact
        {ell + " 3 3", "first"},            // on E1's boundary: distance 0 vs 4.3
        {ell + " -6 3", "second"},          // inside E2: negative distance
        {ell + " 1/1000 0", "first"},       // a hair toward E1 breaks the tie
        {ell + " -0.001 0", "second"},
        {cin + " 100 -100 --cin", "first"},
    };
    for (const Case& c : cases) {
        const Run r = s.ellvor("side-of-bisector " + c.args);
        INFO(c.args << "\n" << r.err);
        CHECK(r.status == 0);
        CHECK(r.out == c.word + "\n");
    }
    // --json: result, sign, stage (the tie needs the exact stage), precision, time.
    const Run r = s.ellvor("side-of-bisector " + ell + " 0 0 --json");
    REQUIRE(r.status == 0);
    const json j = parse(r);
    CHECK(j.at("result") == "equidistant");
    CHECK(j.at("sign") == 0);
    CHECK(j.at("stage") == "exact");
    CHECK(j.contains("precision"));
    CHECK(j.contains("time_us"));
    const json f = parse(s.ellvor("side-of-bisector " + ell + " 3 3 --json"));
    CHECK(f.at("result") == "first");
    CHECK(f.at("sign") == 1);  // CGAL's ON_POSITIVE_SIDE
    const std::string stage = f.at("stage");
    CHECK((stage == "filter" || stage == "subdivision" || stage == "exact"));
    const json g = parse(s.ellvor("side-of-bisector " + ell + " -6 3 --json"));
    CHECK(g.at("result") == "second");
    CHECK(g.at("sign") == -1);
}

// Negative coordinates, also as fractions, are positional arguments, not
// options; "--" ends the options too.
TEST_CASE("side-of-bisector: negative fractions as coordinates", "[cli]") {
    Scratch s;
    const std::string ell = s.write("pair.ell", "1 1 0 3 4\n6 6 0 -6 8\n");
    const Run workaround = s.ellvor("side-of-bisector " + ell + " -- -1/1000 0");
    CHECK(workaround.status == 0);
    CHECK(workaround.out == "second\n");
    const Run r = s.ellvor("side-of-bisector " + ell + " -1/1000 0");
    INFO(r.err);
    CHECK(r.status == 0);
    CHECK(r.out == "second\n");
}

TEST_CASE("bitangent: contacts of two sites, kappa2 with a third", "[cli]") {
    Scratch s;
    // CGAL's kappa2 vectors: p1 = (1, 100, 49), p2 = (0, -100, 50); the
    // bitangent is the line x = 50, touching at (50, 100) and (50, -100).
    const std::string pair = s.write("pair.cin", "1 100 49\n0 -100 50\n");
    Run r = s.ellvor("bitangent " + pair + " --cin");
    INFO(r.err);
    REQUIRE(r.status == 0);
    CHECK(contains(r.out, "contact on E1"));
    CHECK(contains(r.out, "contact on E2"));
    CHECK(contains(r.out, "(50, 100)"));
    CHECK(contains(r.out, "(50, -100)"));
    CHECK(!contains(r.out, "conflict"));  // no third site, no kappa2
    json j = parse(s.ellvor("bitangent " + pair + " --cin --json"));
    CHECK(j.at("first").at("t") == "0");
    CHECK(j.at("first").at("point_approx") == json::array({50.0, 100.0}));
    CHECK(j.at("second").at("point_approx") == json::array({50.0, -100.0}));
    CHECK(!j.contains("infinite_vertex_conflict"));

    // q = (40, 0, 10) touches the line at (50, 0), between the contacts -> conflict.
    const std::string between = s.write("between.cin", "1 100 49\n0 -100 50\n40 0 10\n");
    r = s.ellvor("bitangent " + between + " --cin");
    INFO(r.err);
    REQUIRE(r.status == 0);
    CHECK(contains(r.out, "contact on E1"));
    CHECK(contains(r.out, "\nconflict\n"));
    CHECK(contains(r.out, "voronoi circles: "));
    // q = (-1, 200, 51) touches it at (50, 200), outside -> no conflict.
    const std::string outside = s.write("outside.cin", "1 100 49\n0 -100 50\n-1 200 51\n");
    r = s.ellvor("bitangent " + outside + " --cin");
    INFO(r.err);
    REQUIRE(r.status == 0);
    CHECK(contains(r.out, "\nno-conflict\n"));
    CHECK(contains(r.out, "voronoi circles: "));
    j = parse(s.ellvor("bitangent " + outside + " --cin --json"));
    CHECK(j.at("infinite_vertex_conflict").at("result") == "no-conflict");
    CHECK(j.at("infinite_vertex_conflict").at("sign") == 1);
    CHECK(j.at("infinite_vertex_conflict").contains("stage"));
    const std::string circles = j.at("voronoi_circles");
    CHECK((circles == "none" || circles == "ccw" || circles == "cw" || circles == "both"));
    j = parse(s.ellvor("bitangent " + between + " --cin --json"));
    CHECK(j.at("infinite_vertex_conflict").at("result") == "conflict");
    CHECK(j.at("infinite_vertex_conflict").at("sign") == -1);

    // Three unit circles counter-clockwise around the origin: one Voronoi
    // circle in that orientation; reversed: the other.
    const std::string ccw = s.write("ccw.ell", "1 1 0 6 0\n1 1 0 0 6\n1 1 0 -6 0\n");
    r = s.ellvor("bitangent " + ccw);
    REQUIRE(r.status == 0);
    CHECK(contains(r.out, "voronoi circles: ccw\n"));
    const std::string cw = s.write("cw.ell", "1 1 0 -6 0\n1 1 0 0 6\n1 1 0 6 0\n");
    r = s.ellvor("bitangent " + cw);
    REQUIRE(r.status == 0);
    CHECK(contains(r.out, "voronoi circles: cw\n"));
}

TEST_CASE("incircle: conflict, no-conflict, no-circle and a degenerate tangent case", "[cli]") {
    Scratch s;
    // Unit circles at (6,0), (0,6), (-6,0), counter-clockwise: Voronoi circle
    // centered at the origin, radius 5.
    const std::string triple = "1 1 0 6 0\n1 1 0 0 6\n1 1 0 -6 0\n";
    struct Case {
        std::string sites, word;
        int sign;
    };
    const Case cases[] = {
        {triple + "1 1 0 0 -5\n", "conflict", -1},           // reaches the origin's disk
        {triple + "1 1 0 30 30\n", "no-conflict", 1},        // far away
        {triple + "2 1 1 0 -13/2\n", "conflict", -1},        // an ellipse reaching y = -4.5
        {"1 1 0 -6 0\n1 1 0 0 6\n1 1 0 6 0\n1 1 0 0 -5\n", "no-circle", -1},  // clockwise triple
    };
    int n = 0;
    for (const Case& c : cases) {
        const std::string file = s.write("q" + std::to_string(n++) + ".ell", c.sites);
        Run r = s.ellvor("incircle " + file);
        INFO(c.sites << r.err);
        CHECK(r.status == 0);
        CHECK(r.out == c.word + "\n");
        r = s.ellvor("incircle " + file + " --json");
        CHECK(r.status == 0);
        const json j = parse(r);
        CHECK(j.at("result") == c.word);
        CHECK(j.at("sign") == c.sign);
        for (const char* key : {"stage", "precision", "newton_steps", "time_us"}) CHECK(j.contains(key));
        // The filter decides these clear cases, with no Arb Newton step: the
        // closed form for four circles, the circle certified in double
        // intervals for the ellipse.
        CHECK(j.at("stage") == "filter");
        CHECK(j.at("newton_steps") == 0);
    }
    // 10^-30 away from tangency (the degenerate quadruple below, Q moved
    // away): beyond doubles, Arb decides.
    const std::string near = s.write("near.ell", "2 1 0 5 0\n2 1 1 0 5\n2 1 0 -5 0\n2 1 1 0 -5.000000000000000000000000000001\n");
    Run near_run = s.ellvor("incircle " + near + " --json");
    REQUIRE(near_run.status == 0);
    const json near_json = parse(near_run);
    CHECK(near_json.at("result") == "no-conflict");
    CHECK(near_json.at("stage") == "subdivision");
    CHECK(near_json.at("newton_steps") > 0);
    // CGAL's .cin form.
    const std::string cin = s.write("far.cin", "6 0 1\n0 6 1\n-6 0 1\n30 30 1\n");
    Run r = s.ellvor("incircle " + cin + " --cin");
    CHECK(r.status == 0);
    CHECK(r.out == "no-conflict\n");

    // Exactly degenerate: the ellipse (a=2, b=1, w=0) at (5, 0) and its
    // rotations by 90, 180, 270 degrees about the origin all touch the circle
    // of radius 3 at the origin: Q is tangent to the Voronoi circle. The
    // subdivision stage cannot decide that: at any cap the command accepts it
    // hands over to the exact stage, which proves "tangent" (the command never
    // says undecided). 2^17 and 2^20 are the caps at which the subdivision
    // loop once stopped before handing over.
    const std::string degenerate = s.write("degenerate.ell", "2 1 0 5 0\n2 1 1 0 5\n2 1 0 -5 0\n2 1 1 0 -5\n");
    for (const long cap : {64L, 256L, 4096L, 1L << 17, 1L << 20}) {
        for (const char* json_flag : {"", " --json"}) {
            if (cap > 4096 && !*json_flag) continue;  // the slow caps once, with JSON
            r = s.ellvor("incircle " + degenerate + " --max-precision " + std::to_string(cap) + json_flag);
            INFO("cap " << cap << json_flag << "\nstdout: " << r.out << "\nstderr: " << r.err);
            std::string word = r.out;
            if (*json_flag) {
                const json j = parse(r);
                word = j.at("result").get<std::string>() + "\n";
                CHECK(j.at("precision") >= cap);
                CHECK(j.at("sign") == 0);
                CHECK(j.at("stage") == "exact");
            }
            CHECK(word == "tangent\n");
            CHECK(r.status == 0);
            CHECK(r.err.empty());
        }
    }
    // The bounds of --max-precision are usage errors.
    for (const char* cap : {"63", "16777217"}) {
        r = s.ellvor("incircle " + degenerate + " --max-precision " + cap);
        CHECK(r.status == 2);
    }
}

TEST_CASE("voronoi-circle: certified JSON, clockwise triples, --bits", "[cli]") {
    Scratch s;
    const std::string ccw = s.write("ccw.ell", "1 1 0 6 0\n1 1 0 0 6\n1 1 0 -6 0\n");
    for (long bits : {53L, 200L}) {
        const Run r = s.ellvor("voronoi-circle " + ccw + " --bits " + std::to_string(bits));
        INFO(r.err);
        REQUIRE(r.status == 0);
        const json j = parse(r);
        CHECK(j.at("exists") == true);
        CHECK(j.at("bits") == bits);
        CHECK(j.at("correct_bits").get<long>() >= bits);
        CHECK(j.at("precision").get<long>() > 0);
        CHECK(j.at("newton_steps").get<long>() > 0);
        REQUIRE(j.at("tangency").size() == 3);
        for (const json& t : j.at("tangency")) {
            CHECK(t.at("t").is_string());
            const std::string chart = t.at("chart");
            CHECK((chart == "t" || chart == "-1/t"));
            CHECK(t.at("chart_parameter").is_string());
        }
        REQUIRE(j.at("center").size() == 2);
        // Center (0, 0) and radius 5, as Arb balls "[mid +/- rad]".
        const std::string radius = j.at("radius");
        CHECK(radius.rfind("[5.", 0) == 0);
        const std::string cx = j.at("center")[0];
        CHECK(cx.front() == '[');
    }
    // --cin and an ellipse triple.
    const std::string cin = s.write("ccw.cin", "6 0 1\n0 6 1\n-6 0 1\n");
    Run r = s.ellvor("voronoi-circle " + cin + " --cin --bits 64");
    REQUIRE(r.status == 0);
    CHECK(parse(r).at("exists") == true);
    const std::string ellipses = s.write("ellipses.ell", "2 1 0 5 0\n2 1 1 0 5\n2 1 0 -5 0\n");
    r = s.ellvor("voronoi-circle " + ellipses + " --bits 100");
    REQUIRE(r.status == 0);
    json j = parse(r);
    CHECK(j.at("exists") == true);
    CHECK(j.at("correct_bits").get<long>() >= 100);
    CHECK(j.at("radius").get<std::string>().rfind("[3", 0) == 0);  // the circle of radius 3

    // Clockwise: no counter-clockwise circle.
    const std::string cw = s.write("cw.ell", "1 1 0 -6 0\n1 1 0 0 6\n1 1 0 6 0\n");
    r = s.ellvor("voronoi-circle " + cw + " --bits 64");
    REQUIRE(r.status == 0);
    j = parse(r);
    CHECK(j.at("exists") == false);
    CHECK(j.at("circles") == "cw");

    // --bits is required and must be an integer.
    r = s.ellvor("voronoi-circle " + ccw);
    CHECK(r.status == 2);
    CHECK(contains(r.err, "--bits"));
    CHECK(r.out.empty());
    r = s.ellvor("voronoi-circle " + ccw + " --bits many");
    CHECK(r.status == 2);
    CHECK(r.out.empty());
}

TEST_CASE("voronoi-circle: a triple 10^30 away from the origin is certified", "[cli][voronoi-circle-search]") {
    // Once undecided (exit 3): the floating-point guesses lost the sites'
    // relative geometry. The same triple at the origin has radius 3.0308...
    Scratch s;
    const std::string far = s.write("far.ell",
                                   "4 2 0 1000000000000000000000000000000 0\n"
                                   "3 1.5 1/3 1000000000000000000000000000010 0\n"
                                   "2.5 2.5 0 1000000000000000000000000000005 8\n");
    const Run r = s.ellvor("voronoi-circle " + far + " --bits 60");
    INFO(r.out << r.err);
    REQUIRE(r.status == 0);
    CHECK(r.err.empty());
    const json j = parse(r);
    CHECK(j.at("exists") == true);
    CHECK(j.at("correct_bits").get<long>() >= 60);
    CHECK(j.at("radius").get<std::string>().rfind("[3.030805524129", 0) == 0);
    CHECK(j.at("center")[1].get<std::string>().rfind("[2.584108153271", 0) == 0);
    CHECK(j.at("found_by") == "guess");
    CHECK(j.at("search_boxes") == 0);
    // No exit status 3 (undecided) is left to document.
    const Run help = s.ellvor("voronoi-circle --help");
    const std::size_t exit_status = help.out.find("exit status:");
    REQUIRE(exit_status != std::string::npos);
    CHECK(help.out.find('3', exit_status) == std::string::npos);
    CHECK(contains(help.out, "search_boxes"));
}

TEST_CASE("predicate commands: wrong site counts exit 2", "[cli]") {
    Scratch s;
    const std::string one = s.write("one.ell", "1 1 0 0 0\n");
    const std::string two = s.write("two.ell", "1 1 0 0 0\n1 1 0 10 0\n");
    const std::string three = s.write("three.ell", "1 1 0 0 0\n1 1 0 10 0\n1 1 0 0 10\n");
    const std::string four = s.write("four.ell", "1 1 0 0 0\n1 1 0 10 0\n1 1 0 0 10\n# a comment\n\n1 1 0 10 10\n");
    const std::string five =
        s.write("five.ell", "1 1 0 0 0\n1 1 0 10 0\n1 1 0 0 10\n1 1 0 10 10\n   2 2 0 -10 -10\n");
    struct Case {
        std::string args, location;  // location: ":LINE:" of the surplus site, or "" for too few
    };
    const Case cases[] = {
        {"side-of-bisector " + one + " 0 0", ""},
        {"side-of-bisector " + three + " 0 0", ":3:"},
        {"bitangent " + one, ""},
        {"bitangent " + four, ":6:"},  // comment and blank line counted in line numbers
        {"incircle " + three, ""},
        {"incircle " + five, ":5:"},
        {"voronoi-circle " + two + " --bits 64", ""},
        {"voronoi-circle " + four + " --bits 64", ":6:"},
    };
    for (const Case& c : cases) {
        const Run r = s.ellvor(c.args);
        INFO(c.args << "\nstderr: " << r.err);
        CHECK(r.status == 2);
        CHECK(r.out.empty());  // nothing half-written
        const std::string file = c.args.substr(c.args.find(' ') + 1, c.args.find(".ell") + 4 - c.args.find(' ') - 1);
        CHECK(r.err.rfind("ellvor: " + file + c.location, 0) == 0);
        if (!c.location.empty()) {  // ...:LINE:COL: with a column number
            const std::size_t col = ("ellvor: " + file + c.location).size();
            CHECK(r.err.size() > col + 1);
            CHECK(std::isdigit(static_cast<unsigned char>(r.err[col])));
        }
        CHECK(contains(r.err, "expected"));
        CHECK(contains(r.err, "found"));
    }
}
