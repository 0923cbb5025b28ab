// Deletion (DelaunayGraph::remove): the time to remove a site against the
// time to insert one, and against CGAL's remove on circles, in one run.
//
// For every n (10^3 and 10^4 by default; 10^5 with --full) and set:
//   ellipses  generate_sites(ellipses, seed 1, bits 8, box 100)
//   circles   generate_sites(circles, seed 1, bits 1, box 256 ceil(sqrt n)) (dyadic: exact in
//             double, so CGAL sees the same circles)
// ellvor builds the graph (insert_all), then removes a tenth of the sites, in
// a random order (seed 7) -- the same sites, in the same order, for every
// library. Reported: CPU time per insertion, per removal, and their ratio
// (the target: a removal costs at most 3 insertions). On circles,
// CGAL's Apollonius_graph_hierarchy_2 (and, up to 10^4, Apollonius_graph_2),
// both with Apollonius_graph_filtered_traits_2<Epick>, build by bulk insertion
// and remove the same sites by their vertex handles; the ratios ellvor / CGAL.
//
// Checks: ellvor's graph after the removals passes validate(); up to 10^4
// sites it equals the graph built from the remaining sites; on circles it
// equals CGAL's after the same removals. A failure is an ANOMALY (exit 1).
// Peak memory (n >= 10^4): the build and the removals once more in a forked
// child (peak_memory.hpp), ellvor and CGAL's hierarchy.
//
//   build/experiments/removal_scaling                 # default (make bench): n = 10^3, 10^4
//   build/experiments/removal_scaling --full --out experiments/results   # adds 10^5; removal.csv, .md
#include "experiments/apollonius_comparison.hpp"
#include "experiments/peak_memory.hpp"
#include "experiments/report.hpp"
#include "experiments/run_environment.hpp"
#include "graph/delaunay_graph.hpp"
#include "traits/ellipse_delaunay_traits.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <numeric>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using namespace ellvor;
using namespace ellvor::experiments;

