// ellvor resultant FILE: the wanted factor of the InCircle resultant of the
// ordered triple in FILE (exact/incircle_resultant.hpp).
#include "cli/command_list.hpp"

#include "cli/site_arguments.hpp"
#include "exact/incircle_resultant.hpp"

#include <iostream>
#include <sstream>

namespace ellvor::cli {
namespace {

const char* const kHelp =
    "usage: ellvor resultant FILE [--cin] [--stats]\n"
    "\n"
    "The InCircle resultant of the three sites of FILE (E1 E2 E3; the paper, section 3.1): the\n"
    "univariate polynomial in the boundary parameter t of E1 whose roots include the\n"
    "tangency parameter on E1 of every circle tangent to the three sites. The known\n"
    "extraneous factors (powers of 1+t^2 and of the parallel-normals polynomials) are\n"
    "divided out and the squarefree part is kept: degree 184 for three ellipses in general\n"
    "position, lower with circles. Prints its integer coefficients one a line, constant\n"
    "term first; the polynomial is primitive (content 1) with a positive leading\n"
    "coefficient. The coefficients are proven: a multi-modular computation whose primes'\n"
    "product exceeds twice a Hadamard bound on the full resultant's coefficients, then\n"
    "exact division over the integers.\n"
    "\n"
    "options:\n"
    "  --cin     read CGAL's circle format 'x y r' instead of .ell\n"
    "  --stats   print to stderr: degree, expected degree, the removed factors with their\n"
    "            exponents, whether the paper's exponents held, the proven coefficient\n"
    "            bound, primes used, coefficient bits and the time\n"
    "\n"
    "exit status: 0 done; 2 bad input (FILE must hold exactly three sites, no two\n"
    "crossing); 1 the resultant vanishes identically (a common component, e.g. some\n"
    "placements of three circles).\n";

int run(const std::vector<std::string>& args) {
    Arguments parsed(args, {{"--cin", false}, {"--stats", false}});
    parsed.expect_positional(1, 1, "FILE");
    const SiteFile file = read_site_argument(parsed, parsed.positional()[0]);
    require_site_count(file, 3, 3, "E1 E2 E3");
    require_acceptable_crossings(file);
    const auto& s = file.sites;

    const IncircleResultant r = incircle_resultant(s[0], s[1], s[2]);
    std::ostringstream out;
    for (long i = 0; i <= r.degree; ++i) out << r.polynomial.coeff(i).str() << '\n';
    std::cout << out.str();
    if (parsed.has("--stats")) {
        std::ostringstream e;
        e << "degree: " << r.degree << "\n"
          << "expected degree: " << r.expected_degree << "\n"
          << "full R2 degree: " << r.r2_degree << "\n"
          << "removed factors: " << r.removed_factors.size() << "\n";
        for (const auto& f : r.removed_factors) e << "  " << f.first << "  exponent " << f.second << "\n";
        e
          << "seed exponents held: " << (r.generic_exponents ? "yes" : "no") << "\n"
          << "coefficient bound: 2^" << r.bound_bits << " (full R2)\n"
          << "primes used: " << r.primes_used << "\n"
          << "coefficient bits: " << r.coefficient_bits << "\n"
          << "seconds: " << r.seconds << "\n";
        std::cerr << e.str();
    }
    return kExitOk;
}

}  // namespace

const Command command_resultant = {"resultant", "the InCircle resultant polynomial of three sites", kHelp, run};

}  // namespace ellvor::cli
