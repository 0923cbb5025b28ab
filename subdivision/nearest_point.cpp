#include "subdivision/nearest_point.hpp"

#include <cmath>

namespace ellvor {

double approximate_nearest_angle(double a, double b, double x, double y) {
    double theta = std::atan2(a * y, b * x);
    for (int i = 0; i < 30; ++i) {
        const double s = std::sin(theta), c = std::cos(theta);
        const double g = a * x * s - b * y * c - (a * a - b * b) * s * c;
        const double dg = a * x * c + b * y * s - (a * a - b * b) * (c * c - s * s);
        if (!(dg > 0)) break;  // not near a minimum: keep the last guess
        const double step = std::fmax(-0.5, std::fmin(0.5, g / dg));
        theta -= step;
        // Within a few ulps: rounding keeps a step of about one ulp forever.
        if (std::fabs(step) <= 0x1p-50 * std::fmax(1.0, std::fabs(theta))) break;
    }
    return theta;
}

}  // namespace ellvor
