#include "cells/cell_domain.hpp"

#include "util/error.hpp"

namespace ellvor {

const char* wall_name(Wall w) {
    switch (w) {
        case Wall::left: return "left";
        case Wall::bottom: return "bottom";
        case Wall::right: return "right";
        case Wall::top: return "top";
        case Wall::none: break;
    }
    return "";
}

void require_proper_rectangle(const CellDomain& domain) {
    if (domain.kind == CellDomain::Kind::plane) return;
    const char* what = domain.kind == CellDomain::Kind::box ? "box" : "periodic box";
    if (!(domain.x0 < domain.x1))
        throw InputError(std::string("cells: the ") + what + " needs XMIN < XMAX (got " + domain.x0.str() + " and " +
                         domain.x1.str() + ")");
    if (!(domain.y0 < domain.y1))
        throw InputError(std::string("cells: the ") + what + " needs YMIN < YMAX (got " + domain.y0.str() + " and " +
                         domain.y1.str() + ")");
}

}  // namespace ellvor
