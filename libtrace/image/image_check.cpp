#include "image/image_check.h"

#include <OpenImageIO/imageio.h>

#include <filesystem>
#include <vector>

#include "image/image_header.h"

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

// Whether the header says rt-render wrote the file, in the channels `output` has.
std::string whyNotSameWriter(const OIIO::ImageSpec& spec, const ImageOutputSettings& output) {
    if (spec.nchannels != imageChannels(output))
        return "it has " + std::to_string(spec.nchannels) + " channels, not " + std::to_string(imageChannels(output));
    const std::string software = spec.get_string_attribute("Software");
    if (imageFormatKeepsSoftware(output.format) && !software.starts_with("rt-render"))
        return "rt-render did not write it (Software: '" + software + "')";
    return "";
}

}  // namespace

std::string whyNotCompleteImage(const ImageOutputSettings& output, int fullWidth, int fullHeight,
                                const PixelWindow& window) {
    std::error_code error;
    if (!std::filesystem::exists(output.path, error)) return "missing";
    if (std::optional<std::string> why = imageFileRefusal(output.path)) return *why;  // a FIFO is not opened
    auto in = OIIO::ImageInput::open(output.path);
    if (!in) return "unreadable: " + OIIO::geterror();
    const OIIO::ImageSpec spec = in->spec();
    if (std::string why = whyNotSameWindows(spec, fullWidth, fullHeight, window); !why.empty()) return why;
    if (std::string why = whyNotSameWriter(spec, output); !why.empty()) return why;
    // Every pixel is decoded, so that a truncated or damaged file is found.
    std::vector<float> pixels(spec.image_pixels() * spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data()))
        return "unreadable: " + in->geterror();
    return "";
}

}  // namespace rt
