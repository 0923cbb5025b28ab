// Build time of the Delaunay graph against the number of sites (the paper,
// Table 1, row "insertion": 0.752 / 5.916 / 13.000 / 19.200 / 25.602 s for
// 5 / 10 / 15 / 20 / 25 ellipses, P4 2.6 GHz), and ellvor against CGAL's
// Apollonius_graph_hierarchy_2 (what CGAL's manual advises above about 10^3
// sites) and its plain Apollonius_graph_2 on circles; peak memory of both.
//
// For every n: DelaunayGraph::insert_all on
//   ellipses         generate_sites(ellipses, seed 1, bits 8, box 100)
//   ellipses-nest10  the same with nested fraction 1/10
//   circles          generate_sites(circles, seed 1, bits 1, box 256 ceil(sqrt n)): every number
//                    is a multiple of 1/2 below 2^20, hence exact in double; the same circles,
//                    converted to double, go to CGAL's Apollonius_graph_hierarchy_2 and
//                    Apollonius_graph_2, both with Apollonius_graph_filtered_traits_2<Epick> (bulk
//                    insert, which sorts by decreasing radius as insert_all does), in the same program.
// On the circle sets ellvor's graph (visible sites, hidden pairs, finite edges
// as a multiset, hull) is compared with CGAL's. Each ellvor graph is checked
// with validate(), and with brute_force_check() up to 300 sites.
//
// Times: wall and CPU time of the build only (site generation and checks
// excluded); below 0.3 s a build is repeated (median, at most 20 runs).
// Peak memory, for n >= 1000: one more build of ellipses, of circles and of
// CGAL's hierarchy, each in a forked child (peak_memory.hpp), before any other
// work of the program; both graphs copy their sites from the input, so that
// each counts its own storage of them.
//
//   build/experiments/build_scaling                       # default (make bench): n <= 1000, stdout only
//   build/experiments/build_scaling --full --out experiments/results
//       # adds n = 10^4, 10^5 and 10^6 (about 20 minutes); writes build_scaling.csv, .md and .png
//   build/experiments/build_scaling --full --max-n 100000
//       # the same without the counts above 10^5 (a quick check of the 10^4 and 10^5 rows)
// At 10^6 the nested set and CGAL's plain graph (whose nearest-neighbour walk
// is linear: 4 s at 10^5) are left out.
//
// An invalid graph, a disagreement with CGAL or an exception is printed as an
// ANOMALY and makes the program exit with status 1.
#include "experiments/apollonius_comparison.hpp"
#include "experiments/peak_memory.hpp"
#include "experiments/predicate_stages.hpp"
#include "experiments/report.hpp"
#include "experiments/run_environment.hpp"
#include "graph/delaunay_graph.hpp"
#include "traits/ellipse_delaunay_traits.hpp"
#include "sites/ellipse.hpp"
#include "sites/site_generators.hpp"
#include "util/error.hpp"

#include <CGAL/Apollonius_graph_2.h>
#include <CGAL/Apollonius_graph_filtered_traits_2.h>
#include <CGAL/Apollonius_graph_hierarchy_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <random>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

using namespace ellvor;

