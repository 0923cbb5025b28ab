#include "cells/box_mirrors.hpp"

#include "util/error.hpp"
#include "util/interval.hpp"

#include <algorithm>
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
        for (Wall w : kWalls)
            if (!center_inside || !strictly_beside(e, wall_line(w, box)))
                throw InputError("cells: site " + std::to_string(i) + " is not strictly inside the box (" +
                                     (center_inside ? std::string("it reaches the ") + wall_name(w) + " wall"
                                                    : std::string("its center is outside")) +
                                     ")",
                                 InputError::SitePair{i, i});
    }
}

MirroredSites with_box_mirrors(const std::vector<Ellipse>& sites, const CellDomain& box,
                               const std::vector<WallMirrors>& across) {
    if (across.size() != sites.size()) throw Error("with_box_mirrors: one set of walls a site");
    MirroredSites out;
    out.originals = sites.size();
    out.sites = sites;
    for (SiteId i = 0; i < sites.size(); ++i) out.original.push_back(i);
    out.wall.assign(sites.size(), Wall::none);
    for (SiteId i = 0; i < sites.size(); ++i)
        for (int k = 0; k < 4; ++k)
            if (across[i][static_cast<std::size_t>(k)]) {
                out.sites.push_back(mirror_across(sites[i], wall_line(kWalls[k], box)));
                out.original.push_back(i);
                out.wall.push_back(kWalls[k]);
            }
    return out;
}

double distance_to_wall(const Ellipse& site, Wall wall, const CellDomain& box) {
    const AxisLine line = wall_line(wall, box);
    const Rational difference = (line.vertical ? site.xc() : site.yc()) - line.c;
    return enclose(difference.sign() < 0 ? -difference : difference).lo;
}

std::vector<WallMirrors> walls_near(const std::vector<Ellipse>& sites, const CellDomain& box, double distance) {
    std::vector<WallMirrors> out(sites.size());
    for (SiteId i = 0; i < sites.size(); ++i) {
        const double size = std::max(sites[i].a().to_double(), sites[i].b().to_double());
        for (int k = 0; k < 4; ++k)
            out[i][static_cast<std::size_t>(k)] = distance_to_wall(sites[i], kWalls[k], box) <= distance + size;
    }
    return out;
}

}  // namespace ellvor
