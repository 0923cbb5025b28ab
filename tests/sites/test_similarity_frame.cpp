// SimilarityFrame: exact images, the identity near the unit frame, a unit
// frame for sites far away or of extreme size, and the way back for balls.
#include "sites/similarity_frame.hpp"
#include "tests/support/random_sites.hpp"

#include <catch2/catch.hpp>

#include <random>

using namespace ellvor;

namespace {


// The image of a site in a frame, and its largest semi-axis there, as a double.
double framed_size(const SimilarityFrame& f, const Ellipse& e) {
    const Ellipse g = f.apply(e);
    return std::max(g.a(), g.b()).to_double();
}

}  // namespace

TEST_CASE("similarity frame: the identity near the unit frame", "[sites][frame]") {
    const Ellipse e1(2, 1, Rational(1, 3UL), 10, -20), e2(3, Rational(1, 2UL), 0, 100, 7);
    const SimilarityFrame f = SimilarityFrame::for_sites({&e1, &e2});
    CHECK(f.is_identity());
    CHECK(f.apply(e1) == e1);
}

TEST_CASE("similarity frame: far away, huge and tiny sites get a unit frame", "[sites][frame]") {
    std::mt19937_64 rng(41);
    for (int trial = 0; trial < 60; ++trial) {
        const int kind = trial % 3;
        const Rational shift = kind == 0 ? power_of_ten(20 + trial) : Rational(0);
        const Rational scale = kind == 1 ? power_of_ten(30 + trial) : kind == 2 ? power_of_ten(-30 - trial) : Rational(1);
        auto site = [&](long x, long y) {
            const Rational a = test::random_fraction(rng, 5, 40, 10), b = test::random_fraction(rng, 5, 40, 10);
            return Ellipse(a * scale, b * scale, test::random_fraction(rng, -5, 5, 3), Rational(x) * scale + shift,
                           Rational(y) * scale - shift);
        };
        const Ellipse e1 = site(0, 0), e2 = site(12, 3), e3 = site(-4, 11);
        INFO("trial " << trial << "\n" << e1.str() << "\n" << e2.str() << "\n" << e3.str());
        const SimilarityFrame f = SimilarityFrame::for_sites({&e1, &e2, &e3});
        REQUIRE(!f.is_identity());
        // Unit size (the largest site), centers near the origin.
        double largest = 0;
        for (const Ellipse* e : {&e1, &e2, &e3}) largest = std::max(largest, framed_size(f, *e));
        CHECK(largest >= 0.25);
        CHECK(largest <= 4);
        for (const Ellipse* e : {&e1, &e2, &e3}) {
            const Ellipse g = f.apply(*e);
            CHECK(g.xc().to_double() * g.xc().to_double() + g.yc().to_double() * g.yc().to_double() < 1e4);
            CHECK(g.w() == e->w());
        }
        // Exact: boundary points map to boundary points at the same parameter.
        for (const Rational& t : {Rational(0), Rational(1, 3UL), Rational(-7, 2UL)}) {
            const Point p = e2.point_at(t), q = f.apply(e2).point_at(t), fp = f.apply(p);
            CHECK(fp.x == q.x);
            CHECK(fp.y == q.y);
        }
        // Back to the original frame: an image length and point map onto the
        // originals (balls containing them).
        const Ellipse g = f.apply(e3);
        const long prec = 128;
        CHECK(f.length_to_original(Ball(g.a(), prec), prec).contains(e3.a()));
        CHECK(f.x_to_original(Ball(g.xc(), prec), prec).contains(e3.xc()));
        CHECK(f.y_to_original(Ball(g.yc(), prec), prec).contains(e3.yc()));
        // The way back keeps the frame's relative accuracy.
        const Ball x = f.x_to_original(Ball(g.xc(), prec), prec);
        CHECK(arb_rel_accuracy_bits(x.get()) >= prec - 8);
    }
}
