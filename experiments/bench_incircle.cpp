// Time per InCircle call (kappa3): ellvor's incircle() on
//   (a) random pairwise-disjoint ellipse quadruples (E1 E2 E3 | Q), ordered so
//       that (E1, E2, E3) has its counter-clockwise Voronoi circle;
//   (b) the paper's InCircle circle datasets (1), (2a), (2b), (2c), (3)
//       (generate_paper_dataset), side by side with CGAL's Apollonius
//       Vertex_conflict_2 on the same circles (the paper's Table 2, last five
//       columns: "Our code" 4.22 / 6.01 / 6.09 / 7.02 / 11.18 ms, Apollonius 0.040 /
//       0.052 / 0.057 / 0.069 / 0.295 ms).
//
// Per instance: the median of `reps` timed calls (ellvor: one call each, the
// Voronoi circle certified afresh every time = cold; CGAL: a batch of 32
// calls divided by 32); per dataset: median and p99 (nearest rank) of the
// per-instance times. Warm: the circle of (E1, E2, E3) (VoronoiCircle, as
// the graph caches it) is made and used once with Q, then the call with
// another query Q' (Q with halved semi-axes, same center: disjoint from the
// triple since it lies inside Q) reusing it is timed. The breakdown times the
// parts of a cold call alone: the kappa2 count, the double-interval
// certificate of the circle, and the Arb solver's refine(48).
//
// CGAL reads doubles: each rational is rounded to the nearest double, so CGAL
// sees rounded input except on set (1) (dyadic). Agreement is counted only
// where ellvor's voronoi_circle_count says the counter-clockwise circle exists
// (ccw_only or both); elsewhere ellvor answers no-circle by the rule of docs/DESIGN.md §2
// and CGAL's sign is an artifact of a vertex that does not exist.
//
//   build/experiments/bench_incircle                      # default (make bench), stdout only
//   build/experiments/bench_incircle --full --out experiments/results
//       # 11 repetitions, 2000 random quadruples; writes incircle.csv (one row per
//       # instance; the sites only for notable rows) and incircle.md into the folder
// Each instance's ellvor calls are first run once in a forked child with a
// 20 s limit: a crash or hang of the library becomes an "error" row.
// Options: --reps N, --random N, --seed S, --bits B (random quadruples), --out DIR.
#include "experiments/random_sites.hpp"
#include "experiments/report.hpp"
#include "experiments/run_environment.hpp"
#include "predicates/incircle.hpp"
#include "predicates/voronoi_circle_count.hpp"
#include "sites/ellipse.hpp"
#include "sites/site_generators.hpp"
#include "subdivision/voronoi_circle.hpp"
#include "util/error.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Apollonius_graph_filtered_traits_2.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <optional>
#include <csignal>
#include <sys/wait.h>
#include <unistd.h>
#include <sstream>
#include <string>
#include <vector>

using namespace ellvor;

