// Random ellipses against random circles of the same count, one build each:
// CPU seconds of DelaunayGraph::insert_all (site generation not timed), their
// ratio, and the predicate calls by stage. The sets are build_scaling's
// (ellipses: generate_sites(ellipses, seed 1, bits 8, box 100); circles:
// generate_sites(circles, seed 1, bits 1, box 256 ceil(sqrt n)), dyadic), so
// the rows compare with experiments/results/build_scaling.md. For quick
// before/after measurements of the ellipse build (issue 24, item 3); CPU
// seconds, since the machine is shared (its load is printed).
//
//   build/experiments/ellipse_speed [--n N]...   (default n = 10^3 and 10^4: under a second, for make bench)
//   build/experiments/ellipse_speed --n 10000 --n 100000 --n 1000000   (experiments/results/ellipse_speed.md)
#include "decision/predicate_registry.hpp"
#include "experiments/run_environment.hpp"
#include "graph/delaunay_graph.hpp"
#include "sites/site_generators.hpp"
#include "traits/ellipse_delaunay_traits.hpp"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

using namespace ellvor;
using namespace ellvor::experiments;

namespace {

struct Build {
    double wall = 0, cpu = 0;
    std::string stages;  // "name calls (filter/subdivision/symmetry/exact)" per predicate
    std::string check;
};

Build build(const std::vector<Ellipse>& sites) {
    Build b;
    auto g = std::make_unique<DelaunayGraph>(std::make_unique<EllipseDelaunayTraits>(sites));
    const double w0 = now_wall(), c0 = now_cpu();
    g->insert_all();
    b.cpu = now_cpu() - c0, b.wall = now_wall() - w0;
    const TraitsStats& stats = g->predicate_stats();
    for (const PredicateInfo& p : kPredicates) {
        const PredicateCount& count = stats[p.predicate];
        if (!count.calls) continue;
        b.stages += std::string(b.stages.empty() ? "" : "; ") + p.name + " " + std::to_string(count.calls) + " (";
        for (std::size_t s = 0; s < kStages.size(); ++s)
            b.stages += (s ? "/" : "") + std::to_string(count.stages[kStages[s]]);
        b.stages += ")";
    }
    const std::string problem = sites.size() <= 100000 ? g->validate() : std::string("not run");
    b.check = problem.empty() ? "ok" : problem;
    return b;
}

std::vector<Ellipse> random_set(SiteKind kind, long n) {
    GeneratorOptions o;
    o.kind = kind;
    o.count = n;
    o.seed = 1;
    if (kind == SiteKind::circles) {
        o.bits = 1;
        o.box = Rational(256 * static_cast<long>(std::ceil(std::sqrt(static_cast<double>(n)))));
    }
    return generate_sites(o);
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<long> counts;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--help") || !std::strcmp(argv[i], "-h")) {
            std::cout << "usage: ellipse_speed [--n N]...\n"
                         "  --n N  a site count (repeatable; default 1000 and 10000)\n"
                         "Builds build_scaling's random ellipses and circles of each count once and prints\n"
                         "the CPU seconds of insert_all, their ratio and the predicate stages.\n";
            return 0;
        }
        if (!std::strcmp(argv[i], "--n") && i + 1 < argc) {
            counts.push_back(std::atol(argv[++i]));
            if (counts.back() < 1 || counts.back() > 10000000) {
                std::cerr << "ellipse_speed: --n must be in 1..10^7\n";
                return 2;
            }
            continue;
        }
        std::cerr << "ellipse_speed: unknown argument " << argv[i] << " (see --help)\n";
        return 2;
    }
    if (counts.empty()) counts = {1000, 10000};
    std::cout << "machine: " << cpu_model() << "; source: " << source_state() << "\n";
    std::cout << "| n | ellipses CPU s (wall) | µs / insertion | circles CPU s (wall) | ellipses / circles | load before / after | validate |\n"
                 "|---:|---:|---:|---:|---:|---|---|\n";
    for (long n : counts) {
        const std::string before = loadavg();
        const Build e = build(random_set(SiteKind::ellipses, n));
        const Build c = build(random_set(SiteKind::circles, n));
        std::printf("| %ld | %.3g (%.3g) | %.0f | %.3g (%.3g) | %.2f× | %s / %s | %s, %s |\n", n, e.cpu, e.wall,
                    1e6 * e.cpu / n, c.cpu, c.wall, e.cpu / c.cpu, before.c_str(), loadavg().c_str(), e.check.c_str(),
                    c.check.c_str());
        std::printf("  ellipses n = %ld: %s\n  circles n = %ld: %s\n", n, e.stages.c_str(), n, c.stages.c_str());
        std::fflush(stdout);
    }
    return 0;
}
