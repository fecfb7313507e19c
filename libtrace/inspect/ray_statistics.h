// The work an accelerator does for the rays of one picture: rt-inspect --rays and the heat
// map. The rays are exactly those rt-render traces with the same settings, because they are
// traced by rt-render's own renderer (render/renderer.h, shading included): camera rays (-S
// per pixel), shadow rays (-s, bundles for -D s), mirror and glossy reflections (-d, -D d).
// The counts are exact and independent of the thread count (per-pixel random numbers).
#pragma once

#include <vector>

#include "accel/accelerator.h"
#include "core/names.h"
#include "render/render_settings.h"
#include "render/render_stats.h"
#include "scene/scene.h"

namespace rt {

// Work per ray, 0 when there are no rays.
double stepsPerRay(const RayCounters& c);
double testsPerRay(const RayCounters& c);

// Renders the picture `settings` describes through `accel`, which must be built over
// scene.primitives, and returns its rays by kind with their work. Throws rt::InputError for
// bad settings or an unusable camera.
RenderCounters traceRayStatistics(const Scene& scene, const Accelerator& accel, const RenderSettings& settings);

// Which rays a pixel's work counts: its camera rays alone, or every ray they spawn.
enum class PixelRays { Camera, All };
inline constexpr NamedValues<PixelRays, 2> kPixelRaysNames{{{"camera", PixelRays::Camera}, {"all", PixelRays::All}}};

// The work of each pixel of the whole settings.width x settings.height picture (traversal
// steps plus intersection tests, summed over its rays), row-major with row 0 at the top:
// what the heat map shows. With PixelRays::Camera only the camera rays are traced (as
// many per pixel as settings.pixelSamples); with All, every shadow and reflection ray the
// settings ask for as well. Throws rt::InputError for bad settings or an unusable camera.
std::vector<float> pixelWork(const Scene& scene, const Accelerator& accel, const RenderSettings& settings,
                             PixelRays rays);

}  // namespace rt
