// A cell's local packing fraction, site area / cell area, as a ball
// (interval division: it contains the exact ratio).
#pragma once

#include "cells/cell_tessellation.hpp"

#include <optional>

namespace ellvor {

// Nothing for a hidden site (no cell); exactly 0 for an unbounded cell (the
// ratio's limit); else site_area / area at the cell's precision.
std::optional<Ball> packing_fraction(const Cell& cell);

}  // namespace ellvor
