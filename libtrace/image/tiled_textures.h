// Tiled, MIP-mapped copies of image textures, made once per picture with OpenImageIO's
// ImageBufAlgo::make_texture (what maketx does) and kept in a per-user folder, as renderers'
// "auto-tx" does. OpenImageIO's TextureSystem reads such a file a 64 x 64 tile of one MIP level
// at a time, within its cache; an untiled picture (PNG, JPEG) it holds a whole level at a time,
// outside the cache's limit, and makes its coarser levels on every render (docs/benchmarks.md,
// "Textures"). A copy is named by a hash of what it is made from: every byte of the source (a file,
// or a picture embedded in a .glb or a data: URI) and the settings below, so that a changed source
// gets a new copy and an unchanged one is reused, wherever it lies. A copy that does not read back
// whole (cut short, damaged) is made again.
//
// The folder given (--tx-cache) may hold a user's files: the copies live in its subfolder
// "rt-tx-copies", which rt-render creates with a marker file, and the cache removes nothing but
// files named as it names copies, in that subfolder, under that marker.
//
// Copies are made in a temporary folder (os/atomic_file.h: removed on SIGINT and SIGTERM, and
// by a later render once stale) and renamed into the cache: renders never read half a copy. The
// cache is bounded: before a new copy is added, the least recently used copies are removed until
// all fit in the bound, except copies in use. A render holds a shared flock on every copy it uses
// until it ends; a copy is removed only under an exclusive one, so no render loses a copy it may
// still (re)open by name. Renders take turns to add copies (an exclusive flock on the folder's
// ".lock" file); two making the same copy both succeed, the second using the first's.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace rt {

// The folder rt-render keeps the copies in when --tx-cache does not say: $RT_TX_CACHE, else
// $XDG_CACHE_HOME/rt/tx, else $HOME/.cache/rt/tx; "off" when none is set. "off" (in either)
// means no copies: textures are read as they are.
std::string defaultTxCache();

// Whether `txCache` (an option's or defaultTxCache's value) turns the copies off.
bool txCacheOff(const std::string& txCache);

// The subfolder of the tx cache's folder that holds the copies (and nothing else rt-render made).
constexpr const char* kTxCopiesFolder = "rt-tx-copies";

// The bound on the tx cache's size, when --tx-cache-size does not say.
constexpr double kDefaultTxCacheMegabytes = 2048;

// A picture to copy: a file, or encoded bytes with the name whose extension tells the format.
struct TextureSource {
    std::string path;  // a file; empty for embedded bytes
    std::shared_ptr<const std::vector<std::uint8_t>> bytes;
    std::string name;  // the embedded picture's file name (its extension picks the reader)
};

// A copy in use: while this lives, it holds a shared flock on the file, so that no other render
// removes it from the cache.
class TiledCopy {
public:
    TiledCopy(std::string path, int fd) : path_(std::move(path)), fd_(fd) {}
    TiledCopy(TiledCopy&& other) noexcept : path_(std::move(other.path_)), fd_(std::exchange(other.fd_, -1)) {}
    TiledCopy& operator=(TiledCopy&&) = delete;
    TiledCopy(const TiledCopy&) = delete;
    ~TiledCopy();

    const std::string& path() const { return path_; }

private:
    std::string path_;
    int fd_;
};

// The tiled, MIP-mapped copy of `source` in `folder`'s own subfolder: the existing one, touched (its access
// time, by which copies are ranked for removal, set to now), or one made now (the folder created
// if missing), for which older copies are removed until the folder's copies fit in `maxBytes`.
// Throws std::runtime_error saying why when the copy can neither be found nor made (the folder
// not writable, the source unreadable).
// `beforeMaking`, if given, is called when a copy is to be made (not when one is found): making
// it takes about a second per megapixel, which a tool says rather than seem to hang.
TiledCopy tiledCopy(const std::string& folder, const TextureSource& source,
                    std::uint64_t maxBytes = std::uint64_t(kDefaultTxCacheMegabytes * 1024 * 1024),
                    const std::function<void()>& beforeMaking = {});

}  // namespace rt
