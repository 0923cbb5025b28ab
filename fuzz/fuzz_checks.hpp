// What the fuzz targets check for one input, shared with the regression tests
// (tests/cli/test_fuzz_regressions.cpp) so that a finding replays in the normal
// suite exactly as the fuzzer ran it.
//
// An Outcome is `accepted` (a SiteFile, or a graph that validated), `input_error`
// (an InputError: the message names the file, line and column), or `finding`:
// anything valid input must never give (another exception, an invalid graph, a
// SiteFile that does not survive its own writer). Crashes, hangs and sanitizer
// reports are findings too, but those the fuzzer sees by itself.
#pragma once

#include "graph/delaunay_graph.hpp"
#include "traits/ellipse_delaunay_traits.hpp"
#include "sites/site_io.hpp"
#include "util/error.hpp"

#include <exception>
#include <memory>
#include <sstream>
#include <string>

namespace ellvor::fuzz {

struct Outcome {
    enum Kind { accepted, input_error, finding };
    Kind kind;
    std::string message;  // the InputError's or the finding's; empty when accepted
    SiteFile file;        // what was read (sites empty unless the input parsed)
};

// The parser target: `text` read as a site file in `format` ("fuzz" in messages).
// An accepted file must read back from its exact "p/q" form as the same sites,
// so that a parse which silently changed a value is a finding too.
inline Outcome read_site_text(const std::string& text, SiteFormat format) {
    Outcome out{Outcome::accepted, "", {}};
    try {
        std::istringstream in(text);
        out.file = read_site_file(in, "fuzz", format);
    } catch (const InputError& e) {
        return {Outcome::input_error, e.what(), {}};
    } catch (const std::exception& e) {
        return {Outcome::finding, std::string("reader: not an input error: ") + e.what(), {}};
    }
    if (out.file.lines.size() != out.file.sites.size())
        return {Outcome::finding, "reader: not one line number per site", {}};
    std::ostringstream written;
    write_ell(written, out.file.sites);
    try {
        std::istringstream again(written.str());
        if (read_site_file(again, "rewritten", SiteFormat::ell).sites != out.file.sites)
            return {Outcome::finding, "writer: the sites read back different: " + written.str().substr(0, 400), {}};
    } catch (const std::exception& e) {
        return {Outcome::finding, std::string("writer: the sites do not read back: ") + e.what(), {}};
    }
    return out;
}

// The build target, in two steps: what `ellvor build --validate` does with a
// .ell file ("fuzz.ell" in messages): read it, then insert every site, validate
// the graph and check it by brute force. InputError, IntersectingSites
// included, is the only acceptable failure; any other ellvor::Error is an
// internal error or an uncertified answer on valid input.
inline Outcome read_ell_text(const std::string& text) {
    Outcome out{Outcome::accepted, "", {}};
    try {
        std::istringstream in(text);
        out.file = read_site_file(in, "fuzz.ell", SiteFormat::ell);
    } catch (const InputError& e) {
        return {Outcome::input_error, e.what(), {}};
    } catch (const std::exception& e) {
        return {Outcome::finding, std::string("reader: not an input error: ") + e.what(), {}};
    }
    return out;
}

inline Outcome build_sites(const SiteFile& file) {
    try {
        DelaunayGraph graph(std::make_unique<EllipseDelaunayTraits>(file.sites));
        graph.insert_all();
        std::string problem = graph.validate();
        if (problem.empty()) problem = graph.brute_force_check();
        if (!problem.empty()) return {Outcome::finding, "invalid graph: " + problem, file};
        // Deletion (build --remove): the odd ids, then the graph of the others
        // checked as above (one check: a brute-force check after every removal
        // costs more than the build on the slowest inputs).
        for (SiteId s = 1; s < file.sites.size(); s += 2) graph.remove(s);
        problem = graph.validate();
        if (problem.empty()) problem = graph.brute_force_check();
        if (!problem.empty()) return {Outcome::finding, "invalid graph after removing the odd sites: " + problem, file};
    } catch (const IntersectingSites& e) {
        // Located at the later site's line, as `ellvor build` reports it.
        return {Outcome::input_error, crossing_sites_error(file, e.first(), e.second(), e.why()).what(), file};
    } catch (const InputError& e) {
        return {Outcome::input_error, e.what(), file};
    } catch (const std::exception& e) {
        return {Outcome::finding, std::string("build failed on valid input: ") + e.what(), file};
    }
    return {Outcome::accepted, "", file};
}

inline Outcome build_site_text(const std::string& text) {
    Outcome read = read_ell_text(text);
    return read.kind == Outcome::accepted ? build_sites(read.file) : read;
}

}  // namespace ellvor::fuzz
