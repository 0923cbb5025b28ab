// Certified cell areas against the build: random ellipses (generate_sites,
// seed 1, bits 8, box 100, 10% nested), free plane (no box yet: unbounded
// cells cost nothing), tolerance 1e-9. Per count: the build's CPU time, the
// cells' CPU time, their ratio, and the time per bounded cell.
//   build/experiments/cells_timing [--full] [--out DIR]
//   build/experiments/cells_timing --areas-csv SITES.ell [--tolerance T] [--only ID,ID,...]
// Default counts 10 and 20 (about a minute, as in `make bench`); --full adds
// 50, 100 and 200 (tens of minutes: about 3 s of CPU per bounded cell).
//
// --areas-csv writes instead the certified cell areas of a site file as CSV
// on stdout, for the independent oracle (tests/python/cell_area_oracle.py)
// and the sampling comparison (experiments/cells_vs_sampling.py) while
// `ellvor cells` is not there. One row per site in file order (with --only,
// those sites' rows): site,visible,bounded,area_lo,area_hi,neighbors where
// [area_lo, area_hi] is the Arb ball of cells/cell_area.hpp rounded outward
// to 25 significant digits (lo down, hi up), "inf" for an unbounded cell,
// and `neighbors` the ids across the cell's edges, counter-clockwise
// (space-separated; a site may appear twice). The last line on stderr gives
// the CPU seconds of the build and of the cells.
#include "cells/cell_area.hpp"
#include "cells/face_numbers.hpp"
#include "cells/voronoi_cells.hpp"
#include "experiments/report.hpp"
#include "experiments/run_environment.hpp"
#include "graph/delaunay_graph.hpp"
#include "sites/site_generators.hpp"
#include "sites/site_io.hpp"
#include "traits/ellipse_delaunay_traits.hpp"
#include "util/error.hpp"

#include <mpfr.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

using namespace ellvor;
using namespace ellvor::experiments;

namespace {

const char* const kUsage =
    "usage: cells_timing [--full] [--out DIR]\n"
    "       cells_timing --areas-csv SITES.ell [--tolerance T] [--only ID,ID,...]\n";

TableRow measure_cells(long n) {
    GeneratorOptions o;
    o.count = n;
    o.nested_fraction = Rational(1, 10);
    const std::vector<Ellipse> sites = generate_sites(o);
    DelaunayGraph graph(std::make_unique<EllipseDelaunayTraits>(sites));
    const double c0 = now_cpu();
    graph.insert_all();
    const double c1 = now_cpu();
    const std::vector<CellArea> areas = cell_areas(graph, sites);
    const double c2 = now_cpu();
    long bounded = 0;
    for (const CellArea& a : areas) bounded += a.bounded;
    const double build = c1 - c0, cells = c2 - c1;
    std::cerr << "[cells_timing] " << n << " sites: cells " << cells << " s\n";
    return {integer(n), integer(bounded), fmt("%.3f", build), fmt("%.3f", cells), fmt("%.1f", cells / build),
            fmt("%.2f", 1e3 * cells / static_cast<double>(std::max(1L, bounded)))};
}

constexpr int kDigits = 25;

// An arf as a decimal string of kDigits significant digits, rounded in the
// direction `rnd` (the arf is first copied exactly into an mpfr).
std::string decimal(const arf_t x, mpfr_rnd_t rnd) {
    if (arf_is_pos_inf(x)) return "inf";
    if (arf_is_neg_inf(x)) return "-inf";
    mpfr_t m;
    mpfr_init2(m, std::max<slong>(2, arf_bits(x)));
    arf_get_mpfr(m, x, MPFR_RNDN);  // exact: the precision holds every bit
    char* s = nullptr;
    mpfr_asprintf(&s, rnd == MPFR_RNDD ? "%.*RDe" : "%.*RUe", kDigits - 1, m);
    std::string out(s);
    mpfr_free_str(s);
    mpfr_clear(m);
    return out;
}

// A ball's lower (upper = false) or upper end, rounded outward to decimal.
std::string bound(const Ball& b, bool upper) {
    arf_t x;
    arf_init(x);
    if (upper)
        arb_get_ubound_arf(x, b.get(), 2 * kDigits * 4);
    else
        arb_get_lbound_arf(x, b.get(), 2 * kDigits * 4);
    std::string s = decimal(x, upper ? MPFR_RNDU : MPFR_RNDD);
    arf_clear(x);
    return s;
}

// --areas-csv: see the head of this file.
int dump_areas(int argc, char** argv) {
    CellAreaOptions options;
    for (int i = 3; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--tolerance" && i + 1 < argc) {
            options.tolerance = std::strtod(argv[++i], nullptr);
        } else if (arg == "--only" && i + 1 < argc) {
            std::stringstream ids(argv[++i]);
            std::string id;
            while (std::getline(ids, id, ',')) options.only.push_back(std::stoul(id));
        } else {
            std::cerr << kUsage;
            return 2;
        }
    }
    try {
        const std::vector<Ellipse> sites = read_sites(argv[2]);
        DelaunayGraph graph(std::make_unique<EllipseDelaunayTraits>(sites));
        const double c0 = now_cpu();
        graph.insert_all();
        const double c1 = now_cpu();
        const std::vector<CellArea> areas = cell_areas(graph, sites, options);
        const double c2 = now_cpu();
        const std::vector<VoronoiCell> cells = voronoi_cells(graph, face_numbers(graph));
        std::cout << "site,visible,bounded,area_lo,area_hi,neighbors\n";
        for (SiteId i = 0; i < sites.size(); ++i) {
            if (!options.only.empty() && std::find(options.only.begin(), options.only.end(), i) == options.only.end())
                continue;  // not measured
            const CellArea& a = areas[i];
            std::cout << i << ',' << a.visible << ',' << a.bounded << ',';
            if (!a.visible)
                std::cout << "0,0";
            else if (!a.bounded)
                std::cout << "inf,inf";
            else
                std::cout << bound(a.area, false) << ',' << bound(a.area, true);
            std::cout << ',';
            for (std::size_t k = 0; k < cells[i].edges.size(); ++k)
                std::cout << (k ? " " : "") << cells[i].edges[k].neighbor;
            std::cout << '\n';
        }
        std::cerr << "cpu seconds: build " << (c1 - c0) << " cells " << (c2 - c1) << '\n';
    } catch (const Error& e) {
        std::cerr << "cells_timing: " << e.what() << '\n';
        return 2;
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc >= 2 && std::string(argv[1]) == "--areas-csv") {
        if (argc < 3) {
            std::cerr << kUsage;
            return 2;
        }
        return dump_areas(argc, argv);
    }
    BenchArguments args;
    if (!parse_bench_arguments(argc, argv, "cells_timing", kUsage, args)) return 2;
    std::vector<long> counts = {10, 20};
    if (args.full) counts.insert(counts.end(), {50, 100, 200});
    Report report("Certified cell areas against the build", "cells_timing", args.command);
    Table table("cells", {"sites", "bounded cells", "build s", "cells s", "cells / build", "ms per bounded cell"});
    for (long n : counts) table.add(measure_cells(n));
    report.intro("Random ellipses (generate_sites: seed 1, bits 8, box 100, 10% nested), free plane, T = 1e-9, one "
                 "run each, CPU seconds.");
    report.table(table);
    report.publish(args.out_dir, "cells_timing.md");
    return 0;
}