namespace {

constexpr long kRemovedFraction = 10;  // one site in ten
constexpr std::uint64_t kRemovalSeed = 7;

// A tenth of the ids 0 .. n-1 in a random order (our own shuffle: the same
// everywhere for a seed).
std::vector<SiteId> removal_order(std::size_t n) {
    std::vector<SiteId> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::mt19937_64 rng(kRemovalSeed);
    for (std::size_t i = n; i > 1; --i) std::swap(order[i - 1], order[rng() % i]);
    order.resize(std::max<std::size_t>(1, n / kRemovedFraction));
    return order;
}

struct Row {
    std::string library, set;  // library: ellvor, cgal-hierarchy, cgal-plain
    long n = 0;
    std::size_t removed = 0;
    double insert_cpu = 0, remove_cpu = 0;  // seconds, all insertions / all removals
    std::string check = "-";
    GraphStats graph;  // ellvor only
    PeakMemory memory;
    double insert_us() const { return 1e6 * insert_cpu / double(n); }
    double remove_us() const { return 1e6 * remove_cpu / double(removed); }
};

Row run_ellvor(const std::string& set, const std::vector<Ellipse>& sites, const std::vector<SiteId>& removals,
               Summary& after, int& anomalies) {
    Row r{"ellvor", set, static_cast<long>(sites.size()), removals.size()};
    DelaunayGraph g(std::make_unique<EllipseDelaunayTraits>(sites));
    double c0 = now_cpu();
    g.insert_all();
    r.insert_cpu = now_cpu() - c0;
    c0 = now_cpu();
    for (SiteId s : removals) g.remove(s);
    r.remove_cpu = now_cpu() - c0;
    r.graph = g.stats();
    after = summary_of(g);
    r.check = g.validate();
    if (r.check.empty()) r.check = "valid";
    if (r.check == "valid" && sites.size() <= 10000) {
        // The graph of the remaining sites, built from scratch.
        std::vector<char> gone(sites.size(), 0);
        for (SiteId s : removals) gone[s] = 1;
        std::vector<Ellipse> rest;
        std::vector<SiteId> id_of_rest;
        for (SiteId i = 0; i < sites.size(); ++i)
            if (!gone[i]) {
                rest.push_back(sites[i]);
                id_of_rest.push_back(i);
            }
        DelaunayGraph fresh(std::make_unique<EllipseDelaunayTraits>(rest));
        fresh.insert_all();
        Summary want = summary_of(fresh);
        for (auto* pairs : {&want.hidden, &want.edges, &want.hull})
            for (auto& [a, b] : *pairs) {
                a = id_of_rest[a];
                b = id_of_rest[b];
            }
        for (SiteId& v : want.visible) v = id_of_rest[v];
        for (auto& [a, b] : want.edges)
            if (a > b) std::swap(a, b);
        std::sort(want.edges.begin(), want.edges.end());
        std::sort(want.hidden.begin(), want.hidden.end());
        std::sort(want.hull.begin(), want.hull.end());
        const std::string same = compare(after, want);
        r.check = same == "ok" ? "valid, = rebuilt" : "rebuilt graph differs: " + same;
    }
    if (r.check.rfind("valid", 0) != 0) {
        std::cout << "ANOMALY ellvor " << set << " n " << sites.size() << ": " << r.check << "\n";
        ++anomalies;
    }
    return r;
}

template <class Graph>
Row run_cgal(const std::string& library, const std::vector<Ellipse>& sites, const std::vector<SiteId>& removals,
             const Summary& ellvor_after, int& anomalies) {
    Row r{library, "circles", static_cast<long>(sites.size()), removals.size()};
    const std::vector<AG::Site_2> input = cgal_sites(sites);
    const CgalSiteIds site_id(input);
    Graph ag;
    double c0 = now_cpu();
    ag.insert(input.begin(), input.end());
    r.insert_cpu = now_cpu() - c0;
    std::vector<typename Graph::Vertex_handle> vertex(sites.size());
    for (auto v = ag.finite_vertices_begin(); v != ag.finite_vertices_end(); ++v) vertex[site_id(v->site())] = v;
    c0 = now_cpu();
    for (SiteId s : removals) ag.remove(vertex[s]);
    r.remove_cpu = now_cpu() - c0;
    r.check = compare(summary_of(ag, site_id), ellvor_after);
    if (r.check != "ok") {
        std::cout << "ANOMALY " << library << " n " << sites.size() << ": ellvor's graph after the removals: " << r.check
                  << "\n";
        ++anomalies;
    } else {
        r.check = "= ellvor";
    }
    return r;
}

// The build and the removals once more, in a forked child.
PeakMemory ellvor_memory(const std::string& set, long n) {
    std::vector<Ellipse> sites;
    return peak_memory_in_child([&] { sites = make_sites(set, n); },
                                [&] {
                                    DelaunayGraph g(std::make_unique<EllipseDelaunayTraits>(sites));
                                    g.insert_all();
                                    for (SiteId s : removal_order(sites.size())) g.remove(s);
                                });
}

PeakMemory cgal_memory(long n) {
    std::vector<AG::Site_2> input;
    return peak_memory_in_child([&] { input = cgal_sites(make_sites("circles", n)); },
                                [&] {
                                    const CgalSiteIds site_id(input);
                                    AGH ag;
                                    ag.insert(input.begin(), input.end());
                                    std::vector<AGH::Vertex_handle> vertex(input.size());
                                    for (auto v = ag.finite_vertices_begin(); v != ag.finite_vertices_end(); ++v)
                                        vertex[site_id(v->site())] = v;
                                    for (SiteId s : removal_order(input.size())) ag.remove(vertex[s]);
                                });
}

std::string memory_mb(const PeakMemory& m) {
    if (m.peak_kb < 0) return "-";
    return fmt("%.1f", m.peak_kb / 1024.0) + " (+" + fmt("%.1f", (m.peak_kb - m.start_kb) / 1024.0) + ")";
}

// Peak memory first, in children of a process that has done no large work yet (n >= 10^4).
std::vector<std::pair<std::string, PeakMemory>> measure_peak_memory(const std::vector<long>& sizes) {
    std::vector<std::pair<std::string, PeakMemory>> memory;
    for (long n : sizes) {
        if (n < 10000) continue;
        memory.push_back({"ellvor ellipses " + std::to_string(n), ellvor_memory("ellipses", n)});
        memory.push_back({"ellvor circles " + std::to_string(n), ellvor_memory("circles", n)});
        memory.push_back({"cgal-hierarchy circles " + std::to_string(n), cgal_memory(n)});
    }
    return memory;
}

// Build and removals of every set at every n: ellvor, and CGAL on the circles.
std::vector<Row> measure_removals(const std::vector<long>& sizes, int& anomalies) {
    std::vector<Row> rows;
    for (long n : sizes)
        for (const std::string set : {"ellipses", "circles"}) {
            const std::vector<Ellipse> sites = make_sites(set, n);
            const std::vector<SiteId> removals = removal_order(sites.size());
            Summary after;
            rows.push_back(run_ellvor(set, sites, removals, after, anomalies));
            if (set == std::string("circles")) {
                rows.push_back(run_cgal<AGH>("cgal-hierarchy", sites, removals, after, anomalies));
                if (n <= 10000) rows.push_back(run_cgal<AG>("cgal-plain", sites, removals, after, anomalies));
            }
            const Row& r = rows[rows.size() - (set == std::string("circles") ? (n <= 10000 ? 3 : 2) : 1)];
            std::cerr << "[removal_scaling] " << set << " n " << n << ": insertion " << fmt("%.1f", r.insert_us())
                      << " us, removal " << fmt("%.1f", r.remove_us()) << " us (" << fmt("%.2f", r.remove_us() / r.insert_us())
                      << "x), " << r.check << "\n";
        }
    return rows;
}

// removal.csv: every row.
Table csv_table(const std::vector<Row>& rows) {
    Table t("removal", {"library", "set", "n", "removed", "insert_cpu_seconds", "insert_us_per_site",
                        "remove_cpu_seconds", "remove_us_per_site", "remove_over_insert", "check"});
    for (const Row& r : rows)
        t.add({r.library, r.set, integer(r.n), integer(static_cast<long long>(r.removed)), fmt("%.6g", r.insert_cpu),
               fmt("%.4g", r.insert_us()), fmt("%.6g", r.remove_cpu), fmt("%.4g", r.remove_us()),
               fmt("%.3g", r.remove_us() / r.insert_us()), r.check});
    return t;
}

Table time_table(const std::vector<Row>& rows) {
    Table t("times", {"library", "set", "n", "removed", "insertion (us / site)", "removal (us / site)",
                      "removal / insertion", "check"},
            "llrrrrrl");
    for (const Row& r : rows)
        t.add({r.library, r.set, integer(r.n), integer(static_cast<long long>(r.removed)), fmt("%.1f", r.insert_us()),
               fmt("%.1f", r.remove_us()), fmt("%.2f", r.remove_us() / r.insert_us()), r.check});
    return t;
}

Table cgal_ratio_table(const std::vector<Row>& rows) {
    Table t("against_cgal", {"n", "peer", "insertion ratio", "removal ratio"}, "rlrr");
    for (const Row& mine : rows) {
        if (mine.library != "ellvor" || mine.set != "circles") continue;
        for (const Row& peer : rows)
            if (peer.library != "ellvor" && peer.n == mine.n)
                t.add({integer(mine.n), peer.library, fmt("%.2f", mine.insert_us() / peer.insert_us()),
                       fmt("%.2f", mine.remove_us() / peer.remove_us())});
    }
    return t;
}

Table removal_kind_table(const std::vector<Row>& rows) {
    Table t("removal_kinds", {"set", "n", "small graph", "flips", "rebuilds"});
    for (const Row& r : rows)
        if (r.library == "ellvor")
            t.add({r.set, integer(r.n), integer(static_cast<long long>(r.graph.small_graph_removals)),
                   integer(static_cast<long long>(r.graph.degenerate_flips)),
                   integer(static_cast<long long>(r.graph.removal_rebuilds))});
    return t;
}

Table memory_table(const std::vector<std::pair<std::string, PeakMemory>>& memory) {
    Table t("memory", {"run", "peak RSS"});
    for (const auto& [name, m] : memory) t.add({name, memory_mb(m)});
    return t;
}

}  // namespace

