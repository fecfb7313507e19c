#include "image/mip_map.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <type_traits>

namespace rt {

namespace {

// ---- Stored values ---------------------------------------------------------------------------

float decode(std::uint8_t v, const TexelDecoding& d) { return d.table[v]; }
float decode(std::uint16_t v, const TexelDecoding&) { return float(v) / 65535; }
float decode(half v, const TexelDecoding&) { return float(v); }
float decode(float v, const TexelDecoding&) { return v; }

// Four floats in one SSE register (GCC's and clang's vector extension): a texel's channels, or a
// bilinear probe's four weights. Each lane adds and multiplies as a float does, so sums over lanes
// have the bits of the same sums channel after channel.
using Lanes = float __attribute__((vector_size(16)));

// Channels [0, N) of the texel at `values`, decoded; the lanes beyond N zero. Built in one
// expression, which the compiler makes two or three shuffles (lanes set one by one go through memory).
template <int N, class T>
Lanes decoded(const T* values, const TexelDecoding& d) {
    const auto channel = [&](int c) { return c < N ? decode(values[c], d) : 0.0f; };
    return Lanes{channel(0), channel(1), channel(2), channel(3)};
}

// A box-filtered value back in the stored type (integers rounded to the nearest).
template <class T>
T stored(float v) {
    if constexpr (std::is_integral_v<T>)
        return T(std::clamp(v, 0.0f, float(std::numeric_limits<T>::max())) + 0.5f);
    else
        return T(v);
}

template <class T>
bool isOne(T v) {
    if constexpr (std::is_integral_v<T>)
        return v == std::numeric_limits<T>::max();
    else
        return float(v) >= 1;
}

// ---- The pyramid -----------------------------------------------------------------------------

// The finer texels one coarse texel covers along an axis, and the share of each.
struct BoxTaps {
    int first = 0;
    std::vector<float> weights;
};

// The box filter from `fine` texels down to `coarse` along an axis: coarse texel i covers
// [i * r, (i + 1) * r) of the finer ones, r = fine / coarse; each finer texel weighs the part of it
// inside, over r.
std::vector<BoxTaps> boxTaps(int fine, int coarse) {
    std::vector<BoxTaps> taps(static_cast<std::size_t>(coarse));
    const double r = double(fine) / coarse;
    for (int i = 0; i < coarse; ++i) {
        const double begin = i * r, end = (i + 1) * r;
        BoxTaps& tap = taps[std::size_t(i)];
        tap.first = int(std::floor(begin));
        for (int j = tap.first; j < fine && j < end; ++j)
            tap.weights.push_back(float((std::min<double>(j + 1, end) - std::max<double>(j, begin)) / r));
    }
    return taps;
}

// The next coarser level of `fine`: each side halved, rounded down, at least 1.
template <class T>
MipLevel<T> halved(const MipLevel<T>& fine, int channels) {
    MipLevel<T> coarse{std::max(1, fine.width / 2), std::max(1, fine.height / 2), 0, 0, {}};
    coarse.tilesAcross = coarse.width;
    coarse.texels.resize(std::size_t(coarse.width) * std::size_t(coarse.height) * std::size_t(channels));
    const std::vector<BoxTaps> across = boxTaps(fine.width, coarse.width), down = boxTaps(fine.height, coarse.height);
    const std::size_t fineRow = std::size_t(fine.width) * std::size_t(channels);
    // Rows are independent: the same texels for any number of threads.
#pragma omp parallel for schedule(static)
    for (int y = 0; y < coarse.height; ++y) {
        std::vector<float> row(fineRow, 0.0f);  // the finer rows under this one, filtered down
        const BoxTaps& rows = down[std::size_t(y)];
        for (std::size_t k = 0; k < rows.weights.size(); ++k) {
            const T* src = fine.texels.data() + std::size_t(rows.first + int(k)) * fineRow;
            for (std::size_t i = 0; i < fineRow; ++i) row[i] += rows.weights[k] * float(src[i]);
        }
        T* out = coarse.texels.data() + std::size_t(y) * std::size_t(coarse.width) * std::size_t(channels);
        for (int x = 0; x < coarse.width; ++x) {
            const BoxTaps& cols = across[std::size_t(x)];
            for (int c = 0; c < channels; ++c) {
                float sum = 0;
                for (std::size_t k = 0; k < cols.weights.size(); ++k)
                    sum += cols.weights[k] * row[std::size_t(cols.first + int(k)) * std::size_t(channels) + c];
                out[std::size_t(x) * std::size_t(channels) + std::size_t(c)] = stored<T>(sum);
            }
        }
    }
    return coarse;
}

// A side of a tiled level rounded up to whole tiles.
int wholeTiles(int side) { return (side + (1 << kTileShift) - 1) >> kTileShift << kTileShift; }

// `level`, stored row after row, in tiles of 4 x 4 texels (MipLevel): the same texels. Rows are
// independent: the same texels for any number of threads.
template <class T>
MipLevel<T> tiled(const MipLevel<T>& level, int channels) {
    MipLevel<T> out{level.width, level.height, kTileShift, wholeTiles(level.width) >> kTileShift, {}};
    const std::size_t n = std::size_t(channels);
    out.texels.resize(std::size_t(wholeTiles(level.width)) * std::size_t(wholeTiles(level.height)) * n);
#pragma omp parallel for schedule(static)
    for (int y = 0; y < level.height; ++y)
        for (int x = 0; x < level.width; ++x)
            std::copy_n(&level.texels[level.texel(x, y) * n], n, &out.texels[out.texel(x, y) * n]);
    return out;
}

// ---- Lookups ---------------------------------------------------------------------------------

// floor(v) as an integer, for |v| < 2^31: the truncation, one less where it went up. x86-64's
// baseline (SSE2) has no rounding instruction, and std::floor without one is a dozen.
inline int floorToInt(float v) {
    const int i = int(v);
    return i - int(float(i) > v);
}

// A coordinate brought into the range its wrap mode repeats in (a period of 1, or 2 mirrored),
// so that texel indices stay small; NaN and infinities read the first texel.
[[gnu::always_inline]] inline float reduced(float s, Texture::Wrap wrap) {
    if (!(std::abs(s) < 1e7f)) return 0;
    switch (wrap) {
        case Texture::Wrap::Clamp:
            return std::clamp(s, -1.0f, 2.0f);
        case Texture::Wrap::Mirror:
            return s - 2 * float(floorToInt(s * 0.5f));
        case Texture::Wrap::Repeat:
            break;
    }
    return s - float(floorToInt(s));
}

// Texel index i of a side of n texels wrapped into [0, n); i within a period of `reduced`'s range
// and one beyond.
[[gnu::noinline]] int wrappedIndex(int i, int n, Texture::Wrap wrap) {
    switch (wrap) {
        case Texture::Wrap::Clamp:
            return std::clamp(i, 0, n - 1);
        case Texture::Wrap::Mirror: {
            int m = i % (2 * n);
            if (m < 0) m += 2 * n;
            return m < n ? m : 2 * n - 1 - m;
        }
        case Texture::Wrap::Repeat:
            break;
    }
    const int m = i % n;
    return m < 0 ? m + n : m;
}

// The same, the texels inside inline (nearly every one), the wrapping of those outside called.
inline int wrapped(int i, int n, Texture::Wrap wrap) {
    return unsigned(i) < unsigned(n) ? i : wrappedIndex(i, n, wrap);
}

// Texels i and i + 1 of a side of n texels, wrapped: the two columns (or rows) a bilinear probe
// reads. One test for the pair: both inside for every probe but those at the picture's edges.
struct TexelPair {
    int first, second;
};

inline TexelPair texelPair(int i, int n, Texture::Wrap wrap) {
    if (unsigned(i) < unsigned(n - 1)) return {i, i + 1};
    return {wrappedIndex(i, n, wrap), wrappedIndex(i + 1, n, wrap)};
}

// The footprint of a lookup in level 0's texels: its two axes (one pixel's step right and down).
struct Footprint {
    float ax, ay, bx, by;  // the axes, in texels
    float a2, b2;          // their squared lengths
};

Footprint footprint(const TexCoord& at, int width, int height) {
    const float w = float(width), h = float(height);
    Footprint f{at.dsdx * w, at.dtdx * h, at.dsdy * w, at.dtdy * h, 0, 0};
    f.a2 = f.ax * f.ax + f.ay * f.ay;
    f.b2 = f.bx * f.bx + f.by * f.by;
    return f;
}

// The level whose texels are `texels` level-0 texels wide (0 the finest).
float levelOf(float texels) { return std::log2(std::max(texels, 1e-8f)); }

// A picture of one colour, kept as its one texel (MipMap::build).
template <class T>
bool oneColour(const MipLevels<T>& levels) {
    return levels.size() == 1 && levels[0].width == 1 && levels[0].height == 1;
}

// The filters of one lookup, over the levels of one picture: N channels (1 to 4) from
// how.firstChannel of texels `channels` values wide. Filtered values are summed texel after
// texel in a fixed order (the same bits whatever the layout of the texels), the N channels in the
// lanes of one register (Lanes), which stays in a register from the first probe to the last.
template <class T, int N>
class Sampler {
public:
    Sampler(const MipLevels<T>& levels, int channels, const MipLookup& how)
        : levels_(levels), stride_(std::size_t(channels)), how_(how) {}

