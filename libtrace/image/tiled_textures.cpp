#include "image/tiled_textures.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/hash.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <system_error>

namespace rt {

namespace fs = std::filesystem;

namespace {

// What a copy is made with; part of its name, so that changing anything here makes new copies.
// Tiles of 64 x 64 texels, zip-compressed, MIP levels by make_texture's bilinear resampling, in
// the source's own pixel type (8-bit stays 8-bit: sRGB decoding is done after filtering, as before).
constexpr const char* kCopySettings = "rt tx 1: 64x64 zip, OpenImageIO " OIIO_VERSION_STRING;

std::string hex(std::uint64_t v) {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(v));
    return text;
}

// What the copy of `source` depends on, as text: a file by its absolute path, size and time of
// last change (as make and renderers' auto-tx tell a changed file), an embedded picture by its bytes.
std::string identity(const TextureSource& source) {
    std::string what = kCopySettings;
    if (source.bytes)
        return what + "\nbytes " +
               hex(OIIO::farmhash::Fingerprint64(reinterpret_cast<const char*>(source.bytes->data()),
                                                 source.bytes->size()));
    const fs::path path = fs::absolute(source.path);
    const auto changed = fs::last_write_time(path).time_since_epoch().count();
    return what + "\nfile " + path.string() + "\nsize " + std::to_string(fs::file_size(path)) + "\nchanged " +
           std::to_string(changed);
}

// The copy's file name: the source's stem, for people looking in the folder, and the hash.
std::string copyName(const TextureSource& source) {
    const std::string stem = fs::path(source.bytes ? source.name : source.path).stem().string();
    return stem + "-" + hex(OIIO::farmhash::Fingerprint64(identity(source))) + ".tx";
}

// A name no other writer uses in `folder`: this process's id and a counter.
fs::path temporaryIn(const fs::path& folder, const std::string& name) {
    static std::atomic<unsigned> serial{0};
    return folder / ("." + fs::path(name).stem().string() + ".tmp-" + std::to_string(::getpid()) + "-" +
                     std::to_string(serial++) + ".tx");
}

// Throws unless `copy` reads back as a tiled file with every MIP level down to 1 x 1: OpenImageIO's
// writers can report success for a file a full disk cut short, and a short copy renamed into the
// cache would be read by every later render.
void checkWholeCopy(const fs::path& copy) {
    auto in = OIIO::ImageInput::open(copy.string());
    if (!in) throw std::runtime_error("the copy does not read back: " + OIIO::geterror());
    int levels = 0;
    while (in->seek_subimage(0, levels)) ++levels;
    const OIIO::ImageSpec& top = in->spec(0, 0);
    const int expected = 1 + int(std::floor(std::log2(std::max(top.width, top.height))));
    if (top.tile_width == 0 || levels < expected)
        throw std::runtime_error("the copy is incomplete (" + std::to_string(levels) + " of " +
                                 std::to_string(expected) + " MIP levels)");
}

// Writes the tiled, MIP-mapped texture of `source` to `target`; throws saying why it cannot.
void makeCopy(const TextureSource& source, const fs::path& target) {
    std::unique_ptr<OIIO::Filesystem::IOMemReader> memory;
    if (source.bytes)
        memory = std::make_unique<OIIO::Filesystem::IOMemReader>(source.bytes->data(), source.bytes->size());
    OIIO::ImageBuf picture(source.bytes ? source.name : source.path, 0, 0, nullptr, nullptr, memory.get());
    if (!picture.read(0, 0, /*force=*/true)) throw std::runtime_error("cannot read it: " + picture.geterror());
    OIIO::ImageSpec config;
    config.tile_width = config.tile_height = 64;
    config.attribute("maketx:hash", 0);             // a SHA-1 of the pixels rt does not use
    config.attribute("maketx:compute_average", 0);  // nor their average
    config.attribute("maketx:forcefloat", 0);       // the levels made in the source's type: a quarter the memory
    config.attribute("maketx:fileformatname", "tiff");
    if (!OIIO::ImageBufAlgo::make_texture(OIIO::ImageBufAlgo::MakeTxTexture, picture, target.string(), config))
        throw std::runtime_error(OIIO::geterror());
    checkWholeCopy(target);
}

}  // namespace

std::string defaultTxCache() {
    if (const char* chosen = std::getenv("RT_TX_CACHE"); chosen && *chosen) return chosen;
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return (fs::path(xdg) / "rt" / "tx").string();
    if (const char* home = std::getenv("HOME"); home && *home)
        return (fs::path(home) / ".cache" / "rt" / "tx").string();
    return "off";
}

bool txCacheOff(const std::string& txCache) { return txCache.empty() || txCache == "off"; }

std::string tiledCopy(const std::string& folder, const TextureSource& source) {
    const fs::path target = fs::path(folder) / copyName(source);
    if (fs::exists(target)) return target.string();
    std::error_code error;
    fs::create_directories(folder, error);
    if (error) throw std::runtime_error("cannot create " + folder + ": " + error.message());
    const fs::path temporary = temporaryIn(folder, target.filename().string());
    try {
        makeCopy(source, temporary);
        fs::rename(temporary, target);  // atomic: a concurrent render sees no copy or a whole one
    } catch (const std::exception& e) {
        fs::remove(temporary, error);
        throw std::runtime_error("cannot write " + target.string() + ": " + e.what());
    }
    return target.string();
}

}  // namespace rt
