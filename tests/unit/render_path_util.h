// What the path tracer's tests share: materials by their metallic-roughness factors, a small
// path-traced picture, and the mean of what the camera rays that hit something saw.
#pragma once

#include <algorithm>
#include <cmath>

#include "accel/naive.h"
#include "render/renderer.h"
#include "render_test_scenes.h"

namespace rt::test {

inline Material pbr(Color color, float metallic, float roughness, float specular = 1) {
    Material m{.name = "pbr", .color = color};
    m.metallicRoughness = MetallicRoughness{metallic, roughness, specular};
    return m;
}

inline RenderSettings pathPicture(int size, int samples) {
    RenderSettings r = picture(size, size);
    r.integrator = Integrator::Path;
    r.pixelSamples = samples;
    return r;
}

struct ImageMean {
    double mean = 0;
    double standardError = 0;  // of the mean, from the spread of the pixels
};

// Mean and standard error of the green channel over the pixels whose camera ray hit.
inline ImageMean meanOverHits(const Framebuffer& image) {
    double sum = 0, sumSq = 0;
    int n = 0;
    for (std::size_t i = 0; i < image.pixels().size(); ++i) {
        if (image.alphas()[i] < 1) continue;
        const double g = image.pixels()[i].g;
        sum += g, sumSq += g * g, ++n;
    }
    const double mean = sum / n;
    return {mean, std::sqrt(std::max(0.0, sumSq / n - mean * mean) / n)};
}

// The picture alone, through the naive list, with image textures from `images` (none: white).
inline Framebuffer renderPath(const Scene& s, const RenderSettings& settings, const ImageTextures* images = nullptr) {
    const NaiveAccelerator accel(s.primitives);
    RenderStats stats;
    return render(s, accel, settings, stats, {}, images);
}

}  // namespace rt::test
