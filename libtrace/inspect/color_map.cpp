#include "inspect/color_map.h"

#include <algorithm>
#include <cmath>

namespace rt {

namespace {

// matplotlib's _viridis_data at t = 0, 0.1, ..., 1 (sRGB, 0-1).
constexpr float kViridis[11][3] = {
    {0.267004f, 0.004874f, 0.329415f}, {0.282623f, 0.140926f, 0.457517f}, {0.253935f, 0.265254f, 0.529983f},
    {0.206756f, 0.371758f, 0.553117f}, {0.163625f, 0.471133f, 0.558148f}, {0.127568f, 0.566949f, 0.550556f},
    {0.134692f, 0.658636f, 0.517649f}, {0.266941f, 0.748751f, 0.440573f}, {0.477504f, 0.821444f, 0.318195f},
    {0.741388f, 0.873449f, 0.149561f}, {0.993248f, 0.906157f, 0.143936f},
};

std::uint8_t toByte(float v) { return std::uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); }

}  // namespace

Rgb8 viridis(float t) {
    if (!(t > 0)) t = 0;  // also NaN
    t = std::min(t, 1.0f) * 10.0f;
    const int i = std::min(int(t), 9);
    const float f = t - float(i);
    float c[3];
    for (int k = 0; k < 3; ++k) c[k] = kViridis[i][k] + f * (kViridis[i + 1][k] - kViridis[i][k]);
    return {toByte(c[0]), toByte(c[1]), toByte(c[2])};
}

}  // namespace rt
