// The conflict region of a new site p, as CGAL's Apollonius_graph_2 grows it
// (expand_conflict_region) and then bounds it for star_hole: the faces whose
// Voronoi vertex conflicts with p, grown from a first such face only across
// edges whose whole Voronoi edge is in conflict or one of whose sites p hides.
// (Growing across vertex conflicts alone is wrong for sites of non-zero size:
// a Voronoi edge may have both ends in conflict and not its middle.)
//
// Every predicate answer about p is memoized for the insertion: kappa2/kappa3
// per face, is_hidden(p, .) per vertex.
#pragma once

#include "graph/triangulation.hpp"
#include "graph/triangulation_predicates.hpp"

#include <map>
#include <set>
#include <vector>

namespace ellvor {

class ConflictRegion {
public:
    ConflictRegion(const Triangulation& tds, TriangulationPredicates predicates, SiteId p)
        : tds_(tds), predicates_(predicates), p_(p) {}

    SiteId site() const { return p_; }
    // p meets the open Voronoi disk of face f.
    bool in_conflict(FaceIndex f);
    // p hides the site of v (never the infinite vertex).
    bool hides(VertexIndex v);

    // Grows the region from `start`, breadth first.
    void expand(FaceIndex start);
    // The faces, in the order they were reached.
    const std::vector<FaceIndex>& faces() const { return faces_; }
    bool contains(FaceIndex f) const { return face_set_.count(f) != 0; }
    // The vertices whose sites p hides, by increasing index.
    std::vector<VertexIndex> hidden_vertices() const;
    // The edges between two faces of the region that the growth did not cross,
    // each once: the region touches itself along them, and the hole is a disk
    // only once each is split by a bogus vertex.
    std::vector<Edge> self_touching_edges() const;
    // The boundary edges (their face in the region), counter-clockwise. Throws
    // Error when they do not form one cycle (the region is not a disk).
    std::vector<Edge> boundary() const;
    // Throws Error unless the vertices strictly inside the region are exactly
    // the hidden ones: starring the hole deletes them.
    void check_inner_vertices(const std::vector<Edge>& boundary, const std::vector<VertexIndex>& hidden);

private:
    const Triangulation& tds_;
    TriangulationPredicates predicates_;
    SiteId p_;
    std::map<FaceIndex, Sign> incircle_;  // memo of predicates_.incircle(f, p)
    std::map<VertexIndex, bool> hides_;   // memo of is_hidden(p, site)
    std::vector<FaceIndex> faces_;
    std::set<FaceIndex> face_set_;
    std::map<Edge, bool> crossed_;  // every edge of a region face that was tested (both sides)
};

}  // namespace ellvor
