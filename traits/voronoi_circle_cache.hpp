// Cache of certified Voronoi circles, keyed by the ordered triple of site ids
// (a cyclic rotation of a triple is the same circle with the same
// orientation, so all three rotations share one entry). The cache belongs to
// whoever builds it -- a graph, a benchmark, a CLI call -- and holds pointers
// to sites that must outlive it; sites are never mutated.
#pragma once

#include "traits/triple_key.hpp"
#include "sites/ellipse.hpp"
#include "subdivision/voronoi_circle.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>
#include <vector>

namespace ellvor {

class VoronoiCircleCache {
public:
    // The circle is that of the triple rotated so that the smallest id comes
    // first (triple_key): its sites are in that order. The ids are the
    // slot's key, not repeated here (a build keeps about one entry a site).
    struct Entry {
        VoronoiCircle circle;
    };

    VoronoiCircleCache() = default;
    VoronoiCircleCache(const VoronoiCircleCache&) = delete;
    VoronoiCircleCache& operator=(const VoronoiCircleCache&) = delete;
    ~VoronoiCircleCache() { clear(); }

    // The entry of the Voronoi circle of the ordered triple (i, j, k) of
    // sites, created (not yet certified) on first use.
    Entry& at(SiteId i, const Ellipse& ei, SiteId j, const Ellipse& ej, SiteId k, const Ellipse& ek);

    // The entry of (i, j, k) or of a rotation of it, nullptr if there is none
    // (does not count as a hit or a miss).
    Entry* find(SiteId i, SiteId j, SiteId k);

    // Removes the entry of (i, j, k) or of a rotation of it, if any.
    void erase(SiteId i, SiteId j, SiteId k);

    std::size_t size() const { return size_; }
    std::size_t hits() const { return hits_; }
    std::size_t misses() const { return misses_; }
    void clear();

private:
    // Open addressing on the keys (linear probing, at most 3/4 full;
    // deletion by backward shift, no tombstones), the entries in a pool
    // whose addresses never change (an Entry& stays valid until erased;
    // erased places are reused). A build asks about every face: a lookup
    // reads one slot and then the entry, where a node-based map read a
    // bucket, the node before and the node, scattered in memory (8.6% of a
    // 10^5-site build's profile in its bucket walk). The pool is chunks of
    // raw places, each entry constructed in its place: the slots say which
    // places hold one, so a place costs its entry's size alone (a deque of
    // optionals added an engaged flag and, two entries a block, a block's
    // allocation overhead: 192 bytes a place against 152).
    using Key = std::array<std::uint32_t, 3>;  // ids below 2^32 - 1 (the 10^7-site input limit)
    static constexpr std::uint32_t kEmpty = 0xffffffffu;
    struct Slot {
        Key key;
        std::uint32_t entry = kEmpty;  // index into pool_
    };
    static std::size_t hash(const Key& key);
    // The slot holding `key`, or the empty slot where the probe for it ends.
    std::size_t find_slot(const Key& key) const;
    void grow();
    static constexpr std::uint32_t kChunk = 512;  // places a chunk
    struct Chunk {
        alignas(Entry) unsigned char bytes[kChunk * sizeof(Entry)];
    };
    Entry* place(std::uint32_t n) const {
        return std::launder(reinterpret_cast<Entry*>(chunks_[n / kChunk]->bytes) + n % kChunk);
    }

    std::vector<Slot> slots_;  // a power of two, or empty
    std::vector<std::unique_ptr<Chunk>> chunks_;
    std::uint32_t places_ = 0;         // places handed out (constructed at least once)
    std::vector<std::uint32_t> free_;  // places of erased entries
    std::size_t size_ = 0, hits_ = 0, misses_ = 0;
};

}  // namespace ellvor
