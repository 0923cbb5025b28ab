// Certified cell areas against the build: random ellipses (generate_sites,
// seed 1, bits 8, box 100, 10% nested), free plane (no box yet: unbounded
// cells cost nothing), tolerance 1e-9. Per count: the build's CPU time, the
// cells' CPU time, their ratio, and the time per bounded cell.
//   build/experiments/cells_timing [--full] [--out DIR]
// Default counts 50, 100, 200; --full adds 1000 and 10000.
#include "cells/cell_area.hpp"
#include "experiments/run_environment.hpp"
#include "predicates/ellipse_delaunay_traits.hpp"
#include "sites/site_generators.hpp"

#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

using namespace ellvor;
using namespace ellvor::experiments;

int main(int argc, char** argv) {
    BenchArguments args;
    if (!parse_bench_arguments(argc, argv, "cells_timing", "usage: cells_timing [--full] [--out DIR]\n", args)) return 2;
    std::vector<long> counts = {50, 100, 200};
    if (args.full) counts.insert(counts.end(), {1000, 10000});
    std::ostringstream md;
    md << "# Certified cell areas against the build\n\n"
       << "Command: `" << args.command << "`  \nMachine: " << cpu_model() << ", load " << loadavg()
       << "  \nSource: " << source_state() << "\n\n"
       << "Random ellipses (generate_sites: seed 1, bits 8, box 100, 10% nested), free plane, T = 1e-9, one run "
          "each, CPU seconds.\n\n"
       << "| sites | bounded cells | build s | cells s | cells / build | ms per bounded cell |\n"
       << "|---:|---:|---:|---:|---:|---:|\n";
    for (long n : counts) {
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
        char row[256];
        std::snprintf(row, sizeof row, "| %ld | %ld | %.3f | %.3f | %.1f | %.2f |\n", n, bounded, build, cells,
                      cells / build, 1e3 * cells / std::max(1L, bounded));
        md << row;
        std::cout << row << std::flush;
    }
    if (!args.out_dir.empty()) std::ofstream(args.out_dir + "/cells_timing.md") << md.str();
    return 0;
}
