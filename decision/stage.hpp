// The one result type of every predicate (Shewchuk-style staged evaluation):
// each stage of a cascade either decides with a proof or says "undecided" and
// hands over to the next one. A Decision carries the answer (or nothing, when
// undecided), the stage that decided it and the Arb precision it took.
//
// Stage indices appear only here: code elsewhere names stages (Stage::exact)
// and iterates over kStages.
#pragma once

#include "util/error.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>

namespace ellvor {

enum class Stage : int {
    filter = 0,       // double interval arithmetic with outward rounding, or a closed form
    subdivision = 1,  // Arb balls at adaptive precision
    symmetry = 2,     // an exact symmetry of the sites forces the answer (mirror images, docs/DESIGN.md §3)
    exact = 3,        // FLINT: exact rationals, resultants, real algebraic numbers
    end_,             // not a stage: marks the end, so that the tables below are checked complete
};

// The stages in order of increasing cost, and their names as --stats, the JSON
// and the Python module print them.
constexpr std::array<Stage, 4> kStages = {Stage::filter, Stage::subdivision, Stage::symmetry, Stage::exact};
constexpr std::array<const char*, kStages.size()> kStageNames = {"filter", "subdivision", "symmetry", "exact"};

namespace detail {
constexpr bool stage_table_is_indexed_by_enum() {
    for (std::size_t i = 0; i < kStages.size(); ++i)
        if (static_cast<std::size_t>(kStages[i]) != i) return false;
    return true;
}
}  // namespace detail
static_assert(kStages.size() == static_cast<std::size_t>(Stage::end_), "every Stage needs its place in kStages");
static_assert(detail::stage_table_is_indexed_by_enum(), "kStages must follow the enum's order");

inline const char* stage_name(Stage s) { return kStageNames.at(static_cast<std::size_t>(s)); }

// CGAL's Sign.
enum class Sign : int { negative = -1, zero = 0, positive = 1 };

inline Sign sign_of(int x) { return x < 0 ? Sign::negative : x > 0 ? Sign::positive : Sign::zero; }
inline int to_int(Sign s) { return static_cast<int>(s); }
inline Sign operator-(Sign s) { return sign_of(-to_int(s)); }
inline Sign operator*(Sign a, Sign b) { return sign_of(to_int(a) * to_int(b)); }

template <class T>
class Decision {
public:
    Decision() = default;
    static Decision decided(T value, Stage stage, long precision = 0) {
        Decision d;
        d.value_ = std::move(value);
        d.stage = stage;
        d.precision = precision;
        return d;
    }
    // Undecided after `stage` ran out of precision at `precision` bits.
    static Decision undecided(Stage stage, long precision) {
        Decision d;
        d.stage = stage;
        d.precision = precision;
        return d;
    }

    bool is_decided() const { return value_.has_value(); }
    // The answer; throws Error when undecided (callers that allow undecided
    // answers ask is_decided() first).
    const T& value() const {
        if (!value_) throw Error("a predicate was used undecided (internal error)");
        return *value_;
    }
    const T& operator*() const { return value(); }
    const T* operator->() const { return &value(); }

    // Folds in a sub-decision this one depends on: the later stage and the
    // higher precision.
    template <class U>
    void depends_on(const Decision<U>& other) {
        if (static_cast<int>(other.stage) > static_cast<int>(stage)) stage = other.stage;
        if (other.precision > precision) precision = other.precision;
    }
    // The same provenance with another answer.
    template <class U>
    Decision<U> with(U value) const {
        return Decision<U>::decided(std::move(value), stage, precision);
    }

    Stage stage = Stage::filter;  // the stage that decided (or the last one that ran)
    long precision = 0;           // Arb precision in bits (0: no Arb stage was needed)

private:
    std::optional<T> value_;
};

// How many calls each stage decided; owned by whoever asks (a graph, a
// benchmark, a CLI call), never global.
class StageCounters {
public:
    void record(Stage s) { ++decided_[static_cast<int>(s)]; }
    std::uint64_t operator[](Stage s) const { return decided_[static_cast<int>(s)]; }
    std::uint64_t total() const {
        std::uint64_t n = 0;
        for (std::uint64_t c : decided_) n += c;
        return n;
    }

private:
    std::array<std::uint64_t, kStages.size()> decided_{};
};

}  // namespace ellvor
