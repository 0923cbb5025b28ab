// Counts of the double-interval quadrature's work (cells/edge_quadrature.hpp),
// for the benchmarks.
#pragma once

#include <cstddef>

namespace ellvor {

// What integrate_edge and integrate_edge_in_arb did, added up (for the
// benchmarks and the tests): the pieces integrated, the disks whose
// certificate failed (the piece was halved), the density nodes evaluated, of
// those in Arb the ones the disk's proof certified
// (NormalRayInDoubles::densities_in_balls; the rest by NormalRayBisector),
// the edges whose ends came in reverse order (integrated from the second to
// the first: an edge of length zero).
struct QuadratureCounts {
    std::size_t pieces = 0, failed_disks = 0, nodes = 0, ball_nodes_from_disks = 0, reversed_edges = 0;
    QuadratureCounts& operator+=(const QuadratureCounts& o) {
        pieces += o.pieces, failed_disks += o.failed_disks, nodes += o.nodes;
        ball_nodes_from_disks += o.ball_nodes_from_disks, reversed_edges += o.reversed_edges;
        return *this;
    }
};

}  // namespace ellvor
