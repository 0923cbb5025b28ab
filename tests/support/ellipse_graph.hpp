// A Delaunay graph of ellipse sites, none inserted yet: the graph with the
// ellipse model of its traits, as `ellvor build` makes it.
#pragma once

#include "graph/delaunay_graph.hpp"
#include "traits/ellipse_delaunay_traits.hpp"
#include "sites/ellipse.hpp"

#include <memory>
#include <utility>
#include <vector>

namespace ellvor::test {

inline DelaunayGraph ellipse_graph(std::vector<Ellipse> sites) {
    return DelaunayGraph(std::make_unique<EllipseDelaunayTraits>(std::move(sites)));
}

}  // namespace ellvor::test