    // The filtered channels into out[0..N).
    void filtered(const TexCoord& at, float* out) const {
        const Lanes sum = filtered(at);
        for (int c = 0; c < N; ++c) out[c] = sum[c];
    }

    // Level 0 bilinear, or the one texel of a picture of one colour.
    Lanes finest(float s, float t) const {
        Lanes sum{};
        if (oneColour(levels_))
            add(levels_[0], 0, 1, sum);
        else
            bilinear(levels_[0], s, t, 1, sum);
        return sum;
    }

private:
    Lanes filtered(const TexCoord& at) const {
        if (oneColour(levels_) || how_.filter == TextureFilter::Bilinear) return finest(at.s, at.t);
        Lanes sum{};
        if (how_.filter == TextureFilter::Nearest) {
            nearest(at.s, at.t, sum);
            return sum;
        }
        const Footprint f = footprint(at, levels_[0].width, levels_[0].height);
        // A footprint of at most a texel (none at all: the path tracer's rays after the camera)
        // puts both filters that take one on level 0 or finer, in one probe: level 0 bilinear, as
        // they would give it, without their square roots and logarithm.
        if (f.a2 <= 1 && f.b2 <= 1) return finest(at.s, at.t);
        if (how_.filter == TextureFilter::Trilinear)
            trilinear(at.s, at.t, levelOf(std::sqrt(std::max(f.a2, f.b2))), 1, sum);
        else
            anisotropic(at, f, sum);
        return sum;
    }

