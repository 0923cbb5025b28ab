// ellvor generate: random site sets and the paper's circle datasets.
#include "cli/command_list.hpp"

#include "sites/packing_generator.hpp"
#include "sites/rational_parse.hpp"
#include "sites/site_generators.hpp"
#include "sites/site_io.hpp"
#include "util/error.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <sstream>
#include <sys/stat.h>
#include <tuple>

namespace ellvor::cli {
namespace {

const char* const kHelp =
    "usage: ellvor generate (ellipses|circles|nested) --count N [--seed S] [--bits B] [--box X]\n"
    "                       [--nested-fraction F] [--crossing F] [--cin] [-o FILE]\n"
    "       ellvor generate packing --count N --packing-fraction F [--gap G] [--aspect LO..HI]\n"
    "                       [--seed S] [-o FILE]\n"
    "       ellvor generate paper-dataset (kappa1|kappa2|incircle) --set (1|2a|2b|2c|3) [--seed S]\n"
    "                       [--bits B] [-o DIR/|FILE]\n"
    "\n"
    "Random pairwise-disjoint sites (crossing ones on request), written as a .ell file (exact\n"
    "rationals) with a header comment saying how it was generated. The same arguments give the\n"
    "same file on every machine.\n"
    "  ellipses   N random ellipses in the box [-X, X]^2\n"
    "  circles    N random circles (a = b, w = 0)\n"
    "  nested     ellipses of which a fraction F (default 1/4) lies strictly inside another\n"
    "  packing    a dense packing: N random ellipses in the box [0, L]^2, L = ceil(sqrt(N)), each\n"
    "             inside the box, every two at distance >= G (certified), at packing fraction\n"
    "             >= F, the fraction being the area of the ellipses over the box's, pi sum(a b) / L^2\n"
    "             (so a site's mean area is about F). Made by random sequential addition,\n"
    "             largest sites first (sizes from 1 down to 1/6 of the largest), up to fraction\n"
    "             0.55 (or F if lower; when a site finds no room, again from the start at\n"
    "             0.8 times that, up to 6 times), then growth of each site about its center until the\n"
    "             fraction is reached (so some pairs end about G apart); a fraction the sites\n"
    "             jam below (about 0.63 at aspect 1..4) is an error saying the fraction\n"
    "             reached. The header gives the fraction reached (certified bounds)\n"
    "\n"
    "options:\n"
    "  --count N            number of sites (required, 0..1000000; packing 30..1000000)\n"
    "  --seed S             seed of the generator, an unsigned 64-bit integer (default 1)\n"
    "  --bits B             denominators of the rationals up to 2^B (default 8, at most 1000;\n"
    "                       for paper-dataset set 3 default 16)\n"
    "  --box X              half-width of the box, a positive rational (default 100)\n"
    "  --nested-fraction F  fraction in [0, 1) of sites nested in another (rounded to a count;\n"
    "                       default 0, or 1/4 for 'nested'); exact rationals such as 0.25 or 1/4\n"
    "  --crossing F         exactly round(F N) of the sites, F in [0, 1], cross at least one\n"
    "                       other site (boundaries meeting in exactly two points, checked\n"
    "                       exactly; never three or four); the others cross none; nested sites\n"
    "                       never cross, and a count of 1 is an error. Crossing ellipses are\n"
    "                       thin (aspect ratio up to 16) or fat, at any angle, crossing deep\n"
    "                       (a center inside the other) or shallow. Default 0: the file is the\n"
    "                       same as without it\n"
    "  --packing-fraction F packing: the fraction to reach, a rational in (0, 17/20] (0.58 is\n"
    "                       reached at aspect 1..4; denser ones may jam)\n"
    "  --gap G              packing: the least distance between two sites, a rational in [0, 1/10]\n"
    "                       (default 1/1000; 0: disjoint); the box is about sqrt(N) wide, sites\n"
    "                       about 1\n"
    "  --aspect LO..HI      packing: aspect ratios a/b drawn in [LO, HI], 1 <= LO <= HI <= 16\n"
    "                       (default 1..4), multiples of 1/4096\n"
    "  --cin                write CGAL's 'x y r' circle format (circles only)\n"
    "  -o, --output FILE    write FILE atomically (a temporary file renamed into place)\n"
    "                       instead of standard output\n"
    "\n"
    "paper-dataset writes the circle datasets of Emiris, Tsigaridas and Tzoumas (2007,\n"
    "section 5.1) for kappa1 (sites E1 E2 and a query point), kappa2 (E1 E2 and a query\n"
    "circle Q) and incircle (E1 E2 E3 and Q). Set 1 is the degenerate family, 2a/2b/2c add +-10^-2/-4/-6 (random\n"
    "sign) to every coordinate and radius, 3 has 500 random instances. With -o DIR/ (an\n"
    "existing directory, or a path ending in '/', created if missing) each instance is one\n"
    "site file FAMILY-SET-NNNN.ell with the sites in order and Q last; a kappa1 query point is\n"
    "the comment line '# query-point: X Y'. A manifest FAMILY-SET-manifest.txt lists them.\n"
    "Otherwise all instances go into one listing (FILE or standard output), each introduced\n"
    "by '# instance K'; a listing is not itself a valid site file.\n";

std::string instance_text(const PaperDataset& ds, std::size_t k) {
    const PaperInstance& inst = ds.instances[k];
    std::ostringstream s;
    if (inst.query_point) s << "# query-point: " << inst.query_point->x.str() << ' ' << inst.query_point->y.str() << '\n';
    for (const Ellipse& e : inst.sites) s << e.str() << '\n';
    if (inst.query_site) s << inst.query_site->str() << '\n';
    return s.str();
}

bool is_directory(const std::string& path) {
    struct stat st;
    return ::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}

int run_paper_dataset(const Arguments& parsed) {
    parsed.expect_positional(2, 2, "a family: kappa1, kappa2 or incircle");
    const std::string fam = parsed.positional()[1];
    PaperFamily family;
    if (fam == "kappa1") family = PaperFamily::kappa1;
    else if (fam == "kappa2") family = PaperFamily::kappa2;
    else if (fam == "incircle") family = PaperFamily::incircle;
    else throw UsageError("unknown family '" + fam + "': expected kappa1, kappa2 or incircle");
    parsed.require("--set");
    const std::string set = parsed.value("--set");
    if (set != "1" && set != "2a" && set != "2b" && set != "2c" && set != "3")
        throw UsageError("option --set: expected 1, 2a, 2b, 2c or 3, got '" + set + "'");
    for (const char* o : {"--count", "--box", "--nested-fraction", "--crossing", "--cin", "--packing-fraction", "--gap",
                          "--aspect"})
        if (parsed.has(o)) throw UsageError(std::string("option ") + o + " does not apply to paper-dataset");
    const std::uint64_t seed = parsed.unsigned_integer("--seed", 1);
    const long bits = parsed.integer("--bits", 16, 1, kMaxGeneratorBits);
    const PaperDataset ds = generate_paper_dataset(family, set, seed, bits);

    std::ostringstream header;
    header << "# ellvor generate paper-dataset " << fam << " --set " << set << " --seed " << seed << " --bits " << bits
           << "\n# Emiris, Tsigaridas, Tzoumas (2007) section 5.1, " << fam << " set " << set << ": "
           << ds.instances.size() << " instances\n";
    const std::string sites_line = family == PaperFamily::kappa1   ? "# each instance: E1 E2 (circles); query point in a comment\n"
                                   : family == PaperFamily::kappa2 ? "# each instance: E1 E2 Q (circles, Q the query)\n"
                                                                   : "# each instance: E1 E2 E3 Q (circles, Q the query)\n";
    const std::string out = parsed.value("-o");
    const bool dir_mode = !out.empty() && (out.back() == '/' || is_directory(out));
    if (dir_mode) {
        std::string dir = out;
        while (dir.size() > 1 && dir.back() == '/') dir.pop_back();
        if (!is_directory(dir) && ::mkdir(dir.c_str(), 0777) != 0)
            throw Error("cannot create directory '" + dir + "': " + std::strerror(errno));
        std::ostringstream manifest;
        manifest << header.str() << sites_line << "# file";
        if (family == PaperFamily::kappa1) manifest << " query_x query_y";
        manifest << '\n';
        for (std::size_t k = 0; k < ds.instances.size(); ++k) {
            char name[64];
            std::snprintf(name, sizeof name, "%s-%s-%04zu.ell", fam.c_str(), set.c_str(), k);
            const std::string text = header.str() + sites_line + "# instance " + std::to_string(k) + "\n" +
                                     instance_text(ds, k);
            write_file_atomically(dir + "/" + name, [&](std::ostream& o) { o << text; });
            manifest << name;
            if (const auto& q = ds.instances[k].query_point) manifest << ' ' << q->x.str() << ' ' << q->y.str();
            manifest << '\n';
        }
        write_file_atomically(dir + "/" + fam + "-" + set + "-manifest.txt",
                              [&](std::ostream& o) { o << manifest.str(); });
        std::cerr << "wrote " << ds.instances.size() << " instances to " << dir << "/\n";
        return kExitOk;
    }
    auto write = [&](std::ostream& o) {
        o << header.str() << sites_line << "# listing: instances separated by '# instance K' lines\n";
        for (std::size_t k = 0; k < ds.instances.size(); ++k) o << "# instance " << k << '\n' << instance_text(ds, k);
    };
    if (out.empty()) write(std::cout);
    else write_file_atomically(out, write);
    return kExitOk;
}

// "LO..HI" as two rationals.
std::pair<Rational, Rational> aspect_range(const Arguments& parsed) {
    if (!parsed.has("--aspect")) return {Rational(1), Rational(4)};
    const std::string v = parsed.value("--aspect");
    const auto dots = v.find("..");
    if (dots == std::string::npos)
        throw UsageError("option --aspect: expected LO..HI (e.g. 1..4), got '" + v + "'");
    Rational lo, hi;
    try {
        lo = parse_rational(v.substr(0, dots));
        hi = parse_rational(v.substr(dots + 2));
    } catch (const Error&) {
        throw UsageError("option --aspect: expected LO..HI with rationals LO and HI, got '" + v + "'");
    }
    if (lo < Rational(1) || hi < lo || hi > Rational(16))
        throw UsageError("option --aspect: expected 1 <= LO <= HI <= 16, got '" + v + "'");
    return {lo, hi};
}

int run_packing(const Arguments& parsed) {
    parsed.expect_positional(1, 1, "one kind: packing");
    for (const char* o : {"--bits", "--box", "--nested-fraction", "--crossing", "--cin", "--set"})
        if (parsed.has(o)) throw UsageError(std::string("option ") + o + " does not apply to packing");
    parsed.require("--count");
    parsed.require("--packing-fraction");
    PackingOptions o;
    o.count = parsed.integer("--count", 0, kMinPackingCount, 1'000'000);
    o.seed = parsed.unsigned_integer("--seed", 1);
    o.fraction = parsed.rational("--packing-fraction", Rational(0));
    if (o.fraction.sign() <= 0 || o.fraction > max_packing_fraction())
        throw UsageError("option --packing-fraction: expected a rational in (0, " + max_packing_fraction().str() +
                         "], got " + o.fraction.str());
    o.gap = parsed.rational("--gap", Rational(1, 1000));
    if (o.gap.sign() < 0 || o.gap > Rational(1, 10))
        throw UsageError("option --gap: expected a rational in [0, 1/10], got " + o.gap.str());
    std::tie(o.aspect_lo, o.aspect_hi) = aspect_range(parsed);
    Packing packing;
    try {
        packing = generate_packing(o);
    } catch (const Error& e) {
        throw UsageError(e.what());
    }
    const std::string header = "generated by: " + describe(o) + "\nbox [0, " + std::to_string(packing.box_side) +
                               "]^2; packing fraction in " + fraction_bounds_text(packing) + "\n" +
                               std::to_string(packing.sites.size()) +
                               " sites, ids 0-based in file order; a b w xc yc (exact rationals)";
    auto write = [&](std::ostream& out) { write_ell(out, packing.sites, header); };
    const std::string path = parsed.value("-o");
    if (path.empty()) write(std::cout);
    else write_file_atomically(path, write);
    return kExitOk;
}

int run_generate(const std::vector<std::string>& args) {
    Arguments parsed(args, {{"--count", true},
                            {"--seed", true},
                            {"--bits", true},
                            {"--box", true},
                            {"--nested-fraction", true},
                            {"--crossing", true},
                            {"--set", true},
                            {"--cin", false},
                            {"--packing-fraction", true},
                            {"--gap", true},
                            {"--aspect", true},
                            {"-o", true, "--output"}});
    if (parsed.positional().empty())
        throw UsageError("missing argument: expected ellipses, circles, nested, packing or paper-dataset");
    const std::string kind = parsed.positional()[0];
    if (kind == "paper-dataset") return run_paper_dataset(parsed);
    if (kind == "packing") return run_packing(parsed);
    for (const char* o : {"--packing-fraction", "--gap", "--aspect"})
        if (parsed.has(o)) throw UsageError(std::string("option ") + o + " applies to packing only");
    if (kind != "ellipses" && kind != "circles" && kind != "nested")
        throw UsageError("unknown kind '" + kind + "': expected ellipses, circles, nested, packing or paper-dataset");
    parsed.expect_positional(1, 1, "one kind: ellipses, circles, nested or paper-dataset");
    if (parsed.has("--set")) throw UsageError("option --set applies to paper-dataset only");
    parsed.require("--count");
    GeneratorOptions o;
    o.kind = kind == "circles" ? SiteKind::circles : SiteKind::ellipses;
    o.count = parsed.integer("--count", 0, 0, 1'000'000);
    o.seed = parsed.unsigned_integer("--seed", 1);
    o.bits = parsed.integer("--bits", 8, 1, kMaxGeneratorBits);
    o.box = parsed.rational("--box", Rational(100));
    if (o.box.sign() <= 0) throw UsageError("option --box: expected a positive rational, got " + o.box.str());
    if (o.box.bits() > 64) throw UsageError("option --box: at most 64-bit numerator and denominator");
    o.nested_fraction = parsed.rational("--nested-fraction", kind == "nested" ? Rational(1, 4) : Rational(0));
    if (o.nested_fraction.sign() < 0 || o.nested_fraction >= Rational(1))
        throw UsageError("option --nested-fraction: expected a rational in [0, 1), got " + o.nested_fraction.str());
    o.crossing_fraction = parsed.rational("--crossing", Rational(0));
    if (o.crossing_fraction.sign() < 0 || o.crossing_fraction > Rational(1))
        throw UsageError("option --crossing: expected a rational in [0, 1], got " + o.crossing_fraction.str());
    const bool cin = parsed.has("--cin");
    if (cin && o.kind != SiteKind::circles) throw UsageError("option --cin needs 'circles'");

    std::vector<Ellipse> sites;
    try {
        sites = generate_sites(o);
    } catch (const UsageError&) {
        throw;
    } catch (const Error& e) {
        throw UsageError(e.what());
    }
    std::string header = describe(o);
    if (kind == "nested") header = "ellvor generate nested" + header.substr(std::string("ellvor generate ellipses").size());
    header = "generated by: " + header + "\n" + std::to_string(sites.size()) + " sites, ids 0-based in file order; " +
             (cin ? "x y r" : "a b w xc yc") + " (exact rationals)";
    auto write = [&](std::ostream& out) {
        if (cin) write_cin(out, sites, header);
        else write_ell(out, sites, header);
    };
    const std::string path = parsed.value("-o");
    if (path.empty()) write(std::cout);
    else write_file_atomically(path, write);
    return kExitOk;
}

}  // namespace

const Command command_generate = {"generate", "random, nested, circle and paper site sets (.ell)", kHelp,
                                  run_generate};

}  // namespace ellvor::cli
