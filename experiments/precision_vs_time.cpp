// Precision versus time of the certified Voronoi circle (the paper, Table 1,
// row "subdivision": 2^-b reached in 0.20 / 0.58 / 1.06 / 10.65 / 31.61 s for
// b = 53 / 900 / 2000 / 12000 / 24000).
//
// For a few ordered ellipse triples, each with a counter-clockwise Voronoi
// circle, the wall time of a fresh VoronoiCircleSolver's refine(b) (which
// certifies first): construction + floating-point guess + Krawczyk certificate
// at 64 bits + Newton doubling + final certificate. Small b: median of
// repetitions (repeat until 0.2 s of measured time and 3 runs, at most 50); 10^6 bits:
// once, and only with --full.
//
//   build/experiments/precision_vs_time                  # default (make bench): b <= 100000, stdout only
//   build/experiments/precision_vs_time --full --out experiments/results
//       # adds b = 10^6 and writes precision_vs_time.csv and .md into the folder
//
// Every enclosure is checked against the most accurate one of its triple
// (all six components must overlap); a failed certificate or a mismatch is
// printed as an ANOMALY and makes the program exit with status 1.
#include "experiments/random_sites.hpp"
#include "experiments/report.hpp"
#include "experiments/run_environment.hpp"
#include "predicates/voronoi_circle_count.hpp"
#include "sites/ellipse.hpp"
#include "sites/site_generators.hpp"
#include "subdivision/voronoi_circle_enclosure.hpp"
#include "util/error.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using namespace ellvor;

