// Build time and peak memory on crossing sites against disjoint ones of the
// same size: circles (ellvor and CGAL's Apollonius_graph_hierarchy_2 in one
// run), then ellipses (ellvor alone: no other program builds the Voronoi
// diagram of crossing ellipses).
//
// Circles. For every n (10^2 and 10^3 by default; 10^3, 10^4 and 10^5 with --full) two sets:
//   disjoint  generate_sites(circles, seed 1, bits 1, box 256 ceil(sqrt n)): build_scaling's circles
//   overlap   the same with crossing fraction 3/10: exactly 30% of the circles cross another; the
//             generator's grid and radii are those of the disjoint set, and 85% of its circles are
//             the disjoint set's first ones (the other 15% are the partners that cross them)
// Every number is a multiple of 1/2 below 2^20, hence exact in double, so CGAL's
// Apollonius_graph_hierarchy_2 with Apollonius_graph_filtered_traits_2<Epick> (bulk
// insertion) sees the same circles. Reported: CPU time of the build (ellvor's
// DelaunayGraph::insert_all, CGAL's insert), the ratios overlap / disjoint and
// ellvor / CGAL; peak memory the same way. Beside them, the CPU time of
// relative_position alone on the crossing pairs (the exact stage decides every
// crossing pair), against the overlap set's extra build time.
//
// Ellipses. For n = 10^3 (seed 1) by default; with --full n = 10^3 (seed 1),
// 10^4 and 10^5 (seeds 1, 2, 3 each), two sets of the library's generator,
// the same as `ellvor generate ellipses --count n --seed S [--crossing 0.3]`:
//   disjoint  generate_sites(ellipses, seed S, bits 8, box 100): build_scaling's ellipses (F = 0)
//   overlap   the same with crossing fraction 3/10 (F = 0.3): exactly 30% of the ellipses cross
//             another in two points, thin and fat, deep and shallow; the other sites are the
//             disjoint set's first separated ones
// Reported: CPU time of DelaunayGraph::insert_all (at least 3 runs, median) and
// peak memory (as for circles), the ratios F = 0.3 / F = 0; the graph's
// statistics (sites hidden by a union, insertions searched over the whole
// graph) and the predicate calls per deciding stage, which explain the cost;
// relative_position alone on the crossing pairs. The target: an overlapping
// build within 2x of a disjoint set of the same size, 10^4 sites.
//
// Checks: the crossing sites are counted exactly (sites_cross) and must be
// round(0.3 n); ellvor's graph passes validate() on every set, and on circles
// equals CGAL's (visible sites, hidden pairs, finite edges as a multiset, hull);
// the edge counts are printed. A failure is an ANOMALY (exit status 1).
//
// Times: below 0.3 s a build is repeated (median, at most 20 runs; ellipses at
// least 3 runs). Peak memory: one more build of each in a forked child
// (peak_memory.hpp), before any other work of the program.
//
//   build/experiments/overlap_scaling                 # default (make bench): circles 10^2, 10^3, ellipses 10^3; stdout only
//   build/experiments/overlap_scaling --full --out experiments/results   # overlap.csv, .md
//   build/experiments/overlap_scaling [--full] --only circles|ellipses   # one part, stdout only
#include "experiments/apollonius_comparison.hpp"
#include "experiments/peak_memory.hpp"
#include "experiments/predicate_stages.hpp"
#include "experiments/report.hpp"
#include "experiments/run_environment.hpp"
#include "graph/delaunay_graph.hpp"
#include "traits/ellipse_delaunay_traits.hpp"
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

// Sites that cross at least one other, and the crossing pairs, exactly
// (sites_cross: circles_cross for two circles, the intersection quartic for
// ellipses). Only pairs whose centers are within twice the largest semi-axis in
// x and y can meet (with a margin for the rounding of ellipses' rationals to
// double; circles' data are exact in double), and only pairs whose bounding
// circles meet (exact).
std::pair<long, std::vector<std::pair<SiteId, SiteId>>> crossings(const std::vector<Ellipse>& s) {
    double reach = 0;
    for (const Ellipse& e : s) reach = std::max(reach, 2 * std::max(e.a().to_double(), e.b().to_double()));
    reach = reach * (1 + 1e-9) + 1e-9;
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
            if (std::fabs(f.yc().to_double() - y) > reach || bounding_circles_separated(e, f) || !sites_cross(e, f))
                continue;
            crosses[order[p]] = crosses[order[q]] = 1;
            pairs.push_back({order[p], order[q]});
        }
    }
    return {static_cast<long>(std::count(crosses.begin(), crosses.end(), 1)), pairs};
}

