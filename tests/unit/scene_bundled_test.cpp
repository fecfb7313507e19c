// The scenes shipped in scenes/ load, with the geometry their files describe.
#include <gtest/gtest.h>

#include <sstream>

#include "io/raw_model.h"
#include "io/xml_loader.h"
#include "os/input_file.h"

using namespace rt;

namespace {

Scene bundled(const std::string& name) { return loadSceneXml(RT_SOURCE_DIR "/scenes/" + name); }

}  // namespace

TEST(SceneBundled, Spheres) {
    const Scene scene = bundled("spheres.xml");
    EXPECT_EQ(scene.primitives.count<Triangle>(), 2u);  // the floor quad
    EXPECT_EQ(scene.primitives.count<Sphere>(), 6u);
    EXPECT_EQ(scene.materials.size(), 5u);  // four named and the default
    EXPECT_EQ(scene.lights.size(), 2u);
    EXPECT_TRUE(scene.warnings.empty());
}

TEST(SceneBundled, Transforms) {
    const Scene scene = bundled("transforms.xml");
    EXPECT_EQ(scene.models.size(), 2u);
    EXPECT_EQ(scene.instances.size(), 8u);
    EXPECT_EQ(scene.primitives.count<Triangle>(), 2u + 6 * 8);  // floor and six octahedra
    EXPECT_EQ(scene.primitives.count<Sphere>(), 2u * 6);        // two atoms
    EXPECT_TRUE(scene.warnings.empty());
}

TEST(SceneBundled, Inline) {
    const Scene scene = bundled("inline.xml");
    EXPECT_EQ(scene.models.at(0).triangleCount(), 8u);
    EXPECT_EQ(scene.primitives.count<Triangle>(), 2u + 1 + 2 * 8);
    EXPECT_NEAR(scene.camera.focalPixels(800), 630, 1e-3);  // f in pixels, zoom in percent
    EXPECT_TRUE(scene.warnings.empty());
}

TEST(SceneBundled, RawModelsAreWhatTheWriterWrites) {
    for (const char* name : {"octahedron.raw", "atom.raw"}) {
        const std::string path = RT_SOURCE_DIR "/scenes/models/" + std::string(name);
        std::ostringstream written;
        writeRaw(written, readRawFile(path));
        EXPECT_EQ(written.str(), readInputFile(path)) << name;
    }
}

TEST(Scene, DropDescriptionKeepsThePrimitives) {
    rt::Scene scene;
    rt::Model model;
    model.triangleVertices = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    scene.models.push_back(model);
    scene.instances.push_back({0, 0, rt::Transform::translate({0, 0, 5})});
    scene.flatten();
    scene.dropDescription();
    EXPECT_TRUE(scene.models.empty());
    EXPECT_TRUE(scene.instances.empty());
    ASSERT_EQ(scene.primitives.size(), 1u);
    EXPECT_EQ(scene.primitives.all<Triangle>()[0].p0.z, 5);
}
