#include "cells/box_mirrors.hpp"

#include "util/error.hpp"

#include <string>

namespace ellvor {

AxisLine wall_line(Wall wall, const CellDomain& box) {
    switch (wall) {
        case Wall::left: return {true, box.x0};
        case Wall::bottom: return {false, box.y0};
        case Wall::right: return {true, box.x1};
        case Wall::top: return {false, box.y1};
        case Wall::none: break;
    }
    throw Error("wall_line: no wall");
}

void require_sites_inside_box(const std::vector<Ellipse>& sites, const CellDomain& box) {
    for (SiteId i = 0; i < sites.size(); ++i) {
        const Ellipse& e = sites[i];
        const bool center_inside = box.x0 < e.xc() && e.xc() < box.x1 && box.y0 < e.yc() && e.yc() < box.y1;
        for (Wall w : {Wall::left, Wall::bottom, Wall::right, Wall::top})
            if (!center_inside || !strictly_beside(e, wall_line(w, box)))
                throw InputError("cells: site " + std::to_string(i) + " is not strictly inside the box (" +
                                     (center_inside ? std::string("it reaches the ") + wall_name(w) + " wall"
                                                    : std::string("its center is outside")) +
                                     ")",
                                 InputError::SitePair{i, i});
    }
}

MirroredSites with_box_mirrors(const std::vector<Ellipse>& sites, const CellDomain& box) {
    MirroredSites out;
    out.originals = sites.size();
    out.sites = sites;
    out.sites.reserve(5 * sites.size());
    for (const Ellipse& e : sites)
        for (Wall w : {Wall::left, Wall::bottom, Wall::right, Wall::top}) out.sites.push_back(mirror_across(e, wall_line(w, box)));
    return out;
}

}  // namespace ellvor
