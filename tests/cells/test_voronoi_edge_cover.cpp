// simplified_polyline (cells/voronoi_edge_cover.hpp): the rings' points of an
// edge, fewer of them, against brute-force distances in long double on random
// curves: every dropped point is within the tolerance of the simplified
// polyline and every point of the simplified polyline (sampled along its
// segments) within it of the boxes' polyline.
#include "cells/voronoi_edge_cover.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

using namespace ellvor;

namespace {

using PlanePoint = std::array<double, 2>;

long double distance_to_polyline(const std::array<long double, 2>& q, const std::vector<PlanePoint>& line) {
    long double best = INFINITY;
    for (std::size_t i = 0; i + 1 < line.size(); ++i) {
        const long double ax = line[i][0], ay = line[i][1], dx = line[i + 1][0] - ax, dy = line[i + 1][1] - ay;
        const long double length2 = dx * dx + dy * dy;
        long double t = length2 > 0 ? ((q[0] - ax) * dx + (q[1] - ay) * dy) / length2 : 0;
        t = std::min<long double>(1, std::max<long double>(0, t));
        best = std::min(best, std::hypot(q[0] - (ax + t * dx), q[1] - (ay + t * dy)));
    }
    return best;
}

// Boxes of random sizes over the points of a random smooth curve (a sum of
// a few sines about a random line), consecutive boxes sharing their ends.
std::vector<EdgeCoverBox> random_cover(std::mt19937_64& random, double& scale) {
    std::uniform_real_distribution<double> u(-1, 1);
    scale = std::pow(10.0, 3 * u(random));
    const double amplitude = std::pow(10.0, -3 + 2 * u(random)), frequency = 1 + 20 * std::fabs(u(random));
    const double phase = 3 * u(random), cx = 100 * u(random), cy = 100 * u(random);
    const auto curve = [&](double t) -> PlanePoint {
        return {scale * (cx + t), scale * (cy + 0.3 * t + amplitude * std::sin(frequency * t + phase))};
    };
    std::vector<EdgeCoverBox> boxes;
    const int count = 1 + static_cast<int>(random() % 6);
    const int points = 2 + static_cast<int>(random() % 60);
    int step = 0;
    for (int b = 0; b < count; ++b) {
        EdgeCoverBox box;
        box.error = scale * 1e-4 * std::fabs(u(random));
        if (b > 0) box.points.push_back(boxes.back().points.back());  // the last box's end
        while (static_cast<int>(box.points.size()) < points) box.points.push_back(curve(0.01 * ++step));
        boxes.push_back(box);
    }
    return boxes;
}

}  // namespace

TEST_CASE("simplified_polyline: within the radius less the boxes' error of their points, both ways", "[cells]") {
    std::mt19937_64 random(20261129);
    long dropped = 0, kept = 0;
    for (int trial = 0; trial < 300; ++trial) {
        double scale;
        const std::vector<EdgeCoverBox> boxes = random_cover(random, scale);
        const double radius = scale * std::pow(10.0, -4 + 3 * std::uniform_real_distribution<double>(0, 1)(random));
        double error = 0;
        std::vector<PlanePoint> dense;
        for (const EdgeCoverBox& box : boxes) {
            error = std::max(error, box.error);
            dense.insert(dense.end(), box.points.begin(), box.points.end());
        }
        const std::vector<PlanePoint> simple = simplified_polyline(boxes, radius);
        INFO("trial " << trial);
        REQUIRE(simple.size() >= 2);
        CHECK(simple.front() == dense.front());
        CHECK(simple.back() == dense.back());
        CHECK(simple.size() <= dense.size());
        const long double tolerance = radius - error;
        if (tolerance <= 0) {  // nothing may be dropped but the boxes' shared ends
            CHECK(simple.size() == dense.size() - (boxes.size() - 1));
            continue;
        }
        for (const PlanePoint& q : dense) CHECK(distance_to_polyline({q[0], q[1]}, simple) <= tolerance);
        for (std::size_t i = 0; i + 1 < simple.size(); ++i)
            for (int k = 0; k <= 16; ++k) {
                const long double f = k / 16.0L;
                const std::array<long double, 2> q{simple[i][0] + f * (simple[i + 1][0] - simple[i][0]),
                                                   simple[i][1] + f * (simple[i + 1][1] - simple[i][1])};
                CHECK(distance_to_polyline(q, dense) <= tolerance);
            }
        dropped += static_cast<long>(dense.size() - simple.size());
        kept += static_cast<long>(simple.size());
    }
    // The check can fail: most points go where the curve is flat at the tolerance.
    CHECK(dropped > kept);
}

TEST_CASE("simplified_polyline: a straight edge keeps its two ends", "[cells]") {
    EdgeCoverBox a, b;
    for (int i = 0; i <= 10; ++i) a.points.push_back({0.1 * i, 0.3 * i});
    for (int i = 10; i <= 20; ++i) b.points.push_back({0.1 * i, 0.3 * i});
    const std::vector<PlanePoint> simple = simplified_polyline({a, b}, 1e-9);
    REQUIRE(simple.size() == 2);
    CHECK(simple[0] == a.points.front());
    CHECK(simple[1] == b.points.back());
}
