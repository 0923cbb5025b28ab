// A Delaunay graph of ellipse sites, none inserted yet: the graph with the
// ellipse model of its traits, as `ellvor build` makes it.
#pragma once

#include "graph/delaunay_graph.hpp"
#include "traits/ellipse_delaunay_traits.hpp"
#include "sites/ellipse.hpp"
#include "sites/rational_parse.hpp"

#include <memory>
#include <utility>
#include <vector>

namespace ellvor::test {

// A site from the five numbers of a .ell line, each as the file would spell it.
inline Ellipse ellipse(const char* a, const char* b, const char* w, const char* x, const char* y) {
    return Ellipse(parse_rational(a), parse_rational(b), parse_rational(w), parse_rational(x), parse_rational(y));
}

inline DelaunayGraph ellipse_graph(std::vector<Ellipse> sites) {
    return DelaunayGraph(std::make_unique<EllipseDelaunayTraits>(std::move(sites)));
}

}  // namespace ellvor::test
