// glTF import (libtrace/import/gltf_import.*): the shared glTF and GLB models against the
// Assimp figures of MANIFEST.md, instancing, hierarchy, cameras, lights, and one broken
// rule at a time in small generated files.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "core/error.h"
#include "import_test_util.h"
#include "io/base64.h"
#include "io/import.h"
#include "test_util.h"

namespace rt {
namespace {

using test::GltfFixture;
using test::replaceOnce;
using test::sharedModels;
using test::TempDir;

constexpr Real kLoose = Real(1e-4);  // float data, either Real

// Every glTF and GLB model the manifest lists, however many there are.
TEST(ImportGltf, TriangleCountsMatchTheManifest) {
    SKIP_WITHOUT_SHARED_MODELS();
    EXPECT_EQ(test::expectManifestTriangleCounts({"gltf", "glb"}, [](const ImportResult&) {}),
              test::manifestModelFolders("gltf") + test::manifestModelFolders("glb"));
}

// Assimp's FindDegenerates (its "assimp info" column) finds exactly the triangles dropped here.
TEST(ImportGltf, DegenerateTrianglesAreTheOnesAssimpFinds) {
    SKIP_WITHOUT_SHARED_MODELS();
    const ImportResult engine = importScene(sharedModels() + "/glb/2CylinderEngine/2CylinderEngine.glb");
    EXPECT_EQ(test::modelTriangles(engine.scene), 65311u);
    EXPECT_EQ(engine.report.droppedDegenerate, 75730u - 65311u);
}

TEST(ImportGltf, ASharedMeshIsOneModelWithSeveralInstances) {
    SKIP_WITHOUT_SHARED_MODELS();
    const ImportResult r = importScene(sharedModels() + "/gltf/SharedMesh/02_shared_mesh.gltf");
    ASSERT_EQ(r.scene.models.size(), 1u);
    ASSERT_EQ(r.scene.instances.size(), 2u);
    EXPECT_EQ(r.scene.instances[0].model, r.scene.instances[1].model);
    EXPECT_FALSE(r.scene.instances[0].transform == r.scene.instances[1].transform);
    EXPECT_EQ(r.report.meshes, 1u);
}

// 29 meshes with 34 primitives, placed 115 times: one model per primitive, not per placement.
TEST(ImportGltf, TheEngineKeepsOneModelPerPrimitive) {
    SKIP_WITHOUT_SHARED_MODELS();
    const ImportResult r = importScene(sharedModels() + "/glb/2CylinderEngine/2CylinderEngine.glb");
    EXPECT_EQ(r.report.meshes, 29u);
    EXPECT_EQ(r.scene.models.size(), 34u);
    EXPECT_EQ(r.scene.instances.size(), 115u);
    std::set<std::string> names;
    for (const Model& m : r.scene.models) names.insert(m.name);
    EXPECT_EQ(names.size(), r.scene.models.size()) << "model names must be unique: they name the RAW files";
}

// Cameras.gltf: the perspective camera is node 1 at (0.5, 0.5, 3) looking down -z with
// yfov 0.7 and aspect 1, so the horizontal fov is 0.7 rad as well.
TEST(ImportGltf, CameraLandsWhereTheNodePutsIt) {
    SKIP_WITHOUT_SHARED_MODELS();
    const ImportResult r = importScene(sharedModels() + "/gltf/Cameras/Cameras.gltf");
    const Camera& c = r.scene.camera;
    expectNear(c.origin, {0.5, 0.5, 3}, kLoose);
    expectNear(normalize(c.destination - c.origin), {0, 0, -1}, kLoose);
    expectNear(c.up, {0, 1, 0}, kLoose);
    ASSERT_TRUE(c.fovDegrees);
    EXPECT_NEAR(*c.fovDegrees, 0.7 * 180 / kPi, 1e-3);
    EXPECT_EQ(r.report.cameraUsed, "#0");
    EXPECT_FALSE(r.report.cameraGenerated);
    EXPECT_TRUE(r.report.lightGenerated);  // the file has no light
}

TEST(ImportGltf, AnOrthographicCameraIsRefusedByName) {
    SKIP_WITHOUT_SHARED_MODELS();
    ImportOptions o;
    o.camera = "1";
    EXPECT_THROW(importScene(sharedModels() + "/gltf/Cameras/Cameras.gltf", o), InputError);
    o.camera = "nonesuch";
    EXPECT_THROW(importScene(sharedModels() + "/gltf/Cameras/Cameras.gltf", o), InputError);
}

// Every perspective camera a node places is kept, the one taken first: rt-render --camera
// picks among them after the conversion.
TEST(ImportGltf, EveryPerspectiveCameraIsKeptTheChosenFirst) {
    TempDir dir;
    GltfFixture f;
    f.nodes = R"([{"mesh": 0, "children": [1, 2, 3]}, {"camera": 0, "translation": [0, 0, 5]},
                  {"camera": 1, "translation": [5, 0, 0]}, {"camera": 2}])";
    f.extra = R"(, "cameras": [{"type": "perspective", "name": "front", "perspective": {"yfov": 0.5, "znear": 0.1}},
        {"type": "perspective", "name": "side", "perspective": {"yfov": 0.7, "aspectRatio": 1, "znear": 0.1}},
        {"type": "orthographic", "orthographic": {"xmag": 1, "ymag": 1, "znear": 0.1, "zfar": 10}}])";
    const std::string path = dir.write("cameras.gltf", f.json());
    const ImportResult first = importScene(path);
    EXPECT_EQ(first.scene.camera.name, "front");
    ASSERT_EQ(first.scene.extraCameras.size(), 1u);
    EXPECT_EQ(first.scene.extraCameras[0].name, "side");
    expectNear(first.scene.extraCameras[0].origin, {5, 0, 0}, kLoose);
    EXPECT_NEAR(*first.scene.extraCameras[0].fovDegrees, 0.7 * 180 / kPi, 1e-3);
    ImportOptions o;
    o.camera = "side";
    const ImportResult side = importScene(path, o);
    EXPECT_EQ(side.scene.camera.name, "side");
    ASSERT_EQ(side.scene.extraCameras.size(), 1u);
    EXPECT_EQ(side.scene.extraCameras[0].name, "front");
}

