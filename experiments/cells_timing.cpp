// Certified cells against the build (issue: cells with a box at most 2x the
// build's time). Per set, domain and tolerance: the build's CPU time, the
// cells' CPU time (cell_tessellation: its own build with the box's mirror
// sites, then the integrals), their ratio, the time per bounded cell, and
// the peak memory of the cells in a forked child.
//   random   generate_sites (seed 1, bits 8, box 100, 10% nested)
//   packing  generate_packing (packing fraction 0.55, gap 1/1000, aspect 1..4, seed 1), box [0, L]^2
// The box of a random set: its sites' bounding box widened by 1 on each side.
//   crossing circles  generate_sites (circles, seed 1, half of them crossing another)
//   build/experiments/cells_timing [--full | --large] [--out DIR]
// Without rings but for one row (they cost more than the areas). Default: 20
// random sites (plane and box, T = 1e-9, 1e-15 and 1e-30), a packing of 30
// and 20 crossing circles (about a minute); --full adds 100 and 1000 of each,
// also at 1e-15 (half an hour); --large has only 10^4 and 10^5 of each at
// 1e-9 and 10^4 of each at 1e-15 (about three hours), in cells_timing_large.md.
#include "cells/cell_tessellation.hpp"
#include "experiments/peak_memory.hpp"
#include "experiments/report.hpp"
#include "experiments/run_environment.hpp"
#include "graph/delaunay_graph.hpp"
#include "sites/packing_generator.hpp"
#include "sites/site_generators.hpp"
#include "traits/ellipse_delaunay_traits.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <vector>

using namespace ellvor;
using namespace ellvor::experiments;

namespace {

struct CellSet {
    std::string name;
    std::vector<Ellipse> sites;
    CellDomain box;  // kind box
};

CellSet random_set(long n, SiteKind kind = SiteKind::ellipses, Rational crossing = Rational(0)) {
    GeneratorOptions o;
    o.count = n;
    o.kind = kind;
    o.crossing_fraction = crossing;
    o.nested_fraction = crossing == Rational(0) ? Rational(1, 10) : Rational(0);
    CellSet set{crossing == Rational(0) ? "random" : "crossing circles", generate_sites(o), {}};
    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
    for (const Ellipse& e : set.sites) {
        const double r = std::max(e.a().to_double(), e.b().to_double()), x = e.xc().to_double(), y = e.yc().to_double();
        x0 = std::min(x0, x - r), y0 = std::min(y0, y - r), x1 = std::max(x1, x + r), y1 = std::max(y1, y + r);
    }
    set.box = {CellDomain::Kind::box, Rational(static_cast<long>(std::floor(x0)) - 1),
               Rational(static_cast<long>(std::floor(y0)) - 1), Rational(static_cast<long>(std::ceil(x1)) + 1),
               Rational(static_cast<long>(std::ceil(y1)) + 1)};
    return set;
}

CellSet packing_set(long n) {
    PackingOptions o;
    o.count = n;
    o.fraction = Rational(11, 20);
    const Packing p = generate_packing(o);
    const Rational L(p.box_side);
    return {"packing", p.sites, {CellDomain::Kind::box, Rational(0), Rational(0), L, L}};
}

TableRow measure(const CellSet& set, bool box, double tolerance, bool rings = false) {
    const double b0 = now_cpu();
    DelaunayGraph graph(std::make_unique<EllipseDelaunayTraits>(set.sites));
    graph.insert_all();
    const double build = now_cpu() - b0;
    CellOptions options;
    options.tolerance = tolerance;
    options.rings = rings;
    const CellDomain domain = box ? set.box : CellDomain{};
    const double c0 = now_cpu();
    const CellTessellation cells = cell_tessellation(set.sites, domain, options);
    const double time = now_cpu() - c0;
    long bounded = 0;
    std::size_t in_doubles = 0, nodes_in_arb = 0, by_arb = 0, from_neighbors = 0;
    QuadratureCounts quadrature;
    for (const ellvor::Cell& c : cells.cells) {
        bounded += c.bounded;
        in_doubles += c.edges_in_doubles;
        nodes_in_arb += c.edges_by_nodes_in_arb;
        by_arb += c.edges_by_arb;
        from_neighbors += c.edges_from_neighbors;
        quadrature += c.quadrature;
    }
    const std::size_t certified = in_doubles + nodes_in_arb;  // edges with the double certificate's pieces
    const double edges = static_cast<double>(std::max<std::size_t>(1, certified));
    const auto share = [&](std::size_t k) {
        return fmt("%.1f", 100.0 * static_cast<double>(k) / static_cast<double>(std::max<std::size_t>(1, certified + by_arb)));
    };
    const PeakMemory peak = peak_memory_in_child([] {}, [&] { cell_tessellation(set.sites, domain, options); });
    std::cerr << "[cells_timing] " << set.name << " " << set.sites.size() << (box ? " box" : " plane") << " T "
              << tolerance << ": cells " << time << " s\n";
    return {set.name,
            integer(static_cast<long long>(set.sites.size())),
            std::string(box ? "box" : "plane") + (rings ? " + rings" : ""),
            fmt("%.0e", tolerance),
            integer(bounded),
            fmt("%.3f", build),
            fmt("%.2f", time),
            fmt("%.0f", time / build),
            fmt("%.1f", 1e3 * time / static_cast<double>(std::max(1L, bounded))),
            share(in_doubles),
            share(nodes_in_arb),
            fmt("%.1f", 100.0 * static_cast<double>(from_neighbors) /
                            static_cast<double>(std::max<std::size_t>(1, certified + by_arb + from_neighbors))),
            certified ? fmt("%.1f", static_cast<double>(quadrature.pieces) / edges) : "-",
            certified ? fmt("%.1f", static_cast<double>(quadrature.failed_disks) / edges) : "-",
            certified ? fmt("%.0f", static_cast<double>(quadrature.nodes) / edges) : "-",
            peak.error.empty() ? fmt("%.1f", (peak.peak_kb - peak.start_kb) / 1024.0) : peak.error};
}

}  // namespace

