#include "image/tiled_textures.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/hash.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <system_error>
#include <utility>
#include <vector>

#include "os/atomic_file.h"

namespace rt {

namespace fs = std::filesystem;

namespace {

// What a copy is made with; part of its name, so that changing anything here makes new copies.
// Tiles of 64 x 64 texels, uncompressed (inflating zip tiles took 8-15 % of a textured render,
// docs/benchmarks.md), MIP levels by make_texture's bilinear resampling, in the source's own pixel
// type (8-bit stays 8-bit: sRGB decoding is done after filtering, as before). A picture of one
// colour becomes one small level marked with it (oiio:ConstantColor), whose lookups then need no
// filter (image/texture_files.cpp).
constexpr const char* kCopySettings =
    "rt tx 2: 64x64 uncompressed, constant colour marked, OpenImageIO " OIIO_VERSION_STRING;

std::string hex(std::uint64_t v) {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(v));
    return text;
}

// A hash of every byte of the file at `path`, read a mebibyte at a time: a copy is keyed by what
// its source holds, not by its name, size and time (a different picture of the same size and time,
// unpacked from an archive or given its old time with `touch -r`, rendered the old copy).
std::uint64_t contentHash(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::vector<char> chunk(std::size_t(1) << 20);
    std::vector<std::uint64_t> chunkHashes;
    while (in.read(chunk.data(), std::streamsize(chunk.size())) || in.gcount() > 0)
        chunkHashes.push_back(OIIO::farmhash::Fingerprint64(chunk.data(), std::size_t(in.gcount())));
    if (in.bad()) throw std::runtime_error("cannot read " + path);
    return OIIO::farmhash::Fingerprint64(reinterpret_cast<const char*>(chunkHashes.data()),
                                         chunkHashes.size() * sizeof(std::uint64_t));
}

// What the copy of `source` depends on, as text: the bytes of the picture and the copy's settings.
std::string identity(const TextureSource& source) {
    const std::uint64_t bytes =
        source.bytes
            ? OIIO::farmhash::Fingerprint64(reinterpret_cast<const char*>(source.bytes->data()), source.bytes->size())
            : contentHash(source.path);
    return std::string(kCopySettings) + "\nbytes " + hex(bytes);
}

// The copy's file name: the source's stem, for people looking in the folder, and the hash. The
// cache removes no file but those named so.
std::string copyName(const TextureSource& source) {
    const std::string stem = fs::path(source.bytes ? source.name : source.path).stem().string();
    return stem + "-" + hex(OIIO::farmhash::Fingerprint64(identity(source))) + ".tx";
}

bool isCopyName(const std::string& name) {
    constexpr std::size_t kTail = 1 + 16 + 3;  // "-", the hash's 16 hex digits, ".tx"
    if (name.size() <= kTail || !name.ends_with(".tx") || name[name.size() - kTail] != '-') return false;
    const std::string hash = name.substr(name.size() - kTail + 1, 16);
    return hash.find_first_not_of("0123456789abcdef") == std::string::npos;
}

// The cache's own folder inside the folder it is given, which may hold a user's files (maketx
// output, anything named *.tx): only there, and only once the marker says rt made it, are files
// removed.
constexpr const char* kMarker = ".rt-tx-cache";
constexpr const char* kMarkerText =
    "Tiled, MIP-mapped copies of textures made by rt-render (docs/rt-render.md, \"Texture copies\").\n"
    "rt-render removes the least recently used *-<hash>.tx files here, and only those.\n";

// `folder`'s own subfolder, created with its marker if missing; throws if it cannot be.
fs::path ownFolder(const std::string& folder) {
    const fs::path own = fs::path(folder) / kTxCopiesFolder;
    std::error_code error;
    fs::create_directories(own, error);
    if (error) throw std::runtime_error("cannot create " + own.string() + ": " + error.message());
    if (!fs::exists(own / kMarker, error)) std::ofstream(own / kMarker) << kMarkerText;  // only its presence counts
    return own;
}

// Temporaries of makers that no longer run on this machine and in which nothing changed for this
// long are removed: a folder shared by several machines holds other machines' live ones too, and
// their process ids say nothing here. No copy takes that long to make.
constexpr std::chrono::minutes kStaleAfter{10};

// The copy at `path`, locked shared (the lock is what keeps other renders from removing it) and
// touched; none if there is none, or if it was removed between being opened and locked. Throws
// if it cannot be opened for another reason (no more file descriptors: one is held per copy).
std::optional<TiledCopy> openCopy(const fs::path& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0 && errno != ENOENT && errno != ENOTDIR)  // ENOTDIR: a folder under a file, said below
        throw std::runtime_error("cannot open " + path.string() + ": " + std::strerror(errno));
    if (fd < 0) return std::nullopt;
    struct stat st {};
    // A file system without locks: the copy is used all the same, unprotected.
    const bool locked = ::flock(fd, LOCK_SH) == 0;
    if (locked && (::fstat(fd, &st) != 0 || st.st_nlink == 0)) {
        ::close(fd);
        return std::nullopt;
    }
    // The access time ranks the copies for removal (the modification time says when it was made).
    // It fails on another user's copy without write access: that copy is used all the same.
    const timespec useNow[2] = {{0, UTIME_NOW}, {0, UTIME_OMIT}};
    ::futimens(fd, useNow);
    return TiledCopy(path.string(), fd);
}

