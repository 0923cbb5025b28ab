// Small random site sets drawn with the library's generator, as the
// benchmarks draw their instances (the same arguments give the same sites).
#pragma once

#include "predicates/voronoi_circle_count.hpp"
#include "sites/site_generators.hpp"

#include <cstdint>
#include <utility>
#include <vector>

namespace ellvor::experiments {

// generate_sites(kind, count, seed, bits, box).
inline std::vector<Ellipse> random_sites(SiteKind kind, long count, std::uint64_t seed, long bits, const Rational& box) {
    GeneratorOptions o;
    o.kind = kind;
    o.count = count;
    o.seed = seed;
    o.bits = bits;
    o.box = box;
    return generate_sites(o);
}

// `count` InCircle quadruples E1 E2 E3 Q: random_sites(kind, 4, seed, bits,
// box 10) for seeds first_seed, first_seed + 1, ...; E2 and E3 swapped when
// only the clockwise circle of (E1, E2, E3) exists, the quadruple skipped
// (and counted in `dropped`) when neither does.
inline std::vector<std::vector<Ellipse>> incircle_quadruples(SiteKind kind, long count, std::uint64_t first_seed,
                                                             long bits, long* dropped = nullptr) {
    std::vector<std::vector<Ellipse>> out;
    if (dropped) *dropped = 0;
    for (std::uint64_t seed = first_seed; static_cast<long>(out.size()) < count; ++seed) {
        std::vector<Ellipse> e = random_sites(kind, 4, seed, bits, Rational(10));
        const VoronoiCircles c = *voronoi_circle_count(e[0], e[1], e[2]);
        if (c == VoronoiCircles::none) {
            if (dropped) ++*dropped;
            continue;
        }
        if (c == VoronoiCircles::cw_only) std::swap(e[1], e[2]);
        out.push_back(std::move(e));
    }
    return out;
}

}  // namespace ellvor::experiments
