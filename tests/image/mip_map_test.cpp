// rt's MIP map (libtrace/image/mip_map.*) against analytic answers: the box-filtered levels of
// non-power-of-two pictures, bilinear weights, wrap modes, and a checker seen at a known footprint.
#include "image/mip_map.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

using namespace rt;

namespace {

// A w x h picture of one channel, texel (x, y) = value(x, y).
template <class F>
MipMap grey(int w, int h, F value) {
    std::vector<float> texels;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) texels.push_back(float(value(x, y)));
    return MipMap(w, h, 1, std::move(texels));
}

float at(const MipMap& map, const TexCoord& c, TextureFilter filter, Texture::Wrap wrap = Texture::Wrap::Repeat) {
    float v = -1;
    map.lookup(c, {.filter = filter, .wrapS = wrap, .wrapT = wrap}, &v);
    return v;
}

// A row-major picture and the bilinear filter on it written out as its definition reads, one
// texel and one channel at a time: the reference the sampler's probe (texels in tiles, channels in
// SIMD lanes, the wrapping tested once per pair of texels) must give to the last bit.
template <class T>
struct ReferencePicture {
    int width, height, channels;
    std::vector<T> texels;
    const float* table;  // 8-bit values' decoding; others as they are

    float decoded(int x, int y, int channel) const {
        const T v = texels[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * std::size_t(channels) +
                           std::size_t(channel)];
        if constexpr (std::is_same_v<T, std::uint8_t>)
            return table[v];
        else
            return float(v);
    }

    // The channels [first, first + n) at (s, t), bilinear on level 0.
    std::vector<float> bilinear(float s, float t, Texture::Wrap wrapS, Texture::Wrap wrapT, int first, int n) const {
        const float x = reduced(s, wrapS) * float(width) - 0.5f, y = reduced(t, wrapT) * float(height) - 0.5f;
        const float x0 = std::floor(x), y0 = std::floor(y);
        const float fx = x - x0, fy = y - y0;
        const int xs[2] = {wrappedIndex(int(x0), width, wrapS), wrappedIndex(int(x0) + 1, width, wrapS)};
        const int ys[2] = {wrappedIndex(int(y0), height, wrapT), wrappedIndex(int(y0) + 1, height, wrapT)};
        const float wx[2] = {1 - fx, fx}, wy[2] = {1 - fy, fy};
        std::vector<float> sum(std::size_t(n), 0.0f);
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 2; ++i)
                for (int c = 0; c < n; ++c)
                    sum[std::size_t(c)] += 1.0f * wx[i] * wy[j] * decoded(xs[i], ys[j], first + c);
        return sum;
    }

    // A coordinate in the range its wrap mode repeats in (MipMap's reduction: a period of 1, or 2
    // mirrored; clamped to [-1, 2]); NaN and beyond 1e7 read 0.
    static float reduced(float s, Texture::Wrap wrap) {
        if (!(std::abs(s) < 1e7f)) return 0;
        if (wrap == Texture::Wrap::Clamp) return std::clamp(s, -1.0f, 2.0f);
        if (wrap == Texture::Wrap::Mirror) return s - 2 * std::floor(s * 0.5f);
        return s - std::floor(s);
    }

    static int wrappedIndex(int i, int n, Texture::Wrap wrap) {
        if (wrap == Texture::Wrap::Clamp) return std::clamp(i, 0, n - 1);
        const int period = wrap == Texture::Wrap::Mirror ? 2 * n : n;
        const int m = (i % period + period) % period;
        return m < n ? m : 2 * n - 1 - m;
    }
};

