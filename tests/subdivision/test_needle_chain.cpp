// The needle chains (subdivision/needle_chain.hpp, docs/DESIGN.md §4.2 item 4):
// the links and the maps that carry a contact from one link to the next,
// checked against the boundary itself; and the circles of fuzz F7, F8 (past a
// needle's tip) and F10 (beside a band 10^6 times longer than the other
// sites), certified from the chain, against the MPFR signed-distance oracle
// (tests/support/signed_distance_oracle.hpp), which calls no solver.
#include "predicates/incircle.hpp"
#include "subdivision/boundary_chart.hpp"
#include "subdivision/needle_chain.hpp"
#include "subdivision/voronoi_circle_enclosure.hpp"
#include "tests/support/ellipse_graph.hpp"
#include "tests/support/signed_distance_oracle.hpp"

#include <catch2/catch.hpp>

#include <array>
#include <cmath>

using namespace ellvor;
using ellvor::test::ellipse;
using test::OracleEllipse;
using test::Real;
using test::RealPoint;

namespace {

constexpr long kPrec = 256;

Ball ball(double x) {
    Ball b;
    arb_set_d(b.get(), x);
    return b;
}

double mid(const Ball& b) { return b.mid_double(); }

// The position of the boundary point along the site's major axis and across it.
std::array<double, 2> along_and_across(const Ellipse& e, const BoundaryChart::Local& p) {
    const double c = e.cos_rotation().to_double(), s = e.sin_rotation().to_double();
    const double dx = mid(p.px) - e.xc().to_double(), dy = mid(p.py) - e.yc().to_double();
    const double u = c * dx + s * dy, v = c * dy - s * dx;
    return e.a() < e.b() ? std::array<double, 2>{v, u} : std::array<double, 2>{u, v};
}

}  // namespace

TEST_CASE("thin needle: the links and the maps carrying a contact from one link to the next", "[subdivision][needle]") {
    // A needle along a (aspect 2^20) and one along b (aspect 2^30), rotated.
    for (const Ellipse& needle : {ellipse("3", "3/1048576", "1/3", "1", "2"), ellipse("1/1073741824", "1", "-2/7", "-5", "1")}) {
        const long aspect = aspect_bits(needle);
        CHECK(aspect >= 20);
        for (NeedleChain chain : {NeedleChain::thicker, NeedleChain::shorter}) {
            const Ellipse stout = needle_link(needle, chain, kStoutNeedleBits), middle = needle_link(needle, chain, 10);
            CHECK(aspect_bits(stout) == kStoutNeedleBits);
            CHECK(aspect_bits(middle) == 10);
            CHECK(aspect_bits(needle_link(needle, chain, aspect + 5)) == aspect);  // the needle itself
            // One semi-axis kept: the major one when thickening, the minor one when shortening.
            const bool a_long = !(needle.a() < needle.b());
            CHECK((chain == NeedleChain::thicker) == (a_long ? stout.a() == needle.a() : stout.b() == needle.b()));
            CHECK((chain == NeedleChain::shorter) == (a_long ? stout.b() == needle.b() : stout.a() == needle.a()));
            for (bool flipped : {false, true})
                for (double t : {-0.9, -0.3, -1e-3, 0.0, 2e-4, 0.5, 0.97}) {
                    for (ContactMap map : {ContactMap::same_normal, ContactMap::same_position}) {
                        INFO("aspect " << aspect << " chain " << int(chain) << " map " << int(map) << " chart "
                                       << flipped << " t " << t);
                        bool to_flipped = flipped;
                        Ball parameter = ball(t);
                        carry_contact(stout, middle, map, to_flipped, parameter, kPrec);
                        const BoundaryChart::Local from = BoundaryChart(stout, flipped).evaluate(ball(t), kPrec, false);
                        const BoundaryChart::Local to = BoundaryChart(middle, to_flipped).evaluate(parameter, kPrec, false);
                        if (map == ContactMap::same_normal) {
                            CHECK(std::fabs(mid(from.nx) - mid(to.nx)) < 1e-12);
                            CHECK(std::fabs(mid(from.ny) - mid(to.ny)) < 1e-12);
                        } else {
                            const auto f = along_and_across(stout, from), g = along_and_across(middle, to);
                            CHECK(std::fabs(f[0] - g[0]) < 1e-12 * (1 + std::fabs(f[0])));
                            if (std::fabs(f[1]) > 1e-9) CHECK((f[1] < 0) == (g[1] < 0));  // the same side (a tip has none)
                        }
                    }
                }
        }
    }
    // A contact within sqrt(minor / major) of a tip is carried by its normal first.
    const Ellipse stout = needle_link(ellipse("3", "3/1048576", "1/3", "1", "2"), NeedleChain::thicker, kStoutNeedleBits);
    CHECK(contact_maps(stout, NeedleChain::thicker, false, ball(0.01), kPrec)[0] == ContactMap::same_normal);
    CHECK(contact_maps(stout, NeedleChain::thicker, false, ball(0.9), kPrec)[0] == ContactMap::same_angle);
    CHECK(contact_maps(stout, NeedleChain::shorter, false, ball(0.01), kPrec)[0] == ContactMap::same_position);
}

