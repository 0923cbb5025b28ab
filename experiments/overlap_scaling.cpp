// Build time and peak memory on crossing circles against disjoint ones of the
// same size, ellvor and CGAL's Apollonius_graph_hierarchy_2 in one run.
//
// For every n (10^2 and 10^3 by default; 10^3, 10^4 and 10^5 with --full) two sets:
//   disjoint  generate_sites(circles, seed 1, bits 1, box 256 ceil(sqrt n)): build_scaling's circles
//   overlap   the same with crossing fraction 3/10: exactly 30% of the circles cross another; the
//             generator's grid and radii are those of the disjoint set, and 85% of its circles are
//             the disjoint set's first ones (the other 15% are the partners that cross them)
// Every number is a multiple of 1/2 below 2^20, hence exact in double, so CGAL's
// Apollonius_graph_hierarchy_2 with Apollonius_graph_filtered_traits_2<Epick> (bulk
// insertion) sees the same circles. Reported: CPU time of the build (ellvor's
// DelaunayGraph::insert_all, CGAL's insert), the ratios overlap / disjoint and
// ellvor / CGAL; peak memory the same way. The target for overlapping
// ellipses (later) is an overlapping build within 2x of a disjoint set of the
// same size; the summary says whether circles meet it. Beside them, the CPU
// time of relative_position alone on the crossing pairs (the exact stage
// decides every crossing pair), against the overlap set's extra build time.
//
// Checks: the crossing sites are counted exactly (circles_cross) and must be
// round(0.3 n); ellvor's graph passes validate() and equals CGAL's (visible
// sites, hidden pairs, finite edges as a multiset, hull) on every set; the edge
// counts of both are printed. A failure is an ANOMALY (exit status 1).
//
// Times: below 0.3 s a build is repeated (median, at most 20 runs). Peak memory:
// one more build of each in a forked child (peak_memory.hpp), before any other
// work of the program.
//
//   build/experiments/overlap_scaling                 # default (make bench): n = 10^2, 10^3, stdout only
//   build/experiments/overlap_scaling --full --out experiments/results   # 10^3 .. 10^5; overlap.csv, .md
#include "experiments/apollonius_comparison.hpp"
#include "experiments/peak_memory.hpp"
#include "experiments/predicate_stages.hpp"
#include "experiments/run_environment.hpp"
#include "graph/delaunay_graph.hpp"
#include "predicates/ellipse_delaunay_traits.hpp"
#include "predicates/relative_position.hpp"
#include "sites/site_generators.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <numeric>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

using namespace ellvor;
using namespace ellvor::experiments;

namespace {

const char* const kSets[] = {"disjoint", "overlap"};

std::string generator_set(const std::string& set) { return set == "overlap" ? "circles-cross30" : "circles"; }

std::string fmt(const char* f, double x) {
    char buf[64];
    std::snprintf(buf, sizeof buf, f, x);
    return buf;
}

// CPU seconds of relative_position (the exact stage: the intersection quartic)
// on the crossing pairs: what the graph's is_hidden pays for them once each.
double relative_position_seconds(const std::vector<Ellipse>& s, const std::vector<std::pair<SiteId, SiteId>>& pairs,
                                 int& anomalies) {
    long sum = 0;
    const double c0 = now_cpu();
    for (const auto& [i, j] : pairs) sum += static_cast<long>(*relative_position(s[i], s[j]));
    const double c1 = now_cpu();
    if (sum != static_cast<long>(pairs.size()) * static_cast<long>(RelativePosition::intersecting)) {
        std::cerr << "ANOMALY: relative_position does not find every crossing pair intersecting\n";
        ++anomalies;
    }
    return c1 - c0;
}

// Sites that cross at least one other, and the crossing pairs, exactly. Only
// pairs whose centers are within twice the largest radius in x and y can meet;
// the centers and radii are exact in double, so that window is found in doubles.
std::pair<long, std::vector<std::pair<SiteId, SiteId>>> crossings(const std::vector<Ellipse>& s) {
    double reach = 0;
    for (const Ellipse& e : s) reach = std::max(reach, 2 * e.a().to_double());
    std::vector<std::size_t> order(s.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return s[i].xc() < s[j].xc(); });
    std::vector<char> crosses(s.size(), 0);
    std::vector<std::pair<SiteId, SiteId>> pairs;
    for (std::size_t p = 0; p < order.size(); ++p) {
        const Ellipse& e = s[order[p]];
        const double x = e.xc().to_double(), y = e.yc().to_double();
        for (std::size_t q = p + 1; q < order.size(); ++q) {
            const Ellipse& f = s[order[q]];
            if (f.xc().to_double() - x > reach) break;
            if (std::fabs(f.yc().to_double() - y) > reach || !circles_cross(e, f)) continue;
            crosses[order[p]] = crosses[order[q]] = 1;
            pairs.push_back({order[p], order[q]});
        }
    }
    return {static_cast<long>(std::count(crosses.begin(), crosses.end(), 1)), pairs};
}

