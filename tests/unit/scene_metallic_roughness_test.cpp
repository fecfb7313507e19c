// The metallic-roughness to Phong mapping and back (scene/metallic_roughness.*, docs/conversion.md).
#include <gtest/gtest.h>

#include "scene/metallic_roughness.h"
#include "scene/scene.h"

namespace rt {
namespace {

TEST(MetallicRoughness, RoughDielectricIsDiffuseWithAFaintHighlight) {
    PbrMaterialFactors in;
    in.baseColor = {0.8f, 0.2f, 0.1f};
    in.factors.metallic = 0;
    in.factors.roughness = 1;
    const Material m = phongFromMetallicRoughness(in);
    EXPECT_EQ(m.color, Color(0.8f, 0.2f, 0.1f));
    EXPECT_FLOAT_EQ(m.phong.diffuse, 0.9f);
    EXPECT_NEAR(m.phong.specular, 0.04f, 1e-6);  // ((1.5 - 1) / (1.5 + 1))^2
    EXPECT_FLOAT_EQ(m.phong.reflection, 0);      // no sharp mirror image
    EXPECT_FLOAT_EQ(m.phong.shininess, 1);       // the broadest lobe
}

TEST(MetallicRoughness, PolishedMetalIsAMirrorOfItsColour) {
    PbrMaterialFactors in;
    in.baseColor = {1, 1, 1};
    in.factors.metallic = 1;
    in.factors.roughness = 0;
    const Material m = phongFromMetallicRoughness(in);
    EXPECT_FLOAT_EQ(m.phong.diffuse, 0);
    EXPECT_NEAR(m.phong.reflection, 1, 1e-6);
    EXPECT_NEAR(m.phong.specular, 1, 1e-6);
    EXPECT_FLOAT_EQ(m.phong.shininess, 10000);
    EXPECT_LT(m.phong.spread, 0.01f);
}

// glTF's default metal (metallic 1, roughness 1, as files with only a baseColorFactor have it): its
// lobe is too broad for Phong's highlight, so its colour goes to the diffuse term, which it tints.
TEST(MetallicRoughness, RoughMetalIsDiffuseInItsColour) {
    PbrMaterialFactors in;
    in.baseColor = {0.0055f, 0.3686f, 0.0041f};  // issue-261's green cube
    in.factors.metallic = 1;
    in.factors.roughness = 1;
    const Material m = phongFromMetallicRoughness(in);
    EXPECT_FLOAT_EQ(m.phong.diffuse, 1);
    EXPECT_NEAR(m.phong.specular, 0, 1e-6);
    EXPECT_FLOAT_EQ(m.phong.reflection, 0);
    in.factors.roughness = 0.5f;  // half way: a quarter of the metal's reflectance is diffuse
    const Material satin = phongFromMetallicRoughness(in);
    EXPECT_FLOAT_EQ(satin.phong.diffuse, 0.25f);
    EXPECT_NEAR(satin.phong.specular, 0.75f * luminance(in.baseColor), 1e-6);
    in.factors.metallic = 0.5f;  // and half a metal: the dielectric's diffuse beside it
    EXPECT_FLOAT_EQ(phongFromMetallicRoughness(in).phong.diffuse, 0.9f * 0.5f + 0.5f * 0.25f);
}

// The path tracer renders the factors themselves (docs/path-tracing.md), clamped as the mapping clamps them.
TEST(MetallicRoughness, TheFactorsAreKeptForThePathTracer) {
    PbrMaterialFactors in;
    in.factors.metallic = 0.25f;
    in.factors.roughness = 1.5f;
    in.factors.specular = 0.5f;
    const Material m = phongFromMetallicRoughness(in);
    ASSERT_TRUE(m.pbr.factors);
    EXPECT_EQ(m.pbr.factors->metallic, 0.25f);
    EXPECT_EQ(m.pbr.factors->roughness, 1.0f);
    EXPECT_EQ(m.pbr.factors->specular, 0.5f);
}

TEST(MetallicRoughness, RougherMeansBroaderAndDimmerReflection) {
    PbrMaterialFactors in;
    in.factors.metallic = 1;
    float lastShininess = 1e9f, lastReflection = 2, lastSpread = -1;
    for (float r : {0.1f, 0.3f, 0.5f, 0.8f}) {
        in.factors.roughness = r;
        const Material m = phongFromMetallicRoughness(in);
        EXPECT_LT(m.phong.shininess, lastShininess);
        EXPECT_LT(m.phong.reflection, lastReflection);
        EXPECT_GT(m.phong.spread, lastSpread);
        lastShininess = m.phong.shininess, lastReflection = m.phong.reflection, lastSpread = m.phong.spread;
    }
}

TEST(MetallicRoughness, IorAndSpecularExtensionsSetTheDielectricReflectance) {
    PbrMaterialFactors in;
    in.factors.metallic = 0;
    in.factors.roughness = 0.5f;
    in.ior = 1;  // index matched: no reflection at all
    EXPECT_FLOAT_EQ(phongFromMetallicRoughness(in).phong.specular, 0);
    in.ior = 2;
    const float f0 = (1.0f / 3) * (1.0f / 3);
    EXPECT_NEAR(phongFromMetallicRoughness(in).phong.specular, f0, 1e-6);
    in.factors.specular = 0.5f;
    EXPECT_NEAR(phongFromMetallicRoughness(in).phong.specular, f0 / 2, 1e-6);
}

// Transmission is the dielectric's: a metal lets nothing through.
TEST(MetallicRoughness, OnlyDielectricsTransmit) {
    const Material metal = phongFromMetallicRoughness({.factors = {.metallic = 1, .roughness = 0}, .transmission = 1});
    EXPECT_FALSE(metal.transmission.passesLight());
    const Material half =
        phongFromMetallicRoughness({.factors = {.metallic = 0.5f, .roughness = 0}, .transmission = 1});
    EXPECT_FLOAT_EQ(half.transmission.weight, 0.5f);
    EXPECT_FLOAT_EQ(half.phong.diffuse, 0.9f * 0.5f * 0.5f);
}

TEST(MetallicRoughness, OutOfRangeInputsAreClamped) {
    PbrMaterialFactors in;
    in.baseColor = {-1, 2, 0.5f};
    in.factors.metallic = 3;
    in.factors.roughness = -1;
    const Material m = phongFromMetallicRoughness(in);
    EXPECT_EQ(m.color.r, 0);
    EXPECT_FLOAT_EQ(m.phong.diffuse, 0);
    EXPECT_LE(m.phong.reflection, 1);
}

}  // namespace
}  // namespace rt
