// ellvor side-of-bisector FILE X Y: kappa1 on the two sites of FILE.
#include "cli/command_list.hpp"

#include "predicates/side_of_bisector.hpp"
#include "sites/rational_parse.hpp"
#include "cli/site_arguments.hpp"

#include <nlohmann/json.hpp>

#include <chrono>
#include <iostream>

namespace ellvor::cli {
namespace {

const char* const kHelp =
    "usage: ellvor side-of-bisector FILE X Y [--cin] [--json]\n"
    "\n"
    "kappa1: which of the two sites in FILE (E1 = first, E2 = second) is closer to the point\n"
    "(X, Y), for the signed distance (negative inside a site). X and Y are exact rationals\n"
    "(integers, p/q or decimals such as 0.1 = 1/10). Prints one word:\n"
    "  first        the point is closer to E1 (CGAL's ON_POSITIVE_SIDE)\n"
    "  second       the point is closer to E2 (ON_NEGATIVE_SIDE)\n"
    "  equidistant  the point is on the bisector (proved exactly)\n"
    "\n"
    "options:\n"
    "  --cin    read CGAL's circle format 'x y r' instead of .ell\n"
    "  --json   print {\"result\", \"sign\", \"stage\", \"precision\", \"time_us\"} instead\n"
    "\n"
    "exit status: 0 decided; 2 bad input (FILE must hold exactly two sites, not crossing).\n";

Rational coordinate(const std::string& token, const char* name) {
    Rational value;
    std::string error;
    if (!parse_rational(token, value, error)) throw UsageError(std::string(name) + ": " + error);
    return value;
}

int run(const std::vector<std::string>& args) {
    Arguments parsed(args, {{"--cin", false}, {"--json", false}});
    parsed.expect_positional(3, 3, "FILE X Y");
    const auto& pos = parsed.positional();
    const SiteFile file = read_site_argument(parsed, pos[0]);
    require_site_count(file, 2, 2, "E1 E2");
    require_acceptable_crossings(file);
    const Point p{coordinate(pos[1], "X"), coordinate(pos[2], "Y")};

    const auto start = std::chrono::steady_clock::now();
    const Decision<Sign> d = side_of_bisector(file.sites[0], file.sites[1], p);
    const double us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
    const char* word = *d == Sign::positive ? "first" : *d == Sign::negative ? "second" : "equidistant";
    if (parsed.has("--json")) {
        nlohmann::json j = {{"result", word}, {"sign", to_int(*d)}, {"stage", stage_name(d.stage)},
                            {"precision", d.precision}, {"time_us", us}};
        std::cout << j.dump() << "\n";
    } else {
        std::cout << word << "\n";
    }
    return kExitOk;
}

}  // namespace

const Command command_side_of_bisector = {"side-of-bisector", "kappa1: which of two sites is closer to a point",
                                          kHelp, run};

}  // namespace ellvor::cli
