// The ellvor commands on valid input: help texts, check, generate.
#include <catch2/catch.hpp>

#include "sites/site_io.hpp"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

using namespace ellvor;

namespace {

struct Run {
    int status;
    std::string out, err;
};

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

struct TempDir {
    std::string path;
    TempDir() {
        char t[] = "/tmp/ellvor_cmd_XXXXXX";
        REQUIRE(::mkdtemp(t) != nullptr);
        path = t;
    }
    ~TempDir() { std::system(("rm -rf '" + path + "'").c_str()); }
    std::string write(const std::string& name, const std::string& content) const {
        std::string p = path + "/" + name;
        std::ofstream(p, std::ios::binary) << content;
        return p;
    }
};

Run run_ellvor(const TempDir& dir, const std::string& args, const std::string& stdin_file = "/dev/null") {
    const std::string out = dir.path + "/.stdout", err = dir.path + "/.stderr";
    const std::string cmd = std::string("'") + ELLVOR_BINARY + "' " + args + " >'" + out + "' 2>'" + err + "' <'" +
                            stdin_file + "'";
    int raw = std::system(cmd.c_str());
    return Run{WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(out), slurp(err)};
}

int count_files(const std::string& dir) {
    std::string cmd = "ls -A '" + dir + "' | wc -l";
    FILE* p = ::popen(cmd.c_str(), "r");
    int n = -1;
    if (p) {
        if (std::fscanf(p, "%d", &n) != 1) n = -1;
        ::pclose(p);
    }
    return n;
}

}  // namespace

TEST_CASE("--help of the program and of every command", "[cli]") {
    TempDir dir;
    Run r = run_ellvor(dir, "--help");
    CHECK(r.status == 0);
    CHECK(r.out.find("usage: ellvor COMMAND") != std::string::npos);
    CHECK(r.out.find("check") != std::string::npos);
    CHECK(r.out.find("generate") != std::string::npos);
    for (const char* cmd : {"check", "generate"}) {
        for (const char* form : {" --help", " -h"}) {
            r = run_ellvor(dir, std::string(cmd) + form);
            CHECK(r.status == 0);
            CHECK(r.out.find(std::string("usage: ellvor ") + cmd) == 0);
        }
    }
    r = run_ellvor(dir, "generate paper-dataset --help");
    CHECK(r.status == 0);
    CHECK(r.out.find("paper-dataset") != std::string::npos);
    r = run_ellvor(dir, "help check");
    CHECK(r.status == 0);
    CHECK(r.out.find("usage: ellvor check") == 0);
}

TEST_CASE("check on the bundled example", "[cli]") {
    TempDir dir;
    const std::string example = std::string(ELLVOR_SOURCE_DIR) + "/data/example.ell";
    Run r = run_ellvor(dir, "check " + example);
    CHECK(r.status == 0);
    CHECK(r.out ==
          "hidden: 7 inside 6\nhidden: 9 inside 8\nhidden: 13 inside 12\nhidden: 19 inside 18\n"
          "20 sites (3 circles), 4 hidden, OK\n");
    r = run_ellvor(dir, "check --describe " + example);
    CHECK(r.status == 0);
    CHECK(r.out.find("sites: 20 (3 circles, 17 ellipses)") != std::string::npos);
    CHECK(r.out.find("bounding box") != std::string::npos);
    CHECK(r.out.find("nested pairs: 4") != std::string::npos);
    // standard input
    r = run_ellvor(dir, "check -", example);
    CHECK(r.status == 0);
    CHECK(r.out.find("20 sites (3 circles), 4 hidden, OK") != std::string::npos);
}

TEST_CASE("check reports tangencies and nesting of circles", "[cli]") {
    TempDir dir;
    const std::string f = dir.write("t.ell",
                                    "2 2 0 0 0\n"      // 0
                                    "1 1 0 1 0\n"      // 1: inside 0, internally tangent at (2, 0)
                                    "1 1 0 3 0\n"      // 2: externally tangent to 0 at (2, 0)... and to 1
                                    "1/2 1/2 0 0 10\n" // 3: alone
                                    "4 4 0 0 10\n");   // 4: contains 3
    Run r = run_ellvor(dir, "check " + f);
    CHECK(r.status == 0);
    CHECK(r.out.find("hidden: 1 inside 0 tangent\n") != std::string::npos);
    CHECK(r.out.find("tangent: 0 2\n") != std::string::npos);
    CHECK(r.out.find("tangent: 1 2\n") != std::string::npos);
    CHECK(r.out.find("hidden: 3 inside 4\n") != std::string::npos);
    CHECK(r.out.find("5 sites (5 circles), 2 hidden, OK") != std::string::npos);

    const std::string c = dir.write("c.cin", "# x y r\n0 0 1\n5 0 1\n");
    r = run_ellvor(dir, "check --cin " + c);
    CHECK(r.status == 0);
    CHECK(r.out == "2 sites (2 circles), 0 hidden, OK\n");
    const std::string e = dir.write("empty.ell", "# nothing\n");
    r = run_ellvor(dir, "check " + e);
    CHECK(r.status == 0);
    CHECK(r.out == "0 sites (0 circles), 0 hidden, OK\n");
}