    void nearest(float s, float t, Lanes& sum) const {
        const MipLevel<T>& level = levels_[0];
        const int x = wrapped(floorToInt(reduced(s, how_.wrapS) * float(level.width)), level.width, how_.wrapS);
        const int y = wrapped(floorToInt(reduced(t, how_.wrapT) * float(level.height)), level.height, how_.wrapT);
        add(level, level.texel(x, y), 1, sum);
    }

    // The four texels around (s, t) on `level`, weighted by distance, times `weight`, added to `sum`.
    void bilinear(const MipLevel<T>& level, float s, float t, float weight, Lanes& sum) const {
        bilinearReduced(level, reduced(s, how_.wrapS), reduced(t, how_.wrapT), weight, sum);
    }

    // The same at (s, t) reduced by each axis' wrap mode (`reduced`), as a trilinear probe reduces
    // them once for its two levels. The four texels' places and weights are computed once for all
    // channels (two rows and two columns; the four weights in one register), each texel's channels
    // decoded into one register and added, weighted, in one multiply and one add.
    void bilinearReduced(const MipLevel<T>& level, float s, float t, float weight, Lanes& sum) const {
        const float x = s * float(level.width) - 0.5f;
        const float y = t * float(level.height) - 0.5f;
        const int x0 = floorToInt(x), y0 = floorToInt(y);
        const float fx = x - float(x0), fy = y - float(y0);
        const TexelPair xs = texelPair(x0, level.width, how_.wrapS), ys = texelPair(y0, level.height, how_.wrapT);
        const Corners at = level.tileShift ? corners<kTileShift>(level, xs, ys) : corners<0>(level, xs, ys);
        const Lanes w = weight * Lanes{1 - fx, fx, 1 - fx, fx} * Lanes{1 - fy, 1 - fy, fy, fy};
        const T* texels = level.texels.data() + std::size_t(how_.firstChannel);
        Lanes v = sum;  // in a register: 8-bit texels may alias `sum`, so each add would store it
        for (int k = 0; k < 4; ++k) v += w[k] * decoded<N>(texels + at[std::size_t(k)] * stride_, how_.decoding);
        sum = v;
    }

