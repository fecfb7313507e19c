#include "image/image_output.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <stdexcept>

#include "core/atomic_file.h"
#include "core/error.h"
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

// Which colours a picture takes: as rendered (over the background) for one without alpha;
// premultiplied by alpha for EXR (OpenEXR's convention); straight (not premultiplied) for
// PNG and TGA, whose alpha is unassociated, so that the display transform sees true colours.
enum class Colors { OverBackground, Premultiplied, Straight };

Color colorOf(const Framebuffer& image, std::size_t i, Colors which) {
    if (which == Colors::OverBackground) return image.pixels()[i];
    const Color c = image.premultiplied(i);
    const float a = image.alphas()[i];
    return which == Colors::Premultiplied || a == 0 || a == 1 ? c : c * (1 / a);
}

// The framebuffer's window as packed RGB floats, the layout OIIO and OCIO take.
std::vector<float> packedRgb(const Framebuffer& image, Colors which) {
    std::vector<float> rgb;
    rgb.reserve(image.pixels().size() * 3);
    for (std::size_t i = 0; i < image.pixels().size(); ++i) {
        const Color c = colorOf(image, i, which);
        rgb.insert(rgb.end(), {c.r, c.g, c.b});
    }
    return rgb;
}

// RGB as packedRgb gives it, with the alpha channel when the picture has one.
std::vector<float> withAlpha(const std::vector<float>& rgb, const Framebuffer& image, bool alpha) {
    if (!alpha) return rgb;
    std::vector<float> rgba;
    rgba.reserve(image.alphas().size() * 4);
    for (std::size_t i = 0; i < image.alphas().size(); ++i)
        rgba.insert(rgba.end(), {rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2], image.alphas()[i]});
    return rgba;
}

// The data window is the rendered window, the display window the full image (EXR keeps both).
// Four channels are R G B A, with A as the alpha channel (OpenImageIO's default names).
OIIO::ImageSpec specFor(const Framebuffer& image, OIIO::TypeDesc type, bool alpha) {
    const PixelWindow& w = image.window();
    OIIO::ImageSpec spec(w.width(), w.height(), alpha ? 4 : 3, type);
    spec.x = w.x0;
    spec.y = w.y0;
    spec.full_x = spec.full_y = 0;
    spec.full_width = image.fullWidth();
    spec.full_height = image.fullHeight();
    return spec;
}

void writeExr(const Framebuffer& image, const ImageOutputSettings& s, const ImageMetadata& meta) {
    const ColorPipeline color(s.color);  // resolves and checks the colour space name
    OIIO::ImageSpec spec = specFor(image, s.exrHalf ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT, s.alpha);
    spec.attribute("compression", "zip");
    spec.attribute("Software", meta.software);
    spec.attribute("oiio:ColorSpace", color.colorspace());
    spec.attribute("rt:colorSpace", color.colorspace());
    spec.attribute("rt:colorConfig", color.configName());
    spec.attribute("rt:scene", meta.sceneFile);
    spec.attribute("rt:samplesPerPixel", meta.samplesPerPixel);
    spec.attribute("rt:renderSeconds", float(meta.renderSeconds));
    const Colors which = s.alpha ? Colors::Premultiplied : Colors::OverBackground;
    writeImageFile(s.path, formatName(ImageFormat::Exr).oiioName, spec, OIIO::TypeDesc::FLOAT,
                   withAlpha(packedRgb(image, which), image, s.alpha).data());
}

void writeDisplayImage(const Framebuffer& image, const ImageOutputSettings& s, const ImageMetadata& meta) {
    if (s.pngBits != 8 && s.pngBits != 16) throw std::invalid_argument("PNG bits must be 8 or 16");
    const ColorPipeline color(s.color);
    std::vector<float> rgb = packedRgb(image, s.alpha ? Colors::Straight : Colors::OverBackground);
    color.toDisplay(rgb);
    const bool png = s.format == ImageFormat::Png;
    OIIO::ImageSpec spec =
        specFor(image, png && s.pngBits == 16 ? OIIO::TypeDesc::UINT16 : OIIO::TypeDesc::UINT8, s.alpha);
    spec.attribute("Software", meta.software);
    spec.attribute("oiio:UnassociatedAlpha", 1);  // the colours are straight already: OIIO must not divide
    writeImageFile(s.path, formatName(s.format).oiioName, spec, OIIO::TypeDesc::FLOAT,
                   withAlpha(rgb, image, s.alpha).data());
}

void writeText(const Framebuffer& image, const ImageOutputSettings& s) {
    const ColorPipeline color(s.color);
    std::vector<float> rgb = packedRgb(image, Colors::OverBackground);
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
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    for (const FormatName& f : kFormats)
        if (!ext.empty() && ext == f.extension) return f.format;
    return std::nullopt;
}

const char* imageFormatName(ImageFormat format) { return formatName(format).name; }

bool imageFormatHasAlpha(ImageFormat format) {
    return format == ImageFormat::Png || format == ImageFormat::Exr || format == ImageFormat::Tga;
}

ImageFormat chooseImageFormat(const std::optional<std::string>& type, const std::optional<std::string>& path) {
    const std::optional<ImageFormat> named = type ? parseImageFormat(*type) : std::nullopt;
    if (type && !named) throw InputError("-o " + *type + ": unknown output type (null png exr tga text)");
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