// issue-261.gltf: camera and point light under matrix transforms; the light's 1000 cd
// become 1000 / 683 W/sr with the inverse-square falloff.
TEST(ImportGltf, PointLightAndCameraOfIssue261) {
    SKIP_WITHOUT_SHARED_MODELS();
    const ImportResult r = importScene(sharedModels() + "/gltf/PointLightCamera-issue261/issue-261.gltf");
    const Camera& c = r.scene.camera;
    expectNear(c.origin, {0.9729073377709113, 1.2592438262175363, 2.419918748461627}, kLoose);
    expectNear(normalize(c.destination - c.origin), {-0.290254840694694, -0.48551237507207207, -0.8246392308792816},
               kLoose);
    // yfov 0.9273 (tan of half = 0.5) and aspect 4/3: tan of half the horizontal fov = 2/3.
    EXPECT_NEAR(std::tan(*c.fovDegrees * kPi / 360), 2.0 / 3.0, 1e-5);
    ASSERT_EQ(r.scene.lights.size(), 1u);
    const Light& light = r.scene.lights[0];
    expectNear(light.position, {2.3640632834071384, 2.465226204472449, 2.309515908392224}, kLoose);
    EXPECT_EQ(light.type, Light::Type::Point);
    EXPECT_EQ(light.falloff, Light::Falloff::InverseSquare);
    EXPECT_NEAR(light.color.g, 1000 / 683.0, 1e-4);
    EXPECT_FALSE(r.report.lightGenerated);
    EXPECT_EQ(r.report.cameraUsed, "default");
}

// Unity's export: one directional light and three spots with ranges and cones, kept as they are.
TEST(ImportGltf, SpotAndDirectionalLightsAreKept) {
    SKIP_WITHOUT_SHARED_MODELS();
    const ImportResult r = importScene(sharedModels() + "/gltf/AnimateAllTheThings/24_animation_pointer.gltf");
    ASSERT_EQ(r.scene.lights.size(), 4u);
    for (const std::string& n : r.report.notes) EXPECT_EQ(n.find("approximated"), std::string::npos) << n;
    const Light& sun = r.scene.lights[0];
    EXPECT_EQ(sun.type, Light::Type::Directional);
    expectNear(sun.direction, {0, 0, 1}, kLoose);  // -Z turned half around y
    EXPECT_NEAR(sun.color.r, 3.14159274 / 683, 1e-7);
    const Light& spot = r.scene.lights[1];
    EXPECT_EQ(spot.type, Light::Type::Spot);
    EXPECT_EQ(spot.range, Real(10));
    EXPECT_NEAR(spot.innerConeDegrees, 0.106483668 * 180 / kPi, 1e-4);
    EXPECT_NEAR(spot.outerConeDegrees, 0.133104578 * 180 / kPi, 1e-4);
    EXPECT_EQ(r.scene.lights[3].color.g, 0);  // red
}

// A spot under a rotated, scaled node shines along the node's -Z from the node's origin;
// --scale 2 doubles the range and quadruples the intensity (the same light at twice the distance).
TEST(ImportGltf, PunctualLightsFollowTheirNodes) {
    TempDir dir;
    GltfFixture f;
    const double h = std::sqrt(0.5);  // a quarter turn about x: -Z becomes +Y
    f.nodes = R"([{"mesh": 0, "children": [1, 2]},
        {"translation": [1, 2, 3], "rotation": [)" +
              std::to_string(h) + ", 0, 0, " + std::to_string(h) + R"(], "scale": [5, 5, 5],
         "extensions": {"KHR_lights_punctual": {"light": 0}}},
        {"extensions": {"KHR_lights_punctual": {"light": 1}}}])";
    f.extra = R"(, "extensionsUsed": ["KHR_lights_punctual"], "extensions": {"KHR_lights_punctual": {"lights": [
        {"type": "spot", "color": [1, 0.5, 0], "intensity": 683, "range": 4,
         "spot": {"innerConeAngle": 0.25, "outerConeAngle": 0.5}},
        {"type": "directional", "intensity": 2}]}})";
    const std::string path = dir.write("l.gltf", f.json());
    const ImportResult r = importScene(path);
    ASSERT_EQ(r.scene.lights.size(), 2u);
    const Light& spot = r.scene.lights[0];
    EXPECT_EQ(spot.type, Light::Type::Spot);
    expectNear(spot.position, {1, 2, 3}, kLoose);
    expectNear(spot.direction, {0, 1, 0}, kLoose);
    EXPECT_NEAR(spot.color.r, 1, 1e-6);
    EXPECT_NEAR(spot.color.g, 0.5, 1e-6);
    EXPECT_EQ(spot.falloff, Light::Falloff::InverseSquare);
    EXPECT_EQ(spot.range, 4);
    EXPECT_NEAR(spot.innerConeDegrees, 0.25 * 180 / kPi, 1e-4);
    EXPECT_NEAR(spot.outerConeDegrees, 0.5 * 180 / kPi, 1e-4);
    const Light& sun = r.scene.lights[1];
    EXPECT_EQ(sun.type, Light::Type::Directional);
    expectNear(sun.direction, {0, 0, -1}, kLoose);
    EXPECT_EQ(sun.falloff, Light::Falloff::None);
    EXPECT_NEAR(sun.color.r, 2 / 683.0, 1e-7);

    ImportOptions twice;
    twice.scale = 2;
    const ImportResult scaled = importScene(path, twice);
    EXPECT_EQ(scaled.scene.lights[0].range, 8);
    EXPECT_NEAR(scaled.scene.lights[0].color.r, 4, 1e-5);
    EXPECT_NEAR(scaled.scene.lights[1].color.r, 2 / 683.0, 1e-7);  // irradiance: no distance to scale
}

