#include "scene/model_file.h"

#include "core/error.h"
#include "scene_test_files.h"
#include "test_util.h"

using namespace rt;

TEST(SceneModelFile, FormatNames) {
    EXPECT_EQ(modelFormatFromName("RAW"), Model::Format::Raw);
    EXPECT_EQ(modelFormatFromName("3ds"), Model::Format::Max3ds);
    EXPECT_EQ(modelFormatFromName("obj"), std::nullopt);
    EXPECT_EQ(modelFormatFromExtension("a/b.3DS"), Model::Format::Max3ds);
    EXPECT_EQ(modelFormatFromExtension("a/b.raw"), Model::Format::Raw);
    EXPECT_EQ(modelFormatFromExtension("a/testFormatDetection"), std::nullopt);
    EXPECT_STREQ(modelFormatName(Model::Format::Max3ds), "3ds");
}

// 3ds needs Assimp, which the scene layer does not link (import/model_file.h reads it).
TEST(SceneModelFile, TheScenesOwnReaderReadsRawOnly) {
    TempDir dir;
    writeRawFile(dir.path("s.raw"), rawModel({}, {1, 2, 3, 4}));
    EXPECT_EQ(readRawModelFileOnly(dir.path("s.raw"), Model::Format::Raw).sphereData, (std::vector<float>{1, 2, 3, 4}));
    EXPECT_EQ(inputErrorOf([] { readRawModelFileOnly("a/ship.3ds", Model::Format::Max3ds); }),
              "a/ship.3ds: a 3ds model is read through the import layer (rt::loadScene); "
              "this scene reader takes RAW models only");
}
