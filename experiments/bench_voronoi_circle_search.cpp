// Cost of the exhaustive certified search for the counter-clockwise Voronoi
// circle (subdivision/voronoi_circle_search.hpp), the complete fallback that
// VoronoiCircleSolver::certify() runs when no floating-point guess certifies.
//
// Every call uses a fresh solver: certify_by_search() forces the search,
// certify() is the default path (guesses first, the search only if they all
// fail). Rows:
//   ellipses   random ellipse triples with a CCW circle: search vs default;
//   circles    random circle triples with a CCW circle: search vs default;
//   no-circle  random ellipse triples without one, a row for count cw_only
//              and one for none: the search proves absence, and so must
//              the default path (its guesses fail first);
//   offset X   4 2 0 X 0 / 3 3/2 1/3 X+10 0 / 5/2 5/2 0 X+5 8 for X = 0,
//              10^14, 10^30, 10^100 (sites far from the origin);
//   line k     unit circles at (0,0), (3,10^-k), (6,0), ordered to have a
//              CCW circle (radius ~10^k): near the degenerate collinear
//              triple, on which the search cannot terminate. k = 3, 6, 12;
//              --full adds 16 and 17, the last k that certifies and the
//              first that runs into the search's box cap (see the results).
//
// Checks (each failure is a disagreement, printed as ANOMALY, exit status 1):
// both paths certify exactly when voronoi_circle_count says a CCW circle
// exists, and the two certified enclosures overlap in every component. A call
// that hits the box cap (Error) is no wrong answer but also fails the
// contract for a non-degenerate triple: counted apart, printed as CAP HIT,
// exit status 1 as well.
//
//   build/experiments/bench_voronoi_circle_search          # make bench: 30 random triples a row, < 30 s
//   build/experiments/bench_voronoi_circle_search --full --out experiments/results
//       # 200 random triples a row, more repetitions; writes voronoi_circle_search.{csv,md}
#include "experiments/random_sites.hpp"
#include "experiments/report.hpp"
#include "experiments/run_environment.hpp"
#include "predicates/voronoi_circle_count.hpp"
#include "sites/ellipse.hpp"
#include "sites/site_generators.hpp"
#include "subdivision/voronoi_circle_enclosure.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using namespace ellvor;

