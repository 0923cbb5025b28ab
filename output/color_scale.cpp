#include "output/color_scale.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ellvor {

std::string sequential_color(double t) {
    static constexpr int kStops[5][3] = {{68, 1, 84}, {59, 82, 139}, {33, 145, 140}, {94, 201, 98}, {253, 231, 37}};
    if (!(t >= 0)) t = 0;
    t = std::min(t, 1.0) * 4;
    const int k = std::min(3, static_cast<int>(std::floor(t)));
    const double f = t - k;
    char out[8];
    int c[3];
    for (int i = 0; i < 3; ++i) c[i] = static_cast<int>(std::lround(kStops[k][i] + f * (kStops[k + 1][i] - kStops[k][i])));
    std::snprintf(out, sizeof out, "#%02x%02x%02x", c[0], c[1], c[2]);
    return out;
}

}  // namespace ellvor
