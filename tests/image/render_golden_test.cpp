// Golden images: small scenes rendered and compared with references committed in
// tests/golden/ (linear half-float EXR, 64x48, made by this renderer and checked by eye).
// To regenerate after an intended change: RT_UPDATE_GOLDEN=1 build/release/tests/image_tests
// and look at the pictures before committing them.
//
// Tolerance: every channel within 2e-3 (the reference is half float: 1e-3 steps near 1),
// except at most 1% of the pixels, where float geometry may move a silhouette or a shadow
// edge across a pixel centre compared with double.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include "../unit/render_test_scenes.h"
#include "accel/naive.h"
#include "image/image_output.h"
#include "render/renderer.h"

using namespace rt;

namespace {

constexpr float kChannelTolerance = 2e-3f;
constexpr double kOutlierFraction = 0.01;

std::string goldenPath(const std::string& name) { return RT_SOURCE_DIR "/tests/golden/" + name + ".exr"; }

Framebuffer renderTestScene(const RenderSettings& settings, const Scene& scene = test::spheresOnFloor()) {
    const NaiveAccelerator accel(scene.primitives);
    RenderStats stats;
    return render(scene, accel, settings, stats);
}

void writeGolden(const Framebuffer& image, const std::string& name) {
    ImageOutputSettings out;
    out.format = ImageFormat::Exr;
    out.path = goldenPath(name);
    // The built-in colour config: the header then names no path of the machine that made it.
    writeImage(image, out, {"rt golden test", "tests/unit/render_test_scenes.h", 1, 0});
}

void expectMatchesGolden(const Framebuffer& image, const std::string& name) {
    if (std::getenv("RT_UPDATE_GOLDEN")) {
        writeGolden(image, name);
        GTEST_SKIP() << "wrote " << goldenPath(name);
    }
    auto in = OIIO::ImageInput::open(goldenPath(name));
    ASSERT_TRUE(in) << OIIO::geterror();
    const OIIO::ImageSpec& spec = in->spec();
    ASSERT_EQ(spec.width, image.window().width());
    ASSERT_EQ(spec.height, image.window().height());
    std::vector<float> ref(std::size_t(spec.width) * std::size_t(spec.height) * 3);
    ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, ref.data()));
    std::size_t outliers = 0;
    float worst = 0;
    for (std::size_t i = 0; i < image.pixels().size(); ++i) {
        const Color& c = image.pixels()[i];
        const float d =
            std::max({std::abs(c.r - ref[3 * i]), std::abs(c.g - ref[3 * i + 1]), std::abs(c.b - ref[3 * i + 2])});
        worst = std::max(worst, d);
        if (d > kChannelTolerance) ++outliers;
    }
    EXPECT_LE(double(outliers), kOutlierFraction * double(image.pixels().size()))
        << name << ": " << outliers << " pixels differ by more than " << kChannelTolerance << ", worst " << worst;
}

RenderSettings golden() {
    RenderSettings s;
    s.width = 64;
    s.height = 48;
    return s;
}

}  // namespace

TEST(RenderGolden, WhittedWithShadowsAndReflections) {
    RenderSettings s = golden();
    s.shadows = true;
    s.reflectionDepth = 3;
    expectMatchesGolden(renderTestScene(s), "whitted");
}

TEST(RenderGolden, NoShadowsOneReflection) {
    RenderSettings s = golden();
    s.reflectionDepth = 1;
    expectMatchesGolden(renderTestScene(s), "no_shadows_depth1");
}

TEST(RenderGolden, DistributedSoftShadowsGlossyReflectionsSupersampling) {
    RenderSettings s = golden();
    s.shadows = true;
    s.reflectionDepth = 3;
    s.pixelSamples = 4;
    s.softShadows = s.glossyReflections = true;
    s.distributedSamples = 8;
    expectMatchesGolden(renderTestScene(s), "distributed");
}

TEST(RenderGolden, CylindersAndCones) {
    RenderSettings s = golden();
    s.shadows = true;
    s.reflectionDepth = 3;
    expectMatchesGolden(renderTestScene(s, test::cylindersAndCones()), "cylinders_cones");
}
