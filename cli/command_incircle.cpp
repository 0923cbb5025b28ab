// ellvor incircle FILE: kappa3 on the four sites of FILE.
#include "cli/command_list.hpp"

#include "cli/site_arguments.hpp"
#include "predicates/incircle.hpp"
#include "util/precision.hpp"
#include "exact/medial_axis_tangency.hpp"

#include <nlohmann/json.hpp>

#include <chrono>
#include <iostream>

namespace ellvor::cli {
namespace {

const char* const kHelp =
    "usage: ellvor incircle FILE [--cin] [--json] [--max-precision BITS]\n"
    "\n"
    "InCircle (kappa3, incircle(E1, E2, E3, Q); CGAL's Vertex_conflict_2 with four sites) for the four sites of FILE in\n"
    "the order E1 E2 E3 Q. The Voronoi circle of the ordered triple is externally tangent to\n"
    "E1, E2, E3 with its tangency points counter-clockwise in that order. Prints one word:\n"
    "  conflict      Q meets the open Voronoi disk (NEGATIVE)\n"
    "  no-conflict   it does not (POSITIVE)\n"
    "  tangent       Q is externally tangent to the circle (ZERO, proven by the exact stage)\n"
    "  no-circle     the triple has no counter-clockwise Voronoi circle (NEGATIVE, CGAL's rule)\n"
    "The subdivision stage (Arb) works up to --max-precision bits; beyond, the exact stage\n"
    "(degree-184 resultants) decides whether Q is tangent, and if it is not, the subdivision\n"
    "resumes until it separates.\n"
    "\n"
    "options:\n"
    "  --cin                 read CGAL's circle format 'x y r' instead of .ell\n"
    "  --json                print {result, sign, stage, precision, newton_steps, time_us}\n"
    "  --max-precision BITS  precision at which the exact stage takes over (default 4096)\n"
    "\n"
    "The Voronoi circle is always certified (in double intervals, else in Arb from a\n"
    "floating-point guess or by an exhaustive search), so every answer is decided. --json's\n"
    "stage is the one that decided: filter (doubles), subdivision (Arb) or exact.\n"
    "\n"
    "exit status: 0 decided; 2 bad input (FILE must hold exactly four sites, no two of\n"
    "them crossing); 1 internal error.\n";

int run(const std::vector<std::string>& args) {
    Arguments parsed(args, {{"--cin", false}, {"--json", false}, {"--max-precision", true}});
    parsed.expect_positional(1, 1, "FILE");
    InCircleOptions options;
    options.refinement.cap =
        parsed.integer("--max-precision", options.refinement.cap, precision::kStart, precision::kMaxCap);
    const SiteFile file = read_site_argument(parsed, parsed.positional()[0]);
    require_site_count(file, 4, 4, "E1 E2 E3 Q");
    require_acceptable_crossings(file);
    const auto& s = file.sites;

    const auto start = std::chrono::steady_clock::now();
    VoronoiCircle circle(s[0], s[1], s[2], common_medial_axis_tangency);
    const Decision<InCircle> d = incircle(s[0], s[1], s[2], s[3], options, &circle);
    // Arb Newton steps: none when the double-interval stage decided.
    const long newton_steps = circle.has_solver() ? circle.solver().enclosure().newton_steps : 0;
    const double us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
    if (parsed.has("--json")) {
        nlohmann::json j = {{"result", incircle_name(*d)}, {"sign", to_int(incircle_sign(*d))},
                            {"stage", stage_name(d.stage)}, {"precision", d.precision},
                            {"newton_steps", newton_steps}, {"time_us", us}};
        std::cout << j.dump() << "\n";
    } else {
        std::cout << incircle_name(*d) << "\n";
    }
    return kExitOk;
}

}  // namespace

const Command command_incircle = {"incircle", "kappa3: a site against the Voronoi circle of three", kHelp, run};

}  // namespace ellvor::cli
