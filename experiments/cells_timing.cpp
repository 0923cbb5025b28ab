// Certified cell areas against the build: random ellipses (generate_sites,
// seed 1, bits 8, box 100, 10% nested), free plane (no box yet: unbounded
// cells cost nothing), tolerance 1e-9. Per count: the build's CPU time, the
// cells' CPU time, their ratio, and the time per bounded cell.
//   build/experiments/cells_timing [--full] [--out DIR]
// Default counts 10 and 20 (about a minute, as in `make bench`); --full adds
// 50, 100 and 200 (tens of minutes: about 3 s of CPU per bounded cell).
#include "cells/cell_area.hpp"
#include "experiments/report.hpp"
#include "experiments/run_environment.hpp"
#include "graph/delaunay_graph.hpp"
#include "sites/site_generators.hpp"
#include "traits/ellipse_delaunay_traits.hpp"

#include <algorithm>
#include <iostream>
#include <memory>
#include <vector>

using namespace ellvor;
using namespace ellvor::experiments;

namespace {

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

}  // namespace

int main(int argc, char** argv) {
    BenchArguments args;
    if (!parse_bench_arguments(argc, argv, "cells_timing", "usage: cells_timing [--full] [--out DIR]\n", args)) return 2;
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
