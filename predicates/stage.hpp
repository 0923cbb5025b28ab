// Which stage of a predicate cascade decided an answer (Shewchuk-style staged
// evaluation): each stage either decides with a proof or says "undecided" and
// hands over to the next one.
#pragma once

#include <array>
#include <cstdint>
#include <string>

namespace ellvor {

enum class Stage : int {
    filter = 0,       // double interval arithmetic with outward rounding, or a closed form
    subdivision = 1,  // Arb balls at adaptive precision
    exact = 2,        // FLINT: exact rationals, resultants, real algebraic numbers
};

inline const char* stage_name(Stage s) {
    switch (s) {
        case Stage::filter: return "filter";
        case Stage::subdivision: return "subdivision";
        case Stage::exact: return "exact";
    }
    return "?";
}

// A decided sign together with the stage that proved it and, for the Arb
// stage, the working precision (bits) that sufficed.
struct SignDecision {
    int sign = 0;
    Stage stage = Stage::exact;
    long precision = 0;
};

// How many calls each stage decided; owned by whoever asks (a graph, a
// benchmark, a CLI call), never global.
struct StageCounters {
    std::array<std::uint64_t, 3> decided{};
    void record(Stage s) { ++decided[static_cast<int>(s)]; }
    std::uint64_t total() const { return decided[0] + decided[1] + decided[2]; }
};

}  // namespace ellvor
