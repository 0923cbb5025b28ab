// The predicates the graph asks its traits (docs/DESIGN.md §2), one row each:
// the one name used for the traits method, the statistics row, the JSON key,
// the Python `stats` key and the experiments' columns; the paper's label; the
// command that runs the predicate alone. Everything that lists predicates
// iterates over kPredicates, as everything that lists stages iterates over
// kStages (decision/stage.hpp).
#pragma once

#include "decision/stage.hpp"

#include <array>
#include <cstddef>
#include <cstdint>

namespace ellvor {

enum class Predicate : int {
    is_hidden,
    side_of_bisector,
    infinite_vertex_conflict,
    incircle,
    finite_edge_interior_conflict,
    infinite_edge_interior_conflict,
    is_degenerate_edge,
    end_,  // not a predicate: marks the end, so that kPredicates is checked complete below
};

struct PredicateInfo {
    Predicate predicate;
    const char* name;         // the traits method, statistics row and JSON key
    const char* kappa;        // the paper's label ("" when it has none)
    const char* cli_command;  // the `ellvor` command deciding it alone ("" when none)
    const char* question;     // what it decides, in one line (README.md, `--stats`)
};

inline constexpr std::array<PredicateInfo, 7> kPredicates = {{
    {Predicate::is_hidden, "is_hidden", "", "check", "does one site lie inside another"},
    {Predicate::side_of_bisector, "side_of_bisector", "kappa1", "side-of-bisector",
     "which of two sites is nearer to a point"},
    {Predicate::infinite_vertex_conflict, "infinite_vertex_conflict", "kappa2", "bitangent",
     "does a site meet the half-plane beyond the external bitangent of two sites"},
    {Predicate::incircle, "incircle", "kappa3", "incircle", "does a site meet the Voronoi circle of a triple"},
    {Predicate::finite_edge_interior_conflict, "finite_edge_interior_conflict", "kappa4", "",
     "does a site conflict with (all of) a finite Voronoi edge"},
    {Predicate::infinite_edge_interior_conflict, "infinite_edge_interior_conflict", "kappa4", "",
     "does a site conflict with (all of) an infinite Voronoi edge"},
    {Predicate::is_degenerate_edge, "is_degenerate_edge", "", "", "is a Voronoi edge of length 0 (deletion)"},
}};

namespace detail {
constexpr bool predicate_table_is_indexed_by_enum() {
    for (std::size_t i = 0; i < kPredicates.size(); ++i)
        if (static_cast<std::size_t>(kPredicates[i].predicate) != i) return false;
    return true;
}
}  // namespace detail
static_assert(kPredicates.size() == static_cast<std::size_t>(Predicate::end_),
              "every Predicate needs its row in kPredicates");
static_assert(detail::predicate_table_is_indexed_by_enum(), "kPredicates rows must follow the enum's order");

inline const PredicateInfo& predicate_info(Predicate p) { return kPredicates[static_cast<std::size_t>(p)]; }
inline const char* predicate_name(Predicate p) { return predicate_info(p).name; }

// Calls of one predicate and which stage decided them.
struct PredicateCount {
    std::uint64_t calls = 0;  // calls that reached the predicate (memoized answers excluded)
    StageCounters stages;
};

// The counts of a traits object, one per predicate; owned by the traits
// (never global).
class TraitsStats {
public:
    PredicateCount& operator[](Predicate p) { return counts_[static_cast<std::size_t>(p)]; }
    const PredicateCount& operator[](Predicate p) const { return counts_[static_cast<std::size_t>(p)]; }

private:
    std::array<PredicateCount, kPredicates.size()> counts_{};
};

}  // namespace ellvor
