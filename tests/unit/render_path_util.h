// What the path tracer's tests share: materials by their metallic-roughness factors, a small
// path-traced picture, image textures given as functions, the mean of what the camera rays that hit something saw, and
// a Cornell-like box.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>

#include "accel/naive.h"
#include "render/renderer.h"
#include "render_test_scenes.h"

namespace rt::test {

inline Material pbr(Color color, float metallic, float roughness, float specular = 1) {
    Material m{.name = "pbr", .color = color};
    m.pbr.factors = MetallicRoughness{metallic, roughness, specular};
    return m;
}

inline RenderSettings pathPicture(int size, int samples) {
    RenderSettings r = picture(size, size);
    r.integrator = Integrator::Path;
    r.pixelSamples = samples;
    return r;
}

// Every image texture is the function `value` of the texture coordinates.
class FunctionTextures : public ImageTextures {
public:
    FunctionTextures(const Scene& scene, std::function<Color(float, float)> value)
        : ImageTextures(scene), value_(std::move(value)) {}
    Color lookup(std::uint32_t, const TexCoord& at) const override { return value_(at.s, at.t); }
    Color data(std::uint32_t, const TexCoord& at) const override { return value_(at.s, at.t); }
    float alpha(std::uint32_t, float, float, bool) const override { return 1; }
    bool hasAlpha(std::uint32_t, bool) const override { return false; }

private:
    std::function<Color(float, float)> value_;
};

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
    return render({s, images}, accel, settings, stats);
}

// A closed box of five diffuse walls (red left, green right) with a light panel under its
// ceiling, facing down, seen through its open front: the Cornell box's light transport.
inline Scene boxWithLightPanel() {
    Scene s;
    s.camera.origin = {0, 1, 3.5};
    s.camera.destination = {0, 1, 0};
    s.camera.fovDegrees = 45;
    const auto white = addMaterial(s, pbr({0.7f, 0.7f, 0.7f}, 0, 1, 0));
    const auto red = addMaterial(s, pbr({0.7f, 0.1f, 0.1f}, 0, 1, 0));
    const auto green = addMaterial(s, pbr({0.1f, 0.7f, 0.1f}, 0, 1, 0));
    Material lamp = pbr({0, 0, 0}, 0, 1, 0);
    lamp.emission.color = {15, 15, 15};
    const auto light = addMaterial(s, lamp);
    addQuad(s, {-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}, white);    // floor
    addQuad(s, {-1, 2, -1}, {-1, 2, 1}, {1, 2, 1}, {1, 2, -1}, white);    // ceiling
    addQuad(s, {-1, 0, -1}, {-1, 2, -1}, {1, 2, -1}, {1, 0, -1}, white);  // back
    addQuad(s, {-1, 0, -1}, {-1, 0, 1}, {-1, 2, 1}, {-1, 2, -1}, red);
    addQuad(s, {1, 0, -1}, {1, 2, -1}, {1, 2, 1}, {1, 0, 1}, green);
    // wound so that its front faces down, into the box
    addQuad(s, {-0.3, 1.99, -0.3}, {0.3, 1.99, -0.3}, {0.3, 1.99, 0.3}, {-0.3, 1.99, 0.3}, light);
    s.flatten();
    return s;
}

}  // namespace rt::test
