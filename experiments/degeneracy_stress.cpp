// Degenerate and near-degenerate InCircle inputs of growing bit size.
//
// (i) The InCircle resultant (exact/incircle_resultant.hpp) of a generic
//     ellipse triple whose 15 parameters are each perturbed by +-10^-e
//     (independent seeded signs), e = 4, 8, 12, 16, 20 -- beside the
//     paper's Table 1 row "resultant" (25.12 / 57.24 / 102.63 / 160.44 /
//     231.19 s on a P4 2.6 GHz), with degree, primes and coefficient bits.
// (ii) incircle() on exactly degenerate quadruples (Q externally tangent to
//     the Voronoi circle of E1 E2 E3, built by symmetry) and on the same with
//     Q's center moved by 10^-e away from / toward the circle:
//       axial    E = (2, 1, 0) at (5, 0) and its quarter turns (i-point contacts);
//       rot-B    a generic ellipse (2, 1, w) with w = 1/3 + 2^-B, P = E(1/2),
//                V = P + 6 n (n the max-normed outward normal at P) and three
//                copies of E rotated about V by angles with rational
//                tan(phi/2) = 6/5, -6, -7/10 (contacts at t = 1/2, not at
//                i-points); B = 0 means w = 1/3. The bit size of the sites
//                grows with B.
//     Under the default cap (4096 bits) the subdivision decides the
//     perturbed ones and the exact stage the tangent ones; under a low cap
//     (256 bits) the exact stage runs for every perturbation below 2^-256.
//
// Per row: the median of `reps` (default 3) timed calls (fresh solver every
// call); the calls that run the exact stage on a perturbed Q are timed once.
//
//   build/experiments/degeneracy_stress          # default (make bench): < 1 min, stdout only
//   build/experiments/degeneracy_stress --full --out experiments/results
//       # more bit sizes and exponents (a few minutes); writes degeneracy_stress.csv,
//       # .md, and .png (via experiments/plot_results.py) into the folder
// Options: --reps N, --seed S, --out DIR, --full.
#include "experiments/report.hpp"
#include "experiments/run_environment.hpp"
#include "exact/incircle_resultant.hpp"
#include "predicates/incircle.hpp"
#include "sites/ellipse.hpp"
#include "sites/site_generators.hpp"
#include "util/error.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using namespace ellvor;