TEST_CASE("generate writes reproducible, valid files atomically", "[cli]") {
    TempDir dir;
    const std::string a = dir.path + "/a.ell", b = dir.path + "/b.ell";
    Run r = run_ellvor(dir, "generate nested --count 30 --seed 7 --bits 10 --box 40 -o " + a);
    REQUIRE(r.status == 0);
    CHECK(r.out.empty());
    r = run_ellvor(dir, "generate nested --count=30 --seed=7 --bits=10 --box=40 --output " + b);
    REQUIRE(r.status == 0);
    const std::string ta = slurp(a);
    CHECK(ta == slurp(b));
    CHECK(ta.rfind("# generated by: ellvor generate nested --count 30 --seed 7 --bits 10 --box 40 --nested-fraction 1/4\n",
                   0) == 0);
    CHECK(read_sites(a).size() == 30);
    r = run_ellvor(dir, "check " + a);
    CHECK(r.status == 0);
    CHECK(r.out.find("30 sites (") != std::string::npos);
    CHECK(r.out.find(", 8 hidden, OK") != std::string::npos);  // round(30/4) = 8 (7.5 rounds up)

    r = run_ellvor(dir, "generate nested --count 30 --seed 8 --bits 10 --box 40");
    CHECK(r.status == 0);
    CHECK(r.out != ta);

    // circles, also in .cin form
    r = run_ellvor(dir, "generate circles --count 12 --seed 3 --cin -o " + dir.path + "/c.cin");
    REQUIRE(r.status == 0);
    r = run_ellvor(dir, "check --cin " + dir.path + "/c.cin");
    CHECK(r.status == 0);
    CHECK(r.out == "12 sites (12 circles), 0 hidden, OK\n");
    r = run_ellvor(dir, "generate ellipses --count 20 --seed 3 --nested-fraction 0.1");
    CHECK(r.status == 0);
    const std::string g = dir.write("g.ell", r.out);
    r = run_ellvor(dir, "check " + g);
    CHECK(r.status == 0);
    CHECK(r.out.find("20 sites (") != std::string::npos);
    CHECK(r.out.find(", 2 hidden, OK") != std::string::npos);

    // a failed generate leaves the old file untouched and no temporary behind
    const int before = count_files(dir.path);
    r = run_ellvor(dir, "generate ellipses --count 5000 --box 1/1000000 --bits 1 -o " + a);
    CHECK(r.status == 2);
    CHECK(slurp(a) == ta);
    CHECK(count_files(dir.path) == before);
}

TEST_CASE("generate paper-dataset: directory of instances or one listing", "[cli]") {
    TempDir dir;
    Run r = run_ellvor(dir, "generate paper-dataset incircle --set 2b --seed 5 -o " + dir.path + "/ic/");
    REQUIRE(r.status == 0);
    CHECK(count_files(dir.path + "/ic") == 394);  // 393 instances + manifest
    const std::string first = dir.path + "/ic/incircle-2b-0000.ell";
    auto sites = read_sites(first);
    REQUIRE(sites.size() == 4);
    r = run_ellvor(dir, "check " + first);
    CHECK(r.status == 0);
    CHECK(r.out == "4 sites (4 circles), 0 hidden, OK\n");

    r = run_ellvor(dir, "generate paper-dataset kappa1 --set 1 -o " + dir.path + "/k1.txt");
    REQUIRE(r.status == 0);
    const std::string listing = slurp(dir.path + "/k1.txt");
    CHECK(listing.find("# instance 0\n# query-point: 0 -100\n1 1 0 -2 0\n1 1 0 2 0\n") != std::string::npos);
    CHECK(listing.find("# instance 200\n# query-point: 100 0\n") != std::string::npos);

    r = run_ellvor(dir, "generate paper-dataset kappa2 --set 3 --seed 2");
    CHECK(r.status == 0);
    CHECK(r.out.find("# instance 499\n") != std::string::npos);
    Run again = run_ellvor(dir, "generate paper-dataset kappa2 --set 3 --seed 2");
    CHECK(again.out == r.out);
}