int main(int argc, char** argv) {
    // --large: only the rows of 10^4 and 10^5 sites (about three hours), in cells_timing_large.md.
    bool large = false;
    std::vector<char*> common;
    for (int i = 0; i < argc; ++i)
        if (std::string(argv[i]) == "--large")
            large = true;
        else
            common.push_back(argv[i]);
    BenchArguments args;
    if (!parse_bench_arguments(static_cast<int>(common.size()), common.data(), "cells_timing",
                               "usage: cells_timing [--full | --large] [--out DIR]\n", args))
        return 2;
    if (large) args.command += " --large";
    Report report("Certified cells against the build", "cells_timing", args.command);
    Table table("cells", {"set", "sites", "domain", "T", "bounded cells", "build s", "cells s", "cells / build",
                          "ms per bounded cell", "edges in doubles %", "edges with nodes in Arb %",
                          "edges from neighbours %", "pieces per edge", "failed disks per edge",
                          "nodes per edge", "cells peak MB"});
    if (large) {
        for (long n : {10000L, 100000L})
            for (double T : {1e-9, 1e-15}) {
                if (n > 10000 && T < 1e-9) continue;  // some eight hours
                table.add(measure(random_set(n), true, T));
                table.add(measure(packing_set(n), true, T));
            }
    } else {
        const CellSet random20 = random_set(20);
        table.add(measure(random20, false, 1e-9));
        for (double T : {1e-9, 1e-15, 1e-30}) table.add(measure(random20, true, T));
        table.add(measure(random20, true, 1e-9, true));
        table.add(measure(packing_set(30), true, 1e-9));
        table.add(measure(random_set(20, SiteKind::circles, Rational(1, 2)), true, 1e-9));
    }
    if (args.full && !large)
        for (long n : {100L, 1000L})
            for (double T : {1e-9, 1e-15}) {
                table.add(measure(random_set(n), true, T));
                table.add(measure(packing_set(n), true, T));
            }
    report.intro("CPU seconds, one run each. `build s`: the graph of the sites alone; `cells s`: "
                 "cell_tessellation (with a box: the graph of the sites and their mirror images across nearby walls, then every "
                 "original cell's area, perimeter, centroid and second moments certified to T; `+ rings`: "
                 "the rings too, at the default boundary tolerance, 10^-3 of the median semi-axis). `edges in "
                 "doubles`: the share of the cells' edges integrated by the double-interval stage "
                 "(cells/edge_quadrature.hpp, goals up to 44 bits), `with nodes in Arb` by its pieces with the nodes "
                 "evaluated in Arb (beyond 44 bits), the rest by Arb's integrator (shares of the edges a cell "
                 "integrated itself); `edges from neighbours`: the share of the cells' edges whose integrals the "
                 "neighbour's cell had made for both (docs/DESIGN.md §10); `pieces`, `failed disks` and "
                 "`nodes per edge`: the work of those two stages on each edge they integrated, the pieces it "
                 "integrated, the pieces whose complex disk it could not certify (then halved) and the density "
                 "nodes. Peak memory: " +
                 std::string(kPeakMemoryMethod) + ", here of one cell_tessellation.");
    report.table(table);
    report.publish(args.out_dir, large ? "cells_timing_large.md" : "cells_timing.md");
    return 0;
}