struct Row {
    std::string library, set;  // library: ellvor, cgal; set: disjoint, overlap
    std::string sites = "circles";  // circles, ellipses
    std::uint64_t seed = 1;
    long n = 0;
    double seconds = 0, cpu_seconds = 0, cpu_min = 0, cpu_max = 0;  // medians; the fastest and slowest run (CPU)
    int reps = 0;
    long crossing_sites = 0, crossing_pairs = 0;
    double relative_position_cpu = 0;  // relative_position on the crossing pairs, seconds
    std::size_t visible = 0, hidden = 0, edges = 0;
    std::string validate = "-", cgal = "-";  // "ok", a problem, or "-" (not run)
    TraitsStats stats;                       // ellvor only
    GraphStats graph;                        // ellvor only
    PeakMemory memory;
    long memory_kb() const { return memory.peak_kb < 0 || memory.start_kb < 0 ? -1 : memory.peak_kb - memory.start_kb; }
};


void set_timing(Row& r, const Timing& t) {
    r.seconds = t.wall;
    r.cpu_seconds = t.cpu;
    r.cpu_min = t.cpu_min;
    r.cpu_max = t.cpu_max;
    r.reps = t.reps;
}

Row run_ellvor(const std::string& set, const std::vector<Ellipse>& sites, Summary& summary, int& anomalies,
               const std::string& kind = "circles", std::uint64_t seed = 1, int min_reps = 1) {
    Row r;
    r.library = "ellvor";
    r.set = set;
    r.sites = kind;
    r.seed = seed;
    r.n = static_cast<long>(sites.size());
    try {
        std::unique_ptr<DelaunayGraph> g;
        set_timing(r, timed_runs(
                          [&] {
                              g = std::make_unique<DelaunayGraph>(std::make_unique<EllipseDelaunayTraits>(sites));
                              g->insert_all();
                          },
                          min_reps));
        r.visible = g->visible_sites().size();
        r.hidden = g->hidden().size();
        r.edges = g->edges().size();
        r.stats = g->predicate_stats();
        r.graph = g->stats();
        const std::string v = g->validate();
        r.validate = v.empty() ? "ok" : check_message(v);
        if (!v.empty()) {
            std::cerr << "ANOMALY: ellvor " << kind << " " << set << " n = " << r.n << ": validate: " << v << "\n";
            ++anomalies;
        }
        summary = summary_of(*g);
    } catch (const std::exception& e) {
        std::cerr << "ANOMALY: ellvor " << kind << " " << set << " n = " << r.n << ": " << e.what() << "\n";
        r.validate = std::string("exception: ") + check_message(e.what());
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
    set_timing(r, timed_runs([&] {
                      ag.clear();
                      ag.insert(input.begin(), input.end());
                  }));
    summary = summary_of(ag, CgalSiteIds(input));
    r.visible = summary.visible.size();
    r.hidden = summary.hidden.size();
    r.edges = summary.edges.size();
    return r;
}

// "24.0 GiB RAM, Debian GNU/Linux 12 (bookworm)": /proc/meminfo and /etc/os-release.
std::string machine_memory_and_os() {
    std::string out;
    {
        std::ifstream in("/proc/meminfo");
        std::string key;
        long kb = 0;
        while (in >> key >> kb)
            if (key == "MemTotal:") {
                out = fmt("%.1f GiB RAM", kb / 1048576.0);
                break;
            } else
                in.ignore(1 << 20, '\n');
    }
    std::ifstream in("/etc/os-release");
    std::string line;
    while (std::getline(in, line))
        if (line.rfind("PRETTY_NAME=", 0) == 0) {
            std::string name = line.substr(12);
            name.erase(std::remove(name.begin(), name.end(), '"'), name.end());
            out += (out.empty() ? "" : ", ") + name;
        }
    return out.empty() ? "unknown" : out;
}

// The ellipse cases: (n, seed).
struct EllipseCase {
    long n;
    std::uint64_t seed;
};

std::string ellipse_set(const std::string& set) { return set == "overlap" ? "ellipses-cross30" : "ellipses"; }

// What is measured: circles at every n, ellipses at every (n, seed).
struct Plan {
    std::vector<long> ns;
    std::vector<EllipseCase> ecases;
};

constexpr int kEllipseMinReps = 3;

using MemoryKey = std::tuple<std::string, std::string, std::string, long, std::uint64_t>;  // library, sites, set, n, seed

// Peak memory first, before this program has built anything: each build in
// its own child, which generates its sites and then builds.
std::map<MemoryKey, PeakMemory> measure_peak_memory(const Plan& plan) {
    std::map<MemoryKey, PeakMemory> memory;
    for (long n : plan.ns) {
        for (const std::string set : kSets) {
            std::vector<Ellipse> sites;
            memory[{"ellvor", "circles", set, n, 1}] =
                peak_memory_in_child([&] { sites = make_sites(generator_set(set), n); },
                                     [&] {
                                         DelaunayGraph g(std::make_unique<EllipseDelaunayTraits>(sites));
                                         g.insert_all();
                                     });
            // CGAL's child keeps the generated sites too, as ellvor's does:
            // both builds start from the same allocator state.
            std::vector<AG::Site_2> input;
            memory[{"cgal", "circles", set, n, 1}] =
                peak_memory_in_child([&] { sites = make_sites(generator_set(set), n), input = cgal_sites(sites); },
                                     [&] {
                                         AGH ag;
                                         ag.insert(input.begin(), input.end());
                                     });
        }
        std::cerr << "[overlap_scaling] peak memory measured, circles n = " << n << "\n";
    }
    for (const EllipseCase& c : plan.ecases) {
        for (const std::string set : kSets) {
            std::vector<Ellipse> sites;
            memory[{"ellvor", "ellipses", set, c.n, c.seed}] =
                peak_memory_in_child([&] { sites = make_sites(ellipse_set(set), c.n, c.seed); },
                                     [&] {
                                         DelaunayGraph g(std::make_unique<EllipseDelaunayTraits>(sites));
                                         g.insert_all();
                                     });
        }
        std::cerr << "[overlap_scaling] peak memory measured, ellipses n = " << c.n << " seed " << c.seed << "\n";
    }
    return memory;
}

// The crossing sites and pairs of a set (checked: round(0.3 n) for an
// overlap set, none otherwise) and relative_position's time on the pairs.
void count_crossings(const std::string& what, const std::string& set, long n, const std::vector<Ellipse>& sites,
                     Row& r, int& anomalies) {
    const auto [crossing_sites, pairs] = crossings(sites);
    r.crossing_sites = crossing_sites;
    r.crossing_pairs = static_cast<long>(pairs.size());
    r.relative_position_cpu = relative_position_seconds(sites, pairs, anomalies);
    const long expected = set == "overlap" ? (3 * n + 5) / 10 : 0;  // round(0.3 n), halves up
    if (crossing_sites != expected) {
        std::cerr << "ANOMALY: " << what << " " << set << " n = " << n << ": " << crossing_sites
                  << " crossing sites, expected " << expected << "\n";
        ++anomalies;
    }
}

// Circles: ellvor's and CGAL's builds of both sets at every n.
void measure_circles(const Plan& plan, const std::map<MemoryKey, PeakMemory>& memory, std::vector<Row>& rows,
                     int& anomalies) {
    for (long n : plan.ns) {
        for (const std::string set : kSets) {
            std::vector<Ellipse> sites;
            try {
                sites = make_sites(generator_set(set), n);
            } catch (const std::exception& e) {
                std::cerr << "ANOMALY: cannot generate circles " << set << " n = " << n << ": " << e.what() << "\n";
                ++anomalies;
                continue;
            }
            Row counts;
            count_crossings("circles", set, n, sites, counts, anomalies);
            Summary mine, want;
            Row e = run_ellvor(set, sites, mine, anomalies);
            Row c = run_cgal(set, sites, want);
            for (Row* r : {&e, &c}) {
                r->crossing_sites = counts.crossing_sites;
                r->crossing_pairs = counts.crossing_pairs;
                r->relative_position_cpu = counts.relative_position_cpu;
                r->memory = memory.at({r->library, "circles", set, n, 1});
            }
            if (e.validate.rfind("exception", 0) != 0) {
                e.cgal = c.cgal = compare(mine, want);
                if (e.cgal != "ok") {
                    std::cerr << "ANOMALY: " << set << " n = " << n << ": ellvor differs from CGAL: " << e.cgal << "\n";
                    ++anomalies;
                }
            }
            std::cerr << "[overlap_scaling] circles " << set << " n = " << n << " (" << e.crossing_sites
                      << " crossing sites, " << e.crossing_pairs << " crossing pairs): ellvor "
                      << fmt("%.4f", e.cpu_seconds) << " s cpu (" << e.reps << " runs), " << e.edges
                      << " edges, validate " << e.validate << "; CGAL " << fmt("%.4f", c.cpu_seconds) << " s cpu ("
                      << c.reps << " runs), " << c.edges << " edges; graphs " << e.cgal << "\n";
            rows.push_back(e);
            rows.push_back(c);
        }
    }
}

// Ellipses: ellvor's builds of both sets at every (n, seed).
void measure_ellipses(const Plan& plan, const std::map<MemoryKey, PeakMemory>& memory, std::vector<Row>& rows,
                      int& anomalies) {
    for (const EllipseCase& ec : plan.ecases) {
        for (const std::string set : kSets) {
            std::vector<Ellipse> sites;
            try {
                sites = make_sites(ellipse_set(set), ec.n, ec.seed);
            } catch (const std::exception& e) {
                std::cerr << "ANOMALY: cannot generate ellipses " << set << " n = " << ec.n << " seed " << ec.seed << ": "
                          << e.what() << "\n";
                ++anomalies;
                continue;
            }
            Row counts;
            count_crossings("ellipses", set, ec.n, sites, counts, anomalies);
            Summary mine;
            Row e = run_ellvor(set, sites, mine, anomalies, "ellipses", ec.seed, kEllipseMinReps);
            e.crossing_sites = counts.crossing_sites;
            e.crossing_pairs = counts.crossing_pairs;
            e.relative_position_cpu = counts.relative_position_cpu;
            e.memory = memory.at({"ellvor", "ellipses", set, ec.n, ec.seed});
            std::cerr << "[overlap_scaling] ellipses " << set << " n = " << ec.n << " seed " << ec.seed << " ("
                      << e.crossing_sites << " crossing sites, " << e.crossing_pairs << " crossing pairs): "
                      << fmt("%.4f", e.cpu_seconds) << " s cpu (" << e.reps << " runs, " << fmt("%.4f", e.cpu_min) << "–"
                      << fmt("%.4f", e.cpu_max) << "), " << e.edges << " edges, " << e.hidden << " hidden ("
                      << e.graph.union_hidden << " by a union), " << e.graph.global_searches
                      << " global searches, validate " << e.validate << "\n";
            rows.push_back(e);
        }
    }
}

// ------------------------------------------------------------------ tables --

const Row* find(const std::vector<Row>& rows, const std::string& library, const std::string& set, long n,
                const std::string& kind = "circles", std::uint64_t seed = 1) {
    for (const Row& r : rows)
        if (r.library == library && r.set == set && r.n == n && r.sites == kind && r.seed == seed) return &r;
    return nullptr;
}
std::string time_ratio(const Row* a, const Row* b) {
    return a && b && b->cpu_seconds > 0 ? fmt("%.2f×", a->cpu_seconds / b->cpu_seconds) : std::string("—");
}
std::string memory_ratio(const Row* a, const Row* b) {
    return a && b && a->memory_kb() >= 0 && b->memory_kb() > 0 ? fmt("%.2f×", double(a->memory_kb()) / b->memory_kb())
                                                                : std::string("—");
}
std::string mb(const Row* r) { return r && r->memory_kb() >= 0 ? fmt("%.1f", r->memory_kb() / 1024.0) : std::string("—"); }
std::string secs(const Row* r) {
    return r ? fmt("%.3g", r->cpu_seconds) + " (" + fmt("%.3g", r->seconds) + ")" : std::string("—");
}
std::string secs_spread(const Row* r) {
    return r ? fmt("%.3g", r->cpu_seconds) + " [" + fmt("%.3g", r->cpu_min) + "–" + fmt("%.3g", r->cpu_max) + ", " +
                   std::to_string(r->reps) + "]"
             : std::string("—");
}

// overlap.csv: every row.
Table csv_table(const std::vector<Row>& rows) {
    std::vector<std::string> columns = {"library", "sites", "set", "n", "seed", "seconds", "cpu_seconds",
                                        "cpu_min_seconds", "cpu_max_seconds", "runs", "crossing_sites",
                                        "crossing_pairs", "visible", "hidden", "edges"};
    const std::vector<std::string> predicate_columns = predicate_csv_columns();
    columns.insert(columns.end(), predicate_columns.begin(), predicate_columns.end());
    columns.insert(columns.end(), {"union_hidden", "hidden_on_insert", "global_searches", "conflict_faces", "walk_steps",
                                   "relative_position_cpu_seconds", "validate", "equals_cgal", "peak_rss_growth_bytes"});
    Table t("overlap", columns);
    for (const Row& r : rows) {
        const bool cgal = r.library == "cgal";
        TableRow row = {r.library, r.sites, r.set, integer(r.n), integer(static_cast<long long>(r.seed)),
                        fmt("%.6g", r.seconds), fmt("%.6g", r.cpu_seconds), fmt("%.6g", r.cpu_min),
                        fmt("%.6g", r.cpu_max), integer(r.reps), integer(r.crossing_sites), integer(r.crossing_pairs),
                        integer(static_cast<long long>(r.visible)), integer(static_cast<long long>(r.hidden)),
                        integer(static_cast<long long>(r.edges))};
        for (const std::string& v : predicate_csv_values(cgal ? nullptr : &r.stats)) row.push_back(v);
        if (cgal)
            row.insert(row.end(), {"", "", "", "", ""});
        else
            row.insert(row.end(), {std::to_string(r.graph.union_hidden), std::to_string(r.graph.hidden_on_insert),
                                   std::to_string(r.graph.global_searches), std::to_string(r.graph.conflict_faces),
                                   std::to_string(r.graph.walk_steps)});
        row.insert(row.end(), {fmt("%.6g", r.relative_position_cpu), r.validate, r.cgal,
                               r.memory_kb() < 0 ? std::string() : std::to_string(r.memory_kb() * 1024)});
        t.add(std::move(row));
    }
    return t;
}

Table circle_time_table(const std::vector<Row>& rows, const std::vector<long>& ns) {
    Table t("circle_times", {"n", "ellvor disjoint (s)", "ellvor overlap (s)", "ellvor overlap / disjoint",
                             "CGAL disjoint (s)", "CGAL overlap (s)", "CGAL overlap / disjoint",
                             "ellvor / CGAL, disjoint", "ellvor / CGAL, overlap"},
            std::string(9, 'r'));
    for (long n : ns) {
        const Row *ed = find(rows, "ellvor", "disjoint", n), *eo = find(rows, "ellvor", "overlap", n),
                  *cd = find(rows, "cgal", "disjoint", n), *co = find(rows, "cgal", "overlap", n);
        t.add({integer(n), secs(ed), secs(eo), time_ratio(eo, ed), secs(cd), secs(co), time_ratio(co, cd),
               time_ratio(ed, cd), time_ratio(eo, co)});
    }
    return t;
}

Table circle_memory_table(const std::vector<Row>& rows, const std::vector<long>& ns) {
    Table t("circle_memory", {"n", "ellvor disjoint (MB)", "ellvor overlap (MB)", "ellvor overlap / disjoint",
                              "CGAL disjoint (MB)", "CGAL overlap (MB)", "ellvor / CGAL, disjoint",
                              "ellvor / CGAL, overlap"},
            std::string(8, 'r'));
    for (long n : ns) {
        const Row *ed = find(rows, "ellvor", "disjoint", n), *eo = find(rows, "ellvor", "overlap", n),
                  *cd = find(rows, "cgal", "disjoint", n), *co = find(rows, "cgal", "overlap", n);
        t.add({integer(n), mb(ed), mb(eo), memory_ratio(eo, ed), mb(cd), mb(co), memory_ratio(ed, cd),
               memory_ratio(eo, co)});
    }
    return t;
}

Table circle_graph_table(const std::vector<Row>& rows, const std::vector<long>& ns) {
    Table t("circle_graphs", {"set", "n", "crossing sites", "crossing pairs", "visible", "hidden", "edges, ellvor",
                              "edges, CGAL", "validate()", "equals CGAL"},
            "lrrrrrrrll");
    for (long n : ns)
        for (const std::string set : kSets) {
            const Row *e = find(rows, "ellvor", set, n), *c = find(rows, "cgal", set, n);
            if (!e || !c) continue;
            t.add({set, integer(n), integer(e->crossing_sites), integer(e->crossing_pairs),
                   integer(static_cast<long long>(e->visible)), integer(static_cast<long long>(e->hidden)),
                   integer(static_cast<long long>(e->edges)), integer(static_cast<long long>(c->edges)), e->validate,
                   e->cgal});
        }
    return t;
}

Table circle_extra_time_table(const std::vector<Row>& rows, const std::vector<long>& ns) {
    Table t("circle_extra_time", {"n", "crossing pairs", "extra build time (s)",
                                  "relative_position on the crossing pairs (s)", "µs a pair"},
            std::string(5, 'r'));
    for (long n : ns) {
        const Row *ed = find(rows, "ellvor", "disjoint", n), *eo = find(rows, "ellvor", "overlap", n);
        if (!ed || !eo || eo->crossing_pairs == 0) continue;
        t.add({integer(n), integer(eo->crossing_pairs), fmt("%.3g", eo->cpu_seconds - ed->cpu_seconds),
               fmt("%.3g", eo->relative_position_cpu),
               fmt("%.1f", 1e6 * eo->relative_position_cpu / double(eo->crossing_pairs))});
    }
    return t;
}

// "0.3" or "0": the crossing fraction of a set.
std::string fraction(const std::string& set) { return set == "overlap" ? "0.3" : "0"; }

// Calls per stage of ellvor's graphs of one kind of site.
Table predicate_table(const std::vector<Row>& rows, const std::string& kind) {
    const bool ellipses = kind == "ellipses";
    Table t = predicate_stage_table(kind + "_predicates", ellipses ? std::vector<std::string>{"F", "n", "seed"}
                                                                   : std::vector<std::string>{"set", "n"});
    for (const Row& r : rows) {
        if (r.library != "ellvor" || r.sites != kind) continue;
        add_predicate_stage_row(t, ellipses ? TableRow{fraction(r.set), integer(r.n), integer(static_cast<long long>(r.seed))}
                                            : TableRow{r.set, integer(r.n)},
                                r.stats);
    }
    return t;
}

std::vector<Target> circle_targets(const std::vector<Row>& rows, const std::vector<long>& ns) {
    std::vector<Target> out;
    for (long n : ns) {
        const Row *ed = find(rows, "ellvor", "disjoint", n), *eo = find(rows, "ellvor", "overlap", n);
        if (!ed || !eo || ed->cpu_seconds <= 0) continue;
        const double ratio = eo->cpu_seconds / ed->cpu_seconds;
        out.push_back({"n = " + std::to_string(n), fmt("%.2f×", ratio), ratio <= 2});
    }
    return out;
}

Table ellipse_time_table(const std::vector<Row>& rows, const std::vector<EllipseCase>& ecases) {
    Table t("ellipse_times", {"n", "seed", "F = 0 (s)", "F = 0.3 (s)", "time F = 0.3 / F = 0", "F = 0 (MB)",
                              "F = 0.3 (MB)", "memory F = 0.3 / F = 0"},
            std::string(8, 'r'));
    for (const EllipseCase& c : ecases) {
        const Row *d = find(rows, "ellvor", "disjoint", c.n, "ellipses", c.seed),
                  *o = find(rows, "ellvor", "overlap", c.n, "ellipses", c.seed);
        t.add({integer(c.n), integer(static_cast<long long>(c.seed)), secs_spread(d), secs_spread(o), time_ratio(o, d),
               mb(d), mb(o), memory_ratio(o, d)});
    }
    return t;
}

Table ellipse_graph_table(const std::vector<Row>& rows, const std::vector<EllipseCase>& ecases) {
    Table t("ellipse_graphs", {"F", "n", "seed", "crossing sites", "crossing pairs", "visible", "hidden", "union-hidden",
                               "global searches", "edges", "conflict faces", "walk steps", "validate()"},
            "lrrrrrrrrrrrl");
    for (const EllipseCase& c : ecases)
        for (const std::string set : kSets) {
            const Row* r = find(rows, "ellvor", set, c.n, "ellipses", c.seed);
            if (!r) continue;
            t.add({fraction(set), integer(c.n), integer(static_cast<long long>(c.seed)), integer(r->crossing_sites),
                   integer(r->crossing_pairs), integer(static_cast<long long>(r->visible)),
                   integer(static_cast<long long>(r->hidden)), integer(static_cast<long long>(r->graph.union_hidden)),
                   integer(static_cast<long long>(r->graph.global_searches)), integer(static_cast<long long>(r->edges)),
                   integer(static_cast<long long>(r->graph.conflict_faces)),
                   integer(static_cast<long long>(r->graph.walk_steps)), r->validate});
        }
    return t;
}

// Calls decided past the filter (subdivision + exact), all predicates.
long past_filter(const Row& r) {
    long k = 0;
    for (const PredicateInfo& p : kPredicates) {
        const PredicateCount& c = r.stats[p.predicate];
        k += static_cast<long>(c.stages.total() - c.stages[Stage::filter]);
    }
    return k;
}

Table ellipse_extra_time_table(const std::vector<Row>& rows, const std::vector<EllipseCase>& ecases) {
    Table t("ellipse_extra_time", {"n", "seed", "crossing pairs", "extra build time (s)",
                                   "relative_position on the crossing pairs (s)", "µs a pair",
                                   "extra calls past the filter"},
            std::string(7, 'r'));
    for (const EllipseCase& c : ecases) {
        const Row *d = find(rows, "ellvor", "disjoint", c.n, "ellipses", c.seed),
                  *o = find(rows, "ellvor", "overlap", c.n, "ellipses", c.seed);
        if (!d || !o || o->crossing_pairs == 0) continue;
        t.add({integer(c.n), integer(static_cast<long long>(c.seed)), integer(o->crossing_pairs),
               fmt("%.3g", o->cpu_seconds - d->cpu_seconds), fmt("%.3g", o->relative_position_cpu),
               fmt("%.1f", 1e6 * o->relative_position_cpu / double(o->crossing_pairs)),
               integer(past_filter(*o) - past_filter(*d))});
    }
    return t;
}

std::string ellipse_target_lines(const std::vector<Row>& rows, const std::vector<EllipseCase>& ecases) {
    std::string md;
    for (const EllipseCase& c : ecases) {
        const Row *d = find(rows, "ellvor", "disjoint", c.n, "ellipses", c.seed),
                  *o = find(rows, "ellvor", "overlap", c.n, "ellipses", c.seed);
        if (!d || !o || d->cpu_seconds <= 0) continue;
        const double ratio = o->cpu_seconds / d->cpu_seconds;
        md += "- n = " + std::to_string(c.n) + ", seed " + std::to_string(c.seed) + ": " + fmt("%.2f×", ratio) + " — " +
              (ratio <= 2 ? "met" : "MISSED") + "; memory " + memory_ratio(o, d) + "\n";
    }
    return md;
}

void report_circles(Report& report, const std::vector<Row>& rows, const std::vector<long>& ns, bool full) {
    report.text("\nSite sets (circles):\n\n"
                "- **disjoint**: " + describe_set("circles") + " (build_scaling's circles)\n"
                "- **overlap**: " + describe_set("circles-cross30") +
                ": exactly round(0.3 n) circles cross at least one other (counted exactly below); the same grid and "
                "radius range, and 85% of the circles are the disjoint set's first ones, the other 15% the partners "
                "drawn to cross them\n"
                "- **CGAL**: the same circles in double (exact), bulk-inserted into `Apollonius_graph_hierarchy_2` over "
                "`Apollonius_graph_filtered_traits_2<Epick>`\n");

    report.heading("Times");
    report.table(circle_time_table(rows, ns));
    report.text("\nCPU seconds, wall seconds in parentheses; ratios on CPU time.\n");

    report.heading("Peak memory");
    report.table(circle_memory_table(rows, ns), std::string(kPeakMemoryMethod) + ".");

    report.heading("Graphs and checks");
    report.table(circle_graph_table(rows, ns));
    report.text("\n\"equals CGAL\": the visible sites, the hidden pairs, the finite edges (as a multiset) and the "
                "hull.\n");

    report.heading("Where ellvor's extra time goes");
    report.table(circle_extra_time_table(rows, ns),
                 "The overlap set's extra CPU time against the disjoint set, and the CPU time of `relative_position` "
                 "alone (for two circles a closed form: no filter decides a crossing pair) on the set's crossing "
                 "pairs, which the graph's is_hidden meets about once each.");

    report.heading("Predicate calls per stage (ellvor)");
    report.table(predicate_table(rows, "circles"),
                 "calls (filter / subdivision / symmetry / exact); memoized answers are not counted. is_hidden decides the "
                 "relative position of the pairs the graph meets.");

    report.heading("Target");
    report.text("An overlapping build within 2× of a disjoint set of the same size. On circles, ellvor:\n\n" +
                target_lines(circle_targets(rows, ns)) +
                (full ? "" : "\nCircles: n = 10^4 and 10^5 skipped (run with --full).\n"));
}

void report_ellipses(Report& report, const std::vector<Row>& rows, const std::vector<EllipseCase>& ecases, bool full) {
    report.heading("Crossing ellipses");
    report.text("Site sets, for each n and seed S (`ellvor generate ellipses --count n --seed S`, and the same with "
                "`--crossing 0.3`):\n\n"
                "- **F = 0** (disjoint): generate_sites(ellipses, seed S, bits 8, box 100) — build_scaling's ellipses\n"
                "- **F = 0.3** (overlap): the same with crossing fraction 3/10: exactly round(0.3 n) ellipses cross "
                "at least one other in two points (counted exactly with `sites_cross`), deep and shallow, half the "
                "partners thin (aspect ratio up to 16); the other sites are the F = 0 set's first separated ones\n\n"
                "**No peer.** CGAL has no Voronoi diagram of ellipses (its Apollonius graph takes circles), and the "
                "paper's program published no timings on crossing ellipses, so these rows have no reference column.\n");

    report.heading("Times and peak memory", 3);
    report.table(ellipse_time_table(rows, ecases),
                 "CPU seconds of `DelaunayGraph::insert_all`: the median, [fastest–slowest, runs]; ratios on the "
                 "medians. Peak memory as for circles.");

    report.heading("Graphs and checks", 3);
    report.table(ellipse_graph_table(rows, ecases),
                 "union-hidden: sites hidden by a union of crossing sites (none contains them alone); global searches: "
                 "insertions whose first conflict was sought over the whole graph; conflict faces: faces removed by "
                 "conflict regions, in all.");

    report.heading("Predicate calls per stage", 3);
    report.table(predicate_table(rows, "ellipses"), "calls (filter / subdivision / symmetry / exact), as for circles.");

    report.heading("Where the extra time goes", 3);
    report.table(ellipse_extra_time_table(rows, ecases),
                 "The F = 0.3 set's extra CPU time against F = 0, the CPU time of `relative_position` alone on its "
                 "crossing pairs (the intersection quartic: no filter decides a crossing pair; is_hidden meets each "
                 "about once), and the extra calls decided past the filter (subdivision + exact, all predicates).");

    report.heading("Target", 3);
    report.text("10^4 random ellipses, 30% of them crossing another, built within 2× of a disjoint set of the same "
                "size. ellvor (CPU time, medians):\n\n" +
                ellipse_target_lines(rows, ecases) +
                (full ? "" : "\nEllipses: n = 10^4 and 10^5 skipped (run with --full).\n"));
}

}  // namespace