// A point light at the origin, placed by a node without a transform, is a light at the origin
// (issue 36 asked for this regression test beside the 3DS omni light's; glTF point lights carry
// glTF's default -Z, so only Assimp's zero direction was refused before).
TEST(ImportGltf, PointLightAtTheOriginIsPlaced) {
    TempDir dir;
    GltfFixture f;
    f.nodes = R"([{"mesh": 0, "children": [1]}, {"extensions": {"KHR_lights_punctual": {"light": 0}}}])";
    f.extra = R"(, "extensionsUsed": ["KHR_lights_punctual"], "extensions": {"KHR_lights_punctual": {"lights": [
        {"type": "point", "intensity": 683}]}})";
    const ImportResult r = importScene(dir.write("origin.gltf", f.json()));
    EXPECT_FALSE(r.report.lightGenerated);
    ASSERT_EQ(r.scene.lights.size(), 1u);
    EXPECT_EQ(r.scene.lights[0].type, Light::Type::Point);
    expectNear(r.scene.lights[0].position, {0, 0, 0}, kLoose);
    EXPECT_NEAR(r.scene.lights[0].color.r, 1, 1e-6);
}

TEST(ImportGltf, SpotConeOutsideTheSpecificationIsAnError) {
    TempDir dir;
    GltfFixture f;
    f.nodes = R"([{"mesh": 0, "extensions": {"KHR_lights_punctual": {"light": 0}}}])";
    f.extra = R"(, "extensions": {"KHR_lights_punctual": {"lights": [
        {"type": "spot", "spot": {"innerConeAngle": 0.5, "outerConeAngle": 0.25}}]}})";
    const std::string path = dir.write("bad.gltf", f.json());
    EXPECT_THROW(
        {
            try {
                importScene(path);
            } catch (const InputError& e) {
                EXPECT_NE(std::string(e.what()).find("light 0 (spot): the spot cone needs"), std::string::npos)
                    << e.what();
                throw;
            }
        },
        InputError);
}

TEST(ImportGltf, PointsAndLinesAreSkippedAndCounted) {
    SKIP_WITHOUT_SHARED_MODELS();
    const ImportResult r = importScene(sharedModels() + "/gltf/MeshPrimitiveModes/MeshPrimitiveModes.gltf");
    EXPECT_EQ(r.report.droppedPoints, 1u);
    EXPECT_EQ(r.report.droppedLines, 3u);
    EXPECT_EQ(r.scene.models.size(), 3u);  // triangles, strip, fan
}

TEST(ImportGltf, WithoutCameraAndLightTheSceneIsFramed) {
    SKIP_WITHOUT_SHARED_MODELS();
    const ImportResult r = importScene(sharedModels() + "/gltf/Box/Box.gltf");
    EXPECT_TRUE(r.report.cameraGenerated);
    EXPECT_TRUE(r.report.lightGenerated);
    ASSERT_EQ(r.scene.lights.size(), 1u);
    // The unit box centred at the origin is in front of the camera and inside its view cone.
    const Camera& c = r.scene.camera;
    const Vec3 view = normalize(c.destination - c.origin);
    const Vec3 toCentre = Vec3(0, 0, 0) - c.origin;
    EXPECT_GT(dot(toCentre, view) / length(toCentre), std::cos(25 * kPi / 180));
    EXPECT_GT(length(toCentre), 0.87);  // outside the box's bounding sphere
}

