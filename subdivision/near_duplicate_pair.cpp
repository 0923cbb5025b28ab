#include "subdivision/near_duplicate_pair.hpp"

#include <algorithm>
#include <array>
#include <climits>

namespace ellvor {

namespace {

Rational absolute(const Rational& x) { return x.sign() < 0 ? -x : x; }

// log2(size / difference) within one bit, LONG_MAX for identical pairs.
long closeness_bits(const Ellipse& p, const Ellipse& q) {
    const Rational small = std::min(std::min(p.a(), p.b()), std::min(q.a(), q.b()));
    const Rational large = std::max(std::max(p.a(), p.b()), std::max(q.a(), q.b()));
    const std::array<Rational, 5> differences{absolute(p.a() - q.a()), absolute(p.b() - q.b()),
                                              absolute(p.w() - q.w()) * large, absolute(p.xc() - q.xc()),
                                              absolute(p.yc() - q.yc())};
    const Rational difference = *std::max_element(differences.begin(), differences.end());
    if (difference.is_zero()) return LONG_MAX;
    const Rational ratio = small / difference;
    return static_cast<long>(fmpz_bits(fmpq_numref(ratio.get()))) -
           static_cast<long>(fmpz_bits(fmpq_denref(ratio.get())));
}

}  // namespace

std::optional<NearDuplicatePair> closest_near_duplicate_pair(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3,
                                                             long min_bits) {
    const std::array<const Ellipse*, 3> sites{&e1, &e2, &e3};
    std::optional<NearDuplicatePair> best;
    for (int i = 0; i < 3; ++i)
        for (int j = i + 1; j < 3; ++j) {
            const long bits = closeness_bits(*sites[i], *sites[j]);
            if (bits == LONG_MAX || bits < min_bits) continue;
            if (!best || bits > best->bits) best = NearDuplicatePair{i, j, bits};
        }
    return best;
}

Ellipse ellipse_moved_apart(const Ellipse& from, const Ellipse& to, const Rational& mu) {
    auto between = [&](const Rational& x, const Rational& y) { return x + mu * (y - x); };
    return Ellipse(between(from.a(), to.a()), between(from.b(), to.b()), between(from.w(), to.w()),
                   between(from.xc(), to.xc()), between(from.yc(), to.yc()));
}

}  // namespace ellvor