namespace {

using namespace ellvor::experiments;

struct Row {
    std::string set;
    long n = 0;
    double seconds = 0, cpu_seconds = 0;
    int reps = 0;
    std::size_t edges = 0, faces = 0, hidden = 0, visible = 0;
    TraitsStats stats;
    GraphStats gstats;
    std::string validate = "-", brute = "-", cgal = "-";  // "ok", a problem, or "-" (not run)
    double kappa1_us = 0;  // mean CPU time of one kappa1 call (micro-benchmark)
    PeakMemory memory;     // one build in a forked child (n >= 1000), else not measured
};

bool is_cgal(const Row& r) { return r.set.rfind("cgal-", 0) == 0; }



// CGAL's graph of the circles (bulk insertion; Graph: AG or AGH), its build
// time, and its summary in ellvor's ids.
template <class Graph>
Summary cgal_graph(const std::vector<Ellipse>& sites, double& wall, double& cpu, int& reps) {
    const std::vector<AG::Site_2> input = cgal_sites(sites);
    Graph ag;
    timed([&] {
        ag.clear();
        ag.insert(input.begin(), input.end());
    }, wall, cpu, reps);
    return summary_of(ag, CgalSiteIds(input));
}

Row run_ellvor(const std::string& set, const std::string& label, const std::vector<Ellipse>& sites, Summary* summary,
               int& anomalies) {
    Row r;
    r.set = label;
    r.n = static_cast<long>(sites.size());
    const long n = r.n;
    try {
        std::unique_ptr<DelaunayGraph> g;
        timed([&] {
            g = std::make_unique<DelaunayGraph>(std::make_unique<EllipseDelaunayTraits>(sites));
            std::size_t step = std::max<std::size_t>(1, sites.size() / 10);
            g->insert_all([&](std::size_t done, std::size_t total) {
                if (total >= 1000 && done % step == 0)
                    std::cerr << "\r  " << label << " n = " << n << ": " << done << " / " << total << std::flush;
            });
            if (sites.size() >= 1000) std::cerr << "\n";
        }, r.seconds, r.cpu_seconds, r.reps);
        r.edges = g->edges().size();
        r.faces = g->faces().size();
        r.hidden = g->hidden().size();
        r.visible = g->visible_sites().size();
        r.stats = g->predicate_stats();
        r.gstats = g->stats();
        std::string v = g->validate();
        r.validate = v.empty() ? "ok" : check_message(v);
        if (!v.empty()) {
            std::cerr << "ANOMALY: " << label << " n = " << n << ": validate: " << v << "\n";
            ++anomalies;
        }
        if (n <= 300) {
            std::string b = g->brute_force_check();
            r.brute = b.empty() ? "ok" : check_message(b);
            if (!b.empty()) {
                std::cerr << "ANOMALY: " << label << " n = " << n << ": brute force: " << b << "\n";
                ++anomalies;
            }
        }
        if (summary) *summary = summary_of(*g);
    } catch (const std::exception& e) {
        std::cerr << "ANOMALY: " << label << " n = " << n << ": " << e.what() << "\n";
        r.validate = std::string("exception: ") + check_message(e.what());
        ++anomalies;
    }
    (void)set;
    return r;
}




// Mean time of one kappa1 (side_of_bisector) call, on fresh EllipseDelaunayTraits
// of the sites, for pseudo-random triples of distinct sites (seconds).
double kappa1_seconds(const std::vector<Ellipse>& sites) {
    if (sites.size() < 3) return 0;
    EllipseDelaunayTraits t(sites);
    std::mt19937_64 rng(3);
    const std::size_t calls = 20000, n = sites.size();
    std::vector<std::array<SiteId, 3>> triples;
    while (triples.size() < calls) {
        const SiteId i = rng() % n, j = rng() % n, k = rng() % n;
        if (i != j && j != k && i != k) triples.push_back({i, j, k});
    }
    long sum = 0;
    const double c0 = now_cpu();
    for (const auto& q : triples) sum += to_int(t.side_of_bisector(q[0], q[1], q[2]));
    const double c1 = now_cpu();
    (void)sum;
    return (c1 - c0) / calls;
}

constexpr long kHuge = 1000000;  // from here: no nested set, no plain CGAL graph
const std::vector<std::string> kSets = {"ellipses", "ellipses-nest10", "circles"};

// Peak memory first, before this program has built anything: each build in
// its own child, which generates its sites and then builds (n >= 1000).
std::map<std::pair<std::string, long>, PeakMemory> measure_peak_memory(const std::vector<long>& ns) {
    std::map<std::pair<std::string, long>, PeakMemory> memory;
    for (long n : ns) {
        if (n < 1000) continue;
        for (const std::string set : {"ellipses", "circles"}) {
            std::vector<Ellipse> sites;
            memory[{set == "circles" ? "ellvor-circles" : set, n}] = peak_memory_in_child(
                [&] { sites = make_sites(set, n); },
                [&] {
                    // A copy: the graph's own storage of its sites counts, as CGAL's copies into its vertices do.
                    DelaunayGraph g(std::make_unique<EllipseDelaunayTraits>(sites));
                    g.insert_all();
                });
        }
        // CGAL's child keeps the generated sites too, as ellvor's does: both
        // builds start from the same allocator state.
        std::vector<Ellipse> sites;
        std::vector<AG::Site_2> input;
        memory[{"cgal-hierarchy", n}] = peak_memory_in_child([&] {
                                                                 sites = make_sites("circles", n);
                                                                 input = cgal_sites(sites);
                                                             },
                                                             [&] {
                                                                 AGH ag;
                                                                 ag.insert(input.begin(), input.end());
                                                             });
        std::cerr << "[build_scaling] peak memory measured, n = " << n << "\n";
    }
    return memory;
}

// CGAL's plain graph and its hierarchy on the circles of ellvor's row `r`;
// ellvor's graph `mine` must equal both.
std::vector<Row> cgal_rows(const std::vector<Ellipse>& sites, long n, Row& r, const Summary& mine,
                           const std::map<std::pair<std::string, long>, PeakMemory>& memory, int& anomalies) {
    std::vector<Row> rows;
    for (const bool hierarchy : {false, true}) {
        if (n >= kHuge && !hierarchy) continue;
        Row c;
        c.set = hierarchy ? "cgal-hierarchy" : "cgal-circles";
        c.n = n;
        const Summary want = hierarchy ? cgal_graph<AGH>(sites, c.seconds, c.cpu_seconds, c.reps)
                                       : cgal_graph<AG>(sites, c.seconds, c.cpu_seconds, c.reps);
        c.edges = want.edges.size();
        c.hidden = want.hidden.size();
        c.visible = want.visible.size();
        if (r.validate.rfind("exception", 0) != 0) {
            c.cgal = compare(mine, want);
            if (c.cgal != "ok") {
                std::cerr << "ANOMALY: circles n = " << n << ": ellvor differs from " << c.set << ": " << c.cgal
                          << "\n";
                ++anomalies;
            }
        }
        if (memory.count({c.set, n})) c.memory = memory.at({c.set, n});
        std::cerr << "[build_scaling] " << c.set << " n = " << n << ": " << fmt("%.5f", c.seconds) << " s wall, "
                  << fmt("%.5f", c.cpu_seconds) << " s cpu (" << c.reps << " runs); ellvor / CGAL (cpu) = "
                  << fmt("%.1f", r.cpu_seconds / c.cpu_seconds) << "; graphs " << c.cgal << "\n";
        rows.push_back(c);
    }
    r.cgal = std::all_of(rows.begin(), rows.end(), [](const Row& c) { return c.cgal == "ok"; }) ? "ok" : "differs";
    return rows;
}

// Every set at every n: ellvor's build (and CGAL's on the circles).
std::vector<Row> measure_builds(const std::vector<long>& ns,
                                const std::map<std::pair<std::string, long>, PeakMemory>& memory, int& anomalies) {
    std::vector<Row> rows;
    for (long n : ns) {
        for (const std::string& set : kSets) {
            if (n >= kHuge && set == "ellipses-nest10") continue;
            std::vector<Ellipse> sites;
            try {
                sites = make_sites(set, n);
            } catch (const std::exception& e) {
                std::cerr << "ANOMALY: cannot generate " << set << " n = " << n << ": " << e.what() << "\n";
                ++anomalies;
                continue;
            }
            const std::string label = set == "circles" ? "ellvor-circles" : set;
            Summary mine;
            Row r = run_ellvor(set, label, sites, set == "circles" ? &mine : nullptr, anomalies);
            if (n >= 100) r.kappa1_us = 1e6 * kappa1_seconds(sites);
            if (memory.count({label, n})) r.memory = memory.at({label, n});
            std::cerr << "[build_scaling] " << label << " n = " << n << ": " << fmt("%.4f", r.seconds) << " s wall, "
                      << fmt("%.4f", r.cpu_seconds) << " s cpu (" << r.reps << " runs), " << r.edges << " edges, "
                      << r.hidden << " hidden, validate " << r.validate << ", brute force " << r.brute << "\n";
            if (set == "circles") {
                const std::vector<Row> cgal = cgal_rows(sites, n, r, mine, memory, anomalies);
                rows.push_back(r);
                rows.insert(rows.end(), cgal.begin(), cgal.end());
            } else {
                rows.push_back(r);
            }
        }
    }
    return rows;
}

// ------------------------------------------------------------------ tables --

const Row* find(const std::vector<Row>& rows, const std::string& set, long n) {
    for (const Row& r : rows)
        if (r.set == set && r.n == n) return &r;
    return nullptr;
}

long growth_kb(const PeakMemory& m) { return m.peak_kb - m.start_kb; }

// build_scaling.csv: every row, every count.
Table csv_table(const std::vector<Row>& rows) {
    std::vector<std::string> columns = {"set", "n", "seconds", "cpu_seconds", "runs", "us_per_insertion", "visible",
                                        "hidden", "edges", "faces"};
    const std::vector<std::string> predicate_columns = predicate_csv_columns();
    columns.insert(columns.end(), predicate_columns.begin(), predicate_columns.end());
    columns.insert(columns.end(), {"walk_steps", "conflict_faces", "degree2_insertions", "validate", "brute_force",
                                   "equals_cgal", "kappa1_us_per_call", "peak_rss_growth_bytes"});
    Table t("build_scaling", columns);
    for (const Row& r : rows) {
        const bool cgal = is_cgal(r);
        TableRow row = {r.set, integer(r.n), fmt("%.6g", r.seconds), fmt("%.6g", r.cpu_seconds), integer(r.reps),
                        fmt("%.6g", 1e6 * r.seconds / r.n), integer(static_cast<long long>(r.visible)),
                        integer(static_cast<long long>(r.hidden)), integer(static_cast<long long>(r.edges)),
                        cgal ? std::string() : std::to_string(r.faces)};
        for (const std::string& v : predicate_csv_values(cgal ? nullptr : &r.stats)) row.push_back(v);
        const std::string growth =
            r.memory.peak_kb < 0 || r.memory.start_kb < 0 ? "" : std::to_string(growth_kb(r.memory) * 1024);
        if (cgal)
            row.insert(row.end(), {"", "", "", "-", "-", r.cgal, "", growth});
        else
            row.insert(row.end(), {std::to_string(r.gstats.walk_steps), std::to_string(r.gstats.conflict_faces),
                                   std::to_string(r.gstats.degree_2_insertions), r.validate, r.brute, r.cgal,
                                   fmt("%.4g", r.kappa1_us), growth});
        t.add(std::move(row));
    }
    return t;
}

Table time_table(const std::vector<Row>& rows, const std::vector<long>& ns) {
    // The paper's Table 1, row "insertion", for n = 5 .. 25.
    const std::vector<double> paper = {0.752, 5.916, 13.000, 19.200, 25.602};
    auto ratio = [](const Row* a, const Row* b) {
        return a && b ? fmt("%.1f×", a->cpu_seconds / b->cpu_seconds) : std::string("—");
    };
    auto t = [](const Row* r) {
        return r ? fmt("%.3g", r->cpu_seconds) + " (" + fmt("%.3g", r->seconds) + ")" : std::string("—");
    };
    Table table("times", {"n", "paper (s)", "ellipses (s)", "µs / insertion", "ellipses-nest10 (s)",
                          "ellvor circles (s)", "CGAL hierarchy (s)", "CGAL plain (s)", "ellvor / hierarchy",
                          "ellvor / plain"},
                "rrrrrrrrrr");
    for (std::size_t k = 0; k < ns.size(); ++k) {
        const long n = ns[k];
        const Row *e = find(rows, "ellipses", n), *en = find(rows, "ellipses-nest10", n),
                  *ec = find(rows, "ellvor-circles", n), *cc = find(rows, "cgal-circles", n),
                  *ch = find(rows, "cgal-hierarchy", n);
        table.add({integer(n), k < paper.size() ? fmt("%.3f", paper[k]) : std::string("—"), t(e),
                   e ? fmt("%.0f", 1e6 * e->cpu_seconds / n) : std::string("—"), t(en), t(ec), t(ch), t(cc),
                   ratio(ec, ch), ratio(ec, cc)});
    }
    return table;
}

// The growth of a child's resident memory over its build, in MB ("—" when not measured).
std::string growth_mb(const PeakMemory& m) {
    if (m.peak_kb < 0 || m.start_kb < 0) return "—";
    return fmt("%.1f", growth_kb(m) / 1024.0);
}

Table memory_table(const std::vector<Row>& rows, const std::vector<long>& ns) {
    Table table("memory", {"n", "ellipses (MB)", "per site (KB)", "ellvor circles (MB)", "CGAL hierarchy (MB)",
                           "ellvor / hierarchy"},
                "rrrrrr");
    for (long n : ns) {
        const Row *e = find(rows, "ellipses", n), *ec = find(rows, "ellvor-circles", n),
                  *ch = find(rows, "cgal-hierarchy", n);
        if (!e || e->memory.peak_kb < 0) continue;
        std::string ratio = "—";
        if (ec && ch && ch->memory.peak_kb > ch->memory.start_kb && ec->memory.peak_kb >= 0)
            ratio = fmt("%.1f×", double(growth_kb(ec->memory)) / double(growth_kb(ch->memory)));
        table.add({integer(n), growth_mb(e->memory), fmt("%.1f", double(growth_kb(e->memory)) / n),
                   ec ? growth_mb(ec->memory) : "—", ch ? growth_mb(ch->memory) : "—", ratio});
    }
    return table;
}

Table graph_table(const std::vector<Row>& rows) {
    Table table("graphs", {"set", "n", "visible", "hidden", "Delaunay edges", "faces", "walk steps", "validate()",
                           "brute force (n ≤ 300)", "equals CGAL"},
                "lrrrrrrlll");
    for (const Row& r : rows)
        if (!is_cgal(r))
            table.add({r.set, integer(r.n), integer(static_cast<long long>(r.visible)),
                       integer(static_cast<long long>(r.hidden)), integer(static_cast<long long>(r.edges)),
                       integer(static_cast<long long>(r.faces)), integer(static_cast<long long>(r.gstats.walk_steps)),
                       r.validate, r.brute, r.cgal});
    return table;
}

Table predicate_table(const std::vector<Row>& rows) {
    Table table = predicate_stage_table("predicates", {"set", "n"});
    for (const Row& r : rows)
        if (!is_cgal(r)) add_predicate_stage_row(table, {r.set, integer(r.n)}, r.stats);
    return table;
}

Table walk_table(const std::vector<Row>& rows) {
    Table table("walk", {"set", "n", "kappa1 calls", "per insertion", "µs / call", "estimated kappa1 time (s)",
                         "share of build"});
    for (const Row& r : rows) {
        if (is_cgal(r) || r.kappa1_us <= 0) continue;
        const double calls = double(r.stats[Predicate::side_of_bisector].calls), est = calls * r.kappa1_us * 1e-6;
        table.add({r.set, integer(r.n), integer(static_cast<long long>(r.stats[Predicate::side_of_bisector].calls)),
                   fmt("%.0f", calls / r.n), fmt("%.2f", r.kappa1_us), fmt("%.3g", est),
                   fmt("%.0f%%", 100 * est / r.cpu_seconds)});
    }
    return table;
}

std::string target_list(const std::vector<Row>& rows, const std::vector<long>& ns) {
    std::string md;
    if (const Row* e = find(rows, "ellipses", 10000))
        md += "- 10^4 random ellipses in ≤ 30 s: " + fmt("%.2f", e->cpu_seconds) + " s CPU (" + fmt("%.2f", e->seconds) +
              " s wall) — " + (e->seconds <= 30 ? "met" : "MISSED") + "\n";
    else
        md += "- 10^4 random ellipses in ≤ 30 s: not run (use --full)\n";
    std::vector<Target> targets;
    for (long n : ns) {
        const Row *ec = find(rows, "ellvor-circles", n), *cc = find(rows, "cgal-circles", n);
        if (!ec || !cc || n < 100) continue;
        const double ratio = ec->cpu_seconds / cc->cpu_seconds;
        targets.push_back({"random circles within 5× of CGAL's plain graph, n = " + std::to_string(n),
                           fmt("%.1f×", ratio), ratio <= 5});
    }
    for (long n : ns) {
        const Row *ec = find(rows, "ellvor-circles", n), *ch = find(rows, "cgal-hierarchy", n);
        if (!ec || !ch || n < 10000) continue;
        const double ratio = ec->cpu_seconds / ch->cpu_seconds;
        targets.push_back({"random circles within 2.5× of CGAL's hierarchy, n = " + std::to_string(n),
                           fmt("%.1f×", ratio), ratio <= 2.5});
        const long mine = growth_kb(ec->memory), theirs = growth_kb(ch->memory);
        if (ec->memory.peak_kb >= 0 && ch->memory.peak_kb >= 0 && theirs > 0)
            targets.push_back({"random circles, peak memory within 2× of CGAL's hierarchy, n = " + std::to_string(n),
                               fmt("%.1f×", double(mine) / theirs), mine <= 2 * theirs});
        // Issue 24's targets (dense packings and real data at random-data speed).
        targets.push_back({"random circles ≤ 0.8× the time of CGAL's hierarchy, n = " + std::to_string(n),
                           fmt("%.2f×", ratio), ratio <= 0.8});
        if (ec->memory.peak_kb >= 0 && ch->memory.peak_kb >= 0 && theirs > 0)
            targets.push_back({"random circles, peak memory ≤ 1.2× CGAL's hierarchy, n = " + std::to_string(n),
                               fmt("%.2f×", double(mine) / theirs), 5 * mine <= 6 * theirs});
    }
    md += target_lines(targets);
    if (const Row* e = find(rows, "ellipses", 100000)) {
        const double mb = e->memory.peak_kb < 0 ? -1 : growth_kb(e->memory) / 1024.0;
        md += "- 10^5 random ellipses in ≤ 15 s: " + fmt("%.1f", e->cpu_seconds) + " s CPU — " +
              (e->cpu_seconds <= 15 ? "met" : "MISSED") + "; in ≤ 600 MB: " + fmt("%.0f", mb) + " MB — " +
              (mb >= 0 && mb <= 600 ? "met" : "MISSED") + "\n";
    }
    if (const Row* e = find(rows, "ellipses", kHuge)) {
        const double gb = e->memory.peak_kb < 0 ? -1 : growth_kb(e->memory) / 1048576.0;
        md += "- 10^6 random ellipses in ≤ 4 min: " + fmt("%.0f", e->cpu_seconds) + " s CPU — " +
              (e->cpu_seconds <= 240 ? "met" : "MISSED") + "; in ≤ 6 GB: " + fmt("%.2f", gb) + " GB — " +
              (gb >= 0 && gb <= 6 ? "met" : "MISSED") + "; validate(): " + e->validate + "\n";
    }
    return md;
}

}  // namespace

