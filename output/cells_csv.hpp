// The cells as CSV (`ellvor cells --format csv`): a header, then one row per
// site in input order; the columns and their conventions are in
// `ellvor cells --help`.
#pragma once

#include "cells/cell_tessellation.hpp"

#include <ostream>
#include <string>

namespace ellvor {

extern const char* const kCellsCsvHeader;

// One side's entry in the neighbors column: "7", "wall:left", or "7@1,-1"
// for a periodic neighbour whose image is shifted by (1, -1) box sizes.
std::string neighbor_label(const CellSide& side);

void write_cells_csv(std::ostream& out, const CellTessellation& cells);

}  // namespace ellvor
