#include "image/image_output.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <filesystem>
#include <stdexcept>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/text.h"
#include "image/ascii_art.h"
#include "image/oiio_file.h"

namespace rt {

namespace {

struct FormatName {
    ImageFormat format;
    const char* name;
    const char* extension;
    const char* oiioName;  // OpenImageIO's writer, chosen by name so that any file name works
};
constexpr FormatName kFormats[] = {{ImageFormat::Null, "null", "", ""},
                                   {ImageFormat::Png, "png", ".png", "png"},
                                   {ImageFormat::Exr, "exr", ".exr", "openexr"},
                                   {ImageFormat::Tga, "tga", ".tga", "targa"},
                                   {ImageFormat::Text, "text", ".txt", ""}};

const FormatName& formatName(ImageFormat format) {
    for (const FormatName& f : kFormats)
        if (f.format == format) return f;
    throw std::invalid_argument("unknown image format");
}

// The framebuffer's window as packed RGB floats, the layout OIIO and OCIO take.
std::vector<float> packedRgb(const Framebuffer& image) {
    std::vector<float> rgb;
    rgb.reserve(image.pixels().size() * 3);
    for (const Color& c : image.pixels()) rgb.insert(rgb.end(), {c.r, c.g, c.b});
    return rgb;
}

// The data window is the rendered window, the display window the full image (EXR keeps both).
OIIO::ImageSpec specFor(const Framebuffer& image, OIIO::TypeDesc type) {
    const PixelWindow& w = image.window();
    OIIO::ImageSpec spec(w.width(), w.height(), 3, type);
    spec.x = w.x0;
    spec.y = w.y0;
    spec.full_x = spec.full_y = 0;
    spec.full_width = image.fullWidth();
    spec.full_height = image.fullHeight();
    return spec;
}

void writeExr(const Framebuffer& image, const ImageOutputSettings& s, const ImageMetadata& meta) {
    const ColorPipeline color(s.color);  // resolves and checks the colour space name
    OIIO::ImageSpec spec = specFor(image, s.exrPixels == ExrPixelType::Half ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT);
    spec.attribute("compression", "zip");
    spec.attribute("Software", meta.software);
    spec.attribute("oiio:ColorSpace", color.colorspace());
    spec.attribute("rt:colorSpace", color.colorspace());
    spec.attribute("rt:colorConfig", color.configName());
    spec.attribute("rt:scene", meta.sceneFile);
    spec.attribute("rt:samplesPerPixel", meta.samplesPerPixel);
    spec.attribute("rt:renderSeconds", float(meta.renderSeconds));
    writeImageFile(s.path, formatName(ImageFormat::Exr).oiioName, spec, OIIO::TypeDesc::FLOAT, packedRgb(image).data());
}

void writeDisplayImage(const Framebuffer& image, const ImageOutputSettings& s, const ImageMetadata& meta) {
    if (std::find(kPngBits.begin(), kPngBits.end(), s.pngBits) == kPngBits.end())
        throw std::invalid_argument("PNG bits must be 8 or 16");
    const ColorPipeline color(s.color);
    std::vector<float> rgb = packedRgb(image);
    color.toDisplay(rgb);
    const bool png = s.format == ImageFormat::Png;
    OIIO::ImageSpec spec = specFor(image, png && s.pngBits == 16 ? OIIO::TypeDesc::UINT16 : OIIO::TypeDesc::UINT8);
    spec.attribute("Software", meta.software);
    writeImageFile(s.path, formatName(s.format).oiioName, spec, OIIO::TypeDesc::FLOAT, rgb.data());
}

void writeText(const Framebuffer& image, const ImageOutputSettings& s) {
    const ColorPipeline color(s.color);
    std::vector<float> rgb = packedRgb(image);
    color.toDisplay(rgb);
    const std::string text = asciiArt(rgb, image.window().width(), image.window().height());
    writeFileAtomically(s.path, [&](std::ostream& os) { os << text; });
}

}  // namespace

std::optional<ImageFormat> parseImageFormat(const std::string& name) {
    for (const FormatName& f : kFormats)
        if (name == f.name) return f.format;
    return std::nullopt;
}

std::optional<ImageFormat> imageFormatFromPath(const std::string& path) {
    const std::string ext = lowerCaseExtension(path);
    for (const FormatName& f : kFormats)
        if (!ext.empty() && ext == f.extension) return f.format;
    return std::nullopt;
}

const char* imageFormatName(ImageFormat format) { return formatName(format).name; }

std::vector<std::string> imageFormatNames() {
    std::vector<std::string> names;
    for (const FormatName& f : kFormats) names.emplace_back(f.name);
    return names;
}

ImageFormat chooseImageFormat(const std::optional<std::string>& type, const std::optional<std::string>& path) {
    const std::optional<ImageFormat> named = type ? parseImageFormat(*type) : std::nullopt;
    if (type && !named) {
        std::string known;
        for (const std::string& name : imageFormatNames()) known += (known.empty() ? "" : " ") + name;
        throw InputError("-o " + *type + ": unknown output type (" + known + ")");
    }
    if (!path) return named.value_or(ImageFormat::Null);
    const std::optional<ImageFormat> byExtension = imageFormatFromPath(*path);
    if (!named && *path == "-") throw InputError("-f -: give -o to say what to write to standard output");
    if (!named && !byExtension)
        throw InputError("-f " + *path + ": no writer for this extension (.png .exr .tga .txt); give -o");
    if (named && byExtension && named != byExtension)
        throw InputError("-o " + *type + " and -f " + *path + " disagree: the extension says " +
                         imageFormatName(*byExtension));
    if (named == ImageFormat::Null)
        throw InputError("-o null writes no file, but -f " + *path + " names one: give one of them");
    return named.value_or(*byExtension);
}

void writeImage(const Framebuffer& image, const ImageOutputSettings& s, const ImageMetadata& meta) {
    switch (s.format) {
        case ImageFormat::Null: return;
        case ImageFormat::Exr: return writeExr(image, s, meta);
        case ImageFormat::Png:
        case ImageFormat::Tga: return writeDisplayImage(image, s, meta);
        case ImageFormat::Text: return writeText(image, s);
    }
}

}  // namespace rt
