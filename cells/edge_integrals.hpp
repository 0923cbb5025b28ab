// A cell's area and moments from its edges' Green integrals (docs/DESIGN.md
// §10). By Green's theorem, over a cell's boundary traversed
// counter-clockwise, with (x, y) taken about any point c:
//     area = 1/2 (integral of x dy - y dx),
//     integral of x dA = 1/2 (integral of x^2 dy),   of y dA = -1/2 (y^2 dx),
//     integral of x^2 dA = 1/3 (x^3 dy),   of y^2 dA = -1/3 (y^3 dx),
//     integral of x y dA = 1/2 (x^2 y dy).
// Each edge is integrated once, about an origin O of its own (near it, so
// that its integrals are of its own size), along the angle of one of its two
// sites (the owner): its integrals serve both cells. A cell about its site's
// center c takes x = X + u, y = Y + v with (u, v) = O - c, which expands each
// form above into the edge's integrals of EdgeMeasure and closed forms in its
// two vertices; the other cell traverses the edge backwards.
#pragma once

#include "cells/normal_ray_bisector.hpp"
#include "sites/ellipse.hpp"

#include <array>

namespace ellvor {

// An edge's integrals of EdgeMeasure between its two vertices, along its
// owner's angle (owner's counter-clockwise orientation), about `origin`.
struct EdgeIntegrals {
    std::array<Ball, EdgeMeasure::count> m;
    double origin[2] = {0, 0};
    BallPoint start, end;  // the vertices where the edge starts and ends, along the owner's angle
};

// What a cell's edges add up to, about a point c: area, perimeter, the
// integrals of x and y, and of x^2, x y, y^2 over the cell.
struct CellIntegrals {
    Ball area, perimeter;
    std::array<Ball, 2> first;
    std::array<Ball, 3> second;
};

// Adds the edge to the cell of the site whose center is c, traversed along
// the owner's orientation (forward: the cell is the owner's) or against it.
void add_edge(const EdgeIntegrals& edge, bool forward, const BallPoint& c, long prec, CellIntegrals& cell);

}  // namespace ellvor
