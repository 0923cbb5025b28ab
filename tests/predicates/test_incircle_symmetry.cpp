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
        // The same point set written otherwise (semi-axes swapped, rotated by a quarter turn:
        // w' = tan((omega + pi/2) / 2) = (w + 1) / (1 - w)): the same stage.
        const Rational w = q_mirror.w();
        const Ellipse q_rewritten(q_mirror.b(), q_mirror.a(), (w + Rational(1)) / (Rational(1) - w), q_mirror.xc(),
                                  q_mirror.yc());
        REQUIRE(q_rewritten.point_set_key() == q_mirror.point_set_key());
        REQUIRE(!(q_rewritten == q_mirror));
        const Decision<InCircle> rewritten = incircle(*triple[0], *triple[1], *triple[2], q_rewritten);
        CHECK(*rewritten == InCircle::tangent);
        CHECK(rewritten.stage == Stage::symmetry);
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

namespace {

// P(t) = (X(t), Y(t)) / W(t) exactly.
std::array<Rational, 2> boundary_point(const Ellipse& e, const Rational& t) {
    auto at = [&](const IntPolynomial& p) {
        Rational value, power(1);
        for (long k = 0; k <= p.degree(); ++k, power = power * t) value = value + Rational(p.coeff(k)) * power;
        return value;
    };
    const Rational w = at(e.W());
    return {at(e.X()) / w, at(e.Y()) / w};
}

}  // namespace

TEST_CASE("bisector_line and self_mirror: the lines a medial-axis certificate may use", "[sites][medial-axis]") {
    // Equal circles mirrored across x = 6, crossing: their bisector is exactly x = 6 (mirror_line
    // wants them strictly beside it). Crossing mirrored ellipses: their bisector is not known to be
    // the line. Mirrored ellipses strictly beside it: mirror_line's line.
    const Ellipse c1 = Ellipse::circle(0, 0, 10), c2 = Ellipse::circle(12, 0, 10);
    const std::optional<AxisLine> l = bisector_line(c1, c2);
    REQUIRE(l);
    CHECK(l->vertical);
    CHECK(l->c == Rational(6));
    CHECK(!mirror_line(c1, c2));
    CHECK(!bisector_line(c1, Ellipse::circle(12, 1, 10)));
    CHECK(!bisector_line(c1, Ellipse::circle(12, 0, 9)));
    const Ellipse e(Rational(8), Rational(3), Rational(1, 3), Rational(0), Rational(0));
    CHECK(!bisector_line(e, mirror_across(e, AxisLine{true, Rational(2)})));
    const std::optional<AxisLine> apart = bisector_line(e, mirror_across(e, AxisLine{false, Rational(20)}));
    REQUIRE(apart);
    CHECK((!apart->vertical && apart->c == Rational(20)));

    // The needle (11/30, 10) at (6, 10), a-axis horizontal: x = 6 holds its b-axis (P(t) -> P(1/t)),
    // y = 10 its a-axis (P(t) -> P(-t)); turned a quarter (w = 1) the other way round. Checked on
    // boundary points: the mirror image of P(t) is P(-t) or P(1/t) exactly.
    const Ellipse needle(Rational(11, 30UL), Rational(10), Rational(0), Rational(6), Rational(10));
    const Ellipse turned(Rational(11, 30UL), Rational(10), Rational(1), Rational(6), Rational(10));
    const AxisLine x6{true, Rational(6)}, y10{false, Rational(10)};
    struct Case {
        const Ellipse* e;
        AxisLine line;
        SelfMirror expected;
    };
    for (const Case& c : {Case{&needle, x6, SelfMirror::inverts_parameter}, Case{&needle, y10, SelfMirror::negates_parameter},
                          Case{&turned, x6, SelfMirror::negates_parameter}, Case{&turned, y10, SelfMirror::inverts_parameter}}) {
        REQUIRE(self_mirror(*c.e, c.line) == c.expected);
        for (const Rational& t : {Rational(1, 3UL), Rational(-5, 7UL), Rational(2)}) {
            const std::array<Rational, 2> p = boundary_point(*c.e, t);
            const std::array<Rational, 2> image =
                boundary_point(*c.e, c.expected == SelfMirror::negates_parameter ? -t : Rational(1) / t);
            const Rational two_c = Rational(2) * c.line.c;
            CHECK(image[0] == (c.line.vertical ? two_c - p[0] : p[0]));
            CHECK(image[1] == (c.line.vertical ? p[1] : two_c - p[1]));
        }
    }
    CHECK(self_mirror(needle, AxisLine{true, Rational(7)}) == SelfMirror::none);  // not its axis
    CHECK(self_mirror(Ellipse(Rational(3), Rational(1), Rational(1, 3), Rational(6), Rational(10)), x6) == SelfMirror::none);
    CHECK(self_mirror(Ellipse::circle(6, 10, 1), x6) == SelfMirror::none);  // every line through a circle's center
}
