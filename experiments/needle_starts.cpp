// Needles (docs/DESIGN.md §4.2, item 4): which start certifies the Voronoi
// circle of a triple with a needle, and whether the exhaustive search alone
// would have found the circles that only the needle chains start.
//
// Triples: a needle (major semi-axis 5, aspect 2^k, random rotation) at the
// origin, a long ellipse (minor 1/2 .. 3, major 100 .. 6100, as fuzz F7's
// 3 x 6310) and a small one (semi-axes 1/2 .. 3) around it, disjoint, seeded;
// both orientations when the count says the circle exists. Each circle is
// certified by VoronoiCircleSolver::certify (its `found_by`); each circle the
// chains started is asked again of the search alone, capped.
//
//   build/experiments/needle_starts                  # a short run: k = 28, 40, 8 triples each
//   build/experiments/needle_starts --full --out experiments/results
//       # k = 12, 20, 28, 36, 40, 40 triples each; writes needle_starts.md and .csv
#include "experiments/report.hpp"
#include "experiments/run_environment.hpp"
#include "predicates/relative_position.hpp"
#include "predicates/voronoi_circle_count.hpp"
#include "subdivision/voronoi_circle_enclosure.hpp"
#include "util/error.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <random>
#include <string>
#include <vector>

using namespace ellvor;
namespace ex = ellvor::experiments;

namespace {

constexpr long kSearchAloneBoxes = 50'000;

Rational dyadic(double x) { return Rational(static_cast<long>(std::llround(x * 1024)), 1024UL); }

struct Row {
    long aspect_bits = 0, triples = 0, circles = 0;
    long by_start[5] = {0, 0, 0, 0, 0};  // CircleStart order
    long errors = 0;
    double slowest = 0;
    long chain_circles = 0, search_alone_found = 0, search_alone_capped = 0;
    double search_alone_seconds = 0;
};

double seconds_since(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

Row run(long k, int triples, unsigned seed) {
    Row row;
    row.aspect_bits = k;
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0, 1);
    for (int n = 0; n < triples; ++n) {
        Rational minor(5);
        fmpq_div_2exp(minor.get(), minor.get(), static_cast<unsigned long>(k));
        const Ellipse needle(5, minor, dyadic(2 * u(rng) - 1), 0, 0);
        std::vector<Ellipse> others;
        while (others.size() < 2) {
            const bool long_one = others.empty();
            const double major = long_one ? 100 + 6000 * u(rng) : 0.5 + 2.5 * u(rng);
            const double distance = long_one ? major * (1 + 0.2 * u(rng)) + 3 : 6 + 6 * u(rng), angle = 2 * M_PI * u(rng);
            const Ellipse e(dyadic(0.5 + 2.5 * u(rng)), dyadic(major), dyadic(2 * u(rng) - 1),
                            dyadic(distance * std::cos(angle)), dyadic(distance * std::sin(angle)));
            bool apart = *relative_position(e, needle) == RelativePosition::separated;
            for (const Ellipse& o : others) apart = apart && *relative_position(e, o) == RelativePosition::separated;
            if (apart) others.push_back(e);
        }
        ++row.triples;
        for (int orientation = 0; orientation < 2; ++orientation) {
            const Ellipse &b = others[orientation], &c = others[1 - orientation];
            const VoronoiCircles count = *voronoi_circle_count(needle, b, c);
            if (count == VoronoiCircles::none || count == VoronoiCircles::cw_only) continue;
            ++row.circles;
            const auto start = std::chrono::steady_clock::now();
            VoronoiCircleSolver solver(needle, b, c);
            try {
                solver.certify();
                ++row.by_start[static_cast<int>(solver.enclosure().found_by)];
            } catch (const Error&) {
                ++row.errors;
            }
            row.slowest = std::max(row.slowest, seconds_since(start));
            if (!solver.certified() || solver.enclosure().found_by != CircleStart::needle_chain) continue;
            ++row.chain_circles;
            VoronoiCircleSolver alone(needle, b, c);
            VoronoiCircleSearchOptions capped;
            capped.max_boxes = kSearchAloneBoxes;
            const auto search_start = std::chrono::steady_clock::now();
            try {
                if (alone.certify_by_search(capped)) ++row.search_alone_found;
            } catch (const Error&) {
                ++row.search_alone_capped;
            }
            row.search_alone_seconds += seconds_since(search_start);
        }
    }
    return row;
}

}  // namespace

int main(int argc, char** argv) {
    ex::BenchArguments args;
    if (!ex::parse_bench_arguments(argc, argv, "needle_starts",
                                   "usage: needle_starts [--full] [--out DIR]\n"
                                   "  --full     k = 12, 20, 28, 36, 40, 40 triples each (default: 28 and 40, 8 each)\n"
                                   "  --out DIR  write DIR/needle_starts.csv and .md\n",
                                   args))
        return 2;
    const std::vector<long> aspects = args.full ? std::vector<long>{12, 20, 28, 36, 40} : std::vector<long>{28, 40};
    const int triples = args.full ? 40 : 8;
    ex::Report report("Needles: which start certifies the Voronoi circle", "needle_starts", args.command);
    ex::Table table("needle_starts",
                    {"aspect", "triples", "circles", "guess", "tangent line", "near copy", "needle chain", "search",
                     "errors", "slowest (s)", "chain circles: search alone found", "capped", "search alone (s)"},
                    "rrrrrrrrrrrrr");
    bool failed = false;
    for (long k : aspects) {
        const Row r = run(k, triples, 3);
        std::cerr << "[needle_starts] 2^" << k << ": " << r.circles << " circles, " << r.by_start[3] << " by the chains, "
                  << r.errors << " errors\n";
        failed = failed || r.errors > 0;
        table.add({"2^" + std::to_string(k), ex::integer(r.triples), ex::integer(r.circles), ex::integer(r.by_start[0]),
                   ex::integer(r.by_start[1]), ex::integer(r.by_start[2]), ex::integer(r.by_start[3]),
                   ex::integer(r.by_start[4]), ex::integer(r.errors), ex::fmt("%.3f", r.slowest),
                   std::to_string(r.search_alone_found) + " of " + std::to_string(r.chain_circles),
                   ex::integer(r.search_alone_capped), ex::fmt("%.1f", r.search_alone_seconds)});
    }
    report.intro("A needle (major semi-axis 5, aspect 2^k, random rotation) at the origin, a long ellipse (minor "
                 "1/2 .. 3, major 100 .. 6100, as fuzz F7's 3 x 6310) and a small one around it, disjoint, seeded; "
                 "both orientations where the count says the circle exists. Columns: the start that certified each "
                 "circle (VoronoiCircleSolver's `found_by`, docs/DESIGN.md §4.2), the slowest certificate, and for "
                 "the circles only the needle chains started, the search alone capped at " +
                 std::to_string(kSearchAloneBoxes) + " boxes (found, capped, its total time).");
    report.machine_note("shared with other jobs");
    report.table(table);
    report.publish(args.out_dir, "needle_starts.md", {{"needle_starts.csv", table.csv()}});
    return failed ? 1 : 0;
}
