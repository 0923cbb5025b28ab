// The graph's predicate calls per deciding stage, as the benchmarks print
// them: "calls (filter/subdivision/exact)", one column per predicate of
// kPredicates, the stages in the order of kStages.
#pragma once

#include "decision/predicate_registry.hpp"

#include <string>

namespace ellvor::experiments {

// "12 / 3 / 0": the calls each stage decided, in the order of kStages.
inline std::string stage_counts(const StageCounters& c) {
    std::string s;
    for (Stage stage : kStages) s += (s.empty() ? "" : " / ") + std::to_string(c[stage]);
    return s;
}

// "15 (12/3/0)", or "0" when the predicate was never called.
inline std::string stage_triple(const PredicateCount& p) {
    if (p.calls == 0) return "0";
    std::string s = std::to_string(p.calls) + " (";
    for (Stage stage : kStages) s += (stage == kStages.front() ? "" : "/") + std::to_string(p.stages[stage]);
    return s + ")";
}

// The CSV columns of one predicate: NAME_calls, then NAME_STAGE per stage.
inline std::string predicate_csv_header(const PredicateInfo& p) {
    std::string s = std::string(",") + p.name + "_calls";
    for (Stage stage : kStages) s += std::string(",") + p.name + "_" + stage_name(stage);
    return s;
}

inline std::string predicate_csv_values(const PredicateCount& c) {
    std::string s = "," + std::to_string(c.calls);
    for (Stage stage : kStages) s += "," + std::to_string(c.stages[stage]);
    return s;
}

// As many empty CSV cells as predicate_csv_values writes.
inline std::string predicate_csv_empty() { return std::string(1 + kStages.size(), ','); }

}  // namespace ellvor::experiments
