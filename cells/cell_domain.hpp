// Where cells live: the free plane, a box with walls, or a periodic box (the
// torus), and the walls of a box (docs/DESIGN.md §10).
#pragma once

#include "util/flint_types.hpp"

namespace ellvor {

struct CellDomain {
    enum class Kind { plane, box, periodic };
    Kind kind = Kind::plane;
    // The rectangle [x0, x1] x [y0, y1] of a box or of the periodic box.
    Rational x0, y0, x1, y1;
};

// A wall of a box, as the neighbour across a cell side.
enum class Wall : int { none = 0, left = 1, bottom = 2, right = 3, top = 4 };
const char* wall_name(Wall w);  // "left", "bottom", "right", "top"; "" for none

// Throws InputError unless x0 < x1 and y0 < y1 (a box or a periodic box;
// nothing for the plane).
void require_proper_rectangle(const CellDomain& domain);

}  // namespace ellvor
