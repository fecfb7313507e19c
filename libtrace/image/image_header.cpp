#include "image/image_header.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <memory>

#include "image/exr_header.h"

namespace rt {

namespace {

// What a file that is not a regular one is, for the refusal.
std::string fileKind(mode_t mode) {
    if (S_ISFIFO(mode)) return "a FIFO";
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISDIR(mode)) return "a folder";
    if (S_ISSOCK(mode)) return "a socket";
    return "not a file";
}

// An open file descriptor, closed when it goes.
class FileDescriptor {
public:
    explicit FileDescriptor(int fd) : fd_(fd) {}
    FileDescriptor(const FileDescriptor&) = delete;
    FileDescriptor& operator=(const FileDescriptor&) = delete;
    ~FileDescriptor() {
        if (fd_ >= 0) ::close(fd_);
    }
    int get() const { return fd_; }

private:
    int fd_;
};

std::string gibibytes(double bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f GiB", bytes / double(std::uint64_t(1) << 30));
    return text;
}

// Pixels as stored or as displayed, whichever is more, in the file's own pixel type.
double decodedBytes(const OIIO::ImageSpec& spec) {
    const double pixels = std::max(double(spec.width) * spec.height, double(spec.full_width) * spec.full_height);
    return pixels * std::max(spec.depth, 1) * spec.nchannels * spec.format.size();
}

// The refusal of a header that declares no pixels or more than kMaxDecodedImageBytes of them.
std::optional<std::string> sizeRefusal(const OIIO::ImageSpec& spec) {
    std::string size = std::to_string(spec.width) + " x " + std::to_string(spec.height) + " pixels";
    if (spec.full_width != spec.width || spec.full_height != spec.height)
        size += " displayed at " + std::to_string(spec.full_width) + " x " + std::to_string(spec.full_height);
    const std::string channels = " of " + std::to_string(spec.nchannels) + " channels";
    if (spec.width < 1 || spec.height < 1 || spec.depth < 1 || spec.nchannels < 1)
        return "is " + size + channels + ": no pixels";
    const double bytes = decodedBytes(spec);
    const std::string limit = ", more than the " + gibibytes(double(kMaxDecodedImageBytes)) + " an image may take";
    if (bytes > double(kMaxDecodedImageBytes))
        return "is " + size + channels + ", " + gibibytes(bytes) + " decoded" + limit;
    // A tile is decoded whole, whatever the image's size: a 4 x 4 TIFF may declare tiles of 65536 x 65536.
    const double tileBytes =
        double(spec.tile_width) * spec.tile_height * std::max(spec.tile_depth, 1) * spec.nchannels * spec.format.size();
    if (tileBytes > double(kMaxDecodedImageBytes))
        return "has tiles of " + std::to_string(spec.tile_width) + " x " + std::to_string(spec.tile_height) +
               " pixels, " + gibibytes(tileBytes) + " each" + limit;
    return std::nullopt;
}

// Reads the header of `name` (through `proxy` if given; the extension picks the reader) and checks it.
ImageHeaderCheck checkHeader(const std::string& name, OIIO::Filesystem::IOProxy* proxy) {
    const std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(name, nullptr, proxy);
    if (!in) return {.unreadable = OIIO::geterror()};
    const OIIO::ImageSpec spec = in->spec(0, 0);
    if (std::optional<std::string> why = sizeRefusal(spec)) return {.refusal = std::move(why)};
    return {.header = {.width = spec.width,
                       .height = spec.height,
                       .channels = spec.nchannels,
                       .channelBytes = int(spec.format.size()),
                       .floatingPoint = spec.format.is_floating_point(),
                       .decodedBytes = std::uint64_t(decodedBytes(spec))}};
}

}  // namespace

std::optional<std::string> imageFileRefusal(const std::string& path) {
    // Without blocking: a FIFO's open waits for a writer. The type is that of the file opened, so
    // a link to a device is refused too.
    const FileDescriptor file(::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY));
    struct stat st {};
    if (file.get() < 0 || ::fstat(file.get(), &st) != 0) return std::nullopt;
    if (!S_ISREG(st.st_mode)) return "is " + fileKind(st.st_mode) + ", not a regular file";
    const std::uint64_t size = std::uint64_t(st.st_size);
    const ByteReader read = [&](std::uint64_t offset, std::size_t count, std::uint8_t* out) {
        return offset <= size && count <= size - offset &&
               ::pread(file.get(), out, count, off_t(offset)) == static_cast<ssize_t>(count);
    };
    return exrHeaderProblem(read, size);
}

ImageHeaderCheck checkImageHeader(const std::string& path) {
    if (std::optional<std::string> why = imageFileRefusal(path)) return {.refusal = std::move(why)};
    // OpenImageIO opens it again by name (not every reader takes a proxy): the regular file just
    // checked, unless it was replaced in between.
    return checkHeader(path, nullptr);
}

ImageHeaderCheck checkImageHeader(const std::vector<std::uint8_t>& bytes, const std::string& name) {
    const ByteReader read = [&](std::uint64_t offset, std::size_t count, std::uint8_t* out) {
        if (offset > bytes.size() || count > bytes.size() - offset) return false;
        std::copy_n(bytes.begin() + std::ptrdiff_t(offset), count, out);
        return true;
    };
    if (std::optional<std::string> why = exrHeaderProblem(read, bytes.size())) return {.refusal = std::move(why)};
    OIIO::Filesystem::IOMemReader proxy(bytes.data(), bytes.size());
    return checkHeader(name, &proxy);
}

}  // namespace rt