// Node 0 translates by (1, 0, 0) and turns 90 degrees about y; its child scales by 2.
// A vertex (1, 0, 0) of the child's mesh lands at parent * child * v = (1, 0, -2).
TEST(ImportGltf, HierarchyComposesParentTimesLocal) {
    TempDir dir;
    GltfFixture f;
    const double s = std::sqrt(0.5);
    f.nodes = R"([{"translation": [1, 0, 0], "rotation": [0, )" + std::to_string(s) + ", 0, " + std::to_string(s) +
              R"(], "children": [1]}, {"scale": [2, 2, 2], "mesh": 0}])";
    ImportResult r = importScene(dir.write("h.gltf", f.json()));
    ASSERT_EQ(r.scene.instances.size(), 1u);
    r.scene.flatten();
    const Triangle t = r.scene.primitives.all<Triangle>()[0];
    expectNear(t.p0, {1, 0, 0}, kLoose);
    expectNear(t.p1, {1, 0, -2}, kLoose);
    expectNear(t.p2, {1, 2, 0}, kLoose);
}

TEST(ImportGltf, ScaleAndUpAxisApplyAtTheRoot) {
    TempDir dir;
    const std::string path = dir.write("z.gltf", GltfFixture().json());
    ImportOptions o;
    o.scale = 3;
    o.upAxis = UpAxis::Z;
    ImportResult r = importScene(path, o);
    r.scene.flatten();
    const Triangle t = r.scene.primitives.all<Triangle>()[0];
    expectNear(t.p1, {3, 0, 0}, kLoose);
    expectNear(t.p2, {0, 0, -3}, kLoose);  // +y of a Z-up file points away from the viewer
}

TEST(ImportGltf, StripsAndFansAreUnrolled) {
    TempDir dir;
    GltfFixture f;
    f.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 2, 1.5f, 0};
    f.indices = {0, 1, 2, 3, 4};
    f.mode = 5;
    EXPECT_EQ(test::modelTriangles(importScene(dir.write("strip.gltf", f.json())).scene), 3u);
    f.mode = 6;
    EXPECT_EQ(test::modelTriangles(importScene(dir.write("fan.gltf", f.json())).scene), 3u);
}

// KHR_materials_ior and KHR_materials_specular reach the Phong mapping; a non-number is an error.
TEST(ImportGltf, MaterialExtensionsAreRead) {
    TempDir dir;
    GltfFixture f;
    f.extra = R"(, "materials": [{"name": "glass", "pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.25, 1, 1],)"
              R"( "metallicFactor": 0}, "extensions": {"KHR_materials_ior": {"ior": 2},)"
              R"( "KHR_materials_specular": {"specularFactor": 0.5}}}])";
    const std::string json = replaceOnce(f.json(), R"("mode": 4)", R"("mode": 4, "material": 0)");
    const ImportResult r = importScene(dir.write("m.gltf", json));
    ASSERT_EQ(r.scene.materials.size(), 1u);
    const Material& m = r.scene.materials[0];
    EXPECT_EQ(m.name, "glass");
    EXPECT_EQ(m.color, Color(0.5f, 0.25f, 1));
    EXPECT_NEAR(m.phong.specular, 0.5f / 9, 1e-6);  // ((2 - 1) / (2 + 1))^2 * 0.5
    EXPECT_THROW(importScene(dir.write("bad.gltf", replaceOnce(json, R"("ior": 2)", R"("ior": "two")"))), InputError);
}

// MASK cuts out at alphaCutoff of the base colour's alpha; BLEND is MASK at 0.5, with a note;
// OPAQUE (the default) is no cut-out.
TEST(ImportGltf, AlphaModesBecomeCutouts) {
    TempDir dir;
    GltfFixture f;
    const auto material = [&](const std::string& mode) {
        f.extra = R"(, "materials": [{"name": "leaf", "pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1, 0.5]})" +
                  mode + "}]";
        const std::string json = replaceOnce(f.json(), R"("mode": 4)", R"("mode": 4, "material": 0)");
        return importScene(dir.write("m.gltf", json));
    };
    const ImportResult mask = material(R"(, "alphaMode": "MASK", "alphaCutoff": 0.25)");
    EXPECT_EQ(mask.scene.materials[0].opacity.cutoff, std::optional<float>(0.25f));
    EXPECT_EQ(mask.scene.materials[0].opacity.alpha, 0.5f);
    const ImportResult blend = material(R"(, "alphaMode": "BLEND")");
    EXPECT_EQ(blend.scene.materials[0].opacity.cutoff, std::optional<float>(0.5f));
    const auto& notes = blend.report.notes;
    EXPECT_TRUE(std::any_of(notes.begin(), notes.end(),
                            [](const std::string& n) { return n.find("alphaMode BLEND") != std::string::npos; }));
    EXPECT_FALSE(material("").scene.materials[0].opacity.cutoff);
}

// doubleSided is kept: true two-sided; false, or left out (glTF's default), single-sided, as is
// the default material of a primitive without one.
TEST(ImportGltf, DoubleSidedIsKeptAndSingleSidedIsTheDefault) {
    TempDir dir;
    GltfFixture f;
    f.extra = R"(, "materials": [{"name": "both", "doubleSided": true}, {"name": "front", "doubleSided": false},)"
              R"( {"name": "unsaid"}])";
    const auto materialOf = [&](const std::string& primitiveMaterial) {
        const std::string json = replaceOnce(f.json(), R"("mode": 4)", R"("mode": 4)" + primitiveMaterial);
        return importScene(dir.write("m.gltf", json)).scene.materials.at(0);
    };
    EXPECT_TRUE(materialOf(R"(, "material": 0)").doubleSided);
    EXPECT_FALSE(materialOf(R"(, "material": 1)").doubleSided);
    EXPECT_FALSE(materialOf(R"(, "material": 2)").doubleSided);
    const Material fallback = materialOf("");
    EXPECT_EQ(fallback.name, "default");
    EXPECT_FALSE(fallback.doubleSided);
}