struct Row {
    std::string library, set;  // library: ellvor, cgal; set: disjoint, overlap
    long n = 0;
    double seconds = 0, cpu_seconds = 0;
    int reps = 0;
    long crossing_sites = 0, crossing_pairs = 0;
    double relative_position_cpu = 0;  // relative_position on the crossing pairs, seconds
    std::size_t visible = 0, hidden = 0, edges = 0;
    std::string validate = "-", cgal = "-";  // "ok", a problem, or "-" (not run)
    TraitsStats stats;                       // ellvor only
    PeakMemory memory;
    long memory_kb() const { return memory.peak_kb < 0 || memory.start_kb < 0 ? -1 : memory.peak_kb - memory.start_kb; }
};

std::string one_line(std::string s) {
    for (char& c : s)
        if (c == '\n' || c == ',' || c == '|') c = ' ';
    if (s.size() > 120) s = s.substr(0, 120) + "...";
    return s;
}

Row run_ellvor(const std::string& set, const std::vector<Ellipse>& sites, Summary& summary, int& anomalies) {
    Row r;
    r.library = "ellvor";
    r.set = set;
    r.n = static_cast<long>(sites.size());
    try {
        std::unique_ptr<DelaunayGraph> g;
        timed([&] {
            g = std::make_unique<DelaunayGraph>(std::make_unique<EllipseDelaunayTraits>(sites));
            g->insert_all();
        }, r.seconds, r.cpu_seconds, r.reps);
        r.visible = g->visible_sites().size();
        r.hidden = g->hidden().size();
        r.edges = g->edges().size();
        r.stats = g->predicate_stats();
        const std::string v = g->validate();
        r.validate = v.empty() ? "ok" : one_line(v);
        if (!v.empty()) {
            std::cerr << "ANOMALY: ellvor " << set << " n = " << r.n << ": validate: " << v << "\n";
            ++anomalies;
        }
        summary = summary_of(*g);
    } catch (const std::exception& e) {
        std::cerr << "ANOMALY: ellvor " << set << " n = " << r.n << ": " << e.what() << "\n";
        r.validate = std::string("exception: ") + one_line(e.what());
        ++anomalies;
    }
    return r;
}

Row run_cgal(const std::string& set, const std::vector<Ellipse>& sites, Summary& summary) {
    Row r;
    r.library = "cgal";
    r.set = set;
    r.n = static_cast<long>(sites.size());
    const std::vector<AG::Site_2> input = cgal_sites(sites);
    AGH ag;
    timed([&] {
        ag.clear();
        ag.insert(input.begin(), input.end());
    }, r.seconds, r.cpu_seconds, r.reps);
    summary = summary_of(ag, CgalSiteIds(input));
    r.visible = summary.visible.size();
    r.hidden = summary.hidden.size();
    r.edges = summary.edges.size();
    return r;
}

}  // namespace

