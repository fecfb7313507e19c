// Tiled, MIP-mapped copies of image textures, made once per picture with OpenImageIO's
// ImageBufAlgo::make_texture (what maketx does) and kept in a per-user folder, as renderers'
// "auto-tx" does. OpenImageIO's TextureSystem reads such a file a 64 x 64 tile of one MIP level
// at a time, within its cache; an untiled picture (PNG, JPEG) it holds a whole level at a time,
// outside the cache's limit, and makes its coarser levels on every render (docs/benchmarks.md,
// "Textures"). A copy is named by a hash of what it is made from: the source's absolute path,
// size and modification time (or, for a picture embedded in a .glb or a data: URI, its bytes)
// and the settings below, so that a changed source gets a new copy and an unchanged one is
// reused. Copies are written under a temporary name and renamed: concurrent renders never read
// half a file.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rt {

// The folder rt-render keeps the copies in when --tx-cache does not say: $RT_TX_CACHE, else
// $XDG_CACHE_HOME/rt/tx, else $HOME/.cache/rt/tx; "off" when none is set. "off" (in either)
// means no copies: textures are read as they are.
std::string defaultTxCache();

// Whether `txCache` (an option's or defaultTxCache's value) turns the copies off.
bool txCacheOff(const std::string& txCache);

// A picture to copy: a file, or encoded bytes with the name whose extension tells the format.
struct TextureSource {
    std::string path;  // a file; empty for embedded bytes
    std::shared_ptr<const std::vector<std::uint8_t>> bytes;
    std::string name;  // the embedded picture's file name (its extension picks the reader)
};

// The tiled, MIP-mapped copy of `source` in `folder`: the path of the existing one, or of one
// made now (the folder created if missing). Throws std::runtime_error saying why when the copy
// can neither be found nor made (the folder not writable, the source unreadable).
std::string tiledCopy(const std::string& folder, const TextureSource& source);

}  // namespace rt