int main(int argc, char** argv) {
    BenchArguments args;
    if (!parse_bench_arguments(argc, argv, "removal_scaling",
                               "usage: removal_scaling [--full] [--out DIR]\n"
                               "  --full     also n = 10^5 (minutes)\n"
                               "  --out DIR  write DIR/removal.csv and DIR/removal.md\n",
                               args))
        return 2;
    std::vector<long> sizes = {1000, 10000};
    if (args.full) sizes.push_back(100000);
    Report report("Deletion: removal against insertion, and against CGAL's remove", "removal_scaling", args.command);

    // The measurements.
    int anomalies = 0;
    const auto memory = measure_peak_memory(sizes);
    const std::vector<Row> rows = measure_removals(sizes, anomalies);

    // The report.
    report.note("Sets: ellipses: " + describe_set("ellipses") + "; circles: " + describe_set("circles"));
    report.note("Each library builds the graph, then removes the same tenth of the sites in the same random order "
                "(seed " + std::to_string(kRemovalSeed) +
                "). CPU time of all insertions and of all removals, once; per site.");
    report.note("Checks: ellvor's graph after the removals passes validate(), equals the graph built from the "
                "remaining sites (n <= 10^4), and on circles equals CGAL's after the same removals.");
    report.table(time_table(rows));
    report.text("\n");
    report.table(cgal_ratio_table(rows),
                 "ellvor against CGAL on circles, the same run (ratio of times per site; > 1: ellvor slower):");
    report.text("\n");
    report.table(removal_kind_table(rows), "How ellvor removed the vertices (GraphStats): removals through the "
                                           "neighbours' small graph / edges of length 0 flipped / rebuilds:");
    if (!memory.empty()) {
        report.text("\n");
        report.table(memory_table(memory), "Peak RSS (MB) of the build plus the removals in a forked child (growth "
                                           "over the child's start in parentheses):");
    }

    report.publish(args.out_dir, "removal.md", {{"removal.csv", csv_table(rows).csv()}});
    return anomalies ? 1 : 0;
}
