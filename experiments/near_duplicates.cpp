// Nearly coincident sites (docs/DESIGN.md §4.2, item 3): the time of every
// predicate call while building sets with near copies of some sites.
//
// Families: generated ellipses and circles (4, 50 with 30% crossing, 200
// sites), a tenth of the sites (at least one) copied and moved by 10^-k
// (sites/site_generators.hpp near_copy: shifts for k = 10 .. 100, rotation
// and scaling by 1 +- 10^-30), a five-site example that used to end at the search's cap, and fuzz F5's
// six sites (a copy thinner by 10^-k, k = 6 .. 9). Each graph is
// built through a traits wrapper that times each call of the ellipse traits;
// a row reports the build time, the calls, and the slowest call with its
// predicate. The goal: no call over 1 s.
//
//   build/experiments/near_duplicates                  # a short run: k = 20 and 100
//   build/experiments/near_duplicates --full --out experiments/results
//       # writes near_duplicates.md and near_duplicates.csv
#include "experiments/report.hpp"
#include "experiments/run_environment.hpp"
#include "experiments/timed_traits.hpp"
#include "graph/delaunay_graph.hpp"
#include "predicates/relative_position.hpp"
#include "sites/rational_parse.hpp"
#include "sites/site_generators.hpp"
#include "util/error.hpp"

#include <iostream>
#include <memory>
#include <string>
#include <vector>

using namespace ellvor;
namespace ex = ellvor::experiments;

namespace {

struct Row {
    std::string family;
    long sites = 0, copies = 0, k = 0;
    std::string motion;
    std::string outcome;  // "ok", or the error
    double build_seconds = 0;
    ex::CallProfile profile;  // every predicate call of the build, timed
};

// Builds the sites with every predicate call timed, and validates the graph.
Row build_timed(Row row, const std::vector<Ellipse>& sites);

Row run(const std::string& family, std::vector<Ellipse> sites, long copies, long k, NearCopyMotion motion) {
    Row row{family, static_cast<long>(sites.size()), copies, k, near_copy_motion_name(motion), "ok", 0, {}};
    const std::size_t base = sites.size();
    for (long c = 0; c < copies; ++c) {
        const Ellipse& original = sites[(c * 7919) % base];
        sites.push_back(near_copy(original, motion, k));
    }
    row.sites = static_cast<long>(sites.size());
    for (std::size_t c = base; c < sites.size(); ++c)
        if (!crossing_pair_problem(sites[((c - base) * 7919) % base], sites[c]).empty()) {
            row.outcome = "input error (a copy meets its site in 4 points)";
            return row;
        }
    return build_timed(std::move(row), sites);
}

Row build_timed(Row row, const std::vector<Ellipse>& sites) {
    try {
        auto traits = std::make_unique<ex::TimedTraits>(sites);
        const ex::TimedTraits* timed = traits.get();
        DelaunayGraph g(std::move(traits));
        const double t0 = ex::now_wall();
        g.insert_all();
        row.build_seconds = ex::now_wall() - t0;
        row.profile = timed->profile();
        const std::string problems = g.validate();
        if (!problems.empty()) row.outcome = "INVALID: " + problems.substr(0, 80);
    } catch (const Error& e) {
        row.outcome = std::string("ERROR: ") + e.what();
    }
    return row;
}

// Five sites of which the first two nearly coincide: with a shift of 10^-20
// the search ended at its cap after 30-47 s before the near-duplicate start.
std::vector<Ellipse> near_pair_example() {
    auto q = [](const char* s) { return parse_rational(s); };
    return {Ellipse(q("2"), q("1"), q("1/3"), q("0"), q("0")), Ellipse::circle(6, 1, 1), Ellipse::circle(-5, 3, 1),
            Ellipse(q("3/2"), q("1/2"), q("1"), q("1"), q("-6"))};
}

// Fuzz F5 (experiments/results/fuzz.md): the ellipse and a copy thinner by
// 10^-k, shifted by 6e-30, with four small sites; with k = 6 the search ended
// at its cap before the near-duplicate start took pairs closer than 2^-16.
Row thinner_copy_example(long k) {
    auto q = [](const std::string& s) { return parse_rational(s); };
    const std::vector<Ellipse> sites{Ellipse(q("2"), q("1"), q("1/3"), q("0"), q("0")),
                                     Ellipse(q("2"), q("1") - q("1e-" + std::to_string(k)), q("1/3"), q("6e-30"), q("0")),
                                     Ellipse::circle(6, 1, 1), Ellipse::circle(-5, 6, 1),
                                     Ellipse(q("3/2"), q("1/2"), q("1"), q("5"), q("3")),
                                     Ellipse(q("3/2"), q("1/2"), q("1"), q("1"), q("-6"))};
    return build_timed(Row{"thinner copy (fuzz F5)", 6, 1, k, "b - 1e-k, shift 6e-30", "ok", 0, {}}, sites);
}

}  // namespace