// Every way to read a picture of `channels` channels: each run of channels [first, first + n),
// every wrap mode on each axis, at random points in and beyond [0, 1] (and on texel edges), by
// MipMap::lookup (bilinear; trilinear and anisotropic with footprints under a texel, which read
// level 0 bilinear) and MipMap::bilinear (one channel, the cut-outs' alpha): each equal to the
// reference's bits.
template <class T>
void expectReferenceBits(const ReferencePicture<T>& picture, std::mt19937& random) {
    const MipMap map(picture.width, picture.height, picture.channels, picture.texels);
    std::uniform_real_distribution<float> coordinate(-2.5f, 3.5f), footprint(-0.6f, 0.6f);
    std::uniform_int_distribution<int> edge(-picture.width, 2 * picture.width);
    using W = Texture::Wrap;
    for (int n = 1; n <= picture.channels; ++n)
        for (int first = 0; first + n <= picture.channels; ++first)
            for (const W wrapS : {W::Repeat, W::Clamp, W::Mirror})
                for (const W wrapT : {W::Repeat, W::Clamp, W::Mirror})
                    for (int k = 0; k < 24; ++k) {
                        // Every fourth point on a column of texel edges, where the pair of texels wraps.
                        const float s = k % 4 ? coordinate(random) : float(edge(random)) / float(picture.width);
                        const float t = coordinate(random);
                        const float w = float(picture.width), h = float(picture.height);
                        const TexCoord under{s,
                                             t,
                                             footprint(random) / w,
                                             footprint(random) / h,
                                             footprint(random) / w,
                                             footprint(random) / h};
                        const std::vector<float> expected = picture.bilinear(s, t, wrapS, wrapT, first, n);
                        MipLookup how{.wrapS = wrapS, .wrapT = wrapT, .firstChannel = first, .channels = n};
                        how.decoding.table = picture.table;
                        for (const TextureFilter filter :
                             {TextureFilter::Bilinear, TextureFilter::Trilinear, TextureFilter::Anisotropic}) {
                            how.filter = filter;
                            float out[4] = {-1, -1, -1, -1};
                            map.lookup(filter == TextureFilter::Bilinear ? TexCoord{s, t} : under, how, out);
                            for (int c = 0; c < n; ++c)
                                ASSERT_EQ(out[c], expected[std::size_t(c)])
                                    << picture.width << "x" << picture.height << "x" << picture.channels << " channel "
                                    << first + c << " filter " << int(filter) << " wrap " << int(wrapS) << ","
                                    << int(wrapT) << " at " << s << "," << t;
                            for (int c = n; c < 4; ++c) ASSERT_EQ(out[c], -1) << "written beyond the channels asked";
                        }
                        if (n == 1) {
                            ASSERT_EQ(map.bilinear(s, t, how), expected[0]) << "alpha, channel " << first;
                        }
                    }
}

}  // namespace

// Each side halves, rounded down, to 1; each coarse texel the area-weighted box of the finer ones,
// so every level keeps the picture's mean (the 1 x 1 level is the mean itself).
TEST(MipMap, NonPowerOfTwoLevelsHalveRoundingDownAndKeepTheMean) {
    std::mt19937 random(7);
    std::uniform_real_distribution<float> uniform(0, 1);
    std::vector<float> values(7 * 5);
    for (float& v : values) v = uniform(random);
    const double mean = std::accumulate(values.begin(), values.end(), 0.0) / double(values.size());
    const MipMap map = grey(7, 5, [&](int x, int y) { return values[std::size_t(y * 7 + x)]; });
    EXPECT_EQ(map.levelSizes(), (std::vector<std::array<int, 2>>{{7, 5}, {3, 2}, {1, 1}}));
    // A footprint far larger than the picture reads the last level.
    EXPECT_NEAR(at(map, {0.3f, 0.6f, 100, 0, 0, 100}, TextureFilter::Trilinear), mean, 1e-6);
    // Level 1 (3 x 2): texel (0, 0) covers x in [0, 7/3) and y in [0, 2.5) of level 0.
    double corner = 0;
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 3; ++x)
            corner += values[std::size_t(y * 7 + x)] * (x == 2 ? 1.0 / 3 : 1.0) * (y == 2 ? 0.5 : 1.0);
    corner /= (7.0 / 3) * 2.5;
    const TexCoord texel00{1.0f / 6, 0.25f, 2.0f / 7, 0, 0, 2.0f / 5};  // its centre, level exactly 1
    EXPECT_NEAR(at(map, texel00, TextureFilter::Trilinear), corner, 1e-5);
    EXPECT_EQ(MipMap(6, 1, 1, std::vector<float>{0, 1, 2, 3, 4, 5}).levelSizes(),
              (std::vector<std::array<int, 2>>{{6, 1}, {3, 1}, {1, 1}}));
}

// A 2 x 2 picture: texel centres at 1/4 and 3/4; between them the weights are linear in distance.
TEST(MipMap, BilinearOfATwoByTwoPictureAtKnownPoints) {
    const float a = 0, b = 1, c = 2, d = 4;  // top-left, top-right, bottom-left, bottom-right
    const MipMap map = grey(2, 2, [&](int x, int y) { return y == 0 ? (x == 0 ? a : b) : (x == 0 ? c : d); });
    const auto bilinear = [&](float s, float t) {
        return at(map, {s, t}, TextureFilter::Bilinear, Texture::Wrap::Clamp);
    };
    EXPECT_FLOAT_EQ(bilinear(0.25f, 0.25f), a);
    EXPECT_FLOAT_EQ(bilinear(0.75f, 0.75f), d);
    EXPECT_FLOAT_EQ(bilinear(0.5f, 0.5f), (a + b + c + d) / 4);
    EXPECT_FLOAT_EQ(bilinear(0.375f, 0.25f), 0.75f * a + 0.25f * b);
    EXPECT_FLOAT_EQ(bilinear(0.75f, 0.625f), 0.25f * b + 0.75f * d);
    EXPECT_FLOAT_EQ(bilinear(0.0f, 0.0f), a) << "clamped beyond the edge";
    // Nearest: the texel the point falls in.
    EXPECT_FLOAT_EQ(at(map, {0.49f, 0.51f}, TextureFilter::Nearest), c);
    // Repeat: the corner (0, 0) is between all four texels of the repeated picture.
    EXPECT_FLOAT_EQ(at(map, {0, 0}, TextureFilter::Bilinear), (a + b + c + d) / 4);
}

