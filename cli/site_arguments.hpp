// Reading the site file named on a command line, for commands that take a
// fixed number of sites (E1 E2 [E3] [Q]).
#pragma once

#include "cli/arguments.hpp"
#include "sites/site_io.hpp"

#include <string>

namespace ellvor::cli {

// Reads `path` as .ell, or as CGAL .cin when --cin was given.
SiteFile read_site_argument(const Arguments& parsed, const std::string& path);

// Throws InputError unless the file holds between min and max sites; a
// surplus site is reported at its line. `roles` names them, e.g. "E1 E2 [Q]".
void require_site_count(const SiteFile& file, std::size_t min, std::size_t max, const std::string& roles);

// Throws crossing_sites_error (sites/site_io.hpp) for the first pair of the
// file's sites that crosses in a way the diagram does not accept (only circles
// may cross; predicates/relative_position.hpp). The predicate commands take a
// few sites; `build` learns of crossings from the graph, which tests each pair
// it meets.
void require_acceptable_crossings(const SiteFile& file);

}  // namespace ellvor::cli
