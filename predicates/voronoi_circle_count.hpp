// How many Voronoi circles an ordered triple of sites has (docs/DESIGN.md
// §2): a circle externally tangent to all three with an empty open disk, its
// tangency points counter-clockwise in the order E1, E2, E3 (the CCW circle)
// or E1, E3, E2 (the CW circle). Decided from three kappa2 signs, and by a
// cover proof or the complete solver when a site may be covered by the other two.
#pragma once

#include "decision/stage.hpp"
#include "decision/predicate_answers.hpp"
#include "sites/ellipse.hpp"
#include "subdivision/voronoi_circle_by_bounding_disks.hpp"

namespace ellvor {

// A nested pair gives none. Always decided: for three circles in doubles
// with a static error bound (circle_semi_static.hpp), else by the exact
// closed form (circle_predicates.hpp), otherwise from three kappa2 signs --
// unless two of them conflict and one site crosses both others with no point
// certainly outside them: that site may have an empty cell (docs/DESIGN.md
// §9); a proof that it is so covered that no circle exists
// (covered_without_circle) says "none", else the Voronoi circle solver,
// which is complete, says "both" or "none". The stage is the latest any of
// them needed.
Decision<VoronoiCircles> voronoi_circle_count(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3);

// Whether voronoi_circle_count is `both`, at less cost: sites whose
// bounding disks are uniformly oriented (below), or the count's first two
// kappa2 signs without a conflict, already exclude it (for small sites
// apart, the three signs mostly agree). Same stages.
Decision<bool> has_both_voronoi_circles(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3);

// Whether no site of the three lies inside another (the premise of a Voronoi
// circle; a nested pair has none): every pair separated, externally tangent,
// or crossing.
Decision<bool> none_inside_another(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3);

}  // namespace ellvor