int main(int argc, char** argv) {
    // --only circles|ellipses (one part, stdout only), then the common arguments.
    std::string only;
    std::vector<char*> rest{argv[0]};
    for (int i = 1; i < argc; ++i) {
        if (std::string(argv[i]) == "--only" && i + 1 < argc) only = argv[++i];
        else rest.push_back(argv[i]);
    }
    const char* const usage =
        "usage: overlap_scaling [--full] [--out DIR | --only circles|ellipses]\n"
        "  --full     circles n = 10^3, 10^4, 10^5 (instead of 10^2, 10^3); ellipses n = 10^3, 10^4 and 10^5\n"
        "             (seeds 1, 2, 3; instead of 10^3): about 7 minutes\n"
        "  --out DIR  write DIR/overlap.csv and DIR/overlap.md\n"
        "  --only P   run one part (circles or ellipses), print only\n";
    BenchArguments args;
    if (!parse_bench_arguments(static_cast<int>(rest.size()), rest.data(), "overlap_scaling", usage, args)) return 2;
    if (!(only.empty() || only == "circles" || only == "ellipses") || (!only.empty() && !args.out_dir.empty())) {
        std::fputs(usage, stderr);
        return 2;
    }
    const bool run_circles = only != "ellipses", run_ellipses = only != "circles";
    Plan plan;
    if (run_circles) plan.ns = args.full ? std::vector<long>{1000, 10000, 100000} : std::vector<long>{100, 1000};
    if (run_ellipses)
        plan.ecases = args.full ? std::vector<EllipseCase>{{1000, 1}, {10000, 1}, {10000, 2}, {10000, 3},
                                                           {100000, 1}, {100000, 2}, {100000, 3}}
                                : std::vector<EllipseCase>{{1000, 1}};
    Report report("Crossing sites against disjoint ones", "overlap_scaling", args.command);

    // The measurements.
    int anomalies = 0;
    const std::map<MemoryKey, PeakMemory> memory = measure_peak_memory(plan);
    std::vector<Row> rows;
    measure_circles(plan, memory, rows, anomalies);
    measure_ellipses(plan, memory, rows, anomalies);

    // The report.
    report.intro("Build time and peak memory of the Delaunay graph of n sites of which 30% cross another, against n "
                 "disjoint sites from the same generator: circles (ellvor and CGAL's `Apollonius_graph_hierarchy_2` in "
                 "the same program), then ellipses (ellvor alone, no peer exists). CPU time of the build only (site "
                 "generation and checks excluded); below 0.3 s a build is repeated and the median taken (at most 20 "
                 "runs; ellipses at least " + std::to_string(kEllipseMinReps) + " runs).");
    report.machine_note("a VM with " + machine_memory_and_os() + ", shared with other jobs: compare CPU seconds");
    report.note("By default (`make bench`) circles n = 10^2 and 10^3, ellipses n = 10^3, and nothing is written; "
                "`--full` runs circles n = 10^3, 10^4 and 10^5 and ellipses n = 10^3, 10^4 and 10^5 (seeds 1, 2, 3), "
                "`--out DIR` writes `overlap.csv` and this file; `--only circles` or `--only ellipses` runs one part "
                "and prints it.");
    if (run_circles) report_circles(report, rows, plan.ns, args.full);
    if (run_ellipses) report_ellipses(report, rows, plan.ecases, args.full);
    report.text("\nAnomalies (wrong crossing count, invalid graph, disagreement with CGAL, exception): " +
                std::to_string(anomalies) + ".\n");

    report.publish(args.out_dir, "overlap.md", {{"overlap.csv", csv_table(rows).csv()}});
    return anomalies ? 1 : 0;
}
