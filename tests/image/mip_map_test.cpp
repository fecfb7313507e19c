// rt's MIP map (libtrace/image/mip_map.*) against analytic answers: the box-filtered levels of
// non-power-of-two pictures, bilinear weights, wrap modes, and a checker seen at a known footprint.
#include "image/mip_map.h"

#include <gtest/gtest.h>

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
