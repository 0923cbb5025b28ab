// The cells as JSON (`ellvor cells --format json`, `Cells.to_json()`): the
// domain, the Voronoi vertices and per site its cell, every certified value
// as {"lo", "hi"} doubles rounded outward (see `ellvor cells --help`).
#pragma once

#include "cells/cell_tessellation.hpp"

#include <nlohmann/json.hpp>

#include <ostream>

namespace ellvor {

// A bound as JSON: a number, "inf" or "-inf"; null for NaN.
nlohmann::json json_bound(double x);
// {"lo", "hi"} rounded outward; null for a ball that claims nothing (indeterminate).
nlohmann::json ball_json(const Ball& b);

// Writes the cells' JSON document (one line, no newline), a cell at a time:
// the bytes nlohmann's dump of the whole document would give (its keys in
// order), but the document is never held whole (10^4 random cells with
// rings: 967 MB at the peak for a 67 MB file, 412 MB after).
void write_cells_json(std::ostream& out, const CellTessellation& cells);

}  // namespace ellvor
