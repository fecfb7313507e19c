#include "image/heatmap_png.h"

#include "image/oiio_file.h"
#include "version.h"

namespace rt {

void writeHeatmapPng(const std::string& path, const RgbImage& image) {
    OIIO::ImageSpec spec(image.width(), image.height(), 3, OIIO::TypeDesc::UINT8);
    spec.attribute("oiio:ColorSpace", "sRGB");
    spec.attribute("Software", std::string("rt-inspect ") + kVersion);
    writeImageFile(path, "png", spec, OIIO::TypeDesc::UINT8, image.bytes().data());
}

}  // namespace rt