// KHR_materials_transmission, _ior and _volume make glass tinted by the base colour; without a
// volume (or of thickness 0) it is thin-walled; the transmitted share no longer scatters; a
// transmission texture is kept.
// KHR_materials_clearcoat's factors become the material's clear coat (clamped to 0-1); the
// Phong coefficients stay as without it; a material without the extension has none.
TEST(ImportGltf, ClearcoatFactorsAreRead) {
    TempDir dir;
    GltfFixture f;
    f.extra =
        R"(, "materials": [{"name": "paint", "pbrMetallicRoughness": {"metallicFactor": 0},)"
        R"( "extensions": {"KHR_materials_clearcoat": {"clearcoatFactor": 0.8, "clearcoatRoughnessFactor": 1.5}}},)"
        R"( {"name": "bare", "pbrMetallicRoughness": {"metallicFactor": 0}}])";
    const std::string one = replaceOnce(f.json(), R"("mode": 4)", R"("mode": 4, "material": 0)");
    const Material paint = importScene(dir.write("paint.gltf", one)).scene.materials.at(0);
    EXPECT_EQ(paint.clearcoat.weight, 0.8f);
    EXPECT_EQ(paint.clearcoat.roughness, 1.0f);
    const std::string two = replaceOnce(f.json(), R"("mode": 4)", R"("mode": 4, "material": 1)");
    const Material bare = importScene(dir.write("bare.gltf", two)).scene.materials.at(0);
    EXPECT_EQ(bare.clearcoat.weight, 0.0f);
    EXPECT_EQ(bare.phong.diffuse, paint.phong.diffuse);
    EXPECT_EQ(bare.phong.specular, paint.phong.specular);
    EXPECT_THROW(importScene(dir.write("bad.gltf",
                                       replaceOnce(one, R"("clearcoatFactor": 0.8)", R"("clearcoatFactor": "shiny")"))),
                 InputError);
}

TEST(ImportGltf, TransmissionAndVolumeMakeGlass) {
    TempDir dir;
    GltfFixture f;
    f.extra =
        R"(, "materials": [{"name": "glass", "pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.7, 0.9, 1],)"
        R"( "metallicFactor": 0, "roughnessFactor": 0}, "extensions": {"KHR_materials_ior": {"ior": 1.33},)"
        R"( "KHR_materials_transmission": {"transmissionFactor": 1}, "KHR_materials_volume": {"thicknessFactor": 0.5,)"
        R"( "attenuationColor": [0.5, 0.25, 1], "attenuationDistance": 2}}},)"
        R"( {"name": "sheet", "pbrMetallicRoughness": {"metallicFactor": 0},)"
        R"( "extensions": {"KHR_materials_transmission": {"transmissionFactor": 0.5}}},)"
        R"( {"name": "paper", "pbrMetallicRoughness": {"metallicFactor": 0}, "extensions": {"KHR_materials_transmission": {"transmissionFactor": 1,)"
        R"( "transmissionTexture": {"index": 0}}}}], "textures": [{"source": 0}], "images": [{"uri": "paper.png"}])";
    const std::string one = replaceOnce(f.json(), R"("mode": 4)", R"("mode": 4, "material": 0)");
    const Material glass = importScene(dir.write("glass.gltf", one)).scene.materials.at(0);
    EXPECT_EQ(glass.transmission.weight, 1.0f);
    EXPECT_EQ(glass.transmission.color, Color(0.5f, 0.7f, 0.9f));
    EXPECT_EQ(glass.transmission.ior, 1.33f);
    EXPECT_FALSE(glass.transmission.thin);
    EXPECT_EQ(glass.transmission.attenuationColor, Color(0.5f, 0.25f, 1));
    EXPECT_EQ(glass.transmission.attenuationDistance, 2.0f);
    EXPECT_EQ(glass.phong.diffuse, 0.0f);
    EXPECT_EQ(glass.phong.ambient, 0.0f);
    EXPECT_EQ(glass.phong.reflection, 0.0f) << "the renderer's Fresnel term reflects";
    const std::string two = replaceOnce(f.json(), R"("mode": 4)", R"("mode": 4, "material": 1)");
    const Material sheet = importScene(dir.write("sheet.gltf", two)).scene.materials.at(0);
    EXPECT_EQ(sheet.transmission.weight, 0.5f);
    EXPECT_TRUE(sheet.transmission.thin);
    EXPECT_FLOAT_EQ(sheet.phong.diffuse, 0.45f);
    const std::string three = replaceOnce(f.json(), R"("mode": 4)", R"("mode": 4, "material": 2)");
    const Material paper = importScene(dir.write("paper.gltf", three)).scene.materials.at(0);
    EXPECT_EQ(paper.transmission.weight, 1.0f) << "the renderers follow the texture per hit";
    ASSERT_TRUE(paper.transmission.texture);
    EXPECT_FLOAT_EQ(paper.phong.diffuse, 0.45f) << "the Phong coefficients take a transmission texture as mid-grey";
    EXPECT_THROW(importScene(dir.write(
                     "bad.gltf", replaceOnce(one, R"("transmissionFactor": 1)", R"("transmissionFactor": "all")"))),
                 InputError);
}

