// The one check every image passes before OpenImageIO reads its pixels (image/image_header.h),
// then OpenImageIO's ImageInput on what passed: every subimage's and MIP level's header, and the
// first scanline or tile of the finest level, in the file's own pixel type. The input's first
// byte picks the file's extension (its low three bits) and what the path is (the next two): the
// rest of the input as a file, a FIFO, a link to /dev/zero or to /dev/urandom (the bytes unused),
// or the bytes as a picture embedded in a model. A FIFO must be refused without blocking, a
// device without being read: either hangs the replay, which its timeout reports.
#include <OpenImageIO/imageio.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <filesystem>
#include <memory>
#include <vector>

#include "fuzz_input.h"
#include "image/image_header.h"

namespace {

enum class PathKind { File, Fifo, LinkToZero, LinkToRandom, Embedded };

// `name` in the target's private folder as `kind` says, with `bytes` in it if a file.
std::string placeInput(PathKind kind, const std::uint8_t* bytes, std::size_t size, const std::string& name) {
    const std::string path = rt::fuzz::writeInputFile(bytes, size, name);
    if (kind == PathKind::File) return path;
    std::filesystem::remove(path);
    if (kind == PathKind::Fifo)
        ::mkfifo(path.c_str(), 0600);
    else
        std::filesystem::create_symlink(kind == PathKind::LinkToZero ? "/dev/zero" : "/dev/urandom", path);
    return path;
}

// Reads every header of the file that passed the check, and its first scanline or tile.
void readPassedImage(const std::string& path) {
    const std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path);
    if (!in) return;
    for (int subimage = 0; in->seek_subimage(subimage, 0); ++subimage)
        for (int level = 0; in->seek_subimage(subimage, level); ++level) (void)in->spec();
    if (!in->seek_subimage(0, 0)) return;
    const OIIO::ImageSpec& spec = in->spec();
    std::vector<unsigned char> pixels(spec.tile_width > 0 ? spec.tile_bytes(true) : spec.scanline_bytes(true));
    if (spec.tile_width > 0)
        in->read_tile(spec.x, spec.y, spec.z, OIIO::TypeUnknown, pixels.data());
    else
        in->read_scanline(spec.y, spec.z, OIIO::TypeUnknown, pixels.data());
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static constexpr std::array<const char*, 8> kExtensions{".png", ".jpg", ".exr", ".tif",
                                                            ".tga", ".hdr", ".bmp", ".webp"};
    if (size == 0) return 0;
    const PathKind kind = PathKind(std::min((data[0] >> 3) & 7, int(PathKind::Embedded)));
    const std::string name = std::string("image") + kExtensions[data[0] & 7];
    if (kind == PathKind::Embedded) {
        rt::checkImageHeader(std::vector<std::uint8_t>(data + 1, data + size), name);
        return 0;
    }
    const std::string path = placeInput(kind, data + 1, size - 1, name);
    const rt::ImageHeaderCheck check = rt::checkImageHeader(path);
    if (!check.refusal && !check.unreadable) readPassedImage(path);
    // The next input's file is written at the same path: writing to a FIFO would wait for a reader.
    if (kind != PathKind::File) std::filesystem::remove(path);
    return 0;
}