    // Where the four texels of a probe start in a level of tiles of 1 << Shift texels a side,
    // in texels: (first, first), (second, first), (first, second), (second, second).
    using Corners = std::array<std::size_t, 4>;
    template <int Shift>
    static Corners corners(const MipLevel<T>& level, TexelPair xs, TexelPair ys) {
        const std::size_t ra = level.template row<Shift>(ys.first), rb = level.template row<Shift>(ys.second);
        const std::size_t ca = level.template column<Shift>(xs.first), cb = level.template column<Shift>(xs.second);
        return {ra + ca, ra + cb, rb + ca, rb + cb};
    }

    // Bilinear on the two levels around `level` (fractional: 0 the finest), blended; at or beyond
    // either end, the one level there. The two probes share the coordinates' wrapping and the sum.
    void trilinear(float s, float t, float level, float weight, Lanes& sum) const {
        const int last = int(levels_.size()) - 1;
        if (!(level > 0)) return bilinear(levels_[0], s, t, weight, sum);  // NaN too
        if (level >= float(last)) return bilinear(levels_[std::size_t(last)], s, t, weight, sum);
        const int fine = int(level);
        const float f = level - float(fine);
        const float rs = reduced(s, how_.wrapS), rt = reduced(t, how_.wrapT);
        bilinearReduced(levels_[std::size_t(fine)], rs, rt, weight * (1 - f), sum);
        bilinearReduced(levels_[std::size_t(fine) + 1], rs, rt, weight * f, sum);
    }

    // Up to how.maxProbes trilinear probes spread evenly along the footprint's longer axis, on the
    // level its length over the probes sets (not finer than the shorter axis calls for when the
    // probes do not reach it: the footprint is then widened across, as a GPU's anisotropic filter
    // does).
    void anisotropic(const TexCoord& at, const Footprint& f, Lanes& sum) const {
        const bool aLonger = f.a2 >= f.b2;
        const float major = std::sqrt(aLonger ? f.a2 : f.b2), minor = std::sqrt(aLonger ? f.b2 : f.a2);
        // As many probes as the footprint is longer than wide, and no more than it is texels long
        // (a magnified texture is one bilinear probe however thin the footprint). Rounded, not up:
        // a footprint a shade longer one way than the other (a quad seen nearly head-on) is one
        // probe, not two half a texel apart.
        const float ratio = std::min(major / std::max(minor, 1e-8f), major);
        const int probes = !(ratio < float(how_.maxProbes)) ? how_.maxProbes : std::max(1, int(ratio + 0.5f));
        if (probes == 1) return trilinear(at.s, at.t, levelOf(major), 1, sum);
        const float level = levelOf(major / float(probes));
        const float ds = aLonger ? at.dsdx : at.dsdy, dt = aLonger ? at.dtdx : at.dtdy;
        const float weight = 1.0f / float(probes);
        for (int i = 0; i < probes; ++i) {
            const float along = (float(i) + 0.5f) / float(probes) - 0.5f;
            trilinear(at.s + along * ds, at.t + along * dt, level, weight, sum);
        }
    }

    // The channels of texel number `texel` of `level`, times `weight`, added to `sum`.
    void add(const MipLevel<T>& level, std::size_t texel, float weight, Lanes& sum) const {
        sum +=
            weight * decoded<N>(level.texels.data() + texel * stride_ + std::size_t(how_.firstChannel), how_.decoding);
    }

