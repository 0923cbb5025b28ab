#include "traits/voronoi_circle_cache.hpp"

#include "util/error.hpp"
#include "exact/medial_axis_tangency.hpp"

#include <algorithm>
#include <cstdint>
#include <new>
#include <optional>

namespace ellvor {

namespace {

// The key of a rotated triple, or nullopt when an id does not fit (such a
// triple is never stored: at() refuses it).
std::optional<std::array<std::uint32_t, 3>> narrow(const std::array<SiteId, 3>& ids) {
    std::array<std::uint32_t, 3> key;
    for (int n = 0; n < 3; ++n) {
        if (ids[n] >= 0xffffffffu) return std::nullopt;
        key[n] = static_cast<std::uint32_t>(ids[n]);
    }
    return key;
}

// Whether h lies in the cyclic range (from, to] of slot positions.
bool cyclically_within(std::size_t h, std::size_t from, std::size_t to) {
    return from <= to ? (from < h && h <= to) : (from < h || h <= to);
}

}  // namespace

std::size_t VoronoiCircleCache::hash(const Key& key) {
    // Mixing of the three ids (multipliers from splitmix64): faces of nearby
    // sites differ in few bits.
    std::uint64_t h = 0x9e3779b97f4a7c15ull;
    for (std::uint32_t id : key) {
        h ^= static_cast<std::uint64_t>(id) + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
        h *= 0xbf58476d1ce4e5b9ull;
        h ^= h >> 31;
    }
    return static_cast<std::size_t>(h);
}

std::size_t VoronoiCircleCache::find_slot(const Key& key) const {
    const std::size_t mask = slots_.size() - 1;
    std::size_t n = hash(key) & mask;
    while (slots_[n].entry != kEmpty && slots_[n].key != key) n = (n + 1) & mask;
    return n;
}

void VoronoiCircleCache::grow() {
    std::vector<Slot> old = std::move(slots_);
    slots_.assign(old.empty() ? 64 : 2 * old.size(), Slot{});
    for (const Slot& s : old)
        if (s.entry != kEmpty) slots_[find_slot(s.key)] = s;
}

VoronoiCircleCache::Entry& VoronoiCircleCache::at(SiteId i, const Ellipse& ei, SiteId j, const Ellipse& ej,
                                                   SiteId k, const Ellipse& ek) {
    std::array<SiteId, 3> ids = {i, j, k};
    std::array<const Ellipse*, 3> sites = {&ei, &ej, &ek};
    const int first = first_of_rotation(ids);
    std::rotate(ids.begin(), ids.begin() + first, ids.end());
    std::rotate(sites.begin(), sites.begin() + first, sites.end());
    const std::optional<Key> key = narrow(ids);
    if (!key) throw Error("VoronoiCircleCache: a site id beyond 2^32 - 2");
    if (slots_.empty()) grow();
    std::size_t n = find_slot(*key);
    if (slots_[n].entry != kEmpty) {
        ++hits_;
        return *place(slots_[n].entry);
    }
    ++misses_;
    if (4 * (size_ + 1) > 3 * slots_.size()) {
        grow();
        n = find_slot(*key);
    }
    std::uint32_t at;
    if (!free_.empty()) {
        at = free_.back();
        free_.pop_back();
    } else {
        if (places_ % kChunk == 0) chunks_.push_back(std::make_unique<Chunk>());
        at = places_++;
    }
    Entry* entry = new (place(at)) Entry{VoronoiCircle(*sites[0], *sites[1], *sites[2], common_medial_axis_tangency)};
    slots_[n] = Slot{*key, at};
    ++size_;
    return *entry;
}

VoronoiCircleCache::Entry* VoronoiCircleCache::find(SiteId i, SiteId j, SiteId k) {
    const std::optional<Key> key = narrow(triple_key(i, j, k));
    if (!key || slots_.empty()) return nullptr;
    const std::size_t n = find_slot(*key);
    return slots_[n].entry == kEmpty ? nullptr : place(slots_[n].entry);
}

void VoronoiCircleCache::erase(SiteId i, SiteId j, SiteId k) {
    const std::optional<Key> key = narrow(triple_key(i, j, k));
    if (!key || slots_.empty()) return;
    std::size_t hole = find_slot(*key);
    if (slots_[hole].entry == kEmpty) return;
    place(slots_[hole].entry)->~Entry();
    free_.push_back(slots_[hole].entry);
    --size_;
    // Backward shift: every later slot of the run whose probe start is not
    // in (hole, n] moves into the hole, so no probe meets an empty slot
    // before its key.
    const std::size_t mask = slots_.size() - 1;
    for (std::size_t n = (hole + 1) & mask; slots_[n].entry != kEmpty; n = (n + 1) & mask)
        if (!cyclically_within(hash(slots_[n].key) & mask, hole, n)) {
            slots_[hole] = slots_[n];
            hole = n;
        }
    slots_[hole].entry = kEmpty;
}

void VoronoiCircleCache::clear() {
    for (const Slot& s : slots_)
        if (s.entry != kEmpty) place(s.entry)->~Entry();
    slots_.clear();
    chunks_.clear();
    places_ = 0;
    free_.clear();
    size_ = 0;
}

}  // namespace ellvor
