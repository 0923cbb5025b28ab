// The conflict region of a new site p, as CGAL's Apollonius_graph_2 grows it
// (expand_conflict_region) and then bounds it for star_hole: the faces whose
// Voronoi vertex conflicts with p, grown from a first such face only across
// edges whose whole Voronoi edge is in conflict or one of whose sites p hides.
// (Growing across vertex conflicts alone is wrong for sites of non-zero size:
// a Voronoi edge may have both ends in conflict and not its middle.)
//
// Every predicate answer about p is memoized for the insertion: kappa2/kappa3
// per face, is_hidden(p, .) per vertex. The memo lives in ConflictMarks,
// arrays indexed by face and vertex that the graph keeps from one insertion to
// the next: a region starts in O(1) and looks up in O(1), without allocating.
#pragma once

#include "graph/triangulation.hpp"
#include "graph/triangulation_predicates.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace ellvor {

// What one conflict region knows about each face and vertex. An entry belongs
// to the region whose generation it carries; older entries read as blank, so
// starting a region only advances the generation.
class ConflictMarks {
public:
    // Per face: kappa2/kappa3 against p, membership, and per edge whether the
    // growth tested it and crossed it.
    struct Face {
        std::uint16_t generation = 0;
        signed char incircle = kUnknown;  // a Sign, or kUnknown
        bool in_region = false;
        std::array<signed char, 3> crossed = {kUntested, kUntested, kUntested};
    };
    // Per vertex: whether p hides its site, whether p and others empty its
    // cell, and whether it is on the region's boundary.
    struct Vertex {
        std::uint16_t generation = 0;
        signed char hidden = kUnknown;  // 0, 1, or kUnknown
        signed char swallowed = kUnknown;  // 0, 1, or kUnknown (not examined)
        bool on_boundary = false;
    };
    static constexpr signed char kUnknown = -2;
    static constexpr signed char kUntested = -1;

    // A new region: every entry blank.
    void start();
    // Room for entries of this many vertices and faces.
    void reserve(std::size_t vertices, std::size_t faces) {
        vertices_.reserve(vertices);
        faces_.reserve(faces);
    }
    // The entry of f (v) for the current region, blank if it had none.
    Face& face(FaceIndex f);
    Vertex& vertex(VertexIndex v);
    // The entry if the current region made one, else nullptr.
    const Face* find(FaceIndex f) const;

private:
    template <class Entry>
    Entry& entry(std::vector<Entry>& entries, int index);

    std::uint16_t generation_ = 0;
    std::vector<Face> faces_;
    std::vector<Vertex> vertices_;
};

class ConflictRegion {
public:
    // Starts a region in `marks` (which it uses until the next region starts).
    ConflictRegion(const Triangulation& tds, TriangulationPredicates predicates, SiteId p, ConflictMarks& marks);

    SiteId site() const { return p_; }
    // p meets the open Voronoi disk of face f.
    bool in_conflict(FaceIndex f);
    // p hides the site of v (never the infinite vertex).
    bool hides(VertexIndex v);

    // Grows the region from `start`, breadth first.
    void expand(FaceIndex start);
    // The faces, in the order they were reached.
    const std::vector<FaceIndex>& faces() const { return faces_; }
    bool contains(FaceIndex f) const {
        const ConflictMarks::Face* m = marks_.find(f);
        return m && m->in_region;
    }
    // The vertices whose sites p hides, by increasing index.
    std::vector<VertexIndex> hidden_vertices() const;
    // The vertices whose cells p empties without containing their sites
    // (union hiding, docs/DESIGN.md §9): every face around them is in the
    // region and every Voronoi edge of theirs entirely in conflict. Found
    // by expand(); by increasing index.
    const std::vector<VertexIndex>& swallowed_vertices() const { return swallowed_; }
    // hidden_vertices() and swallowed_vertices(): the vertices starring the
    // hole deletes, by increasing index.
    std::vector<VertexIndex> vanishing_vertices() const;
    // The edges between two faces of the region that the growth did not cross,
    // each once (by increasing face, then index): the region touches itself
    // along them, and the hole is a disk only once each is split by a bogus vertex.
    std::vector<Edge> self_touching_edges() const;
    // The boundary edges (their face in the region), counter-clockwise. Throws
    // Error when they do not form one cycle (the region is not a disk).
    std::vector<Edge> boundary() const;
    // Throws Error unless the vertices strictly inside the region are exactly
    // the vanishing ones: starring the hole deletes them.
    void check_inner_vertices(const std::vector<Edge>& boundary, const std::vector<VertexIndex>& vanishing);

private:
    bool every_edge_around_crossed(VertexIndex v) const;
    void find_swallowed_vertices();

    const Triangulation& tds_;
    TriangulationPredicates predicates_;
    SiteId p_;
    ConflictMarks& marks_;
    std::vector<FaceIndex> faces_;
    std::vector<VertexIndex> hidden_;  // in the order found
    std::vector<VertexIndex> swallowed_;
};

}  // namespace ellvor
