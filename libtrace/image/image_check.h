// Whether an image file already holds a finished render (rt-render --skip-existing): a farm task
// that is run again after its output was written exits at once instead of rendering again.
#pragma once

#include <string>

#include "image/image_output.h"
#include "render/film/framebuffer.h"

namespace rt {

// Empty if `output.path` holds what writing `output` would: rt-render's own Software tag (in the
// formats that keep one), its channels, `window` as its data window in a fullWidth x fullHeight
// image (formats without a display window, such as PNG, must hold the whole image), and pixels
// that read back completely; otherwise why it does not, e.g. "missing" or "its data window is
// 0,0,35,20". The header is checked before any pixel is read: a 1 MB EXR of 1,000 channels at
// the output's path asked for 2.6 GB when it was read first.
std::string whyNotCompleteImage(const ImageOutputSettings& output, int fullWidth, int fullHeight,
                                const PixelWindow& window);

}  // namespace rt
