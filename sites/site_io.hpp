// Reading and writing site files (docs/DESIGN.md §6).
//
// `.ell`: one ellipse a line, "a b w xc yc", each token a rational as accepted
// by parse_rational (integer, p/q, exact decimal). `.cin` (CGAL's Apollonius
// input, read with SiteFormat::cin): one circle a line, "x y r" (center, radius).
// In both: '#' starts a comment anywhere on a line, blank lines are skipped,
// fields are separated by spaces or tabs, a trailing '\r' (CRLF files) is
// ignored, and site ids are 0-based in file order. Unlike CGAL's own reader we
// keep exactly one site per line, so that every error has a line.
//
// Every problem is an InputError "FILE:LINE:COLUMN: what was expected", with the
// 1-based column of the offending token (or of the end of the line for missing
// fields; column 1 for whole-line or whole-file problems):
//   missing or extra fields, a token that is not a rational, nan/inf, zero
//   denominators, numbers beyond kMaxRationalBits, a <= 0, b <= 0 (r <= 0), a
//   semi-axis ratio beyond 2^kMaxAspectBits, a site set whose extent exceeds
//   its smallest semi-axis by more than 2^kMaxDynamicRangeBits, two
//   sites that are the same point set (the message names both lines and ids),
//   a line longer than kMaxLineLength bytes, more than kMaxSites sites, a NUL
//   byte, a file that cannot be opened.
//
// Writers produce exact "p/q" tokens, so reading back gives equal Ellipses.
#pragma once

#include "sites/ellipse.hpp"
#include "util/error.hpp"

#include <cstddef>
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

namespace ellvor {

enum class SiteFormat { ell, cin };

// Input caps: a line longer than this is refused (as soon as the limit is
// passed, without reading the rest of the line into memory), and so is a file
// with more sites than kMaxSites.
constexpr std::size_t kMaxLineLength = 1 << 20;  // 1 MiB
constexpr std::size_t kMaxSites = 10'000'000;
// Shape and scale caps (docs/DESIGN.md §6). The numerical stages resolve a
// site's boundary in doubles first: beyond a semi-axis ratio of 2^40 the tip
// of a needle (radius of curvature b^2 / a) is below their resolution. And
// a set whose extent exceeds its smallest semi-axis by more than 2^256 would
// need thousands of bits per decision. Both are input errors that state the
// limit.
constexpr long kMaxAspectBits = 40;
constexpr long kMaxDynamicRangeBits = 256;

struct SiteFile {
    std::string name;             // the display name used in messages
    std::vector<Ellipse> sites;   // id = index
    std::vector<long> lines;      // 1-based line of each site; empty for sites that come from no file
};

// Read from a stream; `display_name` names it in messages.
SiteFile read_site_file(std::istream& in, const std::string& display_name, SiteFormat format = SiteFormat::ell);
// Read from a path ("-" is standard input). Throws InputError "PATH:1:1: cannot open ..." when unreadable.
SiteFile read_site_file(const std::string& path, SiteFormat format = SiteFormat::ell);

// The checks of a whole site set that the reader makes (no two sites the
// same point set, the dynamic range), for sites made otherwise (the Python
// module); without lines the errors name site ids and carry no location.
// Each site's own checks (a, b > 0, the aspect ratio) are the maker's.
void check_site_set(const SiteFile& file);

std::vector<Ellipse> read_sites(std::istream& in, const std::string& display_name, SiteFormat format = SiteFormat::ell);
std::vector<Ellipse> read_sites(const std::string& path, SiteFormat format = SiteFormat::ell);

// The input error for two sites of a file that cross in a way the diagram does
// not accept (crossing_pair_problem in predicates/relative_position.hpp), at
// the later site's line: "FILE:LINE:1: site j crosses site i (line L): WHY"
// (the reader does not test pairs: the graph and the commands find crossings).
IntersectingSites crossing_sites_error(const SiteFile& file, std::size_t first, std::size_t second, const std::string& why);

// Writers. `header` lines (may be empty) are written first, each prefixed with "# ".
void write_ell(std::ostream& out, const std::vector<Ellipse>& sites, const std::string& header = "");
// Every site must be a circle (a == b), else Error. A circle's rotation is not
// written, so a circle with w != 0 reads back as the same point set with w = 0.
void write_cin(std::ostream& out, const std::vector<Ellipse>& sites, const std::string& header = "");

// Writes a file atomically: `write` fills a temporary file in the same
// directory, which is flushed and renamed onto `path` only if everything
// succeeded; otherwise it is removed and the error rethrown. Throws Error when
// the file cannot be created or written.
void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write);

}  // namespace ellvor