// Nearest texels of a 4-texel row, each texel its index, at points in and beyond [0, 1).
TEST(MipMap, WrapModesRepeatClampAndMirrorTexelIndices) {
    const MipMap map = grey(4, 1, [](int x, int) { return x; });
    const auto texel = [&](float s, Texture::Wrap wrap) { return at(map, {s, 0.5f}, TextureFilter::Nearest, wrap); };
    using W = Texture::Wrap;
    for (const auto& [s, repeat, clamp, mirror] : std::vector<std::array<float, 4>>{{0.1f, 0, 0, 0},
                                                                                    {1.1f, 0, 3, 3},
                                                                                    {1.3f, 1, 3, 2},
                                                                                    {-0.1f, 3, 0, 0},
                                                                                    {-0.3f, 2, 0, 1},
                                                                                    {2.1f, 0, 3, 0},
                                                                                    {-1000.1f, 3, 0, 0}}) {
        EXPECT_EQ(texel(s, W::Repeat), repeat) << s;
        EXPECT_EQ(texel(s, W::Clamp), clamp) << s;
        EXPECT_EQ(texel(s, W::Mirror), mirror) << s;
    }
    // Not a number, or beyond float's integers: the first texel, never an index outside the row.
    EXPECT_EQ(texel(std::nanf(""), W::Repeat), 0);
    EXPECT_EQ(texel(1e30f, W::Mirror), 0);
}

// Levels of kTiledSide texels a side or more are stored in tiles of 4 x 4 texels, tile after tile
// along a row of tiles: texel (5, 1) of an 8 x 8 level is texel (1, 1) of the second tile.
TEST(MipMap, LargeLevelsAreStoredInTilesOfFourByFour) {
    const MipLevel<float> tiled{8, 8, 2, 2, {}}, rows{8, 8, 0, 8, {}};
    EXPECT_EQ(tiled.texel(5, 1), 16u + 4 + 1);
    EXPECT_EQ(tiled.texel(2, 6), 2u * 16 + 2 * 4 + 2);
    EXPECT_EQ(rows.texel(5, 1), 13u);
}

// A picture large enough for tiles, with sides that are not whole tiles, reads back every texel
// (nearest at its centre, bilinear across the edges of the picture and of the tiles) as the
// picture holds it, in every wrap mode.
TEST(MipMap, TiledLevelsReadTheSameTexelsAsThePicture) {
    const int w = kTiledSide + 3, h = kTiledSide + 1;
    const auto value = [](int x, int y) { return float((x * 7 + y * 13) % 101); };
    const MipMap map = grey(w, h, value);
    EXPECT_EQ(map.bytes(), mipMapBytes(w, h, sizeof(float))) << "the estimate counts the padding";
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const TexCoord centre{(float(x) + 0.5f) / float(w), (float(y) + 0.5f) / float(h)};
            ASSERT_EQ(at(map, centre, TextureFilter::Nearest), value(x, y)) << x << " " << y;
        }
    for (const Texture::Wrap wrap : {Texture::Wrap::Repeat, Texture::Wrap::Clamp, Texture::Wrap::Mirror})
        for (const auto& [x, y] : std::vector<std::array<int, 2>>{{3, 3}, {w - 1, 5}, {7, h - 1}, {w - 1, h - 1}}) {
            // Between texels (x, y) and (x + 1, y + 1), wrapped as each mode wraps them.
            const int x1 = wrap == Texture::Wrap::Repeat ? (x + 1) % w : std::min(x + 1, w - 1);
            const int y1 = wrap == Texture::Wrap::Repeat ? (y + 1) % h : std::min(y + 1, h - 1);
            const float expected = (value(x, y) + value(x1, y) + value(x, y1) + value(x1, y1)) / 4;
            const TexCoord corner{float(x + 1) / float(w), float(y + 1) / float(h)};
            EXPECT_FLOAT_EQ(at(map, corner, TextureFilter::Bilinear, wrap), expected) << x << " " << y;
        }
}