int main(int argc, char** argv) {
    ex::BenchArguments args;
    if (!ex::parse_bench_arguments(argc, argv, "near_duplicates",
                                   "usage: near_duplicates [--full] [--out DIR]\n"
                                   "  --full     k = 10, 20, 30, 40, 60, 100 (default: 20 and 100)\n"
                                   "  --out DIR  write DIR/near_duplicates.csv and .md\n",
                                   args))
        return 2;
    const std::vector<long> shifts = args.full ? std::vector<long>{10, 20, 30, 40, 60, 100} : std::vector<long>{20, 100};
    std::vector<Row> rows;
    ex::Report report("Nearly coincident sites: time per predicate call", "near_duplicates", args.command);
    auto record = [&](const Row& r) {
        rows.push_back(r);
        std::cerr << "[near_duplicates] " << r.family << " " << r.sites << " sites, " << r.motion << " 1e-" << r.k << ": "
                  << r.outcome << ", build " << r.build_seconds << " s, slowest " << r.profile.slowest_call << " "
                  << r.profile.slowest << " s\n";
    };
    for (long k : shifts) record(run("five-site example", near_pair_example(), 1, k, NearCopyMotion::shift_x));
    for (long k : args.full ? std::vector<long>{6, 7, 8, 9} : std::vector<long>{6, 9}) record(thinner_copy_example(k));
    for (SiteKind kind : {SiteKind::ellipses, SiteKind::circles})
        for (long count : {4L, 50L, 200L}) {
            GeneratorOptions options;
            options.kind = kind;
            options.count = count;
            options.seed = 7;
            if (count == 50) options.crossing_fraction = Rational(3, 10UL);
            const std::vector<Ellipse> base = generate_sites(options);
            const std::string family = std::string(kind == SiteKind::circles ? "circles" : "ellipses") +
                                       (count == 50 ? " (30% crossing)" : "");
            const long copies = std::max(1L, count / 10);
            for (long k : shifts)
                for (NearCopyMotion m : {NearCopyMotion::shift_x, NearCopyMotion::shift_xy})
                    record(run(family, base, copies, k, m));
            for (NearCopyMotion m : {NearCopyMotion::rotation, NearCopyMotion::scale_up, NearCopyMotion::scale_down})
                record(run(family, base, copies, 30, m));
        }

    ex::Table table("near_duplicates", {"family", "sites", "copies", "motion", "k", "outcome", "build (s)", "calls",
                                        "slowest call (s)", "slowest call"},
                    "lrrlrlrrrl");
    const Row* worst = nullptr;
    for (const Row& r : rows) {
        table.add({r.family, ex::integer(r.sites), ex::integer(r.copies), r.motion, ex::integer(r.k), r.outcome,
                   ex::fmt("%.3f", r.build_seconds), ex::integer(static_cast<long long>(r.profile.calls)),
                   ex::fmt("%.4f", r.profile.slowest), r.profile.slowest_call.empty() ? "-" : r.profile.slowest_call});
        if (!worst || r.profile.slowest > worst->profile.slowest) worst = &r;
    }
    report.intro("A tenth of the sites (at least one) copied and moved by 10^-k (`near_copy`, "
                 "sites/site_generators.hpp), built with every predicate call of the ellipse traits timed "
                 "(experiments/timed_traits.hpp). Goal: every call at most 1 s (docs/DESIGN.md §4.2, item 3). "
                 "Fuzz F5's six sites (a copy 10^-k thinner, shifted by 6e-30) ended at the search's cap "
                 "before the near-duplicate start took pairs closer than 2^-16.");
    report.machine_note("shared with other jobs");
    report.table(table);
    if (worst)
        report.paragraph("\nSlowest call over all rows: " + ex::fmt("%.4f", worst->profile.slowest) + " s (" +
                         worst->family + ", " + worst->motion + " 1e-" + std::to_string(worst->k) + ").");
    report.publish(args.out_dir, "near_duplicates.md", {{"near_duplicates.csv", table.csv()}});
    bool failed = false;
    for (const Row& r : rows) failed = failed || r.outcome.rfind("ERROR", 0) == 0 || r.outcome.rfind("INVALID", 0) == 0;
    return failed ? 1 : 0;
}
