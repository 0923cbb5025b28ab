// ellvor bitangent FILE: the external bitangent of two sites, and kappa2 for a
// third one.
#include "cli/command_list.hpp"

#include "decision/predicate_registry.hpp"
#include "predicates/external_bitangent.hpp"
#include "predicates/infinite_vertex_conflict.hpp"
#include "predicates/relative_position.hpp"
#include "predicates/voronoi_circle_count.hpp"
#include "cli/site_arguments.hpp"

#include <nlohmann/json.hpp>

#include <chrono>
#include <iostream>

namespace ellvor::cli {
namespace {

const char* const kHelp =
    "usage: ellvor bitangent FILE [--cin] [--json]\n"
    "\n"
    "FILE holds two or three sites E1 E2 [Q].\n"
    "Prints the external bitangent L of the ordered pair (E1, E2) -- the infinite Voronoi\n"
    "vertex: the common tangent line with E1's contact point before E2's and both sites on\n"
    "its right -- as the tangency parameters t on E1 and E2 (exact isolating intervals, or\n"
    "'inf' for the i-point) and the contact points (approx.).\n"
    "With a third site Q, also kappa2 = infinite_vertex_conflict(E1, E2, Q):\n"
    "  conflict      Q meets the open half-plane beyond L (CGAL's NEGATIVE)\n"
    "  no-conflict   it does not (POSITIVE); ties are broken as in CGAL, never zero\n"
    "and the number of Voronoi circles of the triple (none, ccw, cw, both). The JSON names\n"
    "kappa2 by its predicate name, \"infinite_vertex_conflict\".\n"
    "\n"
    "options:\n"
    "  --cin    read CGAL's circle format 'x y r' instead of .ell\n"
    "  --json   machine-readable output (adds the deciding stage and the time)\n"
    "\n"
    "exit status: 0 done; 2 bad input (E1 and E2 must be separated or externally tangent;\n"
    "no two sites may cross).\n";

nlohmann::json describe_contact(const Ellipse& e, BoundaryParameter t) {
    nlohmann::json j;
    const BallPoint p = boundary_point(e, t, 64);
    if (t.at_infinity()) {
        j["t"] = "inf";
    } else {
        const AlgebraicReal& v = *t.value;
        j["t"] = v.is_rational() ? nlohmann::json(v.rational_value().str())
                                 : nlohmann::json::array({v.lo().str(), v.hi().str()});
        j["t_approx"] = t.value->to_double();
    }
    j["point_approx"] = {p.x.mid_double(), p.y.mid_double()};
    return j;
}

int run(const std::vector<std::string>& args) {
    Arguments parsed(args, {{"--cin", false}, {"--json", false}});
    parsed.expect_positional(1, 1, "FILE");
    const SiteFile file = read_site_argument(parsed, parsed.positional()[0]);
    const auto& s = file.sites;
    require_site_count(file, 2, 3, "E1 E2 [Q]");
    require_acceptable_crossings(file);
    const RelativePosition position = *relative_position(s[0], s[1]);
    if (position != RelativePosition::separated && position != RelativePosition::externally_tangent)
        throw InputError(file.name + ": sites 0 and 1 are " + relative_position_name(position) +
                         "; an external bitangent needs separated sites");

    const char* const kappa2_key = predicate_name(Predicate::infinite_vertex_conflict);
    nlohmann::json out;
    out["first"] = describe_contact(s[0], external_bitangent_on(s[0], s[1], HullSide::arrival));
    out["second"] = describe_contact(s[1], external_bitangent_on(s[1], s[0], HullSide::departure));
    if (s.size() == 3) {
        const auto start = std::chrono::steady_clock::now();
        const Decision<Sign> d = infinite_vertex_conflict(s[0], s[1], s[2]);
        const double us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
        out[kappa2_key] = {{"result", *d == Sign::negative ? "conflict" : "no-conflict"},
                           {"sign", to_int(*d)}, {"stage", stage_name(d.stage)}, {"time_us", us}};
        out["voronoi_circles"] = voronoi_circles_name(*voronoi_circle_count(s[0], s[1], s[2]));
    }
    if (parsed.has("--json")) {
        std::cout << out.dump() << "\n";
        return kExitOk;
    }
    for (const char* which : {"first", "second"}) {
        const auto& c = out[which];
        std::cout << "contact on " << (which[0] == 'f' ? "E1" : "E2") << ": t = " << c["t"].dump();
        if (c.contains("t_approx")) std::cout << " ~ " << c["t_approx"].get<double>();
        std::cout << ", point ~ (" << c["point_approx"][0].get<double>() << ", " << c["point_approx"][1].get<double>()
                  << ")\n";
    }
    if (s.size() == 3) {
        std::cout << out[kappa2_key]["result"].get<std::string>() << "\n";
        std::cout << "voronoi circles: " << out["voronoi_circles"].get<std::string>() << "\n";
    }
    return kExitOk;
}

}  // namespace

const Command command_bitangent = {"bitangent", "the external bitangent of two sites; kappa2 for a third", kHelp, run};

}  // namespace ellvor::cli