namespace {

using namespace ellvor::experiments;

struct Triple {
    std::string name, description;
    std::vector<Ellipse> sites;  // ordered so that the counter-clockwise circle exists
};

// Puts the triple in an order with a counter-clockwise Voronoi circle (swaps
// E2 and E3 if only the clockwise one exists). False if neither exists.
bool orient(std::vector<Ellipse>& s) {
    const VoronoiCircles c = *voronoi_circle_count(s[0], s[1], s[2]);
    if (c == VoronoiCircles::ccw_only || c == VoronoiCircles::both) return true;
    if (c == VoronoiCircles::cw_only) {
        std::swap(s[1], s[2]);
        return true;
    }
    return false;
}

bool certifies(const std::vector<Ellipse>& s) {
    VoronoiCircleSolver solver(s[0], s[1], s[2]);
    return solver.certify();
}

Triple make_triple(const std::string& name, const std::string& description, std::vector<Ellipse> s) {
    if (!orient(s) || !certifies(s)) throw Error("triple " + name + " has no certifiable counter-clockwise circle");
    return {name, description, std::move(s)};
}

std::string sites_text(const std::vector<Ellipse>& s) {
    std::string out;
    for (std::size_t i = 0; i < s.size(); ++i) out += (i ? " | " : "") + s[i].str();
    return out;
}

// The first random triple of `kind` (count 3, bits 4, box 10, seeds 1, 2, ...)
// that has a certifiable counter-clockwise circle, ordered for it.
Triple first_random_triple(SiteKind kind, const std::string& name, const std::string& kind_name) {
    for (std::uint64_t seed = 1;; ++seed) {
        std::vector<Ellipse> s = random_sites(kind, 3, seed, 4, Rational(10));
        if (!orient(s) || !certifies(s)) continue;
        return {name, "generate_sites(" + kind_name + ", count 3, bits 4, box 10, seed " + std::to_string(seed) + ")",
                std::move(s)};
    }
}

std::vector<Triple> triples() {
    std::vector<Triple> out;
    // (1) Paper style: random ellipses with small rational parameters.
    out.push_back(first_random_triple(SiteKind::ellipses, "random", "ellipses"));
    // (2) Circles: random circles with small rational parameters (generic).
    out.push_back(first_random_triple(SiteKind::circles, "circles", "circles"));
    // (2') The base triple of the paper's InCircle dataset (1): its Voronoi
    // circle is the unit circle centered at 0 (rational, several parameters
    // exactly 0), a special rather than a typical case.
    out.push_back(make_triple("circles-set1", "paper InCircle set (1): (-3,0) r 2, (3/2,0) r 1/2, (0,-2) r 1",
                              {Ellipse::circle(Rational(-3), Rational(0), Rational(2)),
                               Ellipse::circle(Rational(3, 2), Rational(0), Rational(1, 2)),
                               Ellipse::circle(Rational(0), Rational(-2), Rational(1))}));
    // (3) Elongated: a/b = 10, three orientations around a common empty disk.
    out.push_back(make_triple("elongated", "a = 10, b = 1; w = 0, 1/2, -1/3 (no symmetry)",
                              {Ellipse(Rational(10), Rational(1), Rational(0), Rational(0), Rational(-14)),
                               Ellipse(Rational(10), Rational(1), Rational(1, 2), Rational(13), Rational(9)),
                               Ellipse(Rational(10), Rational(1), Rational(-1, 3), Rational(-12), Rational(10))}));
    // (4) Tangency near the i-point: E1 (a = 2, b = 1, w = 0, centered at 0)
    // has its i-point at (-2, 0); two unit circles to the left, nearly
    // symmetric about the x-axis, make the circle touch E1 just off it.
    out.push_back(make_triple("i-point", "E1 = (2, 1, w 0, (0,0)), i-point (-2,0); circles (-6,3) r 1, (-6,-3-1/64) r 1",
                              {Ellipse(Rational(2), Rational(1), Rational(0), Rational(0), Rational(0)),
                               Ellipse::circle(Rational(-6), Rational(3), Rational(1)),
                               Ellipse::circle(Rational(-6), Rational(-3) - Rational(1, 64), Rational(1))}));
    return out;
}


struct Measurement {
    std::string triple;
    long bits = 0;
    double seconds = 0, cpu_seconds = 0;
    int repetitions = 0;
    long newton_steps = 0, correct_bits = 0, precision = 0;
    bool ok = true;
    VoronoiCircleEnclosure enclosure;
};


Measurement measure(const Triple& t, long bits, bool once) {
    Measurement m;
    m.triple = t.name;
    m.bits = bits;
    std::vector<double> wall, cpu;
    double total = 0;
    while (true) {
        const double w0 = now_wall(), c0 = now_cpu();
        VoronoiCircleSolver solver(t.sites[0], t.sites[1], t.sites[2]);
        const bool ok = solver.refine(bits);
        const double w1 = now_wall(), c1 = now_cpu();
        wall.push_back(w1 - w0);
        cpu.push_back(c1 - c0);
        total += w1 - w0;
        m.ok = m.ok && ok;
        m.newton_steps = solver.enclosure().newton_steps;
        m.correct_bits = ok ? solver.enclosure().correct_bits() : -1;
        m.precision = solver.enclosure().precision;
        m.enclosure = solver.enclosure();
        if (once || (total >= 0.2 && wall.size() >= 3) || wall.size() >= 50) break;
    }
    m.seconds = median(wall);
    m.cpu_seconds = median(cpu);
    m.repetitions = static_cast<int>(wall.size());
    return m;
}

bool overlaps(const VoronoiCircleEnclosure& a, const VoronoiCircleEnclosure& b) {
    for (int i = 0; i < 3; ++i)
        if (a.flipped[i] != b.flipped[i] || !arb_overlaps(a.parameter[i].get(), b.parameter[i].get())) return false;
    return arb_overlaps(a.radius.get(), b.radius.get()) && arb_overlaps(a.center_x.get(), b.center_x.get()) &&
           arb_overlaps(a.center_y.get(), b.center_y.get());
}


// Every triple at every precision; an enclosure must overlap the most
// accurate one of its triple.
std::vector<std::vector<Measurement>> measure_all(const std::vector<Triple>& ts, const std::vector<long>& bit_list,
                                                  int& anomalies) {
    std::vector<std::vector<Measurement>> results;
    for (const Triple& t : ts) {
        std::cerr << "[precision_vs_time] " << t.name << ": " << sites_text(t.sites) << "\n";
        std::vector<Measurement> row;
        for (long b : bit_list) {
            Measurement m = measure(t, b, b >= 1000000);
            std::cerr << "  b = " << b << ": " << fmt("%.6f", m.seconds) << " s (" << m.repetitions
                      << " reps), newton " << m.newton_steps << ", prec " << m.precision << ", correct "
                      << m.correct_bits << "\n";
            if (!m.ok || m.correct_bits < b) {
                std::cerr << "ANOMALY: " << t.name << " b = " << b << " not certified (correct bits " << m.correct_bits
                          << "); sites " << sites_text(t.sites) << "\n";
                ++anomalies;
            }
            row.push_back(std::move(m));
        }
        for (const Measurement& m : row)
            if (m.ok && !overlaps(m.enclosure, row.back().enclosure)) {
                std::cerr << "ANOMALY: " << t.name << " b = " << m.bits << " enclosure disjoint from b = "
                          << row.back().bits << "\n";
                ++anomalies;
            }
        results.push_back(std::move(row));
    }
    return results;
}

// precision_vs_time.csv: one line per triple and precision.
Table csv_table(const std::vector<std::vector<Measurement>>& results) {
    Table t("precision_vs_time",
            {"triple", "bits", "seconds", "newton_steps", "correct_bits", "precision", "repetitions", "cpu_seconds"});
    for (const auto& row : results)
        for (const Measurement& m : row)
            t.add({m.triple, integer(m.bits), fmt("%.6g", m.seconds), integer(m.newton_steps), integer(m.correct_bits),
                   integer(m.precision), integer(m.repetitions), fmt("%.6g", m.cpu_seconds)});
    return t;
}

// "- **name**: description — `sites`; circle ...": the triples and their circles.
std::string triple_list(const std::vector<Triple>& ts, const std::vector<std::vector<Measurement>>& results) {
    std::ostringstream md;
    for (std::size_t i = 0; i < ts.size(); ++i) {
        const Triple& t = ts[i];
        const VoronoiCircleEnclosure& e = results[i].front().enclosure;
        md << "- **" << t.name << "**: " << t.description << " — `" << sites_text(t.sites) << "`; circle center ("
           << fmt("%.6g", e.center_x.mid_double()) << ", " << fmt("%.6g", e.center_y.mid_double()) << "), radius "
           << fmt("%.6g", e.radius.mid_double()) << "; chart parameters";
        for (int j = 0; j < 3; ++j)
            md << (j ? ", " : " ") << (e.flipped[j] ? "u" : "t") << (j + 1) << " = "
               << fmt("%.4g", e.parameter[j].mid_double());
        md << " (u = -1/t; u = 0 is the i-point)\n";
    }
    return md.str();
}

// The paper's Table 1, row "subdivision" (s), for b = 53 ... 24000.
const std::vector<double> kPaper = {0.20, 0.58, 1.06, 10.65, 31.61};

Table time_table(const std::vector<Triple>& ts, const std::vector<long>& bit_list,
                 const std::vector<std::vector<Measurement>>& results) {
    std::vector<std::string> columns = {"b", "paper (s)"};
    for (const Triple& t : ts) columns.insert(columns.end(), {t.name + " (ms)", "ratio"});
    Table table("times", columns, std::string(columns.size(), 'r'));
    for (std::size_t k = 0; k < bit_list.size(); ++k) {
        TableRow row = {integer(bit_list[k]), k < kPaper.size() ? fmt("%.2f", kPaper[k]) : std::string("—")};
        for (const auto& r : results) {
            row.push_back(fmt("%.3f", r[k].seconds * 1e3));
            row.push_back(k < kPaper.size() ? fmt("%.0f×", kPaper[k] / r[k].seconds) : std::string("—"));
        }
        table.add(std::move(row));
    }
    return table;
}

Table newton_table(const std::vector<Triple>& ts, const std::vector<long>& bit_list,
                   const std::vector<std::vector<Measurement>>& results) {
    std::vector<std::string> columns = {"b"};
    for (const Triple& t : ts) columns.push_back(t.name);
    Table table("newton", columns, std::string(columns.size(), 'r'));
    for (std::size_t k = 0; k < bit_list.size(); ++k) {
        TableRow row = {integer(bit_list[k])};
        for (const auto& r : results) row.push_back(std::to_string(r[k].newton_steps) + " / " + std::to_string(r[k].precision));
        table.add(std::move(row));
    }
    return table;
}

std::vector<Target> targets(const std::vector<std::vector<Measurement>>& results) {
    std::vector<Target> out;
    for (const auto& row : results)
        for (const Measurement& m : row) {
            if (m.bits == 24000)
                out.push_back({m.triple, "24,000 bits in " + fmt("%.2f", m.seconds * 1e3) + " ms", m.seconds <= 0.010});
            if (m.bits == 1000000)
                out.push_back({m.triple, "10^6 bits in " + fmt("%.3f", m.seconds) + " s", m.seconds <= 1.0});
        }
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    BenchArguments args;
    if (!parse_bench_arguments(argc, argv, "precision_vs_time",
                               "usage: precision_vs_time [--full] [--out DIR]\n"
                               "  --full     also certify 10^6 bits (once per triple; minutes in total)\n"
                               "  --out DIR  write DIR/precision_vs_time.csv and DIR/precision_vs_time.md\n",
                               args))
        return 2;
    std::vector<long> bit_list = {53, 900, 2000, 12000, 24000, 100000};
    if (args.full) bit_list.push_back(1000000);
    Report report("Precision versus time: certified Voronoi circle", "precision_vs_time", args.command);

    // The measurements.
    int anomalies = 0;
    const std::vector<Triple> ts = triples();
    const std::vector<std::vector<Measurement>> results = measure_all(ts, bit_list, anomalies);

    // The report.
    report.intro("Wall time of a fresh `VoronoiCircleSolver(e1, e2, e3).refine(b)` (floating-point guess, Krawczyk "
                 "certificate at 64 bits, Newton at doubling precision, final certificate), until every component of "
                 "the enclosure (three tangency parameters, radius, center) has at least b correct bits. Median of "
                 "repetitions (repeat until 0.2 s measured and at least 3 runs, at most 50); b = 10^6 once. Paper: "
                 "Emiris, Tsigaridas, Tzoumas 2007, Table 1, row \"subdivision\" (mpfr, P4 2.6 GHz); ratio = paper / "
                 "ours.");
    report.note("Plot (`precision_vs_time.png`): `/usr/bin/python3 experiments/plot_results.py precision_vs_time`");
    report.note("By default (`make bench`) b = 10^6 is skipped and nothing is written; `--full` adds it, `--out DIR` "
                "writes the CSV and this file.");
    report.text("\nTriples (ordered E1 E2 E3 with a counter-clockwise Voronoi circle; ellipse = `a b w xc yc`):\n\n" +
                triple_list(ts, results) + "\n");
    report.table(time_table(ts, bit_list, results));
    report.text("\n");
    report.table(newton_table(ts, bit_list, results),
                 "Newton steps (cumulative, all precisions) / final working precision (bits):");
    report.text(std::string("\nTargets: 24,000 bits ≤ 10 ms") + (args.full ? "; 10^6 bits ≤ 1 s" : "") + ".\n\n" +
                target_lines(targets(results)) +
                "\nAnomalies (failed certificate, fewer bits than asked, enclosures disagreeing across b): " +
                std::to_string(anomalies) + ".\n" + (args.full ? "" : "\nb = 10^6 skipped (run with --full).\n"));

    report.publish(args.out_dir, "precision_vs_time.md", {{"precision_vs_time.csv", csv_table(results).csv()}});
    return anomalies ? 1 : 0;
}
