// What the tests print when a check fails (Catch2's INFO) or when asked to
// (ELLVOR_TEST_VERBOSE=1): a decision with its stage and precision, a
// certified Voronoi circle. Shared so that every test reports alike.
#pragma once

#include "decision/predicate_answers.hpp"
#include "decision/stage.hpp"
#include "subdivision/voronoi_circle_enclosure.hpp"

#include <cstdlib>
#include <string>

namespace ellvor::test {

// ELLVOR_TEST_VERBOSE set: tests print what they measured (counts, widths).
inline bool verbose() { return std::getenv("ELLVOR_TEST_VERBOSE") != nullptr; }

inline std::string answer_text(InCircle r) { return incircle_name(r); }
inline std::string answer_text(bool b) { return b ? "true" : "false"; }
inline std::string answer_text(Sign s) { return std::to_string(to_int(s)); }

// "result no-conflict stage filter precision 0".
template <class T>
std::string show(const Decision<T>& d) {
    return "result " + (d.is_decided() ? answer_text(*d) : std::string("undecided")) + " stage " +
           stage_name(d.stage) + " precision " + std::to_string(d.precision);
}

inline std::string show(const VoronoiCircleEnclosure& e) {
    return "center (" + e.center_x.str(25) + ", " + e.center_y.str(25) + ") radius " + e.radius.str(25) +
           " precision " + std::to_string(e.precision) + " correct_bits " + std::to_string(e.correct_bits()) +
           " search boxes " + std::to_string(e.search_boxes) + "\n";
}

}  // namespace ellvor::test
