// Whether an image file already holds a finished render (rt-render --skip-existing): a farm task
// that is run again after its output was written exits at once instead of rendering again.
#pragma once

#include <string>

#include "render/framebuffer.h"

namespace rt {

// Empty if `path` reads back completely through OpenImageIO with `window` as its data window in
// a fullWidth x fullHeight image (formats without a display window, such as PNG, must hold the
// whole image); otherwise why it does not, e.g. "missing" or "its data window is 0,0,35,20".
std::string whyNotCompleteImage(const std::string& path, int fullWidth, int fullHeight, const PixelWindow& window);

}  // namespace rt