namespace {

using Triple = std::array<Ellipse, 3>;

struct Case {
    std::string label;  // seed or parameter, for the CSV
    Triple sites;
    VoronoiCircles count;
};

struct Row {
    std::string group, name, description;  // group: rows of one family share it and the description
    std::vector<Case> cases;
    int repetitions = 1;  // calls per case
};

// One call on a fresh solver.
struct Call {
    double seconds = 0;
    bool found = false, threw = false;
    long boxes = 0;
    VoronoiCircleEnclosure enclosure;
    const char* result() const { return threw ? "cap" : found ? "found" : "none"; }
};

struct Sample {
    std::string row, label, count;
    int repetition = 0;
    Call search, fallback;  // certify_by_search() / certify()
    bool disagreement = false, cap = false;
};

bool has_ccw(VoronoiCircles c) { return c == VoronoiCircles::ccw_only || c == VoronoiCircles::both; }

Call run(const Triple& s, bool forced) {
    Call c;
    VoronoiCircleSolver solver(s[0], s[1], s[2]);
    const auto start = std::chrono::steady_clock::now();
    try {
        c.found = forced ? solver.certify_by_search() : solver.certify();
    } catch (const std::exception&) {  // the search's box cap, its only Error
        c.threw = true;
    }
    c.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    c.boxes = c.threw ? VoronoiCircleSearchOptions{}.max_boxes : solver.enclosure().search_boxes;
    c.enclosure = solver.enclosure();
    return c;
}

// The two paths certify the unique CCW circle: every component overlaps. They
// may pick different charts for a tangency parameter near |t| = 1 (both cover
// it): compare t itself there.
bool same_circle(const VoronoiCircleEnclosure& a, const VoronoiCircleEnclosure& b) {
    for (int i = 0; i < 3; ++i) {
        const bool overlap = a.flipped[i] == b.flipped[i]
                                 ? arb_overlaps(a.parameter[i].get(), b.parameter[i].get())
                                 : arb_overlaps(a.tangency_parameter(i, 256).get(), b.tangency_parameter(i, 256).get());
        if (!overlap) return false;
    }
    return arb_overlaps(a.radius.get(), b.radius.get()) && arb_overlaps(a.center_x.get(), b.center_x.get()) &&
           arb_overlaps(a.center_y.get(), b.center_y.get());
}

Sample measure(const std::string& row, const Case& c, int repetition) {
    Sample m{row, c.label, voronoi_circles_name(c.count), repetition, run(c.sites, true), run(c.sites, false)};
    const bool expected = has_ccw(c.count);
    auto wrong = [&](const Call& call) { return !call.threw && call.found != expected; };
    m.disagreement = wrong(m.search) || wrong(m.fallback) ||
                     (m.search.found && m.fallback.found && !same_circle(m.search.enclosure, m.fallback.enclosure));
    m.cap = m.search.threw || m.fallback.threw;
    return m;
}

// ---- the triples ------------------------------------------------------------

// Random triples from generate_sites (seeds 1, 2, ...; centers in [-10, 10]^2,
// 8-bit rationals) whose count is accepted by `want`.
std::vector<Case> random_cases(SiteKind kind, int n, bool (*want)(VoronoiCircles)) {
    std::vector<Case> out;
    for (std::uint64_t seed = 1; static_cast<int>(out.size()) < n; ++seed) {
        const std::vector<Ellipse> s = experiments::random_sites(kind, 3, seed, 8, Rational(10));
        const VoronoiCircles count = *voronoi_circle_count(s[0], s[1], s[2]);
        if (want(count)) out.push_back({"seed " + std::to_string(seed), {s[0], s[1], s[2]}, count});
    }
    return out;
}


Case offset_case(long k) {  // X = 10^k; k < 0 means X = 0
    const Rational x = k < 0 ? Rational(0) : power_of_ten(k);
    const Triple s = {Ellipse(4, 2, 0, x, 0), Ellipse(3, Rational(3, 2UL), Rational(1, 3UL), x + 10, 0),
                      Ellipse(Rational(5, 2UL), Rational(5, 2UL), 0, x + 5, 8)};
    return {k < 0 ? "X = 0" : "X = 10^" + std::to_string(k), s, *voronoi_circle_count(s[0], s[1], s[2])};
}

// Lifting the middle circle leaves one tangent circle, below the line; the
// order that makes it counter-clockwise is taken from the count.
Case line_case(long k) {
    Triple s = {Ellipse::circle(0, 0, 1), Ellipse::circle(3, power_of_ten(-k), 1), Ellipse::circle(6, 0, 1)};
    if (*voronoi_circle_count(s[0], s[1], s[2]) == VoronoiCircles::cw_only) std::swap(s[1], s[2]);
    return {"k = " + std::to_string(k), s, *voronoi_circle_count(s[0], s[1], s[2])};
}

std::vector<Row> rows(bool full) {
    const int n = full ? 200 : 30;
    auto ccw = [](VoronoiCircles c) { return has_ccw(c); };
    // Random triples without a CCW circle are nearly all cw_only (none: about
    // 1% of the seeds): a row each, so that none is measured too.
    auto cw_only = [](VoronoiCircles c) { return c == VoronoiCircles::cw_only; };
    auto none = [](VoronoiCircles c) { return c == VoronoiCircles::none; };
    std::vector<Row> out = {
        {"ellipses", "ellipses", "random ellipse triples with a CCW circle (count ccw_only or both)",
         random_cases(SiteKind::ellipses, n, ccw)},
        {"circles", "circles", "random circle triples with a CCW circle", random_cases(SiteKind::circles, n, ccw)},
        {"no-circle cw_only", "no-circle cw_only",
         "random ellipse triples with only the clockwise circle (the search proves that there is no CCW one)",
         random_cases(SiteKind::ellipses, n, cw_only)},
        {"no-circle none", "no-circle none", "random ellipse triples with no Voronoi circle at all",
         random_cases(SiteKind::ellipses, n, none)}};
    for (long k : {-1L, 14L, 30L, 100L}) {
        const Case c = offset_case(k);
        out.push_back({"offset", "offset " + c.label, "`4 2 0 X 0`, `3 3/2 1/3 X+10 0`, `5/2 5/2 0 X+5 8`", {c},
                       full ? 21 : 5});
    }
    std::vector<long> lifts = {3, 6, 12};
    if (full) lifts.insert(lifts.end(), {16, 17});
    for (long k : lifts) {
        const Case c = line_case(k);
        out.push_back({"line", "line " + c.label, "unit circles at (0,0), (3,10^-k), (6,0), ordered for the CCW circle "
                       "(radius about 4.5 10^k)", {c}, full ? 11 : 3});
    }
    return out;
}

// ---- statistics and output --------------------------------------------------

using experiments::fmt;
using experiments::quantile;

struct Summary {
    std::vector<double> search, fallback, boxes;
    int calls = 0, fallback_searched = 0, disagreements = 0, caps = 0;
};

Summary summarize(const std::vector<Sample>& samples) {
    Summary s;
    for (const Sample& m : samples) {
        s.search.push_back(m.search.seconds * 1e3);
        s.fallback.push_back(m.fallback.seconds * 1e3);
        s.boxes.push_back(static_cast<double>(m.search.boxes));
        ++s.calls;
        s.fallback_searched += m.fallback.boxes > 0;
        s.disagreements += m.disagreement;
        s.caps += m.cap;
    }
    return s;
}

std::string times(const std::vector<double>& ms) {
    return fmt("%.2f", quantile(ms, 0.5)) + " / " + fmt("%.2f", quantile(ms, 0.9)) + " / " +
           fmt("%.2f", quantile(ms, 1.0));
}

// Every row: each case `repetitions` times (a case that hits the cap once).
std::vector<std::vector<Sample>> measure_rows(const std::vector<Row>& all, int& disagreements, int& caps) {
    std::vector<std::vector<Sample>> results;
    for (const Row& row : all) {
        std::vector<Sample> samples;
        for (const Case& c : row.cases)
            for (int r = 0; r < row.repetitions; ++r) {
                samples.push_back(measure(row.name, c, r));
                const Sample& m = samples.back();
                disagreements += m.disagreement;
                caps += m.cap;
                if (m.disagreement || m.cap)
                    std::cerr << (m.disagreement ? "ANOMALY: " : "CAP HIT: ") << row.name
                              << (row.cases.size() > 1 ? " " + c.label : "") << " (count " << m.count
                              << "): search " << m.search.result() << ", default " << m.fallback.result()
                              << (m.disagreement && m.search.found && m.fallback.found ? ", enclosures disjoint" : "")
                              << "; sites " << c.sites[0].str() << " | " << c.sites[1].str() << " | "
                              << c.sites[2].str() << "\n";
                // A call that hits the cap costs the whole cap (~20 s): once is enough.
                if (m.cap) break;
            }
        const Summary s = summarize(samples);
        std::cerr << "[bench_voronoi_circle_search] " << row.name << ": " << s.calls << " calls, search "
                  << times(s.search) << " ms, default " << times(s.fallback) << " ms\n";
        results.push_back(std::move(samples));
    }
    return results;
}

// voronoi_circle_search.csv: one line per call pair.
experiments::Table csv_table(const std::vector<std::vector<Sample>>& results) {
    experiments::Table t("voronoi_circle_search",
                         {"row", "case", "count", "repetition", "search_seconds", "search_boxes", "search_result",
                          "default_seconds", "default_boxes", "default_result", "disagreement"});
    for (const auto& samples : results)
        for (const Sample& m : samples)
            t.add({m.row, m.label, m.count, std::to_string(m.repetition), fmt("%.6g", m.search.seconds),
                   std::to_string(m.search.boxes), m.search.result(), fmt("%.6g", m.fallback.seconds),
                   std::to_string(m.fallback.boxes), m.fallback.result(), std::to_string(m.disagreement)});
    return t;
}

experiments::Table summary_table(const std::vector<Row>& all, const std::vector<std::vector<Sample>>& results) {
    experiments::Table t("search", {"row", "triples", "calls", "search ms", "boxes median / max", "default ms",
                                    "ratio", "default searched", "disagreements", "cap hits"});
    for (std::size_t i = 0; i < all.size(); ++i) {
        const Summary s = summarize(results[i]);
        t.add({all[i].name, std::to_string(all[i].cases.size()), std::to_string(s.calls), times(s.search),
               fmt("%.0f", quantile(s.boxes, 0.5)) + " / " + fmt("%.0f", quantile(s.boxes, 1.0)), times(s.fallback),
               fmt("%.1f", quantile(s.search, 0.5) / quantile(s.fallback, 0.5)), std::to_string(s.fallback_searched),
               std::to_string(s.disagreements), std::to_string(s.caps)});
    }
    return t;
}

// "- group: description" once per group of rows.
std::string row_groups(const std::vector<Row>& all) {
    std::string md;
    for (std::size_t i = 0; i < all.size(); ++i)
        if (i == 0 || all[i].group != all[i - 1].group) md += "- " + all[i].group + ": " + all[i].description + "\n";
    return md;
}

}  // namespace

