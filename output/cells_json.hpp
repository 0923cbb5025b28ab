// The cells as JSON (`ellvor cells --format json`, `Cells.to_json()`): the
// domain, the Voronoi vertices and per site its cell, every certified value
// as {"lo", "hi"} doubles rounded outward (see `ellvor cells --help`).
#pragma once

#include "cells/cell_tessellation.hpp"

#include <nlohmann/json.hpp>

namespace ellvor {

// A bound as JSON: a number, "inf" or "-inf"; null for NaN.
nlohmann::json json_bound(double x);
// {"lo", "hi"} rounded outward; null for a ball that claims nothing (indeterminate).
nlohmann::json ball_json(const Ball& b);

nlohmann::json cells_json(const CellTessellation& cells);

}  // namespace ellvor
