#include "render/render_settings.h"

#include <cmath>
#include <string>

#include "core/error.h"
#include "render/memory_estimate.h"

namespace rt {

namespace {
// The pixel count bounds one render, whatever --max-memory allows: 2^28 pixels
// (16384 x 16384) take 21.5 GB (render/memory_estimate.h).
constexpr long long kMaxPixels = 1ll << 28;
}  // namespace

void validate(const RenderSettings& s) {
    if (s.width < 1 || s.height < 1 || s.width > kMaxImageSide || s.height > kMaxImageSide)
        throw InputError("image size " + std::to_string(s.width) + "x" + std::to_string(s.height) + " is outside 1-" +
                         std::to_string(kMaxImageSide));
    // Before the window's size is taken: x1 - x0 of a region from INT_MIN to INT_MAX overflows.
    if (s.region && !s.region->inside(s.width, s.height)) {
        const PixelWindow& r = *s.region;
        throw InputError("region " + std::to_string(r.x0) + "," + std::to_string(r.y0) + "," + std::to_string(r.x1) +
                         "," + std::to_string(r.y1) + " is empty or outside the " + std::to_string(s.width) + "x" +
                         std::to_string(s.height) + " image");
    }
    if (const PixelWindow w = s.window(); (long long)w.width() * w.height() > kMaxPixels)
        throw InputError("rendering " + std::to_string(w.width()) + "x" + std::to_string(w.height()) +
                         " pixels at once needs more than " +
                         gigabytes(std::uint64_t(kMaxPixels) * kRenderBytesPerPixel) +
                         "; render it in regions (rt-render --region)");
    if (s.reflectionDepth < 0 || s.reflectionDepth > kMaxReflectionDepth)
        throw InputError("reflection depth " + std::to_string(s.reflectionDepth) + " is outside 0-" +
                         std::to_string(kMaxReflectionDepth));
    if (s.pixelSamples < 1 || s.pixelSamples > kMaxSamples)
        throw InputError("samples per pixel must be 1-" + std::to_string(kMaxSamples));
    if (s.distributedSamples < 1 || s.distributedSamples > kMaxSamples)
        throw InputError("distributed ray tracing samples must be 1-" + std::to_string(kMaxSamples));
    if (s.maxBounces < 0 || s.maxBounces > kMaxBounces)
        throw InputError("--max-bounces must be 0-" + std::to_string(kMaxBounces));
    if (!(s.clampRadiance >= 0) || !std::isfinite(s.clampRadiance))
        throw InputError("--clamp must be a finite number >= 0 (0 is off)");
    if (s.adaptiveGrid != 0 &&
        (s.adaptiveGrid < 2 || s.adaptiveGrid > kMaxAdaptiveGrid || (s.adaptiveGrid & (s.adaptiveGrid - 1)) != 0))
        throw InputError("the adaptive grid must be a power of two from 2 to " + std::to_string(kMaxAdaptiveGrid) +
                         ", got " + std::to_string(s.adaptiveGrid));
    if (!(s.adaptiveThreshold >= 0) || !std::isfinite(s.adaptiveThreshold))
        throw InputError("the adaptive threshold must be a finite number of at least 0");
    if (s.adaptiveGrid && !s.aovs.empty())
        throw InputError("--adaptive interpolates colour only: AOVs (--aov) need every pixel traced");
    if (s.adaptiveGrid && s.integrator == Integrator::Path)
        throw InputError("--adaptive needs the whitted integrator: it compares the objects the camera rays hit");
    if (!(s.noiseThreshold >= 0) || !std::isfinite(s.noiseThreshold))
        throw InputError("--noise-threshold must be a finite number >= 0 (0 is off)");
    if (s.adaptiveMinSamples != 0 && (s.adaptiveMinSamples < 2 || s.adaptiveMinSamples > kMaxSamples))
        throw InputError("--adaptive-min-samples must be 0 (chosen from the threshold) or 2-" +
                         std::to_string(kMaxSamples) + ": a pixel's noise is estimated from two samples or more");
    if (s.noiseThreshold > 0 && s.integrator != Integrator::Path)
        throw InputError(
            "--noise-threshold needs the path integrator (--integrator path): the whitted integrator takes all -S "
            "samples of a pixel at once");
    if (!(s.timeLimitSeconds >= 0) || s.timeLimitSeconds > kMaxTimeLimit)
        throw InputError("--time-limit must be 0 (none) to " + std::to_string(int(kMaxTimeLimit)) + " seconds");
    if (s.threads < 0) throw InputError("the thread count must not be negative");
}

}  // namespace rt