// A checker of 1-texel squares, 0 and 1, seen with a footprint of 8 texels, or 16 by 2 (anisotropic:
// 8 probes on level 1): every filter that takes the footprint gives its grey, 0.5, wherever it falls;
// point sampling gives 0 or 1.
TEST(MipMap, ACheckerSeenAtAKnownFootprintAveragesToGrey) {
    const MipMap map = grey(64, 64, [](int x, int y) { return (x + y) % 2; });
    const float texel = 1.0f / 64;
    std::mt19937 random(3);
    std::uniform_real_distribution<float> uniform(-2, 2);
    for (int i = 0; i < 100; ++i) {
        const float s = uniform(random), t = uniform(random);
        const TexCoord square{s, t, 8 * texel, 0, 0, 8 * texel}, skewed{s, t, 12 * texel, 12 * texel, -texel, texel},
            long_{s, t, 0, 2 * texel, 16 * texel, 0};
        EXPECT_NEAR(at(map, square, TextureFilter::Trilinear), 0.5f, 1e-6f);
        EXPECT_NEAR(at(map, square, TextureFilter::Anisotropic), 0.5f, 1e-6f);
        EXPECT_NEAR(at(map, skewed, TextureFilter::Anisotropic), 0.5f, 1e-6f);
        EXPECT_NEAR(at(map, long_, TextureFilter::Anisotropic), 0.5f, 1e-6f);
        const float point = at(map, square, TextureFilter::Nearest);
        EXPECT_TRUE(point == 0 || point == 1) << point;
    }
}

// Anisotropic probes spread along the longer axis only: a picture of stripes across that axis,
// seen along it, averages to grey; seen with the footprint turned, it keeps the stripe's value.
TEST(MipMap, AnisotropicProbesFollowTheLongerAxis) {
    const MipMap stripes = grey(64, 64, [](int x, int) { return (x / 2) % 2; });  // columns of 2 texels
    const float texel = 1.0f / 64;
    const float s = 5 * texel, t = 0.5f;  // between texels 4 and 5 (value 0), the centre of level 1's texel 2
    EXPECT_NEAR(at(stripes, {s, t, 16 * texel, 0, 0, 2 * texel}, TextureFilter::Anisotropic), 0.5f, 1e-6f);
    EXPECT_NEAR(at(stripes, {s, t, 0, 16 * texel, 0.5f * texel, 0}, TextureFilter::Anisotropic), 0, 1e-6f);
    // Trilinear takes the longer axis for both: grey across the stripes as well.
    EXPECT_NEAR(at(stripes, {s, t, 0, 16 * texel, 0.5f * texel, 0}, TextureFilter::Trilinear), 0.5f, 1e-6f);
}

// 8-bit texels are decoded by the table each lookup gives: sRGB for colour, linear for data.
TEST(MipMap, EightBitTexelsAreDecodedByTheLookupsTable) {
    const MipMap map(2, 1, 1, std::vector<std::uint8_t>{0, 128});
    EXPECT_TRUE(map.storesBytes());
    float srgb = 0, linear = 0;
    MipLookup how{.filter = TextureFilter::Nearest};
    how.decoding.table = srgbByteTable();
    map.lookup({0.75f, 0.5f}, how, &srgb);
    how.decoding.table = linearByteTable();
    map.lookup({0.75f, 0.5f}, how, &linear);
    EXPECT_FLOAT_EQ(linear, 128.0f / 255);
    EXPECT_NEAR(srgb, 0.2158605f, 1e-6f);
    // Level 1 averages the stored values (64), as maketx does.
    how.filter = TextureFilter::Trilinear;
    map.lookup({0.5f, 0.5f, 1, 0, 0, 1}, how, &linear);
    EXPECT_FLOAT_EQ(linear, 64.0f / 255);
}

// The bilinear probe (the texels' places and weights computed once, the channels in SIMD lanes,
// one wrap test per pair of texels) gives the bits of the filter written out texel by texel and
// channel by channel, for 8-bit pictures read as sRGB colour and as data, and float ones, of 1 to
// 4 channels, sides that are not powers of two, one texel wide, and large enough for tiles.
TEST(MipMap, BilinearProbeHasTheBitsOfTheReferenceFilter) {
    std::mt19937 random(11);
    std::uniform_int_distribution<int> byte(0, 255);
    std::uniform_real_distribution<float> real(-1, 4);
    for (const auto& [w, h] : std::vector<std::array<int, 2>>{{7, 5}, {1, 6}, {5, 1}, {kTiledSide + 3, kTiledSide + 1}})
        for (int channels = 1; channels <= 4; ++channels) {
            const std::size_t count = std::size_t(w) * std::size_t(h) * std::size_t(channels);
            // sRGB colour for odd channel counts, data for even ones.
            ReferencePicture<std::uint8_t> bytes{
                w, h, channels, {}, channels % 2 ? srgbByteTable() : linearByteTable()};
            for (std::size_t i = 0; i < count; ++i) bytes.texels.push_back(std::uint8_t(byte(random)));
            expectReferenceBits(bytes, random);
            ReferencePicture<float> floats{w, h, channels, {}, nullptr};
            for (std::size_t i = 0; i < count; ++i) floats.texels.push_back(real(random));
            expectReferenceBits(floats, random);
        }
}
