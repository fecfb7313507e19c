#include "image/heatmap_png.h"

#include "image/oiio_file.h"

namespace rt {

void writeHeatmapPng(const std::string& path, const RgbImage& image, const std::string& software) {
    OIIO::ImageSpec spec(image.width(), image.height(), 3, OIIO::TypeDesc::UINT8);
    spec.attribute("oiio:ColorSpace", "sRGB");
    spec.attribute("Software", software);
    writeImageFile(path, "png", spec, OIIO::TypeDesc::UINT8, image.bytes().data());
}

}  // namespace rt