    const MipLevels<T>& levels_;
    std::size_t stride_;
    const MipLookup& how_;
};

// Calls f(sampler) with the Sampler of how.channels channels.
template <class T, class F>
void withSampler(const MipLevels<T>& levels, int channels, const MipLookup& how, F f) {
    switch (how.channels) {
        case 1:
            return f(Sampler<T, 1>(levels, channels, how));
        case 2:
            return f(Sampler<T, 2>(levels, channels, how));
        case 3:
            return f(Sampler<T, 3>(levels, channels, how));
        default:
            return f(Sampler<T, 4>(levels, channels, how));
    }
}

std::array<float, 256> byteTable(float (*f)(float)) {
    std::array<float, 256> table{};
    for (int i = 0; i < 256; ++i) table[std::size_t(i)] = f(float(i) / 255);
    return table;
}

}  // namespace

MipMap::MipMap(int width, int height, int channels, std::vector<std::uint8_t> texels) : channels_(channels) {
    build(width, height, std::move(texels));
}

MipMap::MipMap(int width, int height, int channels, std::vector<std::uint16_t> texels) : channels_(channels) {
    build(width, height, std::move(texels));
}

MipMap::MipMap(int width, int height, int channels, std::vector<half> texels) : channels_(channels) {
    build(width, height, std::move(texels));
}

MipMap::MipMap(int width, int height, int channels, std::vector<float> texels) : channels_(channels) {
    build(width, height, std::move(texels));
}

template <class T>
void MipMap::build(int width, int height, std::vector<T> texels) {
    const std::size_t n = std::size_t(channels_);
    bool constant = true;
    for (std::size_t i = n; i < texels.size() && constant; i += n)
        constant = std::memcmp(&texels[i], &texels[0], n * sizeof(T)) == 0;
    for (std::size_t c = 0; c < n; ++c) {
        bool one = true;
        for (std::size_t i = c; i < texels.size() && one; i += n) one = isOne(texels[i]);
        allOne_[c] = one;
    }
    MipLevels<T> levels;
    if (constant) {
        texels.resize(n);
        levels.push_back({1, 1, 0, 1, std::move(texels)});
    } else {
        levels.push_back({width, height, 0, width, std::move(texels)});
        while (levels.back().width > 1 || levels.back().height > 1) levels.push_back(halved(levels.back(), channels_));
        for (MipLevel<T>& level : levels)
            if (level.width >= kTiledSide && level.height >= kTiledSide) level = tiled(level, channels_);
    }
    levels_ = std::move(levels);
}

void MipMap::lookup(const TexCoord& at, const MipLookup& how, float* out) const {
    std::visit([&](const auto& levels) { withSampler(levels, channels_, how, [&](auto f) { f.filtered(at, out); }); },
               levels_);
}

float MipMap::bilinear(float s, float t, const MipLookup& how) const {
    return std::visit(
        [&](const auto& levels) {
            using T = typename std::decay_t<decltype(levels)>::value_type::Value;
            return Sampler<T, 1>(levels, channels_, how).finest(s, t)[0];
        },
        levels_);
}

std::vector<std::array<int, 2>> MipMap::levelSizes() const {
    std::vector<std::array<int, 2>> sizes;
    std::visit(
        [&](const auto& levels) {
            for (const auto& level : levels) sizes.push_back({level.width, level.height});
        },
        levels_);
    return sizes;
}

std::uint64_t MipMap::bytes() const {
    std::uint64_t total = 0;
    std::visit(
        [&](const auto& levels) {
            for (const auto& level : levels) total += level.texels.size() * sizeof(level.texels[0]);
        },
        levels_);
    return total;
}

std::uint64_t mipMapBytes(int width, int height, std::uint64_t bytesPerTexel) {
    std::uint64_t total = 0;
    for (;;) {
        const bool tiled = width >= kTiledSide && height >= kTiledSide;  // sides padded to whole tiles
        total += std::uint64_t(tiled ? wholeTiles(width) : width) * std::uint64_t(tiled ? wholeTiles(height) : height) *
                 bytesPerTexel;
        if (width == 1 && height == 1) return total;
        width = std::max(1, width / 2);
        height = std::max(1, height / 2);
    }
}

float srgbToLinear(float v) { return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f); }

const float* srgbByteTable() {
    static const std::array<float, 256> table = byteTable(srgbToLinear);
    return table.data();
}

const float* linearByteTable() {
    static const std::array<float, 256> table = byteTable([](float v) { return v; });
    return table.data();
}

}  // namespace rt