int main(int argc, char** argv) {
    namespace ex = ellvor::experiments;
    ex::BenchArguments args;
    if (!ex::parse_bench_arguments(argc, argv, "bench_voronoi_circle_search",
                                   "usage: bench_voronoi_circle_search [--full] [--out DIR]\n"
                                   "  --full     200 random triples a row and more repetitions (minutes)\n"
                                   "  --out DIR  write DIR/voronoi_circle_search.csv and .md\n",
                                   args))
        return 2;
    ex::Report report("Exhaustive certified search for the Voronoi circle", "bench_voronoi_circle_search",
                      args.command);

    // The measurements.
    int disagreements = 0, caps = 0;
    const std::vector<Row> all = rows(args.full);
    const std::vector<std::vector<Sample>> results = measure_rows(all, disagreements, caps);

    // The report.
    report.intro("`VoronoiCircleSolver::certify()` first certifies from floating-point guesses; when none certifies "
                 "it falls back to an exhaustive search (`subdivision/voronoi_circle_search.hpp`): boxes of the three "
                 "tangency parameters (both charts of each boundary) and the radius are bisected breadth-first and "
                 "excluded by range tests (equations, orientation, Krawczyk); the midpoint of each surviving box is "
                 "offered to a Newton + Krawczyk certificate. It ends with the certified counter-clockwise circle or, "
                 "once every box is excluded, with a proof that there is none. This measures that search, forced by "
                 "`certify_by_search()` on a fresh solver, beside the default path `certify()` on another fresh "
                 "solver.");
    report.note("Full run: `build/experiments/bench_voronoi_circle_search --full --out experiments/results`; without "
                "`--full` (as in `make bench`) 30 random triples a row and fewer repetitions.");
    report.note("Random triples: `generate_sites(count 3, bits 8, box 10, seed 1, 2, ...)`, classified by "
                "`voronoi_circle_count` (seeds in the CSV). Offset and line rows: one triple, repeated.");
    report.note("Times in ms per call, median / p90 / max; ratio = median search / median default; \"default "
                "searched\" = calls in which the default path itself fell back to the search. Where it does (always "
                "for the no-circle rows) the default path is the failing guesses plus the same search, so default "
                "minus search is the cost of the guesses that did not certify. \"cap hits\" = measurements (a search "
                "call and a default call) in which a path was stopped by the search's box cap (" +
                std::to_string(VoronoiCircleSearchOptions{}.max_boxes) +
                " boxes; Error thrown), counted as that many boxes; such a case is measured once.");
    report.text("\n");
    report.table(summary_table(all, results));
    report.text("\nRows:\n\n" + row_groups(all) +
                "\nDisagreements (a path certifying when the count says there is no CCW circle or proving absence "
                "when it says there is one, or search and default enclosures not overlapping in every component): " +
                std::to_string(disagreements) +
                (disagreements ? " — **NOT ZERO, see the ANOMALY lines on stderr**" : "") +
                ".\n\nCap hits (no answer; the solver's contract allows them only for a degenerate triple): " +
                std::to_string(caps) +
                (caps ? " — **NOT ZERO: the search did not decide a non-degenerate triple**" : "") + ".\n");

    report.publish(args.out_dir, "voronoi_circle_search.md", {{"voronoi_circle_search.csv", csv_table(results).csv()}});
    if (disagreements || caps)
        std::cerr << "\n*** " << disagreements << " DISAGREEMENTS, " << caps << " CAP HITS ***\n";
    return disagreements || caps ? 1 : 0;
}
