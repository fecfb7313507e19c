// The heat map: colour map, scale, colour bar, lettering, and a hottest region where the
// geometry is densest.
#include <algorithm>
#include <limits>

#include "core/color.h"
#include "inspect/bitmap_font.h"
#include "inspect/color_map.h"
#include "inspect/heatmap.h"
#include "inspect/ray_statistics.h"
#include "inspect_test_scenes.h"
#include "test_util.h"

using namespace rt;

namespace {

// A stand-in for a tree whose work depends on where the geometry is: one traversal step
// per primitive box tested, one intersection test per box the ray enters. (The BSP and
// KD trees get the same test in inspect_trees_test.cpp.)
class BoxCullingList final : public Accelerator {
public:
    explicit BoxCullingList(const Primitives& prims) : prims_(prims) {}

    bool intersect(const Ray& ray, Real tMax, Hit& hit, RayCounters& counters) const override {
        bool found = false;
        const Vec3 inv = reciprocal(ray.direction);
        for (std::uint32_t id = 0; id < prims_.size(); ++id) {
            ++counters.traversalSteps;
            Real t0 = 0, t1 = tMax;
            if (!clipRay(prims_.bounds(id), ray, inv, t0, t1)) continue;
            ++counters.intersectionTests;
            if (prims_.view().intersect(id, ray, tMax, hit)) tMax = hit.t, found = true;
        }
        return found;
    }
    bool occluded(const Ray& ray, Real tMax, RayCounters& counters) const override {
        Hit hit;
        return intersect(ray, tMax, hit, counters);
    }
    AccelStats stats() const override { return {}; }
    void forEachNode(const std::function<void(const TreeNodeInfo&)>&) const override {}

private:
    const Primitives& prims_;
};

// A dense cluster of small spheres and, apart from it, one sphere.
Scene clusterAndLoneSphere() {
    Scene scene = sceneLookingDownZ();
    addSphereCluster(scene, {-4, -0.75, 10}, 6, Real(0.3), Real(0.12));
    scene.looseObjects.add<Sphere>({{3, 0, 10}, 1}, 0);
    scene.flatten();
    return scene;
}

// The pixel with the largest cost.
std::pair<int, int> hottestPixel(const std::vector<float>& cost, int width) {
    const auto it = std::max_element(cost.begin(), cost.end());
    const int i = int(it - cost.begin());
    return {i % width, i / width};
}

}  // namespace

TEST(Heatmap, HottestWhereTheGeometryIsDensest) {
    const Scene scene = clusterAndLoneSphere();
    const BoxCullingList accel(scene.primitives);
    const int w = 80, h = 60;
    RenderSettings picture;
    picture.width = w;
    picture.height = h;
    const std::vector<float> cost = pixelWork(scene, accel, picture, PixelRays::Camera);
    const auto [x, y] = hottestPixel(cost, w);
    // The cluster spans x in [-4, -2.5] at z >= 10. Looking down +z with +y up in a
    // right-handed world, +x is to the left: the cluster is in the right third of the picture.
    EXPECT_GT(x, 2 * w / 3) << "hottest pixel at " << x << "," << y;
    EXPECT_GT(y, h / 4);
    EXPECT_LT(y, 3 * h / 4);
    // And the lone sphere is cooler than the cluster but warmer than empty space.
    const float lone = cost[std::size_t(h / 2) * w + w / 4 - 5];
    EXPECT_LT(lone, cost[std::size_t(y) * w + x]);
    EXPECT_GT(lone, cost[0]);
}

TEST(Heatmap, ColourMapRunsFromDarkBlueToYellow) {
    EXPECT_EQ(viridis(0), (Rgb8{68, 1, 84}));
    EXPECT_EQ(viridis(1), (Rgb8{253, 231, 37}));
    EXPECT_EQ(viridis(-5), viridis(0));
    EXPECT_EQ(viridis(7), viridis(1));
    // Perceptually ordered: luminance rises monotonically.
    float last = -1;
    for (int i = 0; i <= 100; ++i) {
        const Rgb8 c = viridis(float(i) / 100);
        const float lum = luminance(Color(c.r, c.g, c.b));
        EXPECT_GE(lum, last - 0.5f) << "at " << i;
        last = lum;
    }
}

