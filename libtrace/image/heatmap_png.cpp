#include "image/heatmap_png.h"

#include <OpenImageIO/imageio.h>

#include <stdexcept>

#include "core/atomic_file.h"

namespace rt {

void writeHeatmapPng(const std::string& path, const RgbImage& image, const std::string& software) {
    commitFileAtomically(path, [&](const std::string& tempPath) {
        const auto fail = [&](const std::string& why) {
            throw std::runtime_error(path + ": cannot write the PNG: " + why);
        };
        auto out = OIIO::ImageOutput::create("png");
        if (!out) fail(OIIO::geterror());
        OIIO::ImageSpec spec(image.width(), image.height(), 3, OIIO::TypeDesc::UINT8);
        spec.attribute("oiio:ColorSpace", "sRGB");
        spec.attribute("Software", software);
        if (!out->open(tempPath, spec)) fail(out->geterror());
        if (!out->write_image(OIIO::TypeDesc::UINT8, image.bytes().data()) || !out->close()) fail(out->geterror());
        return true;
    });
}

}  // namespace rt
