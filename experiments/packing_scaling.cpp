// Dense packings against sparse random ellipses: build time per
// insertion, the stage shares of kappa4 (finite edges) and is_hidden, and
// peak memory, in the same run.
//
// For every n:
//   packing-1e-3  generate_packing(n, packing fraction 0.58, gap 1/1000, aspect 1..4, seed 1)
//   packing-1e-6  the same with gap 10^-6 (n <= 10^4)
//   ellipses      generate_sites(ellipses, n, seed 1, bits 8, box 100): `ellvor generate ellipses`
// DelaunayGraph::insert_all on each (CPU time of the build only, median of
// repeated builds below 0.3 s); validate() up to 10^4 sites; the calls of
// every predicate by deciding stage (filter / subdivision / symmetry / exact); the
// generation time of the packings; peak memory of one build in a forked child
// (peak_memory.hpp: the child's VmHWM minus its RSS at the fork, the sites
// already made).
//
//   build/experiments/packing_scaling                 # n = 2000 (make bench)
//   build/experiments/packing_scaling --full --out experiments/results
//       # adds n = 10^4 and 10^5; writes packing_scaling.md
//
// An invalid graph or an exception is printed as an ANOMALY and makes the
// program exit with status 1.
#include "experiments/peak_memory.hpp"
#include "experiments/predicate_stages.hpp"
#include "experiments/report.hpp"
#include "experiments/run_environment.hpp"
#include "graph/delaunay_graph.hpp"
#include "traits/ellipse_delaunay_traits.hpp"
#include "sites/packing_generator.hpp"
#include "sites/site_generators.hpp"
#include "util/error.hpp"

#include <cstdio>
#include <ctime>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

using namespace ellvor;
using namespace ellvor::experiments;

namespace {

std::string percent(const PredicateCount& p, Stage s) {
    return p.calls ? fmt("%.2f%%", 100.0 * static_cast<double>(p.stages[s]) / static_cast<double>(p.calls)) : "-";
}

struct Row {
    std::string set;
    long n = 0;
    double generate_s = 0;  // the packings' generation (wall)
    std::string fraction;   // reached (certified bounds), packings only
    Timing build;
    TraitsStats stats;
    std::string valid;
    long peak_kb = -1;
};

Row measure(const std::string& set, const std::vector<Ellipse>& sites, double generate_s, std::string fraction,
            bool validate) {
    Row r;
    r.set = set;
    r.n = static_cast<long>(sites.size());
    r.generate_s = generate_s;
    r.fraction = std::move(fraction);
    const PeakMemory m = peak_memory_in_child([&] {
        DelaunayGraph g(std::make_unique<EllipseDelaunayTraits>(sites));
        g.insert_all();
    });
    if (m.error.empty() && m.peak_kb >= 0 && m.start_kb >= 0) r.peak_kb = m.peak_kb - m.start_kb;
    std::unique_ptr<DelaunayGraph> kept;
    r.build = timed_runs([&] {
        kept = std::make_unique<DelaunayGraph>(std::make_unique<EllipseDelaunayTraits>(sites));
        kept->insert_all();
    });
    r.stats = kept->predicate_stats();
    r.valid = validate ? (kept->validate().empty() ? "valid" : "INVALID") : "not checked";
    return r;
}

Table build_table(const std::vector<Row>& rows) {
    Table table("builds", {"set", "n", "fraction reached", "generate (s)", "build CPU (s)", "reps", "per insertion (us)",
                           "vs ellipses", "peak memory (MB)", "kappa4 finite exact", "is_hidden exact", "graph"},
                "lrlrrrrrrrrl");
    for (const Row& r : rows) {
        double sparse = 0;
        for (const Row& s : rows)
            if (s.set == "ellipses" && s.n == r.n) sparse = s.build.cpu;
        table.add({r.set, integer(r.n), r.fraction.empty() ? "-" : r.fraction,
                   r.set == "ellipses" ? "-" : fmt("%.2f", r.generate_s), fmt("%.3f", r.build.cpu),
                   integer(r.build.reps), fmt("%.1f", 1e6 * r.build.cpu / static_cast<double>(r.n)),
                   sparse > 0 ? fmt("%.2fx", r.build.cpu / sparse) : "-",
                   r.peak_kb >= 0 ? fmt("%.1f", r.peak_kb / 1024.0) : "-",
                   percent(r.stats[Predicate::finite_edge_interior_conflict], Stage::exact),
                   percent(r.stats[Predicate::is_hidden], Stage::exact), r.valid});
    }
    return table;
}

Table predicate_table(const std::vector<Row>& rows) {
    Table table = predicate_stage_table("predicates", {"set", "n"});
    for (const Row& r : rows) add_predicate_stage_row(table, {r.set, integer(r.n)}, r.stats);
    return table;
}

}  // namespace

int main(int argc, char** argv) {
    BenchArguments args;
    if (!parse_bench_arguments(argc, argv, "packing_scaling", "usage: packing_scaling [--full] [--out DIR]\n", args))
        return 2;
    std::vector<long> sizes = {2000};
    if (args.full) sizes.insert(sizes.end(), {10000, 100000});
    Report report("Dense packings against sparse random ellipses", "packing_scaling", args.command);
    std::vector<Row> rows;
    bool anomaly = false;
    for (long n : sizes) {
        try {
            for (const Rational& gap : {Rational(1, 1000), Rational(1, 1000000)}) {
                if (n > 10000 && gap < Rational(1, 1000)) continue;
                PackingOptions o;
                o.count = n;
                o.fraction = Rational(58, 100);
                o.gap = gap;
                o.seed = 1;
                const double w0 = now_wall();
                const Packing p = generate_packing(o);
                const double generate_s = now_wall() - w0;
                rows.push_back(measure(gap == Rational(1, 1000) ? "packing-1e-3" : "packing-1e-6", p.sites, generate_s,
                                       fraction_bounds_text(p), n <= 10000));
                std::cerr << rows.back().set << " " << n << " done\n";
            }
            GeneratorOptions g;
            g.count = n;
            g.seed = 1;
            rows.push_back(measure("ellipses", generate_sites(g), 0, "", n <= 10000));
            std::cerr << "ellipses " << n << " done\n";
        } catch (const std::exception& e) {
            std::cout << "ANOMALY: n = " << n << ": " << e.what() << "\n";
            anomaly = true;
        }
    }

    for (const Row& r : rows)
        if (r.valid == "INVALID") {
            std::cout << "ANOMALY: " << r.set << " " << r.n << ": invalid graph\n";
            anomaly = true;
        }
    report.intro("packing-G: `ellvor generate packing --count n --packing-fraction 0.58 --gap G --seed 1` (aspect "
                 "1..4); ellipses: `ellvor generate ellipses --count n --seed 1`. Build: DelaunayGraph::insert_all, "
                 "CPU time of the build only (median of `reps` builds); per insertion = build / n. Stages: the share "
                 "of the calls decided by the exact stage.");
    report.note(std::string("Peak memory: ") + kPeakMemoryMethod);
    report.machine_note("shared with other jobs: compare CPU seconds");
    report.heading("Builds");
    report.table(build_table(rows));
    report.heading("Predicate calls per stage");
    report.table(predicate_table(rows), "calls (filter / subdivision / symmetry / exact); memoized answers are not counted.");
    report.publish(args.out_dir, "packing_scaling.md");
    return anomaly ? 1 : 0;
}