TEST(Heatmap, TicksAreRoundNumbers) {
    EXPECT_EQ(heatTicks(57, HeatScale::Linear), (std::vector<float>{0, 10, 20, 30, 40, 50}));
    EXPECT_EQ(heatTicks(5, HeatScale::Linear), (std::vector<float>{0, 1, 2, 3, 4, 5}));
    EXPECT_EQ(heatTicks(1500, HeatScale::Linear), (std::vector<float>{0, 200, 400, 600, 800, 1000, 1200, 1400}));
    EXPECT_EQ(heatTicks(150, HeatScale::Log), (std::vector<float>{0, 1, 2, 5, 10, 20, 50, 100}));
    EXPECT_EQ(heatTicks(20000, HeatScale::Log), (std::vector<float>{0, 1, 10, 100, 1000, 10000}));
    // --heatmap-max at the ends of float: a few ticks, not a loop that fills the memory.
    for (const float extreme : {3.4e38f, 1e-45f, std::numeric_limits<float>::infinity()})
        for (const HeatScale scale : {HeatScale::Linear, HeatScale::Log})
            EXPECT_LE(heatTicks(extreme, scale).size(), 40u) << extreme;
    EXPECT_FLOAT_EQ(heatPosition(50, 100, HeatScale::Linear), 0.5f);
    EXPECT_FLOAT_EQ(heatPosition(200, 100, HeatScale::Linear), 1.0f);
    EXPECT_FLOAT_EQ(heatPosition(9, 99, HeatScale::Log), 0.5f);  // log(10) / log(100)
}

TEST(Heatmap, PictureColourBarAndLabels) {
    const int w = 64, h = 40;
    std::vector<float> cost(std::size_t(w) * h, 0.0f);
    cost[std::size_t(10) * w + 20] = 80;  // one hot pixel
    cost[std::size_t(30) * w + 40] = 40;
    HeatmapOptions options;
    options.caption = "KD";
    const RgbImage image = renderHeatmap(cost, w, h, options);
    ASSERT_EQ(image.width(), w);
    ASSERT_GT(image.height(), h + 2 * kGlyphHeight);
    EXPECT_EQ(image.at(20, 10), viridis(1));
    EXPECT_EQ(image.at(40, 30), viridis(0.5f));
    EXPECT_EQ(image.at(0, 0), viridis(0));
    // The bar runs from the coldest to the hottest colour, left to right.
    const int barY = h + 6;
    EXPECT_EQ(image.at(8, barY), viridis(0));
    EXPECT_EQ(image.at(w - 9, barY), viridis(1));
    // Some lettering below the bar.
    int lit = 0;
    for (int y = barY + 10; y < image.height(); ++y)
        for (int x = 0; x < w; ++x) lit += image.at(x, y) == Rgb8{235, 235, 235};
    EXPECT_GT(lit, 20);
}

TEST(Heatmap, FixedMaximumClampsHotterPixels) {
    std::vector<float> cost{0, 10, 20, 40};
    HeatmapOptions options;
    options.maximum = 20;
    const RgbImage image = renderHeatmap(cost, 4, 1, options);
    EXPECT_EQ(image.at(1, 0), viridis(0.5f));
    EXPECT_EQ(image.at(2, 0), viridis(1));
    EXPECT_EQ(image.at(3, 0), viridis(1));
    EXPECT_THROW(renderHeatmap(cost, 3, 1, options), std::invalid_argument);
}

TEST(BitmapFont, DrawsGlyphsAtScale) {
    RgbImage image(40, 20);
    const Rgb8 white{255, 255, 255};
    drawText(image, 1, 1, "1", 2, white);
    // '1' has its stem in the middle column (x = 2 in font pixels) on every row but the first.
    EXPECT_EQ(image.at(1 + 2 * 2, 1 + 2 * 3), white);
    EXPECT_EQ(image.at(1 + 2 * 2 + 1, 1 + 2 * 3 + 1), white);
    EXPECT_EQ(image.at(1, 1 + 2 * 3), Rgb8{});
    EXPECT_EQ(textWidth("12", 2), (2 * kGlyphAdvance - 1) * 2);
    RgbImage blank(10, 10);
    drawText(blank, 0, 0, " ", 1, white);
    for (int y = 0; y < 10; ++y)
        for (int x = 0; x < 10; ++x) EXPECT_EQ(blank.at(x, y), Rgb8{});
}