namespace {

using namespace ellvor::experiments;

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Traits = CGAL::Apollonius_graph_filtered_traits_2<K>;
using CSite = Traits::Site_2;
using CPoint = Traits::Point_2;

struct Instance {
    std::vector<Ellipse> sites;  // E1 E2 E3
    std::optional<Ellipse> q;
};

struct Dataset {
    std::string name;
    bool circles = false;
    std::vector<Instance> instances;
};

struct Row {
    std::string dataset;
    long index = 0;
    std::string circles;       // voronoi_circle_count of (E1, E2, E3)
    std::string result;        // ellvor's answer (or "error")
    std::string stage;
    long precision = 0, newton_steps = 0;
    double ellvor_us = 0;
    double warm_us = -1;       // only where the CCW circle exists
    std::string warm_result;
    double count_us = -1;      // voronoi_circle_count alone
    double doubles_us = -1;    // the double-interval certificate alone, CCW circle only
    bool doubles_certified = false;
    double solver_us = -1;     // a fresh solver's refine(48) alone (what the 64-bit stage asks), CCW circle only
    int cgal_sign = 2;         // 2: not run (ellipses)
    double cgal_us = -1;
    std::string agree;         // "yes", "no", "n/a" (no CCW circle), "undecided"
    std::string replay;        // the four sites
};




CSite to_cgal(const Ellipse& c) { return CSite(CPoint(c.xc().to_double(), c.yc().to_double()), c.a().to_double()); }

Ellipse shrunk(const Ellipse& q) {
    return Ellipse(q.a() * Rational(1, 2), q.b() * Rational(1, 2), q.w(), q.xc(), q.yc());
}

volatile long sink = 0;

Dataset random_quadruples(long count, std::uint64_t seed, long bits, long& dropped) {
    Dataset ds{"random-ellipses", false, {}};
    for (std::vector<Ellipse>& e : incircle_quadruples(SiteKind::ellipses, count, seed, bits, &dropped)) {
        Ellipse q = e.back();
        e.pop_back();
        ds.instances.push_back({std::move(e), std::move(q)});
    }
    return ds;
}

Dataset paper_set(const std::string& set, std::uint64_t seed, long& swapped) {
    PaperDataset p = generate_paper_dataset(PaperFamily::incircle, set, seed);
    Dataset ds{"paper-" + set, true, {}};
    for (PaperInstance& in : p.instances) {
        // The order the generator gives may have only the clockwise circle
        // (set (1)'s base triple does); swap E2 and E3 then, for both libraries.
        if (*voronoi_circle_count(in.sites[0], in.sites[1], in.sites[2]) == VoronoiCircles::cw_only) {
            std::swap(in.sites[1], in.sites[2]);
            ++swapped;
        }
        ds.instances.push_back({std::move(in.sites), std::move(in.query_site)});
    }
    return ds;
}

std::string sites_text(const Instance& in) {
    return in.sites[0].str() + " | " + in.sites[1].str() + " | " + in.sites[2].str() + " | Q " + in.q->str();
}

int ellvor_sign(InCircle r) {
    switch (r) {
        case InCircle::conflict: return -1;
        case InCircle::no_conflict: return 1;
        case InCircle::tangent: return 0;
        default: return 2;
    }
}

// Runs the instance's ellvor calls (cold, then warm) once in a child process
// with a time limit, so that a crash or a hang in the library is reported as
// an anomaly of that instance instead of ending (or stalling) the benchmark.
// Empty when the calls returned; otherwise what happened.
std::string screen(const Instance& in, unsigned seconds) {
    std::cout.flush();
    std::cerr.flush();
    const pid_t pid = fork();
    if (pid < 0) return std::string();  // cannot screen: run unguarded
    if (pid == 0) {
        alarm(seconds);
        try {
            const Ellipse &e1 = in.sites[0], &e2 = in.sites[1], &e3 = in.sites[2], &q = *in.q;
            incircle(e1, e2, e3, q);
            const VoronoiCircles c = *voronoi_circle_count(e1, e2, e3);
            if (c == VoronoiCircles::ccw_only || c == VoronoiCircles::both) {
                VoronoiCircle circle(e1, e2, e3);
                incircle(e1, e2, e3, q, {}, &circle);
                incircle(e1, e2, e3, shrunk(q), {}, &circle);
            }
        } catch (...) {
        }
        _exit(0);
    }
    int status = 0;
    waitpid(pid, &status, 0);
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return std::string();
    if (WIFSIGNALED(status)) {
        const int sig = WTERMSIG(status);
        return sig == SIGALRM ? "timeout (> " + std::to_string(seconds) + " s)" : "crash (signal " + std::to_string(sig) + ")";
    }
    return "child exit " + std::to_string(WEXITSTATUS(status));
}

Row run_instance(const std::string& dataset, long index, const Instance& in, bool circles, int reps) {
    Row row;
    row.dataset = dataset;
    row.index = index;
    row.replay = sites_text(in);
    const Ellipse &e1 = in.sites[0], &e2 = in.sites[1], &e3 = in.sites[2], &q = *in.q;
    const VoronoiCircles count = *voronoi_circle_count(e1, e2, e3);
    row.circles = voronoi_circles_name(count);
    const bool has_ccw = count == VoronoiCircles::ccw_only || count == VoronoiCircles::both;

    // ellvor, cold (a fresh solver inside every call)
    std::vector<double> t;
    Decision<InCircle> d;
    const std::string failure = screen(in, 20);
    if (!failure.empty()) {
        std::cerr << "ANOMALY: " << dataset << " #" << index << ": " << failure << " — " << row.replay << "\n";
        row.result = "error";
        row.stage = failure;
        row.agree = "error";
        return row;
    }
    try {
        for (int r = 0; r < reps; ++r) {
            const double t0 = now_wall();
            d = incircle(e1, e2, e3, q);
            t.push_back(now_wall() - t0);
            sink += static_cast<int>((*d));
        }
        row.result = (d.is_decided() ? incircle_name(*d) : "undecided");
        row.stage = stage_name(d.stage);
        row.precision = d.precision;
        VoronoiCircle counted(e1, e2, e3);  // one more call, to count its Arb Newton steps
        incircle(e1, e2, e3, q, {}, &counted);
        row.newton_steps = counted.has_solver() ? counted.solver().enclosure().newton_steps : 0;
        row.ellvor_us = median(t) * 1e6;
    } catch (const std::exception& ex) {
        row.result = "error";
        row.stage = ex.what();
    }

    // ellvor, warm: the same triple's circle, another query
    if (has_ccw && row.result != "error") {
        try {
            const Ellipse q2 = shrunk(q);
            VoronoiCircle circle(e1, e2, e3);
            incircle(e1, e2, e3, q, {}, &circle);
            std::vector<double> w;
            Decision<InCircle> d2;
            for (int r = 0; r < reps; ++r) {
                const double t0 = now_wall();
                d2 = incircle(e1, e2, e3, q2, {}, &circle);
                w.push_back(now_wall() - t0);
                sink += static_cast<int>((*d2));
            }
            row.warm_us = median(w) * 1e6;
            row.warm_result = (d2.is_decided() ? incircle_name(*d2) : "undecided");
        } catch (const std::exception& ex) {
            row.warm_result = std::string("error: ") + ex.what();
        }
    }

    // Breakdown: the kappa2-based circle count, the double-interval
    // certificate and the Arb solver, each alone.
    {
        std::vector<double> a, b, c;
        for (int r = 0; r < reps; ++r) {
            double t0 = now_wall();
            sink += static_cast<int>(*voronoi_circle_count(e1, e2, e3));
            a.push_back(now_wall() - t0);
            if (!has_ccw) continue;
            t0 = now_wall();
            row.doubles_certified = certify_voronoi_circle_in_doubles(e1, e2, e3).has_value();
            c.push_back(now_wall() - t0);
            t0 = now_wall();
            VoronoiCircleSolver solver(e1, e2, e3);
            sink += solver.refine(48);
            b.push_back(now_wall() - t0);
        }
        row.count_us = median(a) * 1e6;
        if (!b.empty()) row.solver_us = median(b) * 1e6;
        if (!c.empty()) row.doubles_us = median(c) * 1e6;
    }

    // CGAL on the rounded circles
    if (circles) {
        const Traits traits;
        const auto vc = traits.vertex_conflict_2_object();
        const CSite p1 = to_cgal(e1), p2 = to_cgal(e2), p3 = to_cgal(e3), cq = to_cgal(q);
        constexpr int kBatch = 32;
        std::vector<double> c;
        CGAL::Sign s = CGAL::ZERO;
        for (int r = 0; r < reps; ++r) {
            const double t0 = now_wall();
            for (int k = 0; k < kBatch; ++k) {
                // The sites escape and memory is clobbered: every call is evaluated anew.
                asm volatile("" : : "r"(&p1), "r"(&p2), "r"(&p3), "r"(&cq) : "memory");
                s = vc(p1, p2, p3, cq);
                asm volatile("" : : "r"(&s) : "memory");
            }
            c.push_back((now_wall() - t0) / kBatch);
            sink += static_cast<int>(s);
        }
        row.cgal_sign = static_cast<int>(s);
        row.cgal_us = median(c) * 1e6;
        if (!has_ccw)
            row.agree = "n/a";
        else if (row.result == "undecided" || row.result == "error")
            row.agree = "undecided";
        else
            row.agree = ellvor_sign((*d)) == row.cgal_sign ? "yes" : "no";
    } else {
        row.agree = "-";
    }
    return row;
}




// Rows whose sites go into the CSV (the others are replayed from dataset and
// index: the generators are deterministic).
bool notable(const Row& r) {
    return r.agree == "no" || r.result == "undecided" || r.result == "error" || r.result == "tangent" ||
           r.warm_result == "undecided" || r.warm_result == "tangent" || r.warm_result.rfind("error", 0) == 0;
}

// ------------------------------------------------------------ measurements --

struct Options {
    int reps = 3;
    long random_count = 500, bits = 8;
    std::uint64_t seed = 1;
    bool full = false;
    std::string out_dir, command;
};

// The random quadruples, then the paper's five InCircle sets.
struct Datasets {
    std::vector<Dataset> sets;
    long dropped = 0;                 // random quadruples without either circle
    std::vector<long> swapped_count;  // per paper set: instances with E2, E3 swapped
};

Datasets make_datasets(const Options& o) {
    Datasets d;
    d.sets.push_back(random_quadruples(o.random_count, o.seed, o.bits, d.dropped));
    for (const char* s : {"1", "2a", "2b", "2c", "3"}) {
        long swapped = 0;
        d.sets.push_back(paper_set(s, o.seed, swapped));
        d.swapped_count.push_back(swapped);
    }
    return d;
}

// Every instance of every dataset, one row each.
std::vector<Row> measure_instances(const std::vector<Dataset>& datasets, int reps) {
    std::vector<Row> rows;
    for (const Dataset& ds : datasets) {
        std::cerr << "[bench_incircle] " << ds.name << ": " << ds.instances.size() << " instances\n";
        const double t0 = now_wall();
        for (std::size_t i = 0; i < ds.instances.size(); ++i)
            rows.push_back(run_instance(ds.name, static_cast<long>(i), ds.instances[i], ds.circles, reps));
        std::cerr << "  done in " << fmt("%.2f", now_wall() - t0) << " s\n";
    }
    return rows;
}

// Cross-check of CGAL's per-call time: whole passes over a dataset (a new
// input every call), best of max(reps, 5) passes, divided by the instance
// count (NAN for the ellipse sets).
std::vector<double> cgal_pass_times(const std::vector<Dataset>& datasets, int reps) {
    std::vector<double> cgal_pass_us(datasets.size(), NAN);
    for (std::size_t k = 0; k < datasets.size(); ++k) {
        const Dataset& ds = datasets[k];
        if (!ds.circles) continue;
        std::vector<std::array<CSite, 4>> sites;
        for (const Instance& in : ds.instances)
            sites.push_back({to_cgal(in.sites[0]), to_cgal(in.sites[1]), to_cgal(in.sites[2]), to_cgal(*in.q)});
        const Traits traits;
        const auto vc = traits.vertex_conflict_2_object();
        double best = 1e300;
        for (int r = 0; r < std::max(reps, 5); ++r) {
            const double t0 = now_wall();
            long acc = 0;
            for (const auto& s4 : sites) acc += static_cast<int>(vc(s4[0], s4[1], s4[2], s4[3]));
            best = std::min(best, now_wall() - t0);
            sink += acc;
        }
        cgal_pass_us[k] = best / sites.size() * 1e6;
    }
    return cgal_pass_us;
}

// ----------------------------------------------------------------- summary --

// One dataset's rows, gathered.
struct DatasetSummary {
    std::vector<double> ellvor, cgal, warm, cold_same, count, doubles, solver;
    long certified_in_doubles = 0;
    long circles[4] = {0, 0, 0, 0}, results[6] = {0, 0, 0, 0, 0, 0}, agree = 0, compared = 0, disagree = 0,
         max_precision = 0;
    StageCounters stages;
};

DatasetSummary summarize(const Dataset& ds, const std::vector<Row>& rows) {
    DatasetSummary s;
    for (const Row& r : rows) {
        if (r.dataset != ds.name) continue;
        if (r.result != "error") s.ellvor.push_back(r.ellvor_us);
        if (r.cgal_us >= 0) s.cgal.push_back(r.cgal_us);
        if (r.count_us >= 0) s.count.push_back(r.count_us);
        if (r.solver_us >= 0) s.solver.push_back(r.solver_us);
        if (r.doubles_us >= 0) s.doubles.push_back(r.doubles_us);
        s.certified_in_doubles += r.doubles_certified;
        if (r.warm_us >= 0) {
            s.warm.push_back(r.warm_us);
            s.cold_same.push_back(r.ellvor_us);
        }
        const char* names[4] = {"none", "ccw", "cw", "both"};
        for (int k = 0; k < 4; ++k) s.circles[k] += r.circles == names[k];
        const char* rn[6] = {"conflict", "no-conflict", "tangent", "no-circle", "undecided", "error"};
        for (int k = 0; k < 6; ++k) s.results[k] += r.result == rn[k];
        if (r.result != "undecided" && r.result != "error")
            for (Stage stage : kStages)
                if (r.stage == stage_name(stage)) s.stages.record(stage);
        s.max_precision = std::max(s.max_precision, r.precision);
        if (r.agree == "yes" || r.agree == "no") ++s.compared;
        s.agree += r.agree == "yes";
        s.disagree += r.agree == "no";
    }
    return s;
}

// The paper's ratio ellvor / Apollonius per circle set (Emiris, Tsigaridas,
// Tzoumas 2007, Table 2, ms per call: 4.22 / 6.01 / 6.09 / 7.02 / 11.18
// against 0.040 / 0.052 / 0.057 / 0.069 / 0.295).
std::string paper_ratio(const std::string& dataset) {
    const std::vector<std::pair<std::string, double>> ratios = {
        {"paper-1", 4.220 / 0.040}, {"paper-2a", 6.010 / 0.052}, {"paper-2b", 6.090 / 0.057},
        {"paper-2c", 7.017 / 0.069}, {"paper-3", 11.180 / 0.295}};
    for (const auto& [name, ratio] : ratios)
        if (name == dataset) return fmt("%.0f×", ratio);
    return "—";
}

std::string or_dash(bool have, const std::string& s) { return have ? s : "—"; }

Table time_table(const std::vector<Dataset>& datasets, const std::vector<DatasetSummary>& sums,
                 const std::vector<double>& cgal_pass_us) {
    Table t("times", {"dataset", "n", "ellvor median µs", "ellvor p99 µs", "CGAL median µs", "CGAL p99 µs",
                      "ratio (medians)", "paper ratio", "warm median µs", "cold (same) median µs",
                      "CGAL pass µs/call"});
    for (std::size_t k = 0; k < datasets.size(); ++k) {
        const Dataset& ds = datasets[k];
        const DatasetSummary& s = sums[k];
        const double em = median(s.ellvor), cm = s.cgal.empty() ? NAN : median(s.cgal);
        const bool cgal = !s.cgal.empty();
        t.add({ds.name, integer(static_cast<long long>(ds.instances.size())), fmt("%.1f", em),
               fmt("%.1f", quantile(s.ellvor, 0.99)), or_dash(cgal, fmt("%.2f", cm)),
               or_dash(cgal, fmt("%.2f", quantile(s.cgal, 0.99))), or_dash(cgal, fmt("%.1f×", em / cm)),
               paper_ratio(ds.name), or_dash(!s.warm.empty(), fmt("%.1f", median(s.warm))),
               or_dash(!s.cold_same.empty(), fmt("%.1f", median(s.cold_same))),
               or_dash(ds.circles, fmt("%.3f", cgal_pass_us[k]))});
    }
    return t;
}

// Targets: median <= 5 µs on random ellipses, <= 3x CGAL on circles.
long rows_missing_a_target(const std::vector<Dataset>& datasets, const std::vector<DatasetSummary>& sums) {
    long bad = 0;
    for (std::size_t k = 0; k < datasets.size(); ++k) {
        const double em = median(sums[k].ellvor), cm = sums[k].cgal.empty() ? NAN : median(sums[k].cgal);
        if (datasets[k].name == "random-ellipses" && em > 5) ++bad;
        if (datasets[k].circles && em > 3 * cm) ++bad;
    }
    return bad;
}

Table breakdown_table(const std::vector<Dataset>& datasets, const std::vector<DatasetSummary>& sums) {
    Table t("breakdown", {"dataset", "voronoi_circle_count median µs", "double-interval certificate median µs",
                          "certified in doubles", "solver refine(48) median µs", "solver p99 µs"});
    for (std::size_t k = 0; k < datasets.size(); ++k) {
        const DatasetSummary& s = sums[k];
        const bool dbl = !s.doubles.empty(), sol = !s.solver.empty();
        t.add({datasets[k].name, fmt("%.1f", median(s.count)), or_dash(dbl, fmt("%.1f", median(s.doubles))),
               or_dash(dbl, std::to_string(s.certified_in_doubles) + " / " + std::to_string(s.doubles.size())),
               or_dash(sol, fmt("%.1f", median(s.solver))), or_dash(sol, fmt("%.1f", quantile(s.solver, 0.99)))});
    }
    return t;
}

Table stage_table(const std::vector<Dataset>& datasets, const std::vector<DatasetSummary>& sums) {
    Table t("stages", {"dataset", "circles none/ccw/cw/both", "conflict", "no-conflict", "tangent", "no-circle",
                       "undecided", "error", "decided by filter/subdivision/symmetry/exact", "max precision",
                       "agree / compared", "disagree"},
            "llrrrrrrlrlr");
    for (std::size_t k = 0; k < datasets.size(); ++k) {
        const Dataset& ds = datasets[k];
        const DatasetSummary& s = sums[k];
        std::string decided;
        for (Stage stage : kStages) decided += (decided.empty() ? "" : "/") + std::to_string(s.stages[stage]);
        TableRow row = {ds.name, std::to_string(s.circles[0]) + "/" + std::to_string(s.circles[1]) + "/" +
                                     std::to_string(s.circles[2]) + "/" + std::to_string(s.circles[3])};
        for (long n : s.results) row.push_back(integer(n));
        row.insert(row.end(), {decided, integer(s.max_precision),
                               or_dash(ds.circles, std::to_string(s.agree) + " / " + std::to_string(s.compared)),
                               or_dash(ds.circles, std::to_string(s.disagree))});
        t.add(std::move(row));
    }
    return t;
}

// Undecided, error, tangent, a disagreement with CGAL: at most `shown` lines.
std::string anomaly_lines(const std::vector<Row>& rows, std::size_t shown) {
    std::vector<const Row*> anomalies;
    for (const Row& r : rows)
        if (r.agree == "no" || r.result == "undecided" || r.result == "error" || r.result == "tangent" ||
            r.warm_result == "undecided" || r.warm_result.rfind("error", 0) == 0)
            anomalies.push_back(&r);
    if (anomalies.empty()) return "None.\n";
    std::ostringstream md;
    for (std::size_t k = 0; k < anomalies.size() && k < shown; ++k) {
        const Row& r = *anomalies[k];
        md << "- " << r.dataset << " #" << r.index << ": ellvor " << r.result << " (" << r.stage << ", prec "
           << r.precision << "), warm " << (r.warm_result.empty() ? "—" : r.warm_result) << ", CGAL "
           << (r.cgal_sign == 2 ? std::string("—") : std::to_string(r.cgal_sign)) << ", circles " << r.circles
           << " — `" << r.replay << "`\n";
    }
    if (anomalies.size() > shown) md << "- … " << anomalies.size() - shown << " more (see incircle.csv)\n";
    return md.str();
}

// incircle.csv: one line per instance; the sites only for notable rows.
Table instance_table(const std::vector<Row>& rows) {
    Table t("incircle", {"dataset", "index", "circles", "result", "stage", "precision", "newton_steps", "ellvor_us",
                         "warm_us", "warm_result", "cgal_sign", "cgal_us", "agree", "count_us", "solver_us", "sites"});
    for (const Row& r : rows)
        t.add({r.dataset, integer(r.index), r.circles, r.result, r.stage, integer(r.precision), integer(r.newton_steps),
               fmt("%.3f", r.ellvor_us), r.warm_us >= 0 ? fmt("%.3f", r.warm_us) : std::string(), r.warm_result,
               r.cgal_sign == 2 ? std::string() : std::to_string(r.cgal_sign),
               r.cgal_us >= 0 ? fmt("%.4f", r.cgal_us) : std::string(), r.agree, fmt("%.3f", r.count_us),
               r.solver_us >= 0 ? fmt("%.3f", r.solver_us) : std::string(), notable(r) ? r.replay : std::string()});
    return t;
}

bool parse_options(int argc, char** argv, Options& o) {
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto next = [&]() -> const char* {
            if (i + 1 >= argc) {
                std::cerr << "missing value after " << a << "\n";
                std::exit(2);
            }
            return argv[++i];
        };
        if (a == "--full") {
            o.full = true;
        } else if (a == "--reps") {
            o.reps = std::atoi(next());
        } else if (a == "--random") {
            o.random_count = std::atol(next());
        } else if (a == "--seed") {
            o.seed = std::strtoull(next(), nullptr, 10);
        } else if (a == "--bits") {
            o.bits = std::atol(next());
        } else if (a == "--out") {
            o.out_dir = next();
        } else {
            std::cerr << "usage: bench_incircle [--full] [--reps N] [--random N] [--seed S] [--bits B] [--out DIR]\n";
            return false;
        }
    }
    if (o.full) {
        o.reps = std::max(o.reps, 11);
        o.random_count = std::max(o.random_count, 2000L);
    }
    if (o.reps < 1 || o.random_count < 1) {
        std::cerr << "reps and random must be positive\n";
        return false;
    }
    o.command = "build/experiments/bench_incircle";
    for (int i = 1; i < argc; ++i) o.command += std::string(" ") + argv[i];
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    Options o;
    if (!parse_options(argc, argv, o)) return 2;
    Report report("InCircle: time per call, ellvor vs CGAL Apollonius", "bench_incircle", o.command);

