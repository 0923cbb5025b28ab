// InCircle's symmetry stage: a triple with a mirror pair across an
// axis-parallel line, and Q the mirror of the third site, is tangent (the
// circle's center lies on the line); a Q that is not that mirror goes on to
// the other stages.
#include "predicates/incircle.hpp"
#include "sites/mirror_symmetry.hpp"
#include "subdivision/voronoi_circle_enclosure.hpp"

#include <catch2/catch.hpp>

#include <array>

using namespace ellvor;

TEST_CASE("incircle: the mirror of the third site across a mirror pair's line is tangent", "[predicates][incircle]") {
    const bool vertical = GENERATE(true, false);
    const AxisLine line{vertical, Rational(10)};
    // Two ellipses on one side of the line (x < 10 or y < 10), the same in both cases up to a swap of x and y.
    auto site = [&](Rational a, Rational b, Rational w, Rational u, Rational v) {
        return vertical ? Ellipse(a, b, w, u, v) : Ellipse(a, b, -w, v, u);
    };
    const Ellipse p = site(Rational(3), Rational(1), Rational(1, 3), Rational(5), Rational(2));
    const Ellipse q = site(Rational(2), Rational(3, 2), Rational(-2, 5), Rational(4), Rational(-7));
    const Ellipse p_mirror = mirror_across(p, line), q_mirror = mirror_across(q, line);
    int tangent = 0;
    for (const auto& triple : {std::array<const Ellipse*, 3>{&p, &q, &p_mirror}, {&p, &p_mirror, &q}}) {
        const Decision<InCircle> d = incircle(*triple[0], *triple[1], *triple[2], q_mirror);
        if (*d == InCircle::no_circle) continue;
        ++tangent;
        CHECK(*d == InCircle::tangent);
        CHECK(d.stage == Stage::symmetry);
        // The circle's center is on the line (an independent check of the premise).
        VoronoiCircleSolver solver(*triple[0], *triple[1], *triple[2]);
        REQUIRE(solver.certify());
        CHECK((vertical ? solver.enclosure().center_x : solver.enclosure().center_y).contains(line.c));
        // A Q that is not the mirror: decided by the other stages, not tangent.
        const Ellipse moved(q_mirror.a(), q_mirror.b(), q_mirror.w(), q_mirror.xc() + Rational(1, 1000), q_mirror.yc());
        const Decision<InCircle> other = incircle(*triple[0], *triple[1], *triple[2], moved);
        CHECK(other.stage != Stage::symmetry);
        CHECK(*other != InCircle::tangent);
    }
    CHECK(tangent >= 1);
}

TEST_CASE("mirror_line: only exact mirrors strictly beside an axis-parallel line", "[sites]") {
    const Ellipse e(Rational(3), Rational(1), Rational(1, 3), Rational(5), Rational(2));
    const std::optional<AxisLine> l = mirror_line(e, mirror_across(e, AxisLine{false, Rational(-4)}));
    REQUIRE(l);
    CHECK(!l->vertical);
    CHECK(l->c == Rational(-4));
    // A mirror across a line the site crosses is not a mirror pair for the rule.
    CHECK(!mirror_line(e, mirror_across(e, AxisLine{true, Rational(6)})));
    // The same shape turned the other way is not a mirror image.
    CHECK(!mirror_line(e, Ellipse(Rational(3), Rational(1), Rational(1, 3), Rational(15), Rational(2))));
}
