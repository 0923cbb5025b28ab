// ellvor voronoi-circle FILE --bits N: certified enclosure of the Voronoi
// circle of an ordered triple.
#include "cli/command_list.hpp"

#include "cli/site_arguments.hpp"
#include "predicates/voronoi_circle_count.hpp"
#include "subdivision/voronoi_circle_enclosure.hpp"
#include "exact/medial_axis_tangency.hpp"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <iostream>

namespace ellvor::cli {
namespace {

const char* const kHelp =
    "usage: ellvor voronoi-circle FILE --bits N [--cin]\n"
    "\n"
    "Certified enclosure of the Voronoi circle of the three sites of FILE (E1 E2 E3): the\n"
    "circle externally tangent to them with tangency points counter-clockwise E1 -> E2 -> E3,\n"
    "proved unique in its box by the Krawczyk operator in Arb balls. Every reported ball\n"
    "(tangency parameters t on E1, E2, E3; center; radius) has at least N correct bits\n"
    "(relative to the value when |value| >= 1, absolute below). Prints JSON:\n"
    "  {\"exists\": true, \"bits\": N, \"correct_bits\", \"precision\", \"newton_steps\", \"time_ms\",\n"
    "   \"found_by\": \"guess\"|\"tangent-line\"|\"near-duplicate\"|\"bisector-walk\"|\"needle-chain\"|\"search\",\n"
    "   \"search_boxes\",\n"
    "   \"tangency\": [{\"t\": BALL, \"chart\": \"t\"|\"-1/t\", \"chart_parameter\": BALL}, ...],\n"
    "   \"center\": [BALL, BALL], \"radius\": BALL}\n"
    "where BALL is Arb's \"[mid +/- rad]\" text (t is \"inf\" for a tangency at an i-point).\n"
    "The certificate starts from a floating-point guess; for a circle far larger than the\n"
    "sites (nearly collinear sites), from their nearly common tangent line in high precision;\n"
    "for two nearly coincident sites, from the circle of the pair moved apart; for a needle\n"
    "(aspect 2^12 or more), from the circle with the needle made stout, carried back to it;\n"
    "or else from an exhaustive search over boxes of the tangency parameters and the radius\n"
    "(\"search_boxes\" of them), which finds the circle whenever it exists.\n"
    "A triple without a counter-clockwise circle prints {\"exists\": false, \"circles\": ...}.\n"
    "\n"
    "options:\n"
    "  --bits N   correct bits wanted (1 .. 10^7)\n"
    "  --cin      read CGAL's circle format 'x y r' instead of .ell\n"
    "\n"
    "exit status: 0 done; 2 bad input (three sites needed, no two crossing); 1 internal\n"
    "error.\n";

std::string ball_text(const Ball& b, long bits) {
    const long digits = std::max(20L, static_cast<long>(std::ceil(bits * 0.30103)) + 5);
    return b.str(digits);
}

int run(const std::vector<std::string>& args) {
    Arguments parsed(args, {{"--cin", false}, {"--bits", true}});
    parsed.expect_positional(1, 1, "FILE");
    parsed.require("--bits");
    const long bits = parsed.integer("--bits", 53, 1, 10'000'000);
    const SiteFile file = read_site_argument(parsed, parsed.positional()[0]);
    require_site_count(file, 3, 3, "E1 E2 E3");
    require_acceptable_crossings(file);
    const auto& s = file.sites;

    nlohmann::json j;
    const VoronoiCircles circles = *voronoi_circle_count(s[0], s[1], s[2]);
    if (circles == VoronoiCircles::none || circles == VoronoiCircles::cw_only) {
        j = {{"exists", false}, {"circles", voronoi_circles_name(circles)}};
        std::cout << j.dump() << "\n";
        return kExitOk;
    }
    const auto start = std::chrono::steady_clock::now();
    VoronoiCircleSolver solver(s[0], s[1], s[2], common_medial_axis_tangency);
    // The count said the circle exists; the certification is complete, so a
    // search that proves otherwise is an internal contradiction (thrown).
    solver.refine_existing(bits);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    const VoronoiCircleEnclosure& c = solver.enclosure();
    j = {{"exists", true},
         {"bits", bits},
         {"correct_bits", c.correct_bits()},
         {"precision", c.precision},
         {"newton_steps", c.newton_steps},
         {"time_ms", ms},
         {"found_by", circle_start_name(c.found_by)},
         {"search_boxes", c.search_boxes}};
    for (int i = 0; i < 3; ++i) {
        nlohmann::json t = {{"chart", c.flipped[i] ? "-1/t" : "t"}, {"chart_parameter", ball_text(c.parameter[i], bits)}};
        t["t"] = c.flipped[i] && arb_contains_zero(c.parameter[i].get())
                     ? std::string("inf")
                     : ball_text(c.tangency_parameter(i, c.precision), bits);
        j["tangency"].push_back(t);
    }
    j["center"] = {ball_text(c.center_x, bits), ball_text(c.center_y, bits)};
    j["radius"] = ball_text(c.radius, bits);
    std::cout << j.dump() << "\n";
    return kExitOk;
}

}  // namespace

const Command command_voronoi_circle = {"voronoi-circle", "certified Voronoi circle of three sites to N bits", kHelp,
                                        run};

}  // namespace ellvor::cli