int main(int argc, char** argv) {
    const char* usage =
        "usage: build_scaling [--full] [--max-n N] [--out DIR]\n"
        "  --full     also n = 10^4, 10^5 and 10^6 (about 20 minutes)\n"
        "  --max-n N  leave out the counts above N (e.g. --full --max-n 100000: no 10^6 rows)\n"
        "  --out DIR  write DIR/build_scaling.csv, .md and .png\n";
    // --max-n is this program's own; the rest is the common command line.
    long max_n = 0;  // 0: no limit
    std::vector<char*> common = {argv[0]};
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--max-n") == 0) {
            char* end = nullptr;
            max_n = i + 1 < argc ? std::strtol(argv[++i], &end, 10) : 0;
            if (max_n <= 0 || !end || *end != '\0') {
                std::fputs(usage, stderr);
                return 2;
            }
        } else {
            common.push_back(argv[i]);
        }
    }
    BenchArguments args;
    if (!parse_bench_arguments(static_cast<int>(common.size()), common.data(), "build_scaling", usage, args)) return 2;
    args.command = "build/experiments/build_scaling";
    for (int i = 1; i < argc; ++i) args.command += std::string(" ") + argv[i];
    std::vector<long> ns = {5, 10, 15, 20, 25, 100, 1000};
    if (args.full) ns.insert(ns.end(), {10000, 100000, 1000000});
    if (max_n > 0) ns.erase(std::remove_if(ns.begin(), ns.end(), [&](long n) { return n > max_n; }), ns.end());
    Report report("Build time against the number of sites", "build_scaling", args.command);

    // The measurements.
    int anomalies = 0;
    const auto memory = measure_peak_memory(ns);
    const std::vector<Row> rows = measure_builds(ns, memory, anomalies);

    // The report.
    report.intro("Total time of `DelaunayGraph::insert_all` (every site, largest area first) from a fresh graph; "
                 "site generation and the checks are not timed. Below 0.3 s a build is repeated and the median taken "
                 "(at most 20 runs). Paper: Emiris, Tsigaridas, Tzoumas 2007, Table 1, row \"insertion\" (P4 2.6 "
                 "GHz; its ellipses are not given, so only n matches).");
    report.machine_note("shared with other jobs: compare CPU seconds");
    report.note("Plot (`build_scaling.png`): `/usr/bin/python3 experiments/plot_results.py build_scaling`");
    report.note("By default (`make bench`) n ≤ 1000 and nothing is written; `--full` adds n = 10^4, 10^5 and 10^6 "
                "(at 10^6 without the nested set and CGAL's plain graph), `--out DIR` writes the CSV and this file.");
    std::string sets = "Site sets:\n\n";
    for (const std::string& set : kSets)
        sets += "- **" + (set == "circles" ? std::string("ellvor-circles") : set) + "**: " + describe_set(set) + "\n";
    report.text(sets +
                "- **cgal-circles**, **cgal-hierarchy**: the same circles converted to double (exactly: multiples "
                "of 1/2 below 2^20), bulk-inserted into CGAL's `Apollonius_graph_2` and "
                "`Apollonius_graph_hierarchy_2` over `Apollonius_graph_filtered_traits_2<Epick>` (bulk insertion also "
                "goes by decreasing radius), in the same program. Above about 10^3 sites the hierarchy is what CGAL's "
                "manual advises, so it is the reference.\n");

    report.heading("Times");
    report.table(time_table(rows, ns));
    report.text("\nCPU seconds, wall seconds in parentheses; ratios on CPU time.\n");

    report.heading("Peak memory");
    report.table(memory_table(rows, ns), std::string(kPeakMemoryMethod) +
                                             "; each graph copies its sites from the input (ellvor's traits, CGAL's vertices), so both count their own storage of the sites. CGAL's child generates the same ellvor sites (kept, as ellvor's child keeps them) and converts them.");

    report.heading("Graphs and checks");
    report.table(graph_table(rows));

    report.heading("Predicate calls per stage");
    report.table(predicate_table(rows), "calls (filter / subdivision / symmetry / exact); memoized answers are not counted.");

    report.heading("Where the time goes: the nearest-neighbour walk (kappa1)");
    report.table(walk_table(rows),
                 "kappa1 calls × the mean CPU time of one kappa1 call (20000 calls on random site triples with fresh "
                 "EllipseDelaunayTraits), against the whole build's CPU time. An estimate: the walk's triples are "
                 "neighbours, not random sites.");

    report.heading("Targets");
    report.text(target_list(rows, ns) + "\nAnomalies (invalid graph, disagreement with CGAL, exception): " +
                std::to_string(anomalies) + ".\n" +
                (args.full ? "" : "\nn = 10^4, 10^5 and 10^6 skipped (run with --full).\n") +
                (max_n > 0 ? "\nn above " + std::to_string(max_n) + " left out (--max-n).\n" : std::string()));

    report.publish(args.out_dir, "build_scaling.md", {{"build_scaling.csv", csv_table(rows).csv()}});
    if (!args.out_dir.empty()) {
        // matplotlib is Debian's: its python3, not one earlier on PATH.
        const std::string plot = "/usr/bin/python3 experiments/plot_results.py --dir '" + args.out_dir + "' build_scaling";
        if (std::system(plot.c_str()) != 0) std::cerr << "[build_scaling] plot failed: " << plot << "\n";
    }
    return anomalies ? 1 : 0;
}
