// Mirror images across axis-parallel lines, exactly (docs/DESIGN.md §10: the
// walls of a box are such mirrors, and InCircle's symmetry stage, §3, knows
// the tangencies they force).
#pragma once

#include "sites/ellipse.hpp"

#include <optional>

namespace ellvor {

// The line x = c (vertical) or y = c.
struct AxisLine {
    bool vertical = true;
    Rational c;
};

// The reflection of e across the line: the center reflected, the rotation
// w = tan(omega/2) negated (across x = c the a-axis turns to pi - omega,
// across y = c to -omega; an ellipse is the same point set at omega + pi).
Ellipse mirror_across(const Ellipse& e, const AxisLine& line);

// e lies strictly on one side of the line: its half-extent across the line,
// sqrt(a^2 cos^2 + b^2 sin^2) (or with sin and cos swapped), below its
// center's distance to it; squares compared exactly.
bool strictly_beside(const Ellipse& e, const AxisLine& line);

// The axis-parallel line across which f is the mirror image of e (as point
// sets: centers and normalized quadratic forms, Ellipse::point_set_key), when
// e lies strictly on one side of it; nothing otherwise.
std::optional<AxisLine> mirror_line(const Ellipse& e, const Ellipse& f);

}  // namespace ellvor
