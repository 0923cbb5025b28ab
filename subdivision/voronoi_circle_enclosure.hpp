// Certified enclosure of the Voronoi circle of an ordered triple (E1, E2, E3)
// (docs/DESIGN.md §2: externally tangent to the three, tangency points
// counter-clockwise in that order), by the Krawczyk form of interval Newton
// on the tritangent system
//     P_i(t_i) + rho nu_i(t_i) - V = 0,   i = 1, 2, 3
// (unknowns: the three tangency parameters, the radius rho and the center V;
// nu_i the outward unit normal) in Arb balls at adaptive precision.
//
// Why a certificate identifies THE Voronoi circle: when the Krawczyk image of
// a box lies inside it, the box holds exactly one solution; if moreover rho > 0
// on the box, each P_i is the nearest point of the convex E_i to V (V lies on
// the outward normal ray of P_i), so the circle touches every E_i from outside
// and its open disk misses all three; with the tangency points
// counter-clockwise this is the unique counter-clockwise Voronoi circle.
//
// Where the certificate starts (docs/DESIGN.md §4.2): first from
// floating-point guesses (voronoi_circle_guess.hpp); then, for circles far
// larger than the sites, from their nearly common tangent line
// (huge_circle_start.hpp); for a pair of nearly coincident sites, from the
// circle of the pair moved apart (near_duplicate_pair.hpp); for a needle, from
// the circle with the needle made stout (needle_chain.hpp); when none
// certifies, from the exhaustive search
// (voronoi_circle_search.hpp), which either certifies the circle or proves
// that there is none. The work happens in a similarity frame of the triple
// (docs/DESIGN.md §4.3).
#pragma once

#include "sites/ellipse.hpp"
#include "sites/similarity_frame.hpp"
#include "subdivision/boundary_chart.hpp"
#include "subdivision/medial_axis_circle.hpp"
#include "subdivision/near_duplicate_pair.hpp"
#include "subdivision/needle_chain.hpp"
#include "subdivision/voronoi_circle_guess.hpp"
#include "subdivision/voronoi_circle_search.hpp"

#include <array>
#include <memory>
#include <vector>

namespace ellvor {

// Where the certificate started: a floating-point guess
// (voronoi_circle_guess.hpp), the tangent line of a huge circle
// (huge_circle_start.hpp), the circle of the triple with a nearly
// coincident pair moved apart (near_duplicate_pair.hpp), the circle of the
// triple with its needle made stout (needle_chain.hpp), or the exhaustive search.
enum class CircleStart { guess, tangent_line, near_duplicate, bisector_walk, needle_chain, search };
const char* circle_start_name(CircleStart s);

struct VoronoiCircleEnclosure {
    // Chart parameter of each tangency point: t_i, or u_i = -1/t_i when
    // flipped (u_i = 0 is the i-point).
    std::array<Ball, 3> parameter;
    std::array<bool, 3> flipped{};
    Ball radius, center_x, center_y;
    long precision = 0;     // working precision of the last certificate
    long newton_steps = 0;  // Arb Newton steps so far (all precisions)
    CircleStart found_by = CircleStart::guess;
    // Boxes the exhaustive search examined (also when it proved that there
    // is no circle); 0 when it did not run.
    long search_boxes = 0;
    // The certificate proved rho the signed distance to a site through a
    // proof that V lies exactly on its medial axis (medial_axis_circle.hpp,
    // docs/DESIGN.md §4.2, "On a medial axis").
    bool on_medial_axis = false;

    // Tangency parameter t_i on E_i (an unbounded ball when the box holds the i-point).
    Ball tangency_parameter(int i, long prec) const;
    // Correct bits of the least accurate component: relative to the value for
    // |value| >= 1, absolute below.
    long correct_bits() const;
};

class VoronoiCircleSolver {
public:
    // common_axis_tangency (exact/medial_axis_tangency.hpp, passed in from
    // above: this layer does not know exact/) lets the certificate accept an
    // internal circle centered exactly on a site's medial axis; without it
    // such a triple ends at the search's cap (docs/DESIGN.md §4.2).
    VoronoiCircleSolver(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3,
                        CommonAxisTangency common_axis_tangency = nullptr);

    // Finds and certifies the counter-clockwise Voronoi circle at about 64
    // bits (more when the sites' magnitudes exceed their size in the frame):
    // from the floating-point guesses, the tangent-line starts, then by the
    // exhaustive search. False means proved: the triple has no
    // counter-clockwise Voronoi circle. Throws Error only for a degenerate
    // triple on which the search hits its cap.
    bool certify();
    // certify() from an approximation known to be close to the circle (the
    // midpoint of its certified double enclosure, voronoi_circle_in_doubles.hpp:
    // chart flags and t1, t2, t3, rho, x, y in the sites' coordinates): Newton
    // and Krawczyk from there first, which spares the guesses and the
    // tangent-line starts (milliseconds for a huge circle). The same contract.
    bool certify_near(const std::array<bool, 3>& flipped, const std::array<double, 6>& x);
    // The tangent-line starts of huge circles alone (docs/DESIGN.md §4.2, item
    // 2), which certify() tries after the guesses: for a triple whose double
    // certificate found no root (VoronoiCircle), mostly sites in a row whose
    // circle is 10^7-10^11 times their size, where the guesses take 10-40 ms
    // and these starts about 1. True when they certify the circle; false
    // proves nothing and leaves the solver as it was.
    bool certify_from_tangent_lines();
    // The exhaustive search alone (tests and experiments force this path);
    // the same contract as certify().
    bool certify_by_search(const VoronoiCircleSearchOptions& options = {});
    // The needle chains alone (docs/DESIGN.md §4.2, item 5), which certify()
    // tries after the other starts: for the tests and experiments that
    // compare starts. False means only "not certified".
    bool certify_by_needle_chains();
    // Refines the enclosure until every component has at least `bits`
    // correct bits, doubling the working precision; certifies first if
    // needed. False only when certify() is (no counter-clockwise circle);
    // throws Error if a certified circle cannot be refined (internal error).
    bool refine(long bits);
    // refine(bits) for callers that established that the circle exists (e.g.
    // by voronoi_circle_count): "no circle" contradicts them and throws Error.
    void refine_existing(long bits);

