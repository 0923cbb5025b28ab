// ellvor build FILE: the Delaunay graph of the sites (incremental insertion).
#include "cli/command_list.hpp"

#include "cli/removal_list.hpp"
#include "cli/site_arguments.hpp"
#include "graph/delaunay_graph.hpp"
#include "output/cell_request.hpp"
#include "output/graph_json.hpp"
#include "output/svg_writer.hpp"
#include "traits/ellipse_delaunay_traits.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <unistd.h>

namespace ellvor::cli {
namespace {

const char* const kHelp =
    "usage: ellvor build FILE [--cin] [--remove IDS] [--json OUT] [--svg OUT [--svg-ids] [--color packing-fraction]]\n"
    "                   [--validate] [--stats]\n"
    "\n"
    "Builds the Delaunay graph (the dual of the Voronoi diagram) of the sites of FILE by\n"
    "incremental insertion (Karavelas-Yvinec, as CGAL's Apollonius graph), every predicate\n"
    "certified. Distances are signed (negative inside a site). Sites inside others are hidden:\n"
    "they have no Voronoi cell. Sites may cross in two points; an ellipse inside the union of\n"
    "crossing sites, with an empty cell, is hidden too (listed under a site crossing it).\n"
    "Prints a summary.\n"
    "\n"
    "options:\n"
    "  --cin         read CGAL's circle format 'x y r' instead of .ell\n"
    "  --remove IDS  after building, remove these sites, in this order (as CGAL's remove; the\n"
    "                sites a removed site hid come back): 0-based ids separated by commas\n"
    "                (3,17,4), or @FILE with one id a line ('#' comments); each id once\n"
    "  --json OUT    write {\"sites\", \"removed\", \"hidden\": [[hidden, hiding], ...], \"edges\": [[i, j], ...],\n"
    "                \"faces\": [[i, j, k], ...], \"voronoi_vertices\": [{\"face\", \"center\",\n"
    "                \"radius\", \"error\"}, ...], \"stats\"} ('-' for standard output); finite\n"
    "                edges and faces by site id (0-based, file order); an edge appears twice when\n"
    "                two Voronoi edges separate the same two sites; a Voronoi vertex is the center\n"
    "                and radius (approx.) of the face's Voronoi circle, each within `error` (a\n"
    "                negative radius: the center lies inside the face's three crossing circles);\n"
    "                removed sites are null in \"sites\" and appear nowhere else\n"
    "  --svg OUT     draw the diagram as SVG: the sites (hidden ones dashed, overlaps of\n"
    "                crossing sites shaded), the Delaunay edges, the Voronoi vertices and every\n"
    "                Voronoi edge traced along the bisector of its two sites (floating point, for\n"
    "                the eye: consecutive points of an arc closer than 0.5% of the drawing box's\n"
    "                larger side, each point equidistant from the two sites to ~1e-12 relative);\n"
    "                unbounded edges are clipped to the drawing box (the sites' bounding box plus\n"
    "                an 8% margin); a legend with the counts; y points up. Written atomically\n"
    "                ('-': standard output)\n"
    "  --svg-ids     with --svg: write each site's id at its center\n"
    "  --color packing-fraction   with --svg: fill each bounded cell on a colour scale by its\n"
    "                local packing fraction (site area / cell area; the midpoint of its certified\n"
    "                interval at tolerance 1e-9, as `ellvor cells` computes it; for the eye),\n"
    "                with a colour bar; unbounded and hidden cells stay blank. Where the cells\n"
    "                have no rings yet, the sites are filled with their cell's colour instead\n"
    "                (the legend says so). Costs the cells' computation; not with --remove\n"
    "  --validate    check the graph: combinatorics, every edge against the local conflict\n"
    "                tests, and for up to 300 sites every Voronoi circle empty of all sites\n"
    "  --stats       print the predicate calls per deciding stage and the time per insertion\n"
    "                (and per removal)\n"
    "\n"
    "exit status: 0 built (and valid); 1 the validation failed, or an undecided predicate;\n"
    "2 bad input (sites whose boundaries meet in 3 or 4 points are named).\n";

constexpr std::size_t kBruteForceLimit = 300;

int run(const std::vector<std::string>& args) {
    Arguments parsed(args, {{"--cin", false}, {"--remove", true}, {"--json", true}, {"--svg", true}, {"--svg-ids", false}, {"--color", true},
                            {"--validate", false}, {"--stats", false}});
    parsed.expect_positional(1, 1, "FILE");
    if (parsed.has("--svg-ids") && !parsed.has("--svg")) throw UsageError("option --svg-ids needs --svg OUT");
    if (parsed.has("--color") && !parsed.has("--svg")) throw UsageError("option --color needs --svg OUT");
    if (parsed.has("--color") && parsed.value("--color") != "packing-fraction")
        throw UsageError("option --color: expected packing-fraction, got '" + parsed.value("--color") + "'");
    if (parsed.has("--color") && parsed.has("--remove")) throw UsageError("option --color: not with --remove");
    SiteFile file = read_site_argument(parsed, parsed.positional()[0]);
    const std::vector<SiteId> removals =
        parsed.has("--remove") ? parse_removal_list(parsed.value("--remove"), file.sites.size()) : std::vector<SiteId>{};
    // The traits own the sites (one copy: ~840 bytes a site); the output reads them there.
    auto traits = std::make_unique<EllipseDelaunayTraits>(std::move(file.sites));
    const std::vector<Ellipse>& sites = traits->sites();

    const bool progress = ::isatty(2) && sites.size() > 1000;
    const auto start = std::chrono::steady_clock::now();
    DelaunayGraph graph(std::move(traits));
    try {
        graph.insert_all([&](std::size_t done, std::size_t total) {
            if (progress && (done % 200 == 0 || done == total)) std::fprintf(stderr, "\rinserted %zu of %zu", done, total);
        });
    } catch (const IntersectingSites& e) {
        if (progress) std::fprintf(stderr, "\n");
        throw crossing_sites_error(file, e.first(), e.second(), e.why());
    }
    if (progress) std::fprintf(stderr, "\n");
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const auto removal_start = std::chrono::steady_clock::now();
    const bool removal_progress = ::isatty(2) && removals.size() > 1000;
    for (std::size_t k = 0; k < removals.size(); ++k) {
        graph.remove(removals[k]);
        if (removal_progress && ((k + 1) % 200 == 0 || k + 1 == removals.size()))
            std::fprintf(stderr, "\rremoved %zu of %zu", k + 1, removals.size());
    }
    if (removal_progress) std::fprintf(stderr, "\n");
    const double removal_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - removal_start).count();