struct CachedCopy {
    fs::path path;
    std::uintmax_t bytes = 0;
    timespec lastUse{};
};

// The copies in `folder` (not the hidden temporaries and lock file), least recently used first.
std::vector<CachedCopy> copiesIn(const fs::path& folder) {
    std::vector<CachedCopy> copies;
    std::error_code ec;
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        struct stat st {};
        if (!isCopyName(name) || ::stat(it->path().c_str(), &st) != 0 || !S_ISREG(st.st_mode)) continue;
        copies.push_back({it->path(), std::uintmax_t(st.st_size), st.st_atim});
    }
    std::sort(copies.begin(), copies.end(), [](const CachedCopy& a, const CachedCopy& b) {
        return std::pair(a.lastUse.tv_sec, a.lastUse.tv_nsec) < std::pair(b.lastUse.tv_sec, b.lastUse.tv_nsec);
    });
    return copies;
}

// Removes the copy at `path` unless a render uses it (holds a shared lock on it); true if removed.
// A render that opened it just before waits for this lock, then sees it unlinked and makes it again.
bool removeUnlessInUse(const fs::path& path) {
    int fd = ::open(path.c_str(), O_RDWR | O_CLOEXEC);  // for writing: NFS locks exclusively only so
    if (fd < 0) fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return false;
    const bool removed = ::flock(fd, LOCK_EX | LOCK_NB) == 0 && ::unlink(path.c_str()) == 0;
    ::close(fd);
    return removed;
}

// Removes the least recently used copies in `folder` until they and `incoming` more bytes fit in
// `maxBytes`, or none but copies in use are left; none in a folder without the marker.
void makeRoom(const fs::path& folder, std::uintmax_t incoming, std::uint64_t maxBytes) {
    std::error_code error;
    if (!fs::is_regular_file(folder / kMarker, error)) return;
    const std::vector<CachedCopy> copies = copiesIn(folder);
    std::uintmax_t total = incoming;
    for (const CachedCopy& c : copies) total += c.bytes;
    for (const CachedCopy& c : copies) {
        if (total <= maxBytes) return;
        if (removeUnlessInUse(c.path)) total -= c.bytes;
    }
}

// The bytes a level's uncompressed tiles take in the file.
std::uint64_t tileBytes(const OIIO::ImageSpec& level) {
    const auto tiles = [](int size, int tile) { return std::uint64_t((size + tile - 1) / tile); };
    return tiles(level.width, level.tile_width) * tiles(level.height, level.tile_height) *
           std::uint64_t(level.tile_width) * std::uint64_t(level.tile_height) * level.pixel_bytes();
}

