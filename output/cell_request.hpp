// A request for cells as the interfaces take it (`ellvor cells`,
// `Diagram.cells()`): the domain and tolerances checked with messages naming
// the argument as the caller spells it, the site centres against a box at
// their file lines, and the library's errors about sites (which carry site
// ids) moved to those lines, so that the CLI and Python say the same.
#pragma once

#include "cells/cell_tessellation.hpp"
#include "sites/site_io.hpp"

#include <optional>
#include <string>

namespace ellvor {

// How the caller spells its arguments: "option --box" (CLI), "box" (Python).
struct CellArgumentNames {
    std::string box, periodic, tolerance, boundary_tolerance;
};

// InputError "NAME: what was expected" for a tolerance outside (0, 1] (NaN
// included), a given boundary tolerance that is not a positive number, and a
// box or periodic box with x0 >= x1 or y0 >= y1.
void check_cell_arguments(const CellDomain& domain, double tolerance, std::optional<double> boundary_tolerance,
                          const CellArgumentNames& names);

// For a box: InputError "FILE:LINE:1: site K has its center (x, y) outside
// the box X0 Y0 X1 Y1" for the first site whose centre is not in the closed
// box (the sites' own lines; ids without lines): the same words for every caller.
void check_centers_in_box(const SiteFile& file, const CellDomain& domain);

// A library error that names sites by id (InputError::sites: a pair, or one
// site twice) at the file's line of the (later) site; unchanged when the file
// has no lines or the error names no site.
InputError site_error_at_lines(const SiteFile& file, const InputError& error);

// The checks above, then cell_tessellation(file.sites, ...), its site errors
// at their lines.
CellTessellation cells_of_site_file(const SiteFile& file, const CellDomain& domain, const CellOptions& options,
                                    std::optional<double> boundary_tolerance, const CellArgumentNames& names);

}  // namespace ellvor