TEST(ImportGltf, ChoosesTheSceneAndRejectsAMissingOne) {
    TempDir dir;
    const std::string path = dir.write("s.gltf", GltfFixture().json());
    ImportOptions o;
    o.scene = 0;
    EXPECT_NO_THROW(importScene(path, o));
    o.scene = 1;
    EXPECT_THROW(importScene(path, o), InputError);
}

// Each broken rule is one clear InputError, never a crash or an out-of-bounds read.
struct BrokenRule {
    const char* name;
    const char* from;
    const char* to;
};

class ImportGltfBroken : public ::testing::TestWithParam<BrokenRule> {};

TEST_P(ImportGltfBroken, IsAnInputError) {
    TempDir dir;
    const std::string json = replaceOnce(GltfFixture().json(), GetParam().from, GetParam().to);
    EXPECT_THROW(importScene(dir.write("broken.gltf", json)), InputError);
}

INSTANTIATE_TEST_SUITE_P(
    Rules, ImportGltfBroken,
    ::testing::Values(
        BrokenRule{"AccessorPastItsView", R"("count": 3, "type": "VEC3")", R"("count": 4, "type": "VEC3")"},
        BrokenRule{"AccessorOffsetPastItsView", R"("componentType": 5126,)",
                   R"("componentType": 5126, "byteOffset": 4,)"},
        BrokenRule{"StrideShorterThanAnElement", R"("byteOffset": 0, "byteLength": 36)",
                   R"("byteOffset": 0, "byteLength": 36, "byteStride": 4)"},
        BrokenRule{"ViewPastItsBuffer", R"("byteOffset": 0, "byteLength": 36)", R"("byteOffset": 8, "byteLength": 36)"},
        BrokenRule{"MissingAccessor", R"("POSITION": 0)", R"("POSITION": 7)"},
        BrokenRule{"IndicesOfFloatType", R"("componentType": 5123)", R"("componentType": 5126)"},
        BrokenRule{"PositionsAsVec2", R"("type": "VEC3")", R"("type": "VEC2")"},
        BrokenRule{"MissingMesh", R"([{"mesh": 0}])", R"([{"mesh": 3}])"},
        BrokenRule{"MissingNode", R"("nodes": [0]})", R"("nodes": [5]})"},
        BrokenRule{"NodeIsItsOwnChild", R"([{"mesh": 0}])", R"([{"mesh": 0, "children": [0]}])"},
        BrokenRule{"NodeWithTwoParents", R"([{"mesh": 0}])", R"([{"children": [1, 1]}, {"mesh": 0}])"},
        BrokenRule{"MatrixNotAffine", R"([{"mesh": 0}])",
                   R"([{"mesh": 0, "matrix": [1,0,0,1, 0,1,0,0, 0,0,1,0, 0,0,0,1]}])"},
        BrokenRule{"UnknownMode", R"("mode": 4)", R"("mode": 9)"},
        BrokenRule{"MissingMaterial", R"("mode": 4)", R"("mode": 4, "material": 2)"},
        BrokenRule{"NoScene", R"("scene": 0, "scenes": [{"nodes": [0]}],)", ""}),
    [](const ::testing::TestParamInfo<BrokenRule>& p) { return std::string(p.param.name); });

TEST(ImportGltf, IndexOutOfRangeIsAnInputError) {
    TempDir dir;
    GltfFixture f;
    f.indices = {0, 1, 3};
    EXPECT_THROW(importScene(dir.write("i.gltf", f.json())), InputError);
}

TEST(ImportGltf, NanPositionIsAnInputError) {
    TempDir dir;
    GltfFixture f;
    f.positions[4] = std::nanf("");
    EXPECT_THROW(importScene(dir.write("nan.gltf", f.json())), InputError);
}

// A huge count with no bufferView would be all zeros: bounded by the file's data, not allocated.
TEST(ImportGltf, AHugeCountWithoutDataIsRefusedBeforeAllocating) {
    TempDir dir;
    std::string json = replaceOnce(GltfFixture().json(), R"({"bufferView": 0, "componentType": 5126, "count": 3,)",
                                   R"({"componentType": 5126, "count": 4000000000000,)");
    EXPECT_THROW(importScene(dir.write("huge.gltf", json)), InputError);
}

// A buffer URI may name files in the model's folder and below; "../" would let a model copy any
// readable file into the scene, so it needs ImportOptions::filesOutsideModelFolder.
TEST(ImportGltf, BuffersOutsideTheModelsFolderAreRefused) {
    TempDir dir;
    const std::string json = GltfFixture().json();
    const std::size_t start = json.find("data:application"), end = json.find('"', start);
    std::size_t badAt = 0;
    const auto bytes = decodeBase64(json.substr(json.find(',', start) + 1, end - json.find(',', start) - 1), badAt);
    ASSERT_TRUE(bytes);
    dir.write("outside.bin", std::string(bytes->begin(), bytes->end()));
    dir.write("model/data/inside.bin", std::string(bytes->begin(), bytes->end()));
    const auto naming = [&](const std::string& uri) {
        return dir.write("model/m.gltf", json.substr(0, start) + uri + json.substr(end));
    };
    EXPECT_NO_THROW(importScene(naming("data/inside.bin")));
    for (const std::string uri : {"../outside.bin", "data/../../outside.bin"}) {
        const std::string error = inputErrorOf([&] { importScene(naming(uri)); });
        EXPECT_NE(error.find("outside the model's folder"), std::string::npos) << uri << ": " << error;
        ImportOptions trusting;
        trusting.filesOutsideModelFolder = true;
        EXPECT_NO_THROW(importScene(naming(uri), trusting)) << uri;
    }
}

