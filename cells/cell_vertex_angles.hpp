// The Voronoi vertices of cells as certified balls: each vertex's center and
// its tangency angle theta on a site of its triple, and a bounded cell's
// vertex angles lifted to increase counter-clockwise through one turn
// (docs/DESIGN.md §10). The circles are certified once per face and refined
// on demand: in doubles first (subdivision/voronoi_circle_in_doubles.hpp),
// which give the angles to about 48 bits, then by Arb's solver for more.
#pragma once

#include "cells/voronoi_cells.hpp"
#include "graph/delaunay_graph.hpp"
#include "sites/ellipse.hpp"
#include "subdivision/voronoi_circle_enclosure.hpp"
#include "subdivision/voronoi_circle_in_doubles.hpp"

#include <array>
#include <memory>
#include <optional>
#include <vector>

namespace ellvor {

class CellVertexAngles {
public:
    using Faces = std::vector<std::array<SiteId, 3>>;
    // The sites must outlive this object.
    CellVertexAngles(const DelaunayGraph& graph, const std::vector<Ellipse>& sites);
    // With the graph's faces (DelaunayGraph::faces()) made once for several
    // of these (one a thread).
    CellVertexAngles(std::shared_ptr<const Faces> faces, const std::vector<Ellipse>& sites);

    // The tangency angle on `site` of the Voronoi circle of face number
    // `face`, theta = 2 atan(t) (or pi + 2 atan(u) in the flipped chart), its
    // radius about 2^(24 - prec) (at most that when it comes from the doubles).
    Ball angle(long face, SiteId site, long prec);
    // The center of the Voronoi circle of face number `face`, to prec - 24
    // correct bits (from the circle in doubles when that gives them).
    BallPoint vertex(long face, long prec);
    // The m + 1 angles of a bounded cell's m vertices (the first again at the
    // end), lifted so that consecutive differences lie in [0, 2 pi) (within
    // the balls) and the last is the first plus 2 pi; Error otherwise.
    std::vector<Ball> lifted(const VoronoiCell& cell, long prec);
    // How many angles and vertices so far came from the circles certified in doubles.
    long angles_from_doubles() const { return angles_from_doubles_; }
    long vertices_from_doubles() const { return vertices_from_doubles_; }

private:
    VoronoiCircleSolver& solver(long face, long prec);
    // The face's circle certified in doubles, or null when that fails.
    const DoubleVoronoiCircle* circle_in_doubles(long face);
    // The position of `site` in the face's triple.
    int position(long face, SiteId site) const;

    const std::vector<Ellipse>& sites_;
    std::shared_ptr<const Faces> faces_;
    std::vector<std::unique_ptr<VoronoiCircleSolver>> solvers_;
    std::vector<std::optional<DoubleVoronoiCircle>> circles_in_doubles_;
    std::vector<char> tried_in_doubles_;
    long angles_from_doubles_ = 0, vertices_from_doubles_ = 0;
};

}  // namespace ellvor
