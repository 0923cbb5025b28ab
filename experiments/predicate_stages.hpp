// The graph's predicate calls per deciding stage, as the benchmarks print
// them: "calls (filter/subdivision/exact)", one column per predicate.
#pragma once

#include "predicates/delaunay_traits.hpp"

#include <string>

namespace ellvor::experiments {

struct PredicateColumn {
    const char* name;
    const PredicateCount TraitsStats::*field;
};
inline const PredicateColumn kPredicateColumns[] = {
    {"is_hidden", &TraitsStats::is_hidden},
    {"kappa1", &TraitsStats::side_of_bisector},
    {"kappa2", &TraitsStats::vertex_conflict3},
    {"kappa3", &TraitsStats::vertex_conflict4},
    {"kappa4_finite", &TraitsStats::finite_edge},
    {"kappa4_infinite", &TraitsStats::infinite_edge},
};

inline std::string stage_triple(const PredicateCount& p) {
    if (p.calls == 0) return "0";
    return std::to_string(p.calls) + " (" + std::to_string(p.stages[Stage::filter]) + "/" +
           std::to_string(p.stages[Stage::subdivision]) + "/" + std::to_string(p.stages[Stage::exact]) + ")";
}

}  // namespace ellvor::experiments
