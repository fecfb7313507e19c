// What a render will hold in memory, estimated before the work starts (rt-render --max-memory),
// so that a request the machine cannot meet ends in one clear message instead of swapping, an
// out-of-memory kill, or std::bad_alloc after minutes of work.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "core/text.h"  // gigabytes(), for the messages
#include "render/render_settings.h"

namespace rt {

// Measured peaks (docs/robustness.md), rounded up.
// A pixel: the framebuffer's float RGB and alpha and the output's converted copies (4096 x 4096
// to PNG peaked 1.24 GB above the tool's start, 75.5 bytes a pixel).
constexpr std::uint64_t kRenderBytesPerPixel = 80;
// With --aov, a pixel's PixelAovs (render/film/aov.h) and their channels in the EXR (not measured).
constexpr std::uint64_t kAovBytesPerPixel = 160;
// With the path tracer, which renders in passes (render/renderer.h): each pixel's running
// estimate (render/film/pixel_estimate.h) twice, as the finished passes left it and with the pass
// under way; with --aov also its AovSums (render/film/aov.h) twice.
constexpr std::uint64_t kPathPassBytesPerPixel = 104;
constexpr std::uint64_t kPathAovPassBytesPerPixel = 272;
// A primitive: the scene's geometry and the KD tree's build at its peak (boxes, events of three
// axes, the references of both children); the Stanford bunny's 69,451 triangles took 260.
constexpr std::uint64_t kRenderBytesPerPrimitive = 300;

struct MemoryEstimate {
    std::uint64_t image = 0;
    std::uint64_t sceneAndTree = 0;
    std::uint64_t textures = 0;  // image textures read whole (image/texture_files.h estimateTextureMemory)
    std::uint64_t total() const { return image + sceneAndTree + textures; }
};

// The picture's part is zero when nothing is rendered (-p).
MemoryEstimate estimateRenderMemory(const RenderSettings& settings, std::size_t primitives, bool renders);

// Three quarters of the machine's physical memory: what --max-memory allows unless told.
std::uint64_t defaultMemoryLimit();

// Throws rt::InputError ("rendering needs about 21.5 GB (image 21.5 GB, scene and tree 0.0 GB,
// textures 0.0 GB), more than --max-memory 4.0 GB; render the image in regions (--region) or raise
// --max-memory") when the estimate exceeds `limit` bytes; `smallerImage` says how to need less
// for the picture.
void checkMemoryLimit(const MemoryEstimate& estimate, std::uint64_t limit,
                      const std::string& smallerImage = "render the image in regions (--region)");

}  // namespace rt