    bool certified() const { return certified_; }
    const std::array<const Ellipse*, 3>& sites() const { return sites_; }
    // The enclosure in the sites' own coordinates.
    const VoronoiCircleEnclosure& enclosure() const;
    // The numerical work happens in a frame where the sites have size about
    // one near the origin (similarity_frame.hpp; the identity for most
    // triples); the enclosure there, to measure against other sites mapped by
    // frame().apply. The tangency parameters are the same in both.
    const SimilarityFrame& frame() const { return frame_; }
    const VoronoiCircleEnclosure& frame_enclosure() const { return enclosure_; }

    // Frees the boundary charts (six of them, about 3 KB of small integer
    // polynomials), which only a further Newton step or certificate needs;
    // that rebuilds them. A cache that keeps one solver per face calls this
    // between uses: the enclosure is what later queries read.
    void release_charts();

private:
    // certify() without the exhaustive search: the guesses, the tangent-line
    // starts, the near-duplicate start, the bisector walk and the needle
    // chains. False means only "not certified".
    bool certify_from_starts();
    // A triple with a nearly coincident pair (near_duplicate_pair.hpp): the
    // circle of the triple with the pair moved apart, certified first, gives
    // the start; Newton and Krawczyk at about twice the pair's closeness bits.
    bool certify_near_duplicate();
    // One attempt of it: the pair moved apart to 2^-moved_bits of its size.
    bool certify_from_moved_pair(const NearDuplicatePair& pair, long moved_bits);
    // A triple with a needle (needle_chain.hpp): the circle of the triple with
    // the needle made stout (aspect 2^4: thicker, else shorter), certified by
    // the starts or a short search, carried to the needle along the chain of
    // links between, each started from the last circle with the needle's
    // contact carried over.
    bool certify_from_needle_chains();
    bool certify_along_needle_chain(int needle, NeedleChain chain);
    bool certify_from(const VoronoiCircleGuess& guess);
    // A cheap attempt from the midpoint of a search box: Newton at the box's
    // precision must converge to a counter-clockwise root of positive radius
    // before Krawczyk is tried, at a few doublings of that precision.
    bool certify_from(const VoronoiCircleStart& start);
    // Sets the charts and the exact midpoint (chart parameters, rho, V).
    void start_at(const std::array<bool, 3>& flipped, const std::array<Ball, 3>& parameter, const Ball& radius,
                  const Ball& center_x, const Ball& center_y);
    // Newton steps and the Krawczyk test at `levels` doublings of the
    // precision from `first`, `steps` tries at each.
    bool certify_here(long first, int levels, int steps);
    // Start precision of a certificate: 64 bits, plus the bits by which the
    // sites' magnitude exceeds their size beyond the guard bits.
    long start_precision();
    bool krawczyk(long prec);
    // One Newton step on the midpoint; returns the step's size in bits below
    // the values (larger = smaller step), or -1 if the Jacobian is singular.
    long newton_step(long prec);
    // The charts of the current midpoint (enclosure_.flipped), built on
    // first use: most solvers of a graph's cache are never certified.
    std::array<const BoundaryChart*, 3> charts();

    // Chooses the frame and the sites the numerics work on (once).
    void set_frame();

    std::array<const Ellipse*, 3> sites_;       // as given
    SimilarityFrame frame_;
    std::vector<Ellipse> framed_sites_;         // their images when the frame is not the identity
    std::array<const Ellipse*, 3> work_sites_{};  // what the numerics use: sites_ or framed_sites_
    bool framed_ = false;                       // set_frame() ran
    std::vector<BoundaryChart> site_charts_;  // site i, flipped f at 2 i + f (built by start_at)
    long magnitude_bits_ = -1;  // site_magnitude_bits, computed on first use
    // Bits the Jacobian's conditioning eats beyond the usual (the closeness
    // of a nearly coincident pair once its start was used; 0 otherwise): the
    // low precision of Krawczyk and the orientation test must exceed them.
    long condition_bits_ = 0;
    BallMatrix midpoint_{6, 1};  // exact midpoint of the current box
    VoronoiCircleEnclosure enclosure_;           // in the frame
    // enclosure_ mapped back by enclosure(), allocated only for a frame that
    // is not the identity (one per cached face: keep the solver small).
    mutable std::unique_ptr<VoronoiCircleEnclosure> original_;
    bool certified_ = false;
    CommonAxisTangency common_axis_tangency_ = nullptr;
};

}  // namespace ellvor