    // The build's statistics, before validation asks predicates of its own.
    nlohmann::json stats = build_stats_json(graph, seconds);
    if (!removals.empty()) {
        stats["removed"] = removals.size();
        stats["removal_seconds"] = removal_seconds;
    }
    std::cout << sites.size() << " sites (" << graph.hidden().size() << " hidden), " << graph.edges().size()
              << " Delaunay edges, " << graph.faces().size() << " faces, built in " << seconds << " s\n";
    if (!removals.empty())
        std::cout << removals.size() << " sites removed in " << removal_seconds << " s\n";

    int status = kExitOk;
    if (parsed.has("--validate")) {
        std::string problem = graph.validate();
        if (problem.empty() && sites.size() <= kBruteForceLimit) problem = graph.brute_force_check();
        std::cout << (problem.empty() ? "valid" : "INVALID: " + problem) << "\n";
        if (!problem.empty()) status = kExitFailure;
    }
    if (parsed.has("--stats")) {
        std::cout << "time per insertion: " << 1e6 * seconds / std::max<std::size_t>(1, sites.size()) << " us\n";
        if (!removals.empty())
            std::cout << "time per removal: " << 1e6 * removal_seconds / static_cast<double>(removals.size()) << " us\n";
        std::cout << "predicate calls (decided by";
        for (Stage stage : kStages) std::cout << (stage == kStages.front() ? " " : " / ") << stage_name(stage);
        std::cout << "):\n";
        for (const PredicateInfo& p : kPredicates) {
            const nlohmann::json& row = stats["predicates"][p.name];
            std::cout << "  " << p.name << ": " << row["calls"] << " (";
            for (Stage stage : kStages) std::cout << (stage == kStages.front() ? "" : " / ") << row[stage_name(stage)];
            std::cout << ")\n";
        }
    }
    if (parsed.has("--json")) {
        // Every certified value first: nothing is written when one fails.
        const std::vector<VoronoiVertexValue> vertices = voronoi_vertex_values(graph, sites);
        const auto write = [&](std::ostream& o) { write_graph_json(o, graph, sites, stats, vertices), o << "\n"; };
        const std::string out = parsed.value("--json");
        if (out == "-")
            write(std::cout);
        else
            write_file_atomically(out, write);
    }
    if (parsed.has("--svg")) {
        SvgOptions options;
        options.show_ids = parsed.has("--svg-ids");
        CellTessellation cells;
        if (parsed.has("--color")) {
            // The cells of the same sites (the library builds its own graph).
            const SiteFile named{file.name, sites, file.lines};
            cells = cells_of_site_file(named, CellDomain{}, CellOptions{}, std::nullopt,
                                       {"option --box", "option --periodic", "option --tolerance", "option --boundary-tolerance"});
            options.cells = &cells;
        }
        const TracedDiagram drawn = trace_voronoi_diagram(graph, sites, options.tolerance_fraction, options.margin_fraction);
        const std::string out = parsed.value("--svg");
        if (out == "-") {
            render_svg(std::cout, graph, sites, drawn, options);
        } else {
            write_file_atomically(out, [&](std::ostream& o) { render_svg(o, graph, sites, drawn, options); });
        }
        if (drawn.failed_edges > 0)
            std::cerr << "warning: " << drawn.failed_edges << " Voronoi edge(s) not drawn (uncertified vertex)\n";
    }
    return status;
}

}  // namespace

const Command command_build = {"build", "the Delaunay graph of a site file (JSON output, validation)", kHelp, run};

}  // namespace ellvor::cli
