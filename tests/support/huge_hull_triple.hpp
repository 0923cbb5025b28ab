// Three sites of `ellvor generate ellipses --count 1000000 --seed 1` (ids
// 59590, 863090, 139328, in that order, lines copied from the file): ~0.02
// wide, at x ~ -100 on the left side of the box and nearly on a line, they
// form a hull face whose counter-clockwise Voronoi circle has radius ~3.16e5
// (~1.6e7 times the smallest semi-axis). The double certificate proves it
// only with a box ~1 wide: the tiled build's hull test needs Arb's box.
#pragma once

#include "sites/ellipse.hpp"
#include "sites/site_io.hpp"

#include <sstream>
#include <vector>

namespace ellvor::test {

inline std::vector<Ellipse> huge_hull_triple() {
    std::istringstream lines(
        "2/103 1/125 1/17 -15295/153 2360/31\n"
        "3/166 1/59 -131/172 -3399/34 8314/91\n"
        "2/85 4/207 -74/251 -3299/33 46/15\n");
    return read_sites(lines, "huge_hull_triple");
}

}  // namespace ellvor::test