// Element 0 of the positions is replaced by the fourth point of the data, (5, 5, 5).
TEST(ImportGltf, SparseAccessorsReplaceTheirElements) {
    TempDir dir;
    GltfFixture f;
    f.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 5, 5, 5};
    const std::string json = replaceOnce(
        f.json(), R"("count": 4, "type": "VEC3"})",
        R"("count": 4, "type": "VEC3", "sparse": {"count": 1, "indices": {"bufferView": 1, "componentType": 5123},)"
        R"( "values": {"bufferView": 0, "byteOffset": 36}}})");
    ImportResult r = importScene(dir.write("sparse.gltf", json));
    r.scene.flatten();
    expectNear(r.scene.primitives.all<Triangle>()[0].p0, {5, 5, 5}, kLoose);
}

// Debian's Assimp aborts on these two files; they must reach tinygltf whatever their name.
TEST(ImportGltf, AGlbUnderAnyNameNeverReachesAssimp) {
    SKIP_WITHOUT_SHARED_MODELS();
    TempDir dir;
    for (const char* name : {"CubeInvalidBufferViewLength.glb", "CubeInvalidAccessorByteOffset.glb"}) {
        std::ifstream in(sharedModels() + "/bad/glb-sdk/" + name, std::ios::binary);
        const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        ASSERT_FALSE(bytes.empty());
        EXPECT_THROW(importScene(dir.write("renamed.model", bytes)), InputError);
        EXPECT_THROW(importScene(dir.write("renamed", bytes)), InputError);
    }
}

// NORMAL, TEXCOORD_0 and COLOR_0 reach the models: the Duck has normals and texture
// coordinates, VertexColorTest colours.
TEST(ImportGltf, VertexNormalsTextureCoordinatesAndColoursAreKept) {
    SKIP_WITHOUT_SHARED_MODELS();
    const ImportResult duck = importScene(sharedModels() + "/glb/Duck/Duck.glb");
    ASSERT_EQ(duck.scene.models.size(), 1u);
    const Model& m = duck.scene.models[0];
    EXPECT_EQ(m.vertexNormals.size(), 9 * m.triangleCount());
    EXPECT_EQ(m.vertexUvs.size(), 6 * m.triangleCount());
    for (std::size_t i = 0; i < m.vertexNormals.size(); i += 3)
        EXPECT_NEAR(std::hypot(m.vertexNormals[i], m.vertexNormals[i + 1], m.vertexNormals[i + 2]), 1, 1e-5);
    const ImportResult colors = importScene(sharedModels() + "/glb/VertexColorTest/VertexColorTest.glb");
    std::size_t coloured = 0;
    for (const Model& c : colors.scene.models) coloured += !c.vertexColors.empty();
    EXPECT_GT(coloured, 0u);
}

// NormalTangentMirrorTest gives its tangents (TANGENT): kept, with their handedness, mirrored halves and all.
TEST(ImportGltf, TangentsAreKeptWithTheirHandedness) {
    SKIP_WITHOUT_SHARED_MODELS();
    const ImportResult r = importScene(sharedModels() + "/glb/NormalTangentMirrorTest/NormalTangentMirrorTest.glb");
    std::size_t right = 0, left = 0;
    for (const Model& m : r.scene.models) {
        ASSERT_EQ(m.vertexTangents.size(), 12 * m.triangleCount());
        for (std::size_t i = 3; i < m.vertexTangents.size(); i += 4) {
            right += m.vertexTangents[i] == 1;
            left += m.vertexTangents[i] == -1;
        }
    }
    EXPECT_GT(right, 0u);
    EXPECT_GT(left, 0u) << "the mirrored halves are left-handed";
}

// A 2x2 PNG, red and green in a checkerboard (made with zlib, 73 bytes).
const char* const kCheckerPng =
    "iVBORw0KGgoAAAANSUhEUgAAAAIAAAACCAIAAAD91JpzAAAAEElEQVR42mP4z8DAAMFAEgAd8AP9Cd2apwAAAABJRU5ErkJggg==";

std::vector<std::uint8_t> checkerPng() {
    std::size_t bad = 0;
    return *decodeBase64(kCheckerPng, bad);
}

// A unit quad in z = 0 with texture coordinates, its material's base colour the image `imageJson`.
std::string texturedQuadJson(const std::string& buffers, const std::string& imageJson, std::size_t bufferBytes) {
    return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "indices": 2, "material": 0}]}],
        "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}],
        "textures": [{"source": 0}], "images": [)" +
           imageJson + R"(], "buffers": [)" + buffers + R"(],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 32},
                        {"buffer": 0, "byteOffset": 80, "byteLength": 12}, {"buffer": 0, "byteOffset": 92, "byteLength": )" +
           std::to_string(bufferBytes - 92) + R"(}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
                       "min": [0, 0, 0], "max": [1, 1, 0]},
                      {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC2"},
                      {"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"}]})";
}

