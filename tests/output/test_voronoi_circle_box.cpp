// voronoi_circle_box (output/voronoi_circle_box.hpp): the double certificate's
// box when it is tight, else Arb's at 53 bits; either holds the circle, which
// Arb at 80 bits (the oracle) encloses.
#include "output/voronoi_circle_box.hpp"
#include "subdivision/voronoi_circle_enclosure.hpp"
#include "subdivision/voronoi_circle_in_doubles.hpp"
#include "tests/support/huge_hull_triple.hpp"

#include <catch2/catch.hpp>

using namespace ellvor;

namespace {

bool inside(const Ball& b, const Interval& box) {
    const Interval e = enclose(b);
    return box.lo <= e.lo && e.hi <= box.hi;
}

// The box holds Arb's 80-bit circle and is at most `width` wide.
void check_box(const std::vector<Ellipse>& s, const VoronoiCircleBox& box, double width) {
    VoronoiCircleSolver arb(s[0], s[1], s[2]);
    REQUIRE(arb.refine(80));
    const VoronoiCircleEnclosure& c = arb.enclosure();
    INFO("Arb: x " << c.center_x.str(20) << " y " << c.center_y.str(20) << " radius " << c.radius.str(20));
    CHECK(inside(c.center_x, box.center_x));
    CHECK(inside(c.center_y, box.center_y));
    CHECK(inside(c.radius, box.radius));
    for (const Interval* x : {&box.center_x, &box.center_y, &box.radius}) CHECK(x->hi - x->lo <= width);
}

}  // namespace

TEST_CASE("voronoi_circle_box: a tight double box is kept", "[output][voronoi_circle_box]") {
    const std::vector<Ellipse> s = {Ellipse(2, 1, 0, 6, 0), Ellipse::circle(0, 6, 1), Ellipse(1, Rational(1, 2), 1, -6, 0)};
    // The box written out is the 6 x 6 test's (the narrower one), not the
    // build's certificate by distances.
    const std::optional<DoubleVoronoiCircle> d =
        certify_voronoi_circle_in_doubles(s[0], s[1], s[2], nullptr, DoubleCertificate::tritangent_only);
    REQUIRE(d.has_value());
    CHECK(!d->by_distances);
    CHECK(certify_voronoi_circle_in_doubles(s[0], s[1], s[2])->by_distances);
    const VoronoiCircleBox box = voronoi_circle_box(s, {0, 1, 2});
    CHECK(box.radius.lo == d->radius.lo);
    CHECK(box.radius.hi == d->radius.hi);
    CHECK(box.center_x.lo == d->center_x.lo);
    CHECK(box.center_y.hi == d->center_y.hi);
    check_box(s, box, 1e-12);
}

TEST_CASE("voronoi_circle_box: a huge circle's wide double box gives way to Arb's",
          "[output][voronoi_circle_box]") {
    // The hull face of 10^6 random ellipses whose ~1-wide double box made the
    // tiled build's hull test fail (radius ~3.16e5).
    const std::vector<Ellipse> s = ellvor::test::huge_hull_triple();
    const std::optional<DoubleVoronoiCircle> d = certify_voronoi_circle_in_doubles(s[0], s[1], s[2]);
    REQUIRE(d.has_value());
    CHECK(d->radius.hi - d->radius.lo > 1e-3);
    const VoronoiCircleBox box = voronoi_circle_box(s, {0, 1, 2});
    check_box(s, box, 1e-9);
    CHECK(is_tight(box));
    // Asked for any width, the wide double box itself; without a double certificate, Arb's.
    const VoronoiCircleBox wide = voronoi_circle_box_any_width(s, {0, 1, 2}, &*d);
    CHECK_FALSE(is_tight(wide));
    CHECK(wide.radius.lo == d->radius.lo);
    CHECK(wide.center_x.hi == d->center_x.hi);
    check_box(s, wide, 10);
    const VoronoiCircleBox arb = voronoi_circle_box_any_width(s, {0, 1, 2}, nullptr);
    CHECK(is_tight(arb));
    check_box(s, arb, 1e-9);
}

TEST_CASE("circle_boxes_meet: all three components overlap", "[output][voronoi_circle_box]") {
    const VoronoiCircleBox a{{0, 1}, {0, 1}, {2, 3}};
    CHECK(circle_boxes_meet(a, {{1, 2}, {-1, 0}, {3, 4}}));  // closed intervals: touching meets
    CHECK_FALSE(circle_boxes_meet(a, {{0, 1}, {0, 1}, {3.5, 4}}));
    CHECK_FALSE(circle_boxes_meet(a, {{1.5, 2}, {0, 1}, {2, 3}}));
}

TEST_CASE("circle_differs_by_site: a site of the other face proven off the circle",
          "[output][voronoi_circle_box]") {
    // Four unit circles at the corners of a square share one circle (center 0, radius sqrt(2) - 1): the faces
    // (0, 1, 2) and (0, 2, 3) are one circle. Moving site 3 out makes them differ.
    const std::vector<Ellipse> square = {Ellipse::circle(1, 1, 1), Ellipse::circle(-1, 1, 1),
                                         Ellipse::circle(-1, -1, 1), Ellipse::circle(1, -1, 1),
                                         Ellipse::circle(Rational(3, 2), Rational(-3, 2), 1)};
    const VoronoiCircleBox box = voronoi_circle_box(square, {0, 1, 2});
    CHECK_FALSE(circle_differs_by_site(square, box, {0, 1, 2}, {0, 2, 3}));  // site 3 touches the circle
    CHECK(circle_differs_by_site(square, box, {0, 1, 2}, {0, 2, 4}));        // site 4 is off it
    CHECK_FALSE(circle_differs_by_site(square, box, {0, 1, 2}, {2, 0, 1}));  // no site of its own proves anything
}
