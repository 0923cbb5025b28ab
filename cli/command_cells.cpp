// ellvor cells FILE: the certified Voronoi cells (areas, packing fractions,
// neighbours) as CSV, JSON or GeoJSON.
#include "cli/command_list.hpp"

#include "cli/site_arguments.hpp"
#include "output/cell_request.hpp"
#include "output/cells_csv.hpp"
#include "output/cells_geojson.hpp"
#include "output/cells_json.hpp"
#include "sites/rational_parse.hpp"

#include <array>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <optional>
#include <unistd.h>

namespace ellvor::cli {
namespace {

const char* const kHelp =
    "usage: ellvor cells FILE [--cin] [--box X0 Y0 X1 Y1 | --periodic X0 Y0 X1 Y1] [--tolerance T]\n"
    "                   [--boundary-tolerance D] [--threads N] [--format csv|json|geojson] [-o OUT]\n"
    "\n"
    "The Voronoi cells of the sites of FILE, each certified: every interval printed provably\n"
    "contains the exact value. A cell holds its site (the set-Voronoi convention: the cells tile\n"
    "the plane, or the box). Hidden sites (inside others) have no cell.\n"
    "\n"
    "options:\n"
    "  --cin             read CGAL's circle format 'x y r' instead of .ell\n"
    "  --box X0 Y0 X1 Y1 cells clipped to the rectangle [X0, X1] x [Y0, Y1] (walls), exact\n"
    "                    rationals as in site files; every site must lie strictly inside it\n"
    "                    (the walls are computed as mirrors: a site touching a wall is an error)\n"
    "  --periodic X0 Y0 X1 Y1\n"
    "                    the cells of the periodic tiling of that rectangle (the torus); centres\n"
    "                    are taken into the box by whole periods, sites may straddle its edges,\n"
    "                    no site may meet its own periodic image\n"
    "  --tolerance T     every finite area is certified with hi - lo <= T * area, T in (0, 1]\n"
    "                    (default 1e-9; down to 1e-30 and below, at a higher precision)\n"
    "  --boundary-tolerance D\n"
    "                    the rings' certified distance to the cells' boundaries, D > 0\n"
    "                    (default 1e-3 of the median larger semi-axis); JSON and GeoJSON only:\n"
    "                    the CSV has no rings and is computed without them (faster)\n"
    "  --threads N       measure the areas on N threads (default 1; 0: one per core); the\n"
    "                    output does not depend on N\n"
    "  --format F        csv (default), json or geojson\n"
    "  -o, --output OUT  write to OUT, atomically (default '-': standard output); a summary\n"
    "                    line goes to standard output\n"
    "On a terminal, a progress line goes to standard error for more than 20 sites.\n"
    "\n"
    "CSV: a header, then one row per site in file order:\n"
    "  site                 the site's id (0-based, file order)\n"
    "  visible              1, or 0 for a hidden site (no cell: area 0, packing fraction empty)\n"
    "  area_lo, area_hi     the cell's area (the site's included): lo rounded down, hi rounded up,\n"
    "                       with at least 17 significant digits (more when the interval is\n"
    "                       narrower); 'inf' for a cell reaching infinity (free plane)\n"
    "  site_area            pi a b, its certain digits: the exact value is within one unit of\n"
    "                       the last digit printed (trailing zeros count)\n"
    "  packing_fraction_lo, packing_fraction_hi   site area / cell area, an interval as the\n"
    "                       areas'; 0 for an unbounded cell; empty for a hidden site\n"
    "  perimeter_lo, perimeter_hi   the length of the cell's boundary (walls included), as the\n"
    "                       areas\n"
    "  neighbors            the sides of the cell counter-clockwise, space-separated, one entry\n"
    "                       a side (a neighbour across two sides appears twice): a site id;\n"
    "                       'wall:left', 'wall:bottom', 'wall:right' or 'wall:top' in a box;\n"
    "                       periodic: 'ID@DX,DY' when the neighbour is the image of site ID\n"
    "                       shifted by (DX, DY) box sizes (the field is then quoted, RFC 4180)\n"
    "JSON: {\"domain\": {\"kind\": \"plane\"|\"box\"|\"periodic\", \"box\": [X0, Y0, X1, Y1] (exact,\n"
    "  as strings)}, \"boundary_tolerance\", \"vertices\": [{\"x\", \"y\"}], \"cells\": [{\"site\",\n"
    "  \"visible\", \"bounded\", \"area\", \"site_area\", \"packing_fraction\", \"perimeter\", \"centroid\":\n"
    "  [x, y], \"second_moments\": [xx, xy, yy] (about the centroid), \"neighbors\" (as the CSV's,\n"
    "  ids as numbers), \"sides\": [{\"neighbor\" (null for a wall), \"wall\" (null for a site),\n"
    "  \"shift\": [DX, DY], \"from\", \"to\" (vertex indices, counter-clockwise; -1 at infinity)}],\n"
    "  \"ring\": [[x, y], ...] (not closed; empty when unbounded, hidden or not computed),\n"
    "  \"precision\" (Arb bits)}]}. Each certified value is {\"lo\", \"hi\"}: the interval's ends as\n"
    "  doubles rounded outward (\"inf\" for infinite ends), or null when not computed or not\n"
    "  defined (a hidden site's packing fraction and centroid). Use the CSV for more digits.\n"
    "GeoJSON: a FeatureCollection, one Polygon per cell with a ring (closed, counter-clockwise),\n"
    "  properties site, area_lo, area_hi, packing_fraction_lo, packing_fraction_hi (as the JSON's);\n"
    "  \"cells_without_ring\" counts the cells left out.\n"
    "\n"
    "Sites may touch or cross (signed distances, as in build), unless two cross so deeply that\n"
    "their Voronoi edge runs through a site's medial axis (e.g. a needle's tip deep inside\n"
    "another site): that is refused.\n"
    "\n"
    "exit status: 0 done; 1 a cell could not be certified; 2 bad input (a tolerance out of range,\n"
    "an empty box, a site not strictly inside the box or meeting its own periodic image, sites\n"
    "that cross so deeply: FILE:LINE:COLUMN), nothing written.\n";

// "--box X0 Y0 X1 Y1" (or --periodic) taken out of args: Arguments knows
// options with one value only.
std::optional<std::array<std::string, 4>> take_box_option(std::vector<std::string>& args, const std::string& name) {
    std::optional<std::array<std::string, 4>> found;
    for (std::size_t i = 0; i < args.size() && args[i] != "--";) {
        if (args[i] != name) {
            ++i;
            continue;
        }
        if (found) throw UsageError("option " + name + " given twice");
        if (i + 5 > args.size())
            throw UsageError("option " + name + " needs four numbers X0 Y0 X1 Y1");
        found = std::array<std::string, 4>{args[i + 1], args[i + 2], args[i + 3], args[i + 4]};
        args.erase(args.begin() + static_cast<long>(i), args.begin() + static_cast<long>(i) + 5);
    }
    return found;
}

Rational box_number(const std::string& name, const char* which, const std::string& text) {
    Rational r;
    std::string error;
    if (!parse_rational(text, r, error)) throw UsageError("option " + name + ": " + which + ": " + error);
    return r;
}

CellDomain domain_argument(std::vector<std::string>& args) {
    const auto box = take_box_option(args, "--box"), periodic = take_box_option(args, "--periodic");
    if (box && periodic) throw UsageError("options --box and --periodic exclude each other");
    CellDomain d;
    if (!box && !periodic) return d;
    d.kind = box ? CellDomain::Kind::box : CellDomain::Kind::periodic;
    const std::string name = box ? "--box" : "--periodic";
    const std::array<std::string, 4>& v = box ? *box : *periodic;
    d.x0 = box_number(name, "X0", v[0]);
    d.y0 = box_number(name, "Y0", v[1]);
    d.x1 = box_number(name, "X1", v[2]);
    d.y1 = box_number(name, "Y1", v[3]);
    return d;
}

int run(const std::vector<std::string>& arguments) {
    std::vector<std::string> args = arguments;
    const CellDomain domain = domain_argument(args);
    Arguments parsed(args, {{"--cin", false},
                            {"--tolerance", true},
                            {"--boundary-tolerance", true},
                            {"--threads", true},
                            {"--format", true},
                            {"-o", true, "--output"}});
    parsed.expect_positional(1, 1, "FILE");
    const std::string format = parsed.value("--format", "csv");
    if (format != "csv" && format != "json" && format != "geojson")
        throw UsageError("option --format: expected csv, json or geojson, got '" + format + "'");
    CellOptions options;
    options.tolerance = parsed.real("--tolerance", 1e-9);
    options.rings = format != "csv";  // the CSV has no rings: spare their cost
    options.threads = static_cast<unsigned>(parsed.integer("--threads", 1, 0, 1024));
    std::optional<double> boundary_tolerance;
    if (parsed.has("--boundary-tolerance")) boundary_tolerance = parsed.real("--boundary-tolerance", 0);
    const CellArgumentNames names = {"option --box", "option --periodic", "option --tolerance",
                                     "option --boundary-tolerance"};
    // The arguments first: a bad one is reported before the file is read.
    check_cell_arguments(domain, options.tolerance, boundary_tolerance, names);
    const SiteFile file = read_site_argument(parsed, parsed.positional()[0]);

    const bool progress = ::isatty(2) && file.sites.size() > 20;
    if (progress)
        options.progress = [](std::size_t done, std::size_t total) {
            if (done % 10 == 0 || done == total) std::fprintf(stderr, "\rcells %zu of %zu", done, total);
        };
    const auto start = std::chrono::steady_clock::now();
    CellTessellation cells;
    try {
        cells = cells_of_site_file(file, domain, options, boundary_tolerance, names);
    } catch (...) {
        if (progress) std::fprintf(stderr, "\n");
        throw;
    }
    if (progress) std::fprintf(stderr, "\n");
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    auto write = [&](std::ostream& o) {
        if (format == "csv")
            write_cells_csv(o, cells);
        else if (format == "json")
            write_cells_json(o, cells), o << "\n";
        else
            write_cells_geojson(o, cells), o << "\n";
    };
    const std::string out = parsed.value("-o", "-");
    if (out == "-") {
        write(std::cout);
        return kExitOk;
    }
    write_file_atomically(out, write);
    std::size_t hidden = 0, unbounded = 0;
    for (const Cell& c : cells.cells) {
        hidden += c.visible ? 0 : 1;
        unbounded += c.visible && !c.bounded ? 1 : 0;
    }
    std::cout << cells.cells.size() << " cells (" << hidden << " hidden, " << unbounded << " unbounded) in "
              << seconds << " s, written to " << out << "\n";
    return kExitOk;
}

}  // namespace

const Command command_cells = {"cells", "certified Voronoi cells: areas, packing fractions, neighbours (CSV, JSON, GeoJSON)",
                               kHelp, run};

}  // namespace ellvor::cli
