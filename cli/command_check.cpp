// ellvor check FILE [--cin] [--describe]: validates a site file.
#include "cli/command_list.hpp"
#include "cli/site_arguments.hpp"

#include "predicates/relative_position.hpp"
#include "sites/meeting_pair_candidates.hpp"
#include "sites/site_io.hpp"
#include "util/error.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <set>
#include <sstream>
#include <unistd.h>

namespace ellvor::cli {
namespace {

const char* const kHelp =
    "usage: ellvor check FILE [--cin] [--describe]\n"
    "\n"
    "Validates a site file: every line parses ('a b w xc yc', exact rationals), a, b > 0,\n"
    "no two sites are the same ellipse, and every pair of sites is disjoint, nested, or\n"
    "crossing in two points (signed distances, as CGAL's Apollonius graph).\n"
    "Prints one line per notable pair (ids are 0-based in file order):\n"
    "  crossing: I J               the boundaries cross in two points\n"
    "  invalid: I J WHY            a crossing the diagram does not accept: boundaries meeting in\n"
    "                              3 or 4 points\n"
    "  hidden: I inside J          site I lies inside site J (I is a hidden site; an ellipse\n"
    "                              hidden by a union of crossing sites shows in 'build')\n"
    "  hidden: I inside J tangent  the same, touching J from inside\n"
    "  tangent: I J                externally tangent sites\n"
    "then a summary 'N sites (C circles), H hidden[, X crossing pairs], OK' (or '..., K invalid\n"
    "pairs, INVALID').\n"
    "\n"
    "options:\n"
    "  --cin        read CGAL's circle format 'x y r' instead of .ell\n"
    "  --describe   also print a short description (counts, bounding box, axis ranges, bit sizes,\n"
    "               nested and crossing pairs)\n"
    "  FILE may be '-' for standard input.\n"
    "\n"
    "exit status: 0 valid; 2 a parse error, a duplicate or an invalid pair\n"
    "(message 'ellvor: FILE:LINE:COL: what' on stderr); 1 other failure.\n";

struct PairReport {
    std::size_t i, j;  // i < j
    RelativePosition position;
};

// Up to ten pairs "i in j" (nested) or "i x j" (crossing), then "...".
void list_pairs(std::ostream& out, const char* what, const std::vector<PairReport>& pairs) {
    out << "  " << what << " pairs: " << pairs.size();
    if (!pairs.empty()) {
        out << " (";
        std::size_t shown = 0;
        for (const PairReport& p : pairs) {
            if (shown++ == 10) {
                out << ", ...";
                break;
            }
            if (shown > 1) out << ", ";
            if (p.position == RelativePosition::intersecting) {
                out << p.i << " x " << p.j;
                continue;
            }
            const bool first = p.position == RelativePosition::first_inside ||
                               p.position == RelativePosition::first_inside_tangent;
            out << (first ? p.i : p.j) << " in " << (first ? p.j : p.i);
        }
        out << ")";
    }
    out << '\n';
}

void describe(std::ostream& out, const SiteFile& file, std::size_t circles, const std::vector<PairReport>& nested,
              const std::vector<PairReport>& crossing) {
    const auto& s = file.sites;
    out << "description of " << file.name << ":\n";
    out << "  sites: " << s.size() << " (" << circles << " circles, " << s.size() - circles << " ellipses)\n";
    if (s.empty()) return;
    double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
    Rational amin = s[0].a(), amax = s[0].a(), bmin = s[0].b(), bmax = s[0].b();
    long max_bits = 0;
    for (const Ellipse& e : s) {
        const double a = e.a().to_double(), b = e.b().to_double();
        const double c = e.cos_rotation().to_double(), sn = e.sin_rotation().to_double();
        const double hx = std::sqrt(a * a * c * c + b * b * sn * sn), hy = std::sqrt(a * a * sn * sn + b * b * c * c);
        const double x = e.xc().to_double(), y = e.yc().to_double();
        x0 = std::min(x0, x - hx), x1 = std::max(x1, x + hx);
        y0 = std::min(y0, y - hy), y1 = std::max(y1, y + hy);
        amin = std::min(amin, e.a()), amax = std::max(amax, e.a());
        bmin = std::min(bmin, e.b()), bmax = std::max(bmax, e.b());
        for (const Rational* q : {&e.a(), &e.b(), &e.w(), &e.xc(), &e.yc()}) max_bits = std::max(max_bits, q->bits());
    }
    char buf[256];
    std::snprintf(buf, sizeof buf, "  bounding box (approx.): [%.6g, %.6g] x [%.6g, %.6g]\n", x0, x1, y0, y1);
    out << buf;
    std::snprintf(buf, sizeof buf, "  semi-axis a: %.6g .. %.6g, semi-axis b: %.6g .. %.6g (approx.)\n",
                  amin.to_double(), amax.to_double(), bmin.to_double(), bmax.to_double());
    out << buf;
    out << "  largest numerator/denominator: " << max_bits << " bits\n";
    list_pairs(out, "nested", nested);
    list_pairs(out, "crossing", crossing);
}

int run_check(const std::vector<std::string>& args) {
    Arguments parsed(args, {{"--cin", false}, {"--describe", false}});
    parsed.expect_positional(1, 1, "one site FILE");
    const std::string path = parsed.positional()[0];
    const SiteFile file = read_site_file(path, parsed.has("--cin") ? SiteFormat::cin : SiteFormat::ell);
    const auto& sites = file.sites;
    const std::size_t n = sites.size();

    // Only pairs whose circumscribed disks may meet (a grid, not every pair);
    // relative_position separates the rest of the disjoint ones at once.
    const auto pairs = pairs_that_may_meet(sites);
    const bool progress = pairs.size() > 20000 && ::isatty(2);
    std::vector<PairReport> reports;
    for (std::size_t k = 0; k < pairs.size(); ++k) {
        if (progress && k % 5000 == 0) std::fprintf(stderr, "\rchecking pair %zu of %zu", k, pairs.size());
        const auto [i, j] = pairs[k];
        const RelativePosition pos = *relative_position(sites[i], sites[j]);
        if (pos != RelativePosition::separated) reports.push_back({i, j, pos});
    }
    if (progress) std::fprintf(stderr, "\rchecking pair %zu of %zu\n", pairs.size(), pairs.size());
    std::sort(reports.begin(), reports.end(),
              [](const PairReport& x, const PairReport& y) { return x.i != y.i ? x.i < y.i : x.j < y.j; });

    std::set<std::size_t> hidden;
    std::vector<PairReport> nested, crossing;
    std::vector<std::pair<PairReport, std::string>> invalid;  // with the reason
    std::size_t circles = 0;
    for (const Ellipse& e : sites) circles += e.is_circle() ? 1 : 0;
    std::ostream& out = std::cout;
    auto report_nested = [&](const PairReport& r, std::size_t inner, std::size_t outer, bool tangent) {
        out << "hidden: " << inner << " inside " << outer << (tangent ? " tangent" : "") << '\n';
        hidden.insert(inner);
        nested.push_back(r);
    };
    for (const PairReport& r : reports) {
        switch (r.position) {
            case RelativePosition::intersecting: {
                const std::string problem = crossing_pair_problem(sites[r.i], sites[r.j]);
                if (problem.empty()) {
                    out << "crossing: " << r.i << ' ' << r.j << '\n';
                    crossing.push_back(r);
                } else {
                    out << "invalid: " << r.i << ' ' << r.j << ' ' << problem << '\n';
                    invalid.push_back({r, problem});
                }
                break;
            }
            case RelativePosition::identical:
                // The reader rejects duplicates; report it like one all the same.
                throw InputError(file.name, file.lines[r.j], 1,
                                 "duplicate site: site " + std::to_string(r.j) + " is the same point set as site " +
                                     std::to_string(r.i) + " (line " + std::to_string(file.lines[r.i]) + ")");
            case RelativePosition::first_inside:
            case RelativePosition::first_inside_tangent:
                report_nested(r, r.i, r.j, r.position == RelativePosition::first_inside_tangent);
                break;
            case RelativePosition::second_inside:
            case RelativePosition::second_inside_tangent:
                report_nested(r, r.j, r.i, r.position == RelativePosition::second_inside_tangent);
                break;
            case RelativePosition::externally_tangent:
                out << "tangent: " << r.i << ' ' << r.j << '\n';
                break;
            case RelativePosition::separated:
                break;
        }
    }
    if (parsed.has("--describe")) describe(out, file, circles, nested, crossing);
    out << n << " sites (" << circles << " circles), " << hidden.size() << " hidden";
    if (!crossing.empty()) out << ", " << crossing.size() << " crossing pair" << (crossing.size() == 1 ? "" : "s");
    if (!invalid.empty()) {
        out << ", " << invalid.size() << " invalid pair" << (invalid.size() == 1 ? "" : "s") << ", INVALID\n";
        out.flush();
        const auto& [r, why] = invalid.front();
        std::cerr << "ellvor: " << crossing_sites_error(file, r.i, r.j, why).what() << " (" << invalid.size()
                  << " invalid pair" << (invalid.size() == 1 ? "" : "s") << " in all)\n";
        return kExitInput;
    }
    out << ", OK\n";
    return kExitOk;
}

}  // namespace

const Command command_check = {"check", "validate a site file (parse, a, b > 0, pairwise positions)", kHelp,
                               run_check};

}  // namespace ellvor::cli
