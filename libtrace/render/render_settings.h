// What rt-render's rendering options control (thesis appendix B), with their defaults.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "accel/settings.h"
#include "core/names.h"
#include "render/film/aov.h"
#include "render/film/framebuffer.h"

namespace rt {

// The limits validate() enforces; the tools' options check the same numbers.
inline constexpr int kMaxImageSide = 65536;  // width and height: larger than any real image
inline constexpr int kMaxReflectionDepth = 10;
inline constexpr int kMaxSamples = 1 << 20;   // -S and -r
inline constexpr int kMaxBounces = 1000;      // --max-bounces
inline constexpr int kMaxAdaptiveGrid = 256;  // --adaptive: the coarsest corner spacing
inline constexpr double kMaxTimeLimit = 1e9;  // --time-limit, seconds: about 32 years

// --integrator: the thesis's Whitted ray tracer (render/integrators/tracer.h) or the path tracer
// (render/integrators/path_tracer.h, docs/path-tracing.md).
enum class Integrator { Whitted, Path };
inline constexpr NamedValues<Integrator, 2> kIntegratorNames{
    {{"whitted", Integrator::Whitted}, {"path", Integrator::Path}}};

// --light-sampler: how the path tracer's next-event estimation picks a light
// (render/lights/light_distribution.h): a light tree over the local lights (the default), or in
// proportion to power alone.
enum class LightSampler { Tree, Power };
inline constexpr NamedValues<LightSampler, 2> kLightSamplerNames{
    {{"tree", LightSampler::Tree}, {"power", LightSampler::Power}}};

// The structure an integrator traces with when none is asked for (docs/trees.md, "The path
// tracer's structure"): the thesis's KD tree for its Whitted tracer; the BVH for the path tracer,
// whose rays after the first bounce go every way: on bench/path_structures.sh's twelve scenes the
// BVH renders 0.86-2.36x as fast as the KD tree (median 1.29) and, with its build, is faster on all.
inline constexpr AccelKind defaultAccelKind(Integrator integrator) {
    return integrator == Integrator::Path ? AccelKind::Bvh : AccelKind::Kd;
}

struct RenderSettings {
    int width = 800;                    // -x
    int height = 600;                   // -y
    std::optional<PixelWindow> region;  // --region: render only this window
    int reflectionDepth = 5;            // -d: reflection rays that may follow one camera ray (0-kMaxReflectionDepth)
    bool shadows = false;               // -s: a shadow ray to each light (the thesis's default is off)
    // -S: camera rays per pixel on a jittered grid (thesis 2.6.1); 1 shoots one ray through the centre.
    int pixelSamples = 1;
    // -D s|d|b (thesis 2.6.2): soft shadows over each light's size, glossy reflections over
    // each material's spread, with -r rays per bundle.
    bool softShadows = false;
    bool glossyReflections = false;
    int distributedSamples = 128;  // -r
    int threads = 0;               // --threads; 0 lets OpenMP use every core
    std::uint32_t seed = 0;        // --seed: another seed gives independent noise, as deterministic
    std::vector<Aov> aovs;         // --aov: fill each pixel's PixelAovs (render/film/aov.h) too, for these layers
    Integrator integrator = Integrator::Whitted;
    int maxBounces = 8;       // --max-bounces: the path tracer's surface interactions after the camera ray
    float clampRadiance = 0;  // --clamp: the path tracer's indirect samples capped at this value; 0 is off
    LightSampler lightSampler = LightSampler::Tree;  // --light-sampler
    // --adaptive (thesis 2.3, render/adaptive.h): the spacing of the grid of traced corners, a
    // power of two; 0 traces every pixel. A block whose corners differ by less than
    // adaptiveThreshold (linear colour and alpha) and see the same object is interpolated.
    int adaptiveGrid = 0;
    float adaptiveThreshold = 0.02f;  // --adaptive-threshold
    // --noise-threshold (render/film/noise_threshold.h): the path tracer stops sampling a pixel once
    // the relative standard error of its mean luminance is below this, judged first after
    // adaptiveMinSamples samples (0: Cycles' rule from the threshold); 0 is off, every pixel -S.
    float noiseThreshold = 0;
    int adaptiveMinSamples = 0;  // --adaptive-min-samples: 0 or 2-kMaxSamples
    // --time-limit: seconds after which the render stops; 0 is none. The path tracer keeps its
    // last whole pass (render/renderer.h); a render with no whole pass yet keeps nothing.
    double timeLimitSeconds = 0;
    // --packets: the Whitted tracer finds the first hits of one-sample pixels' camera rays eight
    // at a time with Accelerator::intersectPacket (render/integrators/tracer.h); the same bits either way.
    bool packets = true;

    PixelWindow window() const { return region.value_or(PixelWindow{0, 0, width, height}); }
};

// Throws rt::InputError when a setting is out of range (sizes, depth 0-10, samples, region).
void validate(const RenderSettings& settings);

}  // namespace rt
