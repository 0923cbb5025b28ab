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

// The axis-parallel line L that is exactly the bisector {x : delta(x, e) =
// delta(x, f)} of two sites mirrored across it: mirror_line's, or L between
// two equal circles that overlap (|x - C1| = |x - C2| exactly on L). Nothing
// when f is not e's mirror image or the bisector of the crossing ellipses
// is not known to be L.
std::optional<AxisLine> bisector_line(const Ellipse& e, const Ellipse& f);

// How the reflection across `line` acts on the boundary parameter t of e
// (Ellipse::X, Y, W; t = tan(theta/2)) when e, not a circle, is its own
// mirror image: P(t) -> P(-t) when the line holds e's a-axis, P(t) -> P(1/t)
// when it holds the b-axis.
enum class SelfMirror { none, negates_parameter, inverts_parameter };
SelfMirror self_mirror(const Ellipse& e, const AxisLine& line);

}  // namespace ellvor