namespace {

using namespace ellvor::experiments;

struct Row {
    std::string part;    // "resultant" or "incircle"
    std::string series;  // plot series
    std::string family;
    long bits = 0;       // max bit size of the input rationals
    int e = 0;           // perturbation 10^-e (0: none)
    std::string direction;  // "", "away", "toward", "exact"
    long cap = 0;
    std::string result, stage;
    long precision = 0;
    double seconds = 0;
    long degree = -1, primes = 0, coefficient_bits = 0;
    std::string exponents;  // "yes"/"no" (resultant rows)
    double paper_seconds = 0;
};



Rational two_to_minus(long k) {
    Integer p;
    fmpz_ui_pow_ui(p.get(), 2, static_cast<unsigned long>(k));
    return Rational(Integer(1), p);
}

long site_bits(const std::vector<const Ellipse*>& sites) {
    long b = 0;
    for (const Ellipse* e : sites)
        for (const Rational* r : {&e->a(), &e->b(), &e->w(), &e->xc(), &e->yc()}) b = std::max(b, r->bits());
    return b;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// ---- (i) resultant of perturbed generic triples ------------------------------

const double kPaperResultant[] = {25.12, 57.24, 102.63, 160.44, 231.19};  // e = 4, 8, 12, 16, 20

Ellipse perturbed(const Ellipse& e, const Rational& eps, SiteRandom& rng) {
    auto p = [&](const Rational& x) { return x + (rng.sign() > 0 ? eps : -eps); };
    return Ellipse(p(e.a()), p(e.b()), p(e.w()), p(e.xc()), p(e.yc()));
}

void resultant_rows(int reps, std::uint64_t seed, bool full, std::vector<Row>& rows) {
    const Ellipse g1(2, 1, Rational(1, 3UL), 0, 0), g2(Rational(3, 2UL), 1, 2, 9, 1),
        g3(1, Rational(5, 2UL), Rational(-1, 2UL), 2, 10);
    std::vector<int> exponents = {0, 4, 8, 12, 16, 20};
    if (full)
        for (int e : {30, 40, 60, 80, 100}) exponents.push_back(e);
    for (int e : exponents) {
        SiteRandom rng(seed + static_cast<std::uint64_t>(e));
        const Rational eps = e ? power_of_ten(-e) : Rational(0);
        const Ellipse e1 = e ? perturbed(g1, eps, rng) : g1, e2 = e ? perturbed(g2, eps, rng) : g2,
                      e3 = e ? perturbed(g3, eps, rng) : g3;
        std::vector<double> times;
        IncircleResultant r;
        for (int i = 0; i < reps; ++i) {
            const auto start = std::chrono::steady_clock::now();
            r = incircle_resultant(e1, e2, e3);
            times.push_back(seconds_since(start));
        }
        Row row;
        row.part = "resultant";
        row.series = "resultant (ellvor)";
        row.family = "generic triple +-10^-e";
        row.bits = site_bits({&e1, &e2, &e3});
        row.e = e;
        row.seconds = median(times);
        row.degree = r.degree;
        row.primes = r.primes_used;
        row.coefficient_bits = r.coefficient_bits;
        row.exponents = r.generic_exponents ? "yes" : "no";
        if (e >= 4 && e <= 20 && e % 4 == 0) row.paper_seconds = kPaperResultant[e / 4 - 1];
        rows.push_back(row);
        std::printf("resultant e=%3d bits=%4ld degree=%ld primes=%ld coeff_bits=%ld %.4f s%s\n", e, row.bits,
                    row.degree, row.primes, row.coefficient_bits, row.seconds,
                    row.paper_seconds > 0 ? (" (paper " + std::to_string(row.paper_seconds) + " s)").c_str() : "");
        std::fflush(stdout);
    }
}

// ---- (ii) InCircle on degenerate quadruples ---------------------------------

struct Degenerate {
    std::string name;
    std::vector<Ellipse> s;  // E1 E2 E3 Q
    Rational out_x, out_y;   // direction from the circle's center toward Q's contact
};

Ellipse rotated(const Ellipse& e, const Rational& vx, const Rational& vy, const Rational& s) {
    const Rational d = Rational(1) + s * s;
    const Rational c = (Rational(1) - s * s) / d, sn = Rational(2) * s / d;
    const Rational dx = e.xc() - vx, dy = e.yc() - vy;
    const Rational w = (e.w() + s) / (Rational(1) - e.w() * s);
    return Ellipse(e.a(), e.b(), w, vx + c * dx - sn * dy, vy + sn * dx + c * dy);
}

Rational max_abs(const Rational& x, const Rational& y) {
    const Rational ax = x.sign() < 0 ? -x : x, ay = y.sign() < 0 ? -y : y;
    return ax > ay ? ax : ay;
}

Degenerate axial() {
    return {"axial", {Ellipse(2, 1, 0, 5, 0), Ellipse(2, 1, 1, 0, 5), Ellipse(2, 1, 0, -5, 0), Ellipse(2, 1, 1, 0, -5)},
            Rational(0), Rational(-1)};
}

Degenerate rotated_family(long bits) {
    const Rational w = bits ? Rational(1, 3UL) + two_to_minus(bits) : Rational(1, 3UL);
    const Ellipse e(2, 1, w, 0, 0);
    const Rational t0(1, 2UL);
    const Point p = e.point_at(t0);
    auto at = [&](const IntPolynomial& f) {
        return Rational(f.coeff(0)) + t0 * Rational(f.coeff(1)) + t0 * t0 * Rational(f.coeff(2));
    };
    const Rational tx = at(e.tangent_x()), ty = at(e.tangent_y());
    const Rational m = max_abs(tx, ty);
    const Rational nx = ty / m, ny = -tx / m;  // outward (the boundary runs counter-clockwise)
    const Rational vx = p.x + Rational(6) * nx, vy = p.y + Rational(6) * ny;
    const Ellipse e2 = rotated(e, vx, vy, Rational(6, 5UL)), e3 = rotated(e, vx, vy, Rational(-6)),
                  q = rotated(e, vx, vy, Rational(-7, 10UL));
    const Point pq = q.point_at(t0);
    return {"rot-" + std::to_string(bits), {e, e2, e3, q}, pq.x - vx, pq.y - vy};
}

Ellipse moved(const Degenerate& c, const Rational& eps, int dir) {
    const Ellipse& q = c.s[3];
    const Rational s = (dir > 0 ? eps : -eps) / max_abs(c.out_x, c.out_y);
    return Ellipse(q.a(), q.b(), q.w(), q.xc() + s * c.out_x, q.yc() + s * c.out_y);
}

void incircle_rows(int reps, bool full, std::vector<Row>& rows) {
    std::vector<Degenerate> families = {axial(), rotated_family(0), rotated_family(8), rotated_family(16)};
    if (full)
        for (long b : {32L, 64L}) families.push_back(rotated_family(b));
    std::vector<int> exponents = {10, 30, 100};
    if (full) exponents = {10, 20, 30, 50, 70, 100};
    for (const Degenerate& c : families) {
        const Ellipse &e1 = c.s[0], &e2 = c.s[1], &e3 = c.s[2];
        struct Job {
            int e, dir;
            long cap;
        };
        std::vector<Job> jobs = {{0, 0, 4096}, {0, 0, 256}};
        for (int e : exponents)
            for (int dir : {1, -1}) {
                jobs.push_back({e, dir, 4096});
                // The low cap on the axial family with 10^-100 takes ~10 s a call
                // (twin-chart resultants with a 333-bit Q): --full only.
                if (full || c.name != "axial" || e <= 30) jobs.push_back({e, dir, 256});
            }
        for (const Job& job : jobs) {
            const Ellipse q = job.e ? moved(c, power_of_ten(-job.e), job.dir) : c.s[3];
            InCircleOptions options;
            options.refinement.cap = job.cap;
            std::vector<double> times;
            Decision<InCircle> d;
            // Calls that run the exact stage on a perturbed Q (10^-e below 2^-cap)
            // take seconds: one timed call each.
            const int n = (job.e && job.e * 3.33 > job.cap) ? 1 : reps;
            for (int i = 0; i < n; ++i) {
                const auto start = std::chrono::steady_clock::now();
                d = incircle(e1, e2, e3, q, options);
                times.push_back(seconds_since(start));
            }
            Row row;
            row.part = "incircle";
            row.family = c.name;
            row.series = "incircle " + c.name + " cap " + std::to_string(job.cap);
            row.bits = site_bits({&e1, &e2, &e3, &q});
            row.e = job.e;
            row.direction = job.e ? (job.dir > 0 ? "away" : "toward") : "exact";
            row.cap = job.cap;
            row.result = (d.is_decided() ? incircle_name(*d) : "undecided");
            row.stage = stage_name(d.stage);
            row.precision = d.precision;
            row.seconds = median(times);
            rows.push_back(row);
            const char* want = job.e ? (job.dir > 0 ? "no-conflict" : "conflict") : "tangent";
            std::printf("incircle %-7s bits=%4ld e=%3d %-6s cap=%4ld: %-11s stage=%-11s prec=%6ld %.4f s%s\n",
                        c.name.c_str(), row.bits, job.e, row.direction.c_str(), job.cap, row.result.c_str(),
                        row.stage.c_str(), row.precision, row.seconds, row.result == want ? "" : "  WRONG");
            std::fflush(stdout);
        }
    }
}

// ---- output -----------------------------------------------------------------


// degeneracy_stress.csv: every row of both parts.
Table csv_table(const std::vector<Row>& rows) {
    Table t("degeneracy_stress", {"part", "series", "family", "bits", "e", "direction", "cap", "result", "stage",
                                  "precision", "seconds", "degree", "primes", "coefficient_bits", "seed_exponents",
                                  "paper_seconds", "paper_ratio"});
    for (const Row& r : rows) {
        const bool paper = r.paper_seconds > 0;
        t.add({r.part, r.series, r.family, integer(r.bits), integer(r.e), r.direction, integer(r.cap), r.result, r.stage,
               integer(r.precision), fmt("%g", r.seconds), integer(r.degree), integer(r.primes),
               integer(r.coefficient_bits), r.exponents, paper ? fmt("%g", r.paper_seconds) : std::string(),
               paper ? fmt("%g", r.paper_seconds / r.seconds) : std::string()});
    }
    return t;
}

Table resultant_table(const std::vector<Row>& rows) {
    Table t("resultant", {"e", "input bits", "degree", "seed exponents", "primes", "coefficient bits", "ellvor s",
                          "paper s", "paper / ellvor"},
            "lllllllll");
    for (const Row& r : rows) {
        if (r.part != "resultant") continue;
        t.add({integer(r.e), integer(r.bits), integer(r.degree), r.exponents, integer(r.primes),
               integer(r.coefficient_bits), fmt("%.4f", r.seconds),
               r.paper_seconds > 0 ? fmt("%.2f", r.paper_seconds) : std::string("-"),
               r.paper_seconds > 0 ? fmt("%.0f", r.paper_seconds / r.seconds) : std::string("-")});
    }
    return t;
}

Table incircle_table(const std::vector<Row>& rows) {
    Table t("incircle", {"family", "input bits", "e", "Q", "cap", "result", "stage", "precision", "seconds"},
            "lllllllll");
    for (const Row& r : rows) {
        if (r.part != "incircle") continue;
        const bool right = r.result == (r.direction == "exact" ? "tangent" : r.direction == "away" ? "no-conflict"
                                                                                                    : "conflict");
        t.add({r.family, integer(r.bits), r.e ? std::to_string(r.e) : std::string("-"), r.direction, integer(r.cap),
               r.result + (right ? "" : " (WRONG)"), r.stage, integer(r.precision), fmt("%.4f", r.seconds)});
    }
    return t;
}

std::string report_markdown(Report& report, const std::vector<Row>& rows, bool full, int reps) {
    report.machine_note("shared; medians of " + std::to_string(reps) +
                        " calls, one call for the exact stage on perturbed inputs");
    if (full) report.note("Full run (`--full`).");
    report.note("Plot: `degeneracy_stress.png` (seconds against e, log-log; the paper's Table 1 row as markers; "
                "`/usr/bin/python3 experiments/plot_results.py degeneracy_stress`).");

    report.heading("(i) InCircle resultant, generic ellipse triple with every parameter perturbed by +-10^-e");
    report.table(resultant_table(rows),
                 "Sites before perturbation: `2 1 1/3 0 0`, `3/2 1 2 9 1`, `1 5/2 -1/2 2 10`; signs from a seeded "
                 "generator. Paper (Emiris, Tsigaridas, Tzoumas 2007, Table 1, P4 2.6 GHz): 25.12 / 57.24 / 102.63 / "
                 "160.44 / 231.19 s for e = 4 .. 20; its ellipses and their bit sizes are not given, so the ratio "
                 "compares like-for-like only in e.");

    report.heading("(ii) incircle() on exactly tangent quadruples and their 10^-e perturbations");
    report.table(incircle_table(rows),
                 "`axial`: (2,1,0) at (5,0) and its quarter turns, touching |x| = 3 at i-points. `rot-B`: a "
                 "(2,1,1/3+2^-B) ellipse and three copies rotated about a rational V by angles with rational "
                 "tan(phi/2), all tangent to one circle at t = 1/2. `exact` = Q tangent (answer: tangent); "
                 "`away`/`toward` = Q's center moved by 10^-e (answers: no-conflict / conflict). cap = "
                 "InCircleOptions::max_precision.");
    std::vector<double> tangent_times;
    for (const Row& r : rows)
        if (r.part == "incircle" && r.direction == "exact") tangent_times.push_back(r.seconds);
    if (!tangent_times.empty())
        report.text("\nMedian time of the exactly degenerate calls (all families and caps): " +
                    fmt("%.4f", median(tangent_times)) + " s.\n");
    return report.markdown();
}

}  // namespace

int main(int argc, char** argv) {
    int reps = 3;
    std::uint64_t seed = 2007;
    bool full = false;
    std::string out_dir;
    std::string command = "build/experiments/degeneracy_stress";
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        command += " " + a;
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) {
                std::fprintf(stderr, "degeneracy_stress: %s needs a value\n", a.c_str());
                std::exit(2);
            }
            command += std::string(" ") + argv[i + 1];
            return argv[++i];
        };
        if (a == "--full") full = true;
        else if (a == "--reps") reps = std::max(1, std::atoi(value().c_str()));
        else if (a == "--seed") seed = std::strtoull(value().c_str(), nullptr, 10);
        else if (a == "--out") out_dir = value();
        else if (a == "--help" || a == "-h") {
            std::printf("usage: degeneracy_stress [--full] [--reps N] [--seed S] [--out DIR]\n");
            return 0;
        } else {
            std::fprintf(stderr, "degeneracy_stress: unknown argument %s\n", a.c_str());
            return 2;
        }
    }
    try {
        Report report("Degenerate and near-degenerate InCircle inputs", "degeneracy_stress", command);
        std::vector<Row> rows;
        resultant_rows(reps, seed, full, rows);
        incircle_rows(reps, full, rows);
        if (!out_dir.empty()) {
            const std::string base = out_dir + "/degeneracy_stress";
            write_result(out_dir, "degeneracy_stress.csv", csv_table(rows).csv());
            write_result(out_dir, "degeneracy_stress.md", report_markdown(report, rows, full, reps));
            // matplotlib is Debian's: its python3, not one earlier on PATH.
            const std::string plot =
                "/usr/bin/python3 experiments/plot_results.py --dir '" + out_dir + "' degeneracy_stress";
            if (std::system(plot.c_str()) != 0) std::fprintf(stderr, "degeneracy_stress: plot failed\n");
            std::printf("wrote %s.{csv,md,png}\n", base.c_str());
        }
    } catch (const std::exception& ex) {
        std::fprintf(stderr, "degeneracy_stress: %s\n", ex.what());
        return 1;
    }
    return 0;
}
