#include "image/image_output.h"

#include <OpenImageIO/half.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "core/error.h"
#include "core/text.h"
#include "image/ascii_art.h"
#include "image/oiio_file.h"
#include "os/atomic_file.h"

namespace rt {

namespace {

struct FormatName {
    ImageFormat format;
    const char* name;
    const char* extensions;  // each with its dot, separated by spaces
    const char* oiioName;    // OpenImageIO's writer, chosen by name so that any file name works
    bool linear;             // scene-referred: the linear values (else through the OCIO view)
    bool alpha;              // has an alpha channel
    bool software;           // keeps the Software tag (ImageMetadata::software)
};
constexpr FormatName kFormats[] = {{ImageFormat::Null, "null", "", "", false, false, false},
                                   {ImageFormat::Png, "png", ".png", "png", false, true, true},
                                   {ImageFormat::Exr, "exr", ".exr", "openexr", true, true, true},
                                   {ImageFormat::Tga, "tga", ".tga", "targa", false, true, true},
                                   {ImageFormat::Text, "text", ".txt", "", false, false, false},
                                   {ImageFormat::Jpeg, "jpeg", ".jpg .jpeg", "jpeg", false, false, true},
                                   {ImageFormat::Tiff, "tiff", ".tif .tiff", "tiff", false, true, true},
                                   {ImageFormat::Hdr, "hdr", ".hdr", "hdr", true, false, false},
                                   {ImageFormat::Pfm, "pfm", ".pfm", "pnm", true, false, false},
                                   {ImageFormat::Webp, "webp", ".webp", "webp", false, true, false}};

// One field of every format, non-empty ones, separated by spaces.
std::string joined(const char* FormatName::*field) {
    std::string out;
    for (const FormatName& f : kFormats) {
        if (!*(f.*field)) continue;
        if (!out.empty()) out += ' ';
        out += f.*field;
    }
    return out;
}

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

// A file whose channels differ in type (half or float colours, float AOVs, uint32 ids) takes
// its pixels in that native layout, channel after channel.
class NativePixels {
public:
    void add(float v, OIIO::TypeDesc type) {
        if (type == OIIO::TypeDesc::HALF)
            append(Imath::half(v));
        else
            append(v);
    }
    void add(std::uint32_t v) { append(v); }
    const unsigned char* data() const { return bytes_.data(); }

private:
    template <class T>
    void append(T v) {
        const std::size_t at = bytes_.size();
        bytes_.resize(at + sizeof v);
        std::memcpy(bytes_.data() + at, &v, sizeof v);
    }
    std::vector<unsigned char> bytes_;
};

// The colour channels as `spec` names them, then the AOVs' (aov.h), in one EXR.
void writeExrWithAovs(const Framebuffer& image, const ImageOutputSettings& s, OIIO::ImageSpec spec,
                      const std::vector<float>& colors) {
    const OIIO::TypeDesc colorType = spec.format;
    const std::size_t colorChannels = std::size_t(spec.nchannels);
    std::vector<OIIO::TypeDesc> formats(colorChannels, colorType);
    for (const AovLayer& layer : aovLayers()) {
        if (std::find(s.aovs.begin(), s.aovs.end(), layer.aov) == s.aovs.end()) continue;
        if (layer.aov == Aov::Z) spec.z_channel = int(spec.channelnames.size());
        for (const char* name : layer.channels) {
            spec.channelnames.emplace_back(name);
            formats.push_back(layer.integer ? OIIO::TypeDesc::UINT : OIIO::TypeDesc::FLOAT);
        }
    }
    spec.nchannels = int(spec.channelnames.size());
    spec.channelformats = formats;
    NativePixels pixels;
    for (std::size_t i = 0; i < image.pixels().size(); ++i) {
        for (std::size_t c = 0; c < colorChannels; ++c) pixels.add(colors[i * colorChannels + c], colorType);
        const PixelAovs& a = image.aovs()[i];
        for (const Aov aov : s.aovs) {
            if (aov == Aov::Id) {
                pixels.add(a.material);
                pixels.add(a.primitive);
            }
            for (const float v : aovValues(a, aov)) pixels.add(v, OIIO::TypeDesc::FLOAT);
        }
    }
    writeImageFile(s.path, formatName(ImageFormat::Exr).oiioName, spec, OIIO::TypeDesc::UNKNOWN, pixels.data());
}

// Holds every value of `values` to +-kMaxHalfValue (half's +inf otherwise) and counts those it changed.
std::uint64_t clipToHalfRange(std::vector<float>& values) {
    std::uint64_t clipped = 0;
    for (float& v : values) {
        if (std::abs(v) <= kMaxHalfValue) continue;
        v = std::copysign(kMaxHalfValue, v);
        ++clipped;
    }
    return clipped;
}

std::uint64_t writeExr(const Framebuffer& image, const ImageOutputSettings& s, const ImageMetadata& meta) {
    const ColorPipeline color(s.color);  // resolves and checks the colour space name
    OIIO::ImageSpec spec =
        specFor(image, s.exrPixels == ExrPixelType::Half ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT, s.alpha);
    spec.attribute("compression", s.exrCompression);
    spec.attribute("Software", meta.software);
    spec.attribute("oiio:ColorSpace", color.colorspace());
    spec.attribute("rt:colorSpace", color.colorspace());
    spec.attribute("rt:colorConfig", color.configName());
    spec.attribute("rt:scene", meta.sceneFile);
    spec.attribute("rt:samplesPerPixel", meta.samplesPerPixel);
    spec.attribute("rt:renderSeconds", float(meta.renderSeconds));
    const Colors which = s.alpha ? Colors::Premultiplied : Colors::OverBackground;
    std::vector<float> colors = withAlpha(packedRgb(image, which), image, s.alpha);
    const std::uint64_t clipped = s.exrPixels == ExrPixelType::Half ? clipToHalfRange(colors) : 0;
    if (!s.aovs.empty()) {
        if (!image.hasAovs()) throw std::invalid_argument("AOVs asked of a picture rendered without them");
        writeExrWithAovs(image, s, spec, colors);
    } else {
        writeImageFile(s.path, formatName(ImageFormat::Exr).oiioName, spec, OIIO::TypeDesc::FLOAT, colors.data());
    }
    return clipped;
}

// The integer type a display-referred file stores: 16 bits where asked and the format has them.
OIIO::TypeDesc displayType(const ImageOutputSettings& s) {
    const bool sixteen =
        (s.format == ImageFormat::Png && s.pngBits == 16) || (s.format == ImageFormat::Tiff && s.tiffBits == 16);
    return sixteen ? OIIO::TypeDesc::UINT16 : OIIO::TypeDesc::UINT8;
}

void writeDisplayImage(const Framebuffer& image, const ImageOutputSettings& s, const ImageMetadata& meta) {
    if (std::find(kPngBits.begin(), kPngBits.end(), s.pngBits) == kPngBits.end())
        throw std::invalid_argument("PNG bits must be 8 or 16");
    const ColorPipeline color(s.color);
    std::vector<float> rgb = packedRgb(image, s.alpha ? Colors::Straight : Colors::OverBackground);
    color.toDisplay(rgb);
    OIIO::ImageSpec spec = specFor(image, displayType(s), s.alpha);
    spec.attribute("Software", meta.software);
    spec.attribute("oiio:UnassociatedAlpha", 1);  // the colours are straight already: OIIO must not divide
    if (s.format == ImageFormat::Jpeg) spec.attribute("Compression", "jpeg:" + std::to_string(s.jpegQuality));
    writeImageFile(s.path, formatName(s.format).oiioName, spec, OIIO::TypeDesc::FLOAT,
                   withAlpha(rgb, image, s.alpha).data());
}

// Radiance HDR, PFM and float TIFF: the linear values as EXR keeps them (premultiplied alpha in TIFF).
void writeLinearImage(const Framebuffer& image, const ImageOutputSettings& s, const ImageMetadata& meta) {
    const ColorPipeline color(s.color);
    OIIO::ImageSpec spec = specFor(image, OIIO::TypeDesc::FLOAT, s.alpha);
    spec.attribute("Software", meta.software);
    spec.attribute("oiio:ColorSpace", color.colorspace());
    const Colors which = s.alpha ? Colors::Premultiplied : Colors::OverBackground;
    writeImageFile(s.path, formatName(s.format).oiioName, spec, OIIO::TypeDesc::FLOAT,
                   withAlpha(packedRgb(image, which), image, s.alpha).data());
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
    const std::string ext = lowerCaseExtension(path);
    for (const FormatName& f : kFormats) {
        // A plain loop, not std::views::istream: clang 14 (the tsan preset) rejects that view
        // with GCC 12's standard library.
        std::istringstream list(f.extensions);
        for (std::string known; list >> known;)
            if (ext == known) return f.format;
    }
    return std::nullopt;
}

const char* imageFormatName(ImageFormat format) { return formatName(format).name; }

bool imageFormatHasAlpha(ImageFormat format) { return formatName(format).alpha; }

bool imageFormatKeepsSoftware(ImageFormat format) { return formatName(format).software; }

int imageChannels(const ImageOutputSettings& s) {
    int channels = s.alpha ? 4 : 3;
    if (s.format != ImageFormat::Exr) return channels;
    for (const AovLayer& layer : aovLayers())
        if (std::find(s.aovs.begin(), s.aovs.end(), layer.aov) != s.aovs.end()) channels += int(layer.channels.size());
    return channels;
}

std::vector<std::string> imageFormatNames() {
    std::vector<std::string> names;
    for (const FormatName& f : kFormats) names.emplace_back(f.name);
    return names;
}

std::string imageFormatExtensions() { return joined(&FormatName::extensions); }

ImageFormat chooseImageFormat(const std::optional<std::string>& type, const std::optional<std::string>& path) {
    const std::optional<ImageFormat> named = type ? parseImageFormat(*type) : std::nullopt;
    if (type && !named) throw InputError("-o " + *type + ": unknown output type (" + joined(&FormatName::name) + ")");
    if (!path) return named.value_or(ImageFormat::Null);
    const std::optional<ImageFormat> byExtension = imageFormatFromPath(*path);
    if (!named && *path == "-") throw InputError("-f -: give -o to say what to write to standard output");
    if (!named && !byExtension)
        throw InputError("-f " + *path + ": no writer for this extension (" + imageFormatExtensions() + "); give -o");
    if (named && byExtension && named != byExtension)
        throw InputError("-o " + *type + " and -f " + *path + " disagree: the extension says " +
                         imageFormatName(*byExtension));
    if (named == ImageFormat::Null)
        throw InputError("-o null writes no file, but -f " + *path + " names one: give one of them");
    const ImageFormat format = named.value_or(*byExtension);
    // A format this OpenImageIO was built without (WebP, say) is found before anything renders.
    if (!imageFormatWritable(format))
        throw InputError(std::string(imageFormatName(format)) + ": the installed OpenImageIO cannot write this format");
    return format;
}

bool imageFormatWritable(ImageFormat format) {
    const FormatName& f = formatName(format);
    if (!*f.oiioName) return true;  // null and text need no writer
    // By a file name, as OpenImageIO finds its writer: its PNM writer writes PFM only from 2.5 on.
    const std::string extension(f.extensions, std::strcspn(f.extensions, " "));
    return OIIO::ImageOutput::create("probe" + extension) != nullptr;
}

std::uint64_t writeImage(const Framebuffer& image, const ImageOutputSettings& s, const ImageMetadata& meta) {
    switch (s.format) {
        case ImageFormat::Null:
            break;
        case ImageFormat::Exr:
            return writeExr(image, s, meta);
        case ImageFormat::Hdr:
        case ImageFormat::Pfm:
            writeLinearImage(image, s, meta);
            break;
        case ImageFormat::Tiff:
            if (s.tiffBits == 32)
                writeLinearImage(image, s, meta);
            else
                writeDisplayImage(image, s, meta);
            break;
        case ImageFormat::Png:
        case ImageFormat::Tga:
        case ImageFormat::Jpeg:
        case ImageFormat::Webp:
            writeDisplayImage(image, s, meta);
            break;
        case ImageFormat::Text:
            writeText(image, s);
            break;
    }
    return 0;  // float and display-referred files hold every value the renderer makes (kMaxColorValue)
}

}  // namespace rt
