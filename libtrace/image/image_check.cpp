#include "image/image_check.h"

#include <OpenImageIO/imageio.h>

#include <filesystem>
#include <vector>

namespace rt {

namespace {

std::string windowText(int x0, int y0, int x1, int y1) {
    return std::to_string(x0) + "," + std::to_string(y0) + "," + std::to_string(x1) + "," + std::to_string(y1);
}

// The data and display windows the file records, against the ones the render would write.
std::string whyNotSameWindows(const OIIO::ImageSpec& spec, int fullWidth, int fullHeight, const PixelWindow& w) {
    const std::string data = windowText(spec.x, spec.y, spec.x + spec.width, spec.y + spec.height);
    if (data != windowText(w.x0, w.y0, w.x1, w.y1)) return "its data window is " + data;
    if (spec.full_x != 0 || spec.full_y != 0 || spec.full_width != fullWidth || spec.full_height != fullHeight)
        return "its display window is " +
               windowText(spec.full_x, spec.full_y, spec.full_x + spec.full_width, spec.full_y + spec.full_height);
    return "";
}

}  // namespace

std::string whyNotCompleteImage(const std::string& path, int fullWidth, int fullHeight, const PixelWindow& window) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error)) return "missing";
    auto in = OIIO::ImageInput::open(path);
    if (!in) return "unreadable: " + OIIO::geterror();
    const OIIO::ImageSpec spec = in->spec();
    if (std::string why = whyNotSameWindows(spec, fullWidth, fullHeight, window); !why.empty()) return why;
    // Every pixel is decoded, so that a truncated or damaged file is found.
    std::vector<float> pixels(spec.image_pixels() * spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data()))
        return "unreadable: " + in->geterror();
    return "";
}

}  // namespace rt