TEST_CASE("thin needle: circles past a needle's tip and beside a long band are certified along the chain "
          "(fuzz F7, F8, F10)",
          "[subdivision][needle]") {
    struct Case {
        const char* what;
        std::array<Ellipse, 3> triple;  // counter-clockwise circle asked; the needle first
        bool at_tip;                    // the needle's contact at a tip (else on its side)
        Ellipse query;                  // another site of the input, for InCircle
    };
    const Case cases[] = {
        {"F7: a needle 10^8 : 1, a long ellipse, a thin one",
         {ellipse("47/1444446440", "24/5", "-47/50", "91/5", "058/5"), ellipse("3", "6310.", "-7/10", "24/2", "41/29"),
          ellipse("9/54", "49/5", "1/50", "5", "137/5")},
         true, ellipse("92/5", "09", "-13/50", "2080/1", "58/5")},
        {"F8: a needle 10^9 : 1, two crossing ellipses",
         {ellipse("47/14444442880", "23/5", "-47/50", "91/5", "116/5"), ellipse("3", "63/10", "-7/10", "24/25", "41/2"),
          ellipse("92/5", "10", "-7/10", "24/25", "58/5")},
         true, ellipse("8/54", "49/5", "20/5", "5", "137/5")},
        {"F10: a band 8.4e6 x 9.8 crossing two small sites",
         {ellipse("84E5", "49/5", "1/05", "5", "137/5"), ellipse("47/10", "03/74", "-47/49", "91/5", "116/5"),
          ellipse("3", "63/95", "-7/10", "25/2", "41/2")},
         false, ellipse("92/5", "10", "-13/50", "206/11", "58/5")},
    };
    for (const Case& c : cases) {
        INFO(c.what);
        const auto& [needle, second, third] = c.triple;
        // The chains alone: certify() now finds these circles by the bisector walk, tried first
        // (test_bisector_walk_start.cpp).
        VoronoiCircleSolver solver(needle, second, third);
        REQUIRE(solver.certify_by_needle_chains());
        const VoronoiCircleEnclosure& found = solver.enclosure();
        CHECK(found.found_by == CircleStart::needle_chain);
        // The oracle's signed distances from the certified center: each site at the radius.
        const RealPoint v{Real(found.center_x.mid_double()), Real(found.center_y.mid_double())};
        const double rho = found.radius.mid_double();
        for (const Ellipse* e : {&needle, &second, &third})
            CHECK(std::fabs(OracleEllipse(*e).signed_distance_value(v).to_double() - rho) < 1e-9 * (1 + std::fabs(rho)));
        // Where the needle is touched: within 10^-6 of a tip, or near the middle of its side.
        const test::SignedDistance d = OracleEllipse(needle).signed_distance(v);
        const bool a_long = !(needle.a() < needle.b());
        const double major = (a_long ? needle.a() : needle.b()).to_double();
        const double angle = 2 * std::atan(needle.w().to_double()) + (a_long ? 0 : M_PI / 2);
        const double dx = d.foot.x.to_double() - needle.xc().to_double(), dy = d.foot.y.to_double() - needle.yc().to_double();
        const double along = std::cos(angle) * dx + std::sin(angle) * dy;
        if (c.at_tip)
            CHECK(std::fabs(std::fabs(along) - major) < 1e-6);
        else
            CHECK(std::fabs(along) < 100);
        // InCircle of another site decided from a certified circle (no search, no exact stage), as
        // the oracle says: the double certificate's (from the bisector walk's start) or Arb's.
        const Decision<InCircle> answer = incircle(needle, second, third, c.query);
        CHECK((answer.stage == Stage::filter || answer.stage == Stage::subdivision));
        const double gap = OracleEllipse(c.query).signed_distance_value(v).to_double() - rho;
        REQUIRE(std::fabs(gap) > 1e-6);
        CHECK(*answer == (gap < 0 ? InCircle::conflict : InCircle::no_conflict));
    }
}