// The quad's geometry, then `image`.
std::vector<std::uint8_t> quadBuffer(const std::vector<std::uint8_t>& image) {
    const float positions[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, uvs[] = {0, 1, 1, 1, 1, 0, 0, 0};
    const std::uint16_t indices[] = {0, 1, 2, 0, 2, 3};
    std::vector<std::uint8_t> bytes;
    const auto append = [&](const void* p, std::size_t n) {
        bytes.insert(bytes.end(), static_cast<const std::uint8_t*>(p), static_cast<const std::uint8_t*>(p) + n);
    };
    append(positions, sizeof positions);
    append(uvs, sizeof uvs);
    append(indices, sizeof indices);
    append(image.data(), image.size());
    return bytes;
}

// A .glb (glTF 2.0 binary: header, JSON chunk, BIN chunk) of `json` and `bin`.
std::string glbOf(std::string json, std::vector<std::uint8_t> bin) {
    while (json.size() % 4) json += ' ';
    while (bin.size() % 4) bin.push_back(0);
    std::string glb;
    const auto u32 = [&](std::uint32_t v) {
        for (int i = 0; i < 4; ++i) glb += char((v >> (8 * i)) & 0xff);
    };
    glb += "glTF";
    u32(2);
    u32(std::uint32_t(12 + 8 + json.size() + 8 + bin.size()));
    u32(std::uint32_t(json.size()));
    u32(0x4E4F534A);  // JSON
    glb += json;
    u32(std::uint32_t(bin.size()));
    u32(0x004E4942);  // BIN
    glb.append(bin.begin(), bin.end());
    return glb;
}

// The quad with the PNG in a bufferView, as a .glb.
std::string glbWithEmbeddedPng() {
    const std::vector<std::uint8_t> bin = quadBuffer(checkerPng());
    return glbOf(texturedQuadJson(R"({"byteLength": )" + std::to_string(bin.size()) + "}",
                                  R"({"bufferView": 3, "mimeType": "image/png", "name": "checker"})", bin.size()),
                 bin);
}

// Images in a .glb's binary chunk and in data: URIs are kept as their encoded bytes
// (Texture::embedded), under a file name with the format's extension.
TEST(ImportGltf, EmbeddedImagesAreKeptAsTheirBytes) {
    TempDir dir;
    const ImportResult glb = importScene(dir.write("quad.glb", glbWithEmbeddedPng()));
    ASSERT_EQ(glb.scene.textures.size(), 1u);
    const Texture& t = glb.scene.textures[0];
    ASSERT_TRUE(t.embedded);
    EXPECT_EQ(*t.embedded, checkerPng());
    EXPECT_EQ(t.file, "checker.png");
    EXPECT_TRUE(t.path.empty());
    ASSERT_TRUE(glb.scene.materials.at(glb.scene.instances.at(0).material).colorTexture);

    const std::vector<std::uint8_t> buffer = quadBuffer({});
    const std::string json = texturedQuadJson(
        R"({"byteLength": 92, "uri": "data:application/octet-stream;base64,)" + test::base64(buffer) + R"("})",
        std::string(R"({"uri": "data:image/png;base64,)") + kCheckerPng + R"("})", 92 + 73);
    const ImportResult dataUri = importScene(dir.write("quad.gltf", json));
    ASSERT_EQ(dataUri.scene.textures.size(), 1u);
    ASSERT_TRUE(dataUri.scene.textures[0].embedded);
    EXPECT_EQ(*dataUri.scene.textures[0].embedded, checkerPng());
    EXPECT_EQ(dataUri.scene.textures[0].file, "image0.png");
}

// tinygltf throws std::out_of_range for a .glb whose buffer 0 declares byteLength 0 beside a BIN
// chunk of data (fuzz/corpus/gltf_import/glb_buffer_of_length_0): an input error naming the file,
// not an exception that ends rt-convert with exit 1 (or, in the fuzzer, std::terminate).
TEST(ImportGltf, AGlbWhoseBufferDeclaresNoBytesIsAnInputError) {
    TempDir dir;
    const std::vector<std::uint8_t> bin = quadBuffer(checkerPng());
    const std::string path = dir.write(
        "empty-buffer.glb",
        glbOf(texturedQuadJson(R"({"byteLength": 0})", R"({"bufferView": 3, "mimeType": "image/png"})", bin.size()),
              bin));
    try {
        importScene(path);
        FAIL() << "imported";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("empty-buffer.glb"), std::string::npos) << e.what();
    }
}

// A bufferView that reaches past its buffer is an error, not a read outside it.
TEST(ImportGltf, EmbeddedImageOutsideItsBufferIsAnError) {
    TempDir dir;
    std::string glb = glbWithEmbeddedPng();
    const std::string from = R"("byteOffset": 92, "byteLength": 73)";
    const std::size_t at = glb.find(from);
    ASSERT_NE(at, std::string::npos);
    glb.replace(at, from.size(), R"("byteOffset": 92, "byteLength": 99)");
    EXPECT_THROW(importScene(dir.write("bad.glb", glb)), InputError);
}

}  // namespace
}  // namespace rt