int main(int argc, char** argv) {
    BenchArguments args;
    if (!parse_bench_arguments(argc, argv, "overlap_scaling",
                               "usage: overlap_scaling [--full] [--out DIR]\n"
                               "  --full     n = 10^3, 10^4 and 10^5 (about a minute) instead of 10^2, 10^3\n"
                               "  --out DIR  write DIR/overlap.csv and DIR/overlap.md\n",
                               args))
        return 2;
    const std::vector<long> ns = args.full ? std::vector<long>{1000, 10000, 100000} : std::vector<long>{100, 1000};

    const std::string load_before = loadavg();
    // Peak memory first, before this program has built anything: each build in
    // its own child, which generates its sites and then builds.
    std::map<std::tuple<std::string, std::string, long>, PeakMemory> memory;
    for (long n : ns) {
        for (const std::string set : kSets) {
            std::vector<Ellipse> sites;
            memory[{"ellvor", set, n}] = peak_memory_in_child([&] { sites = make_sites(generator_set(set), n); },
                                                              [&] {
                                                                  DelaunayGraph g(std::make_unique<EllipseDelaunayTraits>(sites));
                                                                  g.insert_all();
                                                              });
            std::vector<AG::Site_2> input;
            memory[{"cgal", set, n}] = peak_memory_in_child([&] { input = cgal_sites(make_sites(generator_set(set), n)); },
                                                            [&] {
                                                                AGH ag;
                                                                ag.insert(input.begin(), input.end());
                                                            });
        }
        std::cerr << "[overlap_scaling] peak memory measured, n = " << n << "\n";
    }

    std::vector<Row> rows;
    int anomalies = 0;
    for (long n : ns) {
        for (const std::string set : kSets) {
            std::vector<Ellipse> sites;
            try {
                sites = make_sites(generator_set(set), n);
            } catch (const std::exception& e) {
                std::cerr << "ANOMALY: cannot generate " << set << " n = " << n << ": " << e.what() << "\n";
                ++anomalies;
                continue;
            }
            const auto [crossing_sites, pairs] = crossings(sites);
            const long crossing_pairs = static_cast<long>(pairs.size());
            const double relative_position_cpu = relative_position_seconds(sites, pairs, anomalies);
            const long expected = set == "overlap" ? (3 * n + 5) / 10 : 0;  // round(0.3 n), halves up
            if (crossing_sites != expected) {
                std::cerr << "ANOMALY: " << set << " n = " << n << ": " << crossing_sites << " crossing sites, expected "
                          << expected << "\n";
                ++anomalies;
            }
            Summary mine, want;
            Row e = run_ellvor(set, sites, mine, anomalies);
            Row c = run_cgal(set, sites, want);
            for (Row* r : {&e, &c}) {
                r->crossing_sites = crossing_sites;
                r->crossing_pairs = crossing_pairs;
                r->relative_position_cpu = relative_position_cpu;
                r->memory = memory.at({r->library, set, n});
            }
            if (e.validate.rfind("exception", 0) != 0) {
                e.cgal = c.cgal = compare(mine, want);
                if (e.cgal != "ok") {
                    std::cerr << "ANOMALY: " << set << " n = " << n << ": ellvor differs from CGAL: " << e.cgal << "\n";
                    ++anomalies;
                }
            }
            std::cerr << "[overlap_scaling] " << set << " n = " << n << " (" << crossing_sites << " crossing sites, "
                      << crossing_pairs << " crossing pairs): ellvor " << fmt("%.4f", e.cpu_seconds) << " s cpu ("
                      << e.reps << " runs), " << e.edges << " edges, validate " << e.validate << "; CGAL "
                      << fmt("%.4f", c.cpu_seconds) << " s cpu (" << c.reps << " runs), " << c.edges
                      << " edges; graphs " << e.cgal << "\n";
            rows.push_back(e);
            rows.push_back(c);
        }
    }
    const std::string load_after = loadavg();

    auto find = [&](const std::string& library, const std::string& set, long n) -> const Row* {
        for (const Row& r : rows)
            if (r.library == library && r.set == set && r.n == n) return &r;
        return nullptr;
    };
    auto time_ratio = [](const Row* a, const Row* b) {
        return a && b && b->cpu_seconds > 0 ? fmt("%.2f×", a->cpu_seconds / b->cpu_seconds) : std::string("—");
    };
    auto memory_ratio = [](const Row* a, const Row* b) {
        return a && b && a->memory_kb() >= 0 && b->memory_kb() > 0 ? fmt("%.2f×", double(a->memory_kb()) / b->memory_kb())
                                                                    : std::string("—");
    };
    auto mb = [](const Row* r) { return r && r->memory_kb() >= 0 ? fmt("%.1f", r->memory_kb() / 1024.0) : std::string("—"); };
    auto secs = [](const Row* r) {
        return r ? fmt("%.3g", r->cpu_seconds) + " (" + fmt("%.3g", r->seconds) + ")" : std::string("—");
    };

    // CSV
    std::ostringstream csv;
    csv << "library,set,n,seconds,cpu_seconds,runs,crossing_sites,crossing_pairs,visible,hidden,edges";
    for (const PredicateColumn& p : kPredicateColumns)
        csv << "," << p.name << "_calls," << p.name << "_filter," << p.name << "_subdivision," << p.name << "_exact";
    csv << ",relative_position_cpu_seconds,validate,equals_cgal,peak_rss_growth_bytes\n";
    for (const Row& r : rows) {
        csv << r.library << "," << r.set << "," << r.n << "," << fmt("%.6g", r.seconds) << "," << fmt("%.6g", r.cpu_seconds)
            << "," << r.reps << "," << r.crossing_sites << "," << r.crossing_pairs << "," << r.visible << "," << r.hidden
            << "," << r.edges;
        for (const PredicateColumn& p : kPredicateColumns) {
            const PredicateCount& c = r.stats.*(p.field);
            if (r.library == "cgal")
                csv << ",,,,";
            else
                csv << "," << c.calls << "," << c.stages[Stage::filter] << "," << c.stages[Stage::subdivision] << ","
                    << c.stages[Stage::exact];
        }
        csv << "," << fmt("%.6g", r.relative_position_cpu) << "," << r.validate << "," << r.cgal << "," << (r.memory_kb() < 0 ? std::string() : std::to_string(r.memory_kb() * 1024))
            << "\n";
    }

    // Markdown
    std::ostringstream md;
    md << "# Crossing circles against disjoint ones\n\n"
       << "Build time and peak memory of the Delaunay graph (Apollonius graph) of n circles of which 30% cross "
          "another, against n disjoint circles from the same generator; ellvor and CGAL's "
          "`Apollonius_graph_hierarchy_2` in the same program. CPU time of the build only (site generation and "
          "checks excluded); below 0.3 s a build is repeated and the median taken (at most 20 runs).\n\n"
       << "- Machine: " << cpu_model() << " (shared with other jobs: compare CPU seconds)\n"
       << "- Load average before / after: " << load_before << " / " << load_after << "\n"
       << "- Source: " << source_state() << "\n"
       << "- Command: `make build/experiments/overlap_scaling && " << args.command << "`\n"
       << "- By default (`make bench`) n = 10^2 and 10^3 and nothing is written; `--full` runs n = 10^3, 10^4 and "
          "10^5, `--out DIR` writes `overlap.csv` and this file.\n\n"
       << "Site sets:\n\n"
       << "- **disjoint**: " << describe_set("circles") << " (build_scaling's circles)\n"
       << "- **overlap**: " << describe_set("circles-cross30")
       << ": exactly round(0.3 n) circles cross at least one other (counted exactly below); the same grid and radius "
          "range, and 85% of the circles are the disjoint set's first ones, the other 15% the partners drawn to cross "
          "them\n"
       << "- **CGAL**: the same circles in double (exact), bulk-inserted into `Apollonius_graph_hierarchy_2` over "
          "`Apollonius_graph_filtered_traits_2<Epick>`\n\n";

    md << "## Times\n\n| n | ellvor disjoint (s) | ellvor overlap (s) | ellvor overlap / disjoint | CGAL disjoint (s) | "
          "CGAL overlap (s) | CGAL overlap / disjoint | ellvor / CGAL, disjoint | ellvor / CGAL, overlap |\n"
          "|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (long n : ns) {
        const Row *ed = find("ellvor", "disjoint", n), *eo = find("ellvor", "overlap", n), *cd = find("cgal", "disjoint", n),
                  *co = find("cgal", "overlap", n);
        md << "| " << n << " | " << secs(ed) << " | " << secs(eo) << " | " << time_ratio(eo, ed) << " | " << secs(cd) << " | "
           << secs(co) << " | " << time_ratio(co, cd) << " | " << time_ratio(ed, cd) << " | " << time_ratio(eo, co) << " |\n";
    }
    md << "\nCPU seconds, wall seconds in parentheses; ratios on CPU time.\n\n";

    md << "## Peak memory\n\nOne more build each, in a child forked from this program before it builds anything "
          "else; the child generates its sites, then builds. The growth of the child's resident memory over the "
          "build (VmHWM after it minus VmRSS before it).\n\n"
          "| n | ellvor disjoint (MB) | ellvor overlap (MB) | ellvor overlap / disjoint | CGAL disjoint (MB) | "
          "CGAL overlap (MB) | ellvor / CGAL, disjoint | ellvor / CGAL, overlap |\n"
          "|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (long n : ns) {
        const Row *ed = find("ellvor", "disjoint", n), *eo = find("ellvor", "overlap", n), *cd = find("cgal", "disjoint", n),
                  *co = find("cgal", "overlap", n);
        md << "| " << n << " | " << mb(ed) << " | " << mb(eo) << " | " << memory_ratio(eo, ed) << " | " << mb(cd) << " | "
           << mb(co) << " | " << memory_ratio(ed, cd) << " | " << memory_ratio(eo, co) << " |\n";
    }
    md << "\n";

    md << "## Graphs and checks\n\n| set | n | crossing sites | crossing pairs | visible | hidden | edges, ellvor | "
          "edges, CGAL | validate() | equals CGAL |\n|---|---:|---:|---:|---:|---:|---:|---:|---|---|\n";
    for (long n : ns)
        for (const std::string set : kSets) {
            const Row *e = find("ellvor", set, n), *c = find("cgal", set, n);
            if (!e || !c) continue;
            md << "| " << set << " | " << n << " | " << e->crossing_sites << " | " << e->crossing_pairs << " | " << e->visible
               << " | " << e->hidden << " | " << e->edges << " | " << c->edges << " | " << e->validate << " | " << e->cgal
               << " |\n";
        }
    md << "\n\"equals CGAL\": the visible sites, the hidden pairs, the finite edges (as a multiset) and the hull.\n";

    md << "\n## Where ellvor's extra time goes\n\nThe overlap set's extra CPU time against the disjoint set, and "
          "the CPU time of `relative_position` alone (its exact stage, the intersection quartic: no filter decides a "
          "crossing pair) on the set's crossing pairs, which the graph's is_hidden meets about once each (see "
          "is_hidden's exact calls below).\n\n"
          "| n | crossing pairs | extra build time (s) | relative_position on the crossing pairs (s) | µs a pair |\n"
          "|---:|---:|---:|---:|---:|\n";
    for (long n : ns) {
        const Row *ed = find("ellvor", "disjoint", n), *eo = find("ellvor", "overlap", n);
        if (!ed || !eo || eo->crossing_pairs == 0) continue;
        md << "| " << n << " | " << eo->crossing_pairs << " | " << fmt("%.3g", eo->cpu_seconds - ed->cpu_seconds) << " | "
           << fmt("%.3g", eo->relative_position_cpu) << " | "
           << fmt("%.1f", 1e6 * eo->relative_position_cpu / double(eo->crossing_pairs)) << " |\n";
    }

    md << "\n## Predicate calls per stage (ellvor)\n\ncalls (filter / subdivision / exact); memoized answers are not "
          "counted. is_hidden decides the relative position of the pairs the graph meets; kappa1 = side_of_bisector, "
          "kappa2 = infinite Voronoi vertex, kappa3 = InCircle, kappa4 = edge conflicts.\n\n| set | n |";
    for (const PredicateColumn& p : kPredicateColumns) md << " " << p.name << " |";
    md << "\n|---|---:|";
    for (std::size_t i = 0; i < sizeof kPredicateColumns / sizeof kPredicateColumns[0]; ++i) md << "---|";
    md << "\n";
    for (const Row& r : rows) {
        if (r.library != "ellvor") continue;
        md << "| " << r.set << " | " << r.n << " |";
        for (const PredicateColumn& p : kPredicateColumns) md << " " << stage_triple(r.stats.*(p.field)) << " |";
        md << "\n";
    }

    md << "\n## Target\n\nThe issue's target (for overlapping ellipses, later): an overlapping build within 2× of a "
          "disjoint set of the same size. On circles, ellvor:\n\n";
    for (long n : ns) {
        const Row *ed = find("ellvor", "disjoint", n), *eo = find("ellvor", "overlap", n);
        if (!ed || !eo || ed->cpu_seconds <= 0) continue;
        const double ratio = eo->cpu_seconds / ed->cpu_seconds;
        md << "- n = " << n << ": " << fmt("%.2f×", ratio) << " — " << (ratio <= 2 ? "met" : "MISSED") << "\n";
    }
    md << "\nAnomalies (wrong crossing count, invalid graph, disagreement with CGAL, exception): " << anomalies << ".\n";
    if (!args.full) md << "\nn = 10^4 and 10^5 skipped (run with --full).\n";

    std::cout << md.str();
    if (!args.out_dir.empty()) {
        std::ofstream(args.out_dir + "/overlap.csv") << csv.str();
        std::ofstream(args.out_dir + "/overlap.md") << md.str();
        std::cerr << "[overlap_scaling] wrote " << args.out_dir << "/overlap.{csv,md}\n";
    }
    return anomalies ? 1 : 0;
}
