// A sequential colour scale for drawings (viridis's endpoints and three
// stops between, interpolated in sRGB): dark blue at the low end, yellow at
// the high end, readable in grey and by colour-blind readers.
#pragma once

#include <string>

namespace ellvor {

// "#rrggbb" for t in [0, 1] (clamped; NaN gives the low end).
std::string sequential_color(double t);

}  // namespace ellvor
