#include "render/render_settings.h"

#include <cmath>
#include <string>

#include "core/error.h"

namespace rt {

namespace {
// The most pixels rendered at once: the framebuffer (12 bytes a pixel) stays below 3.3 GB.
constexpr long long kMaxPixels = 1ll << 28;
}  // namespace

void validate(const RenderSettings& s) {
    if (s.width < 1 || s.height < 1 || s.width > kMaxImageSide || s.height > kMaxImageSide)
        throw InputError("image size " + std::to_string(s.width) + "x" + std::to_string(s.height) + " is outside 1-" +
                         std::to_string(kMaxImageSide));
    if (const PixelWindow w = s.window(); (long long)w.width() * w.height() > kMaxPixels)
        throw InputError("rendering " + std::to_string(w.width()) + "x" + std::to_string(w.height()) +
                         " pixels at once needs more than 3 GB; render it in regions (--region)");
    if (s.reflectionDepth < 0 || s.reflectionDepth > kMaxReflectionDepth)
        throw InputError("reflection depth " + std::to_string(s.reflectionDepth) + " is outside 0-" +
                         std::to_string(kMaxReflectionDepth));
    if (s.pixelSamples < 1 || s.pixelSamples > kMaxSamples)
        throw InputError("samples per pixel must be 1-" + std::to_string(kMaxSamples));
    if (s.distributedSamples < 1 || s.distributedSamples > kMaxSamples)
        throw InputError("distributed ray tracing samples must be 1-" + std::to_string(kMaxSamples));
    if (s.adaptiveGrid != 0 &&
        (s.adaptiveGrid < 2 || s.adaptiveGrid > kMaxAdaptiveGrid || (s.adaptiveGrid & (s.adaptiveGrid - 1)) != 0))
        throw InputError("the adaptive grid must be a power of two from 2 to " + std::to_string(kMaxAdaptiveGrid) +
                         ", got " + std::to_string(s.adaptiveGrid));
    if (!(s.adaptiveThreshold >= 0) || !std::isfinite(s.adaptiveThreshold))
        throw InputError("the adaptive threshold must be a finite number of at least 0");
    if (s.adaptiveGrid && s.aovs)
        throw InputError("--adaptive interpolates colour only: AOVs (--aov) need every pixel traced");
    if (s.threads < 0) throw InputError("the thread count must not be negative");
    if (s.region && !s.region->inside(s.width, s.height)) {
        const PixelWindow& r = *s.region;
        throw InputError("region " + std::to_string(r.x0) + "," + std::to_string(r.y0) + "," + std::to_string(r.x1) +
                         "," + std::to_string(r.y1) + " is empty or outside the " + std::to_string(s.width) + "x" +
                         std::to_string(s.height) + " image");
    }
}

}  // namespace rt