    // The measurements.
    const Datasets data = make_datasets(o);
    const std::vector<Row> rows = measure_instances(data.sets, o.reps);
    const std::vector<double> cgal_pass_us = cgal_pass_times(data.sets, o.reps);
    std::vector<DatasetSummary> sums;
    for (const Dataset& ds : data.sets) sums.push_back(summarize(ds, rows));

    // The report.
    const std::vector<long>& sw = data.swapped_count;
    report.note("Repetitions per instance: " + std::to_string(o.reps) +
                " (per-instance time = median of the repetitions; ellvor: one call each, the circle certified afresh; "
                "CGAL: batches of 32 calls / 32); median and p99 (nearest rank) over instances. \"CGAL pass\": best "
                "of " + std::to_string(std::max(o.reps, 5)) +
                " whole passes over the dataset (a new input every call) / n, a cross-check.");
    report.note("Random ellipses: generate_sites(ellipses, count 4, bits " + std::to_string(o.bits) + ", box 10, seeds " +
                std::to_string(o.seed) + ", " + std::to_string(o.seed + 1) +
                ", ...): E1 E2 E3 | Q, E2 and E3 swapped when only the clockwise circle exists; " +
                std::to_string(data.dropped) + " quadruples without either circle skipped.");
    report.note("Paper sets: generate_paper_dataset(incircle, set, seed " + std::to_string(o.seed) +
                "), circles; E2 and E3 swapped for both libraries where only the clockwise circle exists (instances "
                "swapped: 1: " + std::to_string(sw[0]) + ", 2a: " + std::to_string(sw[1]) + ", 2b: " +
                std::to_string(sw[2]) + ", 2c: " + std::to_string(sw[3]) + ", 3: " + std::to_string(sw[4]) +
                "). CGAL: Apollonius_graph_filtered_traits_2<Epick>::Vertex_conflict_2 on the circles rounded to "
                "double (exact input only for set (1), which is dyadic).");
    report.note("Warm: a second call on the same triple with Q' = Q with halved semi-axes, reusing the triple's "
                "VoronoiCircle (as the graph caches it); only where the CCW circle exists. \"cold (same)\" is the "
                "cold median over those same instances.");
    report.note("Agreement: sign of ellvor (conflict -1, no-conflict +1, tangent 0) vs CGAL's sign, only where "
                "voronoi_circle_count is ccw or both. Paper ratio: Emiris, Tsigaridas, Tzoumas 2007, Table 2.");
    report.table(time_table(data.sets, sums, cgal_pass_us));
    report.text("\nTargets: median ≤ 5 µs on random ellipses; ≤ 3× CGAL on circles (the paper: 38–116× slower "
                "than CGAL). Rows missing a target: " +
                std::to_string(rows_missing_a_target(data.sets, sums)) + ".\n");

    report.heading("Where the cold time goes");
    report.table(breakdown_table(data.sets, sums),
                 "Each part of a cold call timed alone (median of the repetitions per instance, median over instances; "
                 "the certificates only where the CCW circle exists). On ellipses a cold call is the double-interval "
                 "certificate + d(V, Q) in double intervals; only when that does not decide, the count + the Arb "
                 "solver + the distance at 64 bits. Four circles take the closed form.");

    report.heading("Which stage decided");
    report.table(stage_table(data.sets, sums));
    report.text("\nStages of answered calls by the last stage that ran; max precision = largest Arb precision any "
                "call used (the cap is 4096).\n");

    report.heading("Anomalies and degenerate cases (undecided, error = crash/timeout/exception in a child run, "
                   "tangent, disagreement with CGAL where the CCW circle exists)");
    report.text(anomaly_lines(rows, 20));

    report.publish(o.out_dir, "incircle.md", {{"incircle.csv", instance_table(rows).csv()}});
    return 0;
}
