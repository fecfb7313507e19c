// AOVs (arbitrary output variables): what each pixel's camera rays found, written beside its
// colour into one multi-channel EXR, named layer.channel as OpenImageIO and compositors expect
// (`oiiotool --ch N.X,N.Y,N.Z`). Supersampling averages Z, N, Ng, P, albedo and cost over the
// camera samples (Z, N, Ng, P and albedo over those that hit something); the ids are the first
// sample's. The cost layer is rt-inspect's heat map as data: the traversal steps and
// intersection tests of the pixel's camera rays, and of every ray they spawned (a whole path
// with the path tracer). Both integrators sum them in AovSums, sample by sample. The variance
// layer is a noise figure: the variance of the pixel's mean colour, per channel, estimated from
// its samples (render/film/pixel_estimate.h); it falls as 1/N with N samples, and is 0 with one. The
// samples layer is the pixel's count of camera samples: -S everywhere, except where the path
// tracer's --noise-threshold stopped a pixel early (render/film/noise_threshold.h).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/color.h"

namespace rt {

struct Hit;
struct RenderCounters;
struct Scene;
struct SurfacePoint;

enum class Aov { Z, N, Ng, P, Albedo, Id, Cost, Variance, Samples };

struct AovLayer {
    Aov aov;
    const char* name;                   // as --aov names it
    std::vector<const char*> channels;  // EXR channel names
    bool integer;                       // uint32 channels (ids), else float
};

// Every AOV, in the order the channels are written.
const std::vector<AovLayer>& aovLayers();

// The name --aov gives `aov`.
const char* aovName(Aov aov);

// "Z,N,cost" or "all" as the list of AOVs, in aovLayers() order; throws rt::InputError
// naming an unknown one.
std::vector<Aov> parseAovList(const std::string& list);

// The id of nothing: a sample that hit no primitive.
inline constexpr std::uint32_t kNoId = 0xffffffffu;

// One pixel's AOVs, as the renderer fills them.
struct PixelAovs {
    float z = 0;  // distance along the camera ray; +inf where no sample hit
    float n[3] = {}, ng[3] = {}, p[3] = {};
    Color albedo;
    std::uint32_t material = kNoId, primitive = kNoId;
    float steps = 0, tests = 0;        // per camera ray: its own traversal steps and tests
    float allSteps = 0, allTests = 0;  // per camera ray: with every shadow and reflection ray it spawned
    Color variance;                    // of the mean colour, per channel
    float samples = 0;                 // camera samples taken
};

// A pixel's AOVs summed over its camera samples, taken one at a time in sample order: by the
// Whitted tracer in one loop, by the path tracer one per pass (K passes give the bits of -S K).
class AovSums {
public:
    // What sample's camera ray hit (before finishSample()): the surface point, shading normal and
    // colour (`albedo`) the shading uses; the ids are taken from the pixel's first sample only.
    void addHit(const Scene& scene, const SurfacePoint& s, const Hit& hit, const Color& albedo);
    // Ends a sample with its work: the tracing thread's counters before and after it.
    void finishSample(const RenderCounters& before, const RenderCounters& after);
    // The averages so far (see the file comment), with the variance the caller estimated.
    PixelAovs mean(const Color& varianceOfMean) const;

private:
    PixelAovs sum_;  // z, n, ng, p and albedo summed; the ids as taken
    std::uint64_t steps_ = 0, tests_ = 0, allSteps_ = 0, allTests_ = 0;
    int samples_ = 0, hits_ = 0;
};

// The float values of `aov` for a pixel, in the order of its channels (not for Aov::Id).
std::vector<float> aovValues(const PixelAovs& pixel, Aov aov);

}  // namespace rt
