// The cells as GeoJSON (RFC 7946; `ellvor cells --format geojson`,
// `Cells.to_geojson()`): a FeatureCollection with one Polygon per cell that
// has a ring (closed and counter-clockwise, as RFC 7946 wants), properties site, area_lo,
// area_hi, packing_fraction_lo, packing_fraction_hi (outward doubles, as the
// JSON's). Cells without a ring (hidden, unbounded, or rings not computed)
// are left out and counted in the member "cells_without_ring".
#pragma once

#include "cells/cell_tessellation.hpp"

#include <ostream>

namespace ellvor {

// One line, no newline, a feature at a time (as write_cells_json).
void write_cells_geojson(std::ostream& out, const CellTessellation& cells);

}  // namespace ellvor
