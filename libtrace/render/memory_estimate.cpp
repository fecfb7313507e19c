#include "render/memory_estimate.h"

#include <unistd.h>

#include "core/error.h"

namespace rt {

MemoryEstimate estimateRenderMemory(const RenderSettings& settings, std::size_t primitives, bool renders) {
    MemoryEstimate e;
    if (renders) {
        const PixelWindow w = settings.window();
        const bool aovs = !settings.aovs.empty(), path = settings.integrator == Integrator::Path;
        const std::uint64_t perPixel = kRenderBytesPerPixel + (aovs ? kAovBytesPerPixel : 0) +
                                       (path ? kPathPassBytesPerPixel : 0) +
                                       (path && aovs ? kPathAovPassBytesPerPixel : 0);
        e.image = std::uint64_t(w.width()) * std::uint64_t(w.height()) * perPixel;
    }
    e.sceneAndTree = std::uint64_t(primitives) * kRenderBytesPerPrimitive;
    return e;
}

std::uint64_t defaultMemoryLimit() {
    const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGESIZE);
    if (pages <= 0 || pageSize <= 0) return std::uint64_t(16) << 30;  // unknown: a typical machine's
    return std::uint64_t(pages) * std::uint64_t(pageSize) / 4 * 3;
}

void checkMemoryLimit(const MemoryEstimate& e, std::uint64_t limit, const std::string& smallerImage) {
    if (e.total() <= limit) return;
    const std::string remedy = e.textures > e.image ? "make the textures smaller (fewer pixels)" : smallerImage;
    throw InputError("rendering needs about " + gigabytes(e.total()) + " (image " + gigabytes(e.image) +
                     ", scene and tree " + gigabytes(e.sceneAndTree) + ", textures " + gigabytes(e.textures) +
                     "), more than --max-memory " + gigabytes(limit) + "; " + remedy + " or raise --max-memory");
}

}  // namespace rt
