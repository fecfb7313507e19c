#include "io/model_file.h"

#include "core/error.h"
#include "scene_test_files.h"
#include "test_util.h"

using namespace rt;

namespace {

const std::string kModels = RT_SHARED_DIR "/models/";

}  // namespace

TEST(ImportModelFile, FormatNames) {
    EXPECT_EQ(modelFormatFromName("RAW"), Model::Format::Raw);
    EXPECT_EQ(modelFormatFromName("3ds"), Model::Format::Max3ds);
    EXPECT_EQ(modelFormatFromName("obj"), std::nullopt);
    EXPECT_EQ(modelFormatFromExtension("a/b.3DS"), Model::Format::Max3ds);
    EXPECT_EQ(modelFormatFromExtension("a/b.raw"), Model::Format::Raw);
    EXPECT_EQ(modelFormatFromExtension("a/testFormatDetection"), std::nullopt);
    EXPECT_STREQ(modelFormatName(Model::Format::Max3ds), "3ds");
}

TEST(ImportModelFile, ThreeDsTriangleCountsMatchTheManifest) {
    SKIP_WITHOUT_SHARED_MODELS();
    // Assimp with aiProcess_Triangulate: MANIFEST.md "triangles (mesh data)"; every node places its meshes once.
    EXPECT_EQ(readModelFile(kModels + "3ds/fels/fels.3ds", Model::Format::Max3ds).triangleCount(), 768u);
    EXPECT_EQ(readModelFile(kModels + "3ds/test1/test1.3ds", Model::Format::Max3ds).triangleCount(), 108u);
    EXPECT_EQ(
        readModelFile(kModels + "3ds/cubes_with_alpha/cubes_with_alpha.3DS", Model::Format::Max3ds).triangleCount(),
        60u);
    // No extension: Assimp detects the format from the content.
    const Model m = readModelFile(kModels + "3ds/testFormatDetection/testFormatDetection", Model::Format::Max3ds);
    EXPECT_EQ(m.triangleCount(), 1368u);
    EXPECT_TRUE(m.sphereData.empty());
}

TEST(ImportModelFile, BrokenThreeDsFilesAreInputErrors) {
    SKIP_WITHOUT_SHARED_MODELS();
    for (const char* bad :
         {"bad/derived-3ds/fels_truncated_4096.3ds", "bad/derived-3ds/test1_bad_main_chunk_length.3ds",
          "bad/derived-3ds/random_bytes_named.3ds", "bad/assimp-invalid/empty.3ds"}) {
        const std::string path = kModels + bad;
        const std::string error = inputErrorOf([&] { readModelFile(path, Model::Format::Max3ds); });
        EXPECT_EQ(error.rfind(path + ": cannot read 3ds model: ", 0), 0u) << error;
    }
    // Other formats never reach Assimp's other importers (some crash on bad input).
    for (const char* other :
         {"gltf/Box/Box.gltf", "glb/Box/Box.glb", "bad/gltf-tinygltf-fuzz/tinygltf-afl-000062.gltf"})
        EXPECT_EQ(inputErrorOf([&] { readModelFile(kModels + other, Model::Format::Max3ds); }),
                  kModels + other + ": cannot read 3ds model: not a 3DS file (no 0x4D4D main chunk at byte 0)");
    EXPECT_EQ(inputErrorOf([&] { readModelFile(kModels + "none.3ds", Model::Format::Max3ds); }),
              kModels + "none.3ds: cannot open: No such file or directory");
}

TEST(ImportModelFile, RawFilesGoThroughTheRawReader) {
    TempDir dir;
    writeRawFile(dir.path("s.raw"), rawModel({}, {1, 2, 3, 4}));
    EXPECT_EQ(readModelFile(dir.path("s.raw"), Model::Format::Raw).sphereData, (std::vector<float>{1, 2, 3, 4}));
}
