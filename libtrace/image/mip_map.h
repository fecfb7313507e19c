// rt's own MIP map: an image texture's pyramid of levels and the filters that read it, as
// pbrt-v4's MIPMap and the GPUs do. OpenImageIO only decodes the picture (texture_files.cpp);
// the levels and every lookup are rt's, a few dozen instructions a texel instead of the ~2,200 of
// an OpenImageIO TextureSystem call (docs/benchmarks.md, "Textures").
//
// Texels are kept as the source stores them, 8 bits a channel for 8-bit pictures (decoded by a
// 256-entry table per lookup: sRGB for colour, linear for data), 16 bits for 16-bit pictures (as
// fractions of 65535; colour decoded after filtering), half for half-float pictures, float for
// the rest.
//
// The pyramid: level 0 is the picture; each next level halves each side, rounded down, down to
// 1 x 1 (a non-power-of-two side halves unevenly: 5, 2, 1). A coarse texel is the box filter of
// the finer texels it covers, each weighted by the share of its area inside: exact for even sides,
// and no texel lost or counted twice for odd ones. Values are averaged as stored (an 8-bit sRGB
// picture's encoded values, as maketx does), so that one pyramid serves colour and data lookups.
//
// Coordinates: (s, t) = (0, 0) is the top-left corner of the picture, (1, 1) its bottom-right;
// texel (x, y) of a w x h level has its centre at ((x + 0.5) / w, (y + 0.5) / h).
#pragma once

#include <OpenImageIO/half.h>

#include <array>
#include <cstdint>
#include <variant>
#include <vector>

#include "render/texture.h"
#include "scene/scene.h"

namespace rt {

// How a lookup filters the texels under its footprint (rt-render --texture-filter).
enum class TextureFilter {
    Nearest,      // the texel the point falls in, level 0
    Bilinear,     // the four nearest texels of level 0, weighted by distance
    Trilinear,    // bilinear on the two levels whose texels are nearest the footprint's longer side
    Anisotropic,  // trilinear probes along the footprint's longer side, the level set by its shorter
};

// The side from which levels are stored in tiles, and the tiles' side, 1 << kTileShift texels.
constexpr int kTiledSide = 256;
constexpr int kTileShift = 2;

// Stored texels of one level: width x height texels of `channels` values each. A level of at
// least kTiledSide texels a side is stored in tiles of 4 x 4 texels, tile after tile along a row
// of tiles, row of tiles after row, its sides rounded up to whole tiles (the padding is never
// read): the four texels of a bilinear probe then share one or two cache lines and one page,
// where a row-major 2048-texel level puts them two rows, 6 KB, apart. Smaller levels stay in
// cache and are stored row after row.
template <class T>
struct MipLevel {
    using Value = T;
    int width = 0, height = 0;
    int tileShift = 0;    // log2 of the tiles' side: 0 (row after row) or kTileShift
    int tilesAcross = 0;  // tiles in a row of tiles (the width, row after row)
    std::vector<T> texels;

    // Where texel (x, y) starts in `texels`, in texels (times the channels for values): the sum of
    // a part for its row and one for its column, so that a probe computes two of each for its four.
    std::size_t texel(int x, int y) const { return row(y) + column(x); }
    std::size_t row(int y) const { return tileShift ? row<kTileShift>(y) : row<0>(y); }
    std::size_t column(int x) const { return tileShift ? column<kTileShift>(x) : column<0>(x); }

    // The same for a known tileShift (Shift): shifts by constants, for the lookups' inner loop.
    template <int Shift>
    std::size_t row(int y) const {
        return (std::size_t(y >> Shift) * std::size_t(tilesAcross) << (2 * Shift)) +
               std::size_t((y & ((1 << Shift) - 1)) << Shift);
    }
    template <int Shift>
    std::size_t column(int x) const {
        return (std::size_t(x >> Shift) << (2 * Shift)) + std::size_t(x & ((1 << Shift) - 1));
    }
};

// A picture's levels in its stored type.
template <class T>
using MipLevels = std::vector<MipLevel<T>>;

// Turns a stored value into a float: 8-bit values through `table` (256 entries), 16-bit ones
// over 65535, others as they are.
struct TexelDecoding {
    const float* table = nullptr;
};

// What a lookup asks for besides its coordinates.
struct MipLookup {
    TextureFilter filter = TextureFilter::Anisotropic;
    int maxProbes = 8;  // anisotropic: the most trilinear probes along the footprint
    Texture::Wrap wrapS = Texture::Wrap::Repeat, wrapT = Texture::Wrap::Repeat;
    TexelDecoding decoding{};
    int firstChannel = 0, channels = 1;  // the stored channels to filter, at most 4
};

class MipMap {
public:
    // Takes level 0, `width` x `height` texels of `channels` (1 to 4) values, and builds the
    // coarser levels. A picture of one colour keeps one texel: every lookup is that texel.
    MipMap(int width, int height, int channels, std::vector<std::uint8_t> texels);
    MipMap(int width, int height, int channels, std::vector<std::uint16_t> texels);
    MipMap(int width, int height, int channels, std::vector<half> texels);
    MipMap(int width, int height, int channels, std::vector<float> texels);

    // The filtered channels [firstChannel, firstChannel + channels) at `at` into out[0..channels).
    void lookup(const TexCoord& at, const MipLookup& how, float* out) const;

    // Channel `channel` at (s, t) on level 0, bilinear: alpha for cut-outs, tested during traversal,
    // where rays carry no footprint.
    float bilinear(float s, float t, const MipLookup& how) const;

    int channels() const { return channels_; }
    bool storesBytes() const { return std::holds_alternative<MipLevels<std::uint8_t>>(levels_); }
    // Whether every texel's `channel` holds 1 (255 in 8 bits): an opaque alpha channel.
    bool allOne(int channel) const { return allOne_[std::size_t(channel)]; }
    // The levels' sizes, finest first.
    std::vector<std::array<int, 2>> levelSizes() const;
    // The bytes the levels take.
    std::uint64_t bytes() const;

private:
    template <class T>
    void build(int width, int height, std::vector<T> texels);

    int channels_;
    std::array<bool, 4> allOne_{};
    std::variant<MipLevels<std::uint8_t>, MipLevels<std::uint16_t>, MipLevels<half>, MipLevels<float>> levels_;
};

// The bytes a picture of `width` x `height` texels of `bytesPerTexel` takes with its coarser levels.
std::uint64_t mipMapBytes(int width, int height, std::uint64_t bytesPerTexel);

// The sRGB transfer function, inverted (IEC 61966-2-1): for 16-bit pictures, whose filtered
// values are decoded after each lookup.
float srgbToLinear(float v);

// The 256-entry tables for 8-bit values: srgbToLinear, and value / 255.
const float* srgbByteTable();
const float* linearByteTable();

}  // namespace rt