// Throws unless `copy` reads back as a tiled file with every MIP level down to 1 x 1, each level's
// tiles within the file: OpenImageIO's writers can report success for a file a full disk cut
// short, and a copy cut short (or damaged later) would be read by every later render.
void checkWholeCopy(const fs::path& copy) {
    auto in = OIIO::ImageInput::open(copy.string());
    if (!in) throw std::runtime_error("the copy does not read back: " + OIIO::geterror());
    const OIIO::ImageSpec top = in->spec(0, 0);
    int levels = 0;
    std::uint64_t pixelBytes = 0;
    for (; in->seek_subimage(0, levels); ++levels)
        if (in->spec().tile_width > 0) pixelBytes += tileBytes(in->spec());
    const int expected = 1 + int(std::floor(std::log2(std::max(top.width, top.height))));
    if (top.tile_width == 0 || levels < expected)
        throw std::runtime_error("the copy is incomplete (" + std::to_string(levels) + " of " +
                                 std::to_string(expected) + " MIP levels)");
    if (fs::file_size(copy) < pixelBytes)
        throw std::runtime_error("the copy is cut short (" + std::to_string(fs::file_size(copy)) + " bytes, its " +
                                 std::to_string(pixelBytes) + " bytes of tiles)");
}

// Writes the tiled, MIP-mapped texture of `source` to `target`; throws saying why it cannot.
void makeCopy(const TextureSource& source, const std::string& target) {
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
    config.attribute("maketx:constant_color_detect", 1);
    config.attribute("compression", "none");
    // OpenImageIO believes a file's oiio:ConstantColor only where its Software tag says OpenImageIO made it.
    picture.specmod().attribute("Software", std::string("OpenImageIO ") + OIIO_VERSION_STRING + " : " + kCopySettings);
    if (!OIIO::ImageBufAlgo::make_texture(OIIO::ImageBufAlgo::MakeTxTexture, picture, target, config))
        throw std::runtime_error(OIIO::geterror());
    checkWholeCopy(target);
}

// The copy at `target` if it is there and reads back whole; one that does not is removed (unless a
// render uses it), to be made again.
std::optional<TiledCopy> wholeCopy(const fs::path& target) {
    std::optional<TiledCopy> existing = openCopy(target);
    if (!existing) return std::nullopt;
    try {
        checkWholeCopy(target);
        return existing;
    } catch (const std::runtime_error&) {
        existing.reset();
        removeUnlessInUse(target);
        return std::nullopt;
    }
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

TiledCopy::~TiledCopy() {
    if (fd_ >= 0) ::close(fd_);  // releases the lock
}

TiledCopy tiledCopy(const std::string& folder, const TextureSource& source, std::uint64_t maxBytes,
                    const std::function<void()>& beforeMaking) {
    const fs::path own = ownFolder(folder);
    const fs::path target = own / copyName(source);
    if (std::optional<TiledCopy> existing = wholeCopy(target)) return std::move(*existing);
    if (beforeMaking) beforeMaking();
    removeStaleTemporariesIn(own.string(), kStaleAfter);
    try {
        // make_texture writes a temporary of its own beside the name it is given: both in here.
        const TemporaryFolder temporary(target.string());
        makeCopy(source, temporary.file());
        const ExclusiveLock turn((own / ".lock").string(), own.string());
        // Another render may have added the same copy meanwhile: it is used, this one dropped.
        if (std::optional<TiledCopy> theirs = wholeCopy(target)) return std::move(*theirs);
        makeRoom(own, fs::file_size(temporary.file()), maxBytes);
        temporary.commit();
        if (std::optional<TiledCopy> ours = openCopy(target)) return std::move(*ours);
        throw std::runtime_error("it is gone after being written");
    } catch (const std::exception& e) {
        throw std::runtime_error("cannot write " + target.string() + ": " + e.what());
    }
}

}  // namespace rt
