// The graph's predicate calls per deciding stage, as the benchmarks print
// them: "calls (filter/subdivision/exact)", one column per predicate of
// kPredicates, the stages in the order of kStages.
#pragma once

#include "decision/predicate_registry.hpp"
#include "experiments/report.hpp"

#include <string>
#include <vector>

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

// The CSV columns of the predicates: NAME_calls, then NAME_STAGE per stage,
// for every predicate of kPredicates.
inline std::vector<std::string> predicate_csv_columns() {
    std::vector<std::string> columns;
    for (const PredicateInfo& p : kPredicates) {
        columns.push_back(std::string(p.name) + "_calls");
        for (Stage stage : kStages) columns.push_back(std::string(p.name) + "_" + stage_name(stage));
    }
    return columns;
}

// The values of those columns (all empty for a graph without the counts).
inline std::vector<std::string> predicate_csv_values(const TraitsStats* stats) {
    std::vector<std::string> values;
    for (const PredicateInfo& p : kPredicates) {
        const PredicateCount* c = stats ? &(*stats)[p.predicate] : nullptr;
        values.push_back(c ? std::to_string(c->calls) : "");
        for (Stage stage : kStages) values.push_back(c ? std::to_string(c->stages[stage]) : "");
    }
    return values;
}

// The predicates' calls per stage of a graph as table cells ("15 (12/3/0)").
inline std::vector<std::string> predicate_stage_triples(const TraitsStats& stats) {
    std::vector<std::string> cells;
    for (const PredicateInfo& p : kPredicates) cells.push_back(stage_triple(stats[p.predicate]));
    return cells;
}

// A table of the predicates' calls per stage: the leading columns (the first
// left-aligned, the others right), then one column per predicate.
inline Table predicate_stage_table(const std::string& id, std::vector<std::string> columns) {
    const std::string align = "l" + std::string(columns.size() - 1, 'r') + std::string(kPredicates.size(), 'l');
    for (const PredicateInfo& p : kPredicates) columns.push_back(p.name);
    return Table(id, columns, align);
}

inline void add_predicate_stage_row(Table& table, TableRow row, const TraitsStats& stats) {
    for (const std::string& cell : predicate_stage_triples(stats)) row.push_back(cell);
    table.add(std::move(row));
}

}  // namespace ellvor::experiments
