// Writing the rendered picture (thesis 3.4.4): EXR, Radiance HDR, PFM and float TIFF keep the
// linear scene-referred values; PNG, TGA, JPEG, WebP, 8- and 16-bit TIFF and text are
// display-referred through the OpenColorIO pipeline; null writes nothing (benchmarks). Every file is written
// atomically: a failed or interrupted write leaves an existing file untouched and no partial file; "-" writes to
// standard output.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/names.h"
#include "image/color_pipeline.h"
#include "render/film/aov.h"
#include "render/film/framebuffer.h"

namespace rt {

enum class ImageFormat { Null, Png, Exr, Tga, Text, Jpeg, Tiff, Hdr, Pfm, Webp };

// null png exr tga text jpeg tiff hdr pfm webp
std::optional<ImageFormat> parseImageFormat(const std::string& name);
// From a file name's extension (.png .exr .tga .txt .jpg .jpeg .tif .tiff .hdr .pfm .webp), case-insensitive.
std::optional<ImageFormat> imageFormatFromPath(const std::string& path);
const char* imageFormatName(ImageFormat format);
// Every format's name, as parseImageFormat knows it (rt-render -o takes these).
std::vector<std::string> imageFormatNames();

// The pixel type of EXR files: half (16-bit float, the default) or float (32-bit).
enum class ExrPixelType { Half, Float };
inline constexpr NamedValues<ExrPixelType, 2> kExrPixelTypeNames{
    {{"half", ExrPixelType::Half}, {"float", ExrPixelType::Float}}};
// The bits per channel PNG files may have.
inline constexpr std::array<int, 2> kPngBits{8, 16};
// The bits per channel TIFF files may have: 8 and 16 display-referred, 32 float and linear.
inline constexpr std::array<int, 3> kTiffBits{8, 16, 32};
// OpenEXR's compression methods, as OpenImageIO names them.
inline constexpr std::array<const char*, 10> kExrCompressions{"none",  "rle", "zips", "zip",  "piz",
                                                              "pxr24", "b44", "b44a", "dwaa", "dwab"};
// Whether the installed OpenImageIO writes the format (PFM needs OpenImageIO 2.5, WebP libwebp).
bool imageFormatWritable(ImageFormat format);
std::string imageFormatExtensions();  // ".png .exr ...", for help and messages
// Whether the format has an alpha channel (PNG, EXR, TGA, TIFF, WebP): rt-render writes one there by default.
bool imageFormatHasAlpha(ImageFormat format);

// rt-render's rule for -o `type` and -f `path`: the extension picks the format unless `type`
// names one; neither gives null. Throws rt::InputError if the two contradict each other
// (-o png -f a.exr, -o null -f a.png), or if `path` has no extension a writer handles and no
// type is given. With a type, a path without a known extension is written in that type. A
// format the installed OpenImageIO cannot write is an rt::InputError too.
ImageFormat chooseImageFormat(const std::optional<std::string>& type, const std::optional<std::string>& path);

struct ImageOutputSettings {
    ImageFormat format = ImageFormat::Null;
    std::string path;  // "-" is standard output
    ExrPixelType exrPixels = ExrPixelType::Half;
    std::string exrCompression = "zip";  // one of kExrCompressions
    int pngBits = 8;                     // 8 or 16
    int tiffBits = 8;                    // 8 or 16 (display-referred), or 32: float, linear
    int jpegQuality = 90;                // 1-100
    // RGBA: alpha is the pixel's coverage (0 where every camera ray missed); EXR colours are
    // premultiplied by it, PNG and TGA colours straight. Without it, RGB over the background.
    bool alpha = false;
    std::vector<Aov> aovs;  // EXR only: these AOVs' channels after the colour (render/film/aov.h)
    ColorSettings color;
};

// The channels writeImage writes for `settings`: colour, alpha if asked, the AOVs' (EXR).
int imageChannels(const ImageOutputSettings& settings);
// Whether the format's files keep the Software tag (ImageMetadata::software): PNG, EXR, TGA, JPEG, TIFF.
bool imageFormatKeepsSoftware(ImageFormat format);

// What the EXR header records about the render.
struct ImageMetadata {
    std::string software;  // "rt-render 0.1.0"
    std::string sceneFile;
    int samplesPerPixel = 1;
    double renderSeconds = 0;
};

// The largest value a half-float EXR holds; a larger one would be written as +inf.
inline constexpr float kMaxHalfValue = 65504.0f;

// Writes `image` as the settings say and returns how many values it had to change to fit: the
// colour values beyond kMaxHalfValue of a half-float EXR, written as kMaxHalfValue (the tool
// says so; --exr-pixels float keeps them). Throws rt::InputError for bad colour settings and
// std::runtime_error when the file cannot be written.
std::uint64_t writeImage(const Framebuffer& image, const ImageOutputSettings& settings, const ImageMetadata& metadata);

}  // namespace rt
