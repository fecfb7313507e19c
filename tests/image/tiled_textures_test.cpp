// The tx cache (libtrace/image/tiled_textures.*): stale temporaries of dead makers are removed,
// the cache keeps within its bound by removing the least recently used copies not in use, and
// makers of the same copy at the same time all succeed with one copy.
#include "image/tiled_textures.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <future>
#include <thread>
#include <vector>

using namespace rt;
namespace fs = std::filesystem;

namespace {

fs::path freshFolder(const std::string& name) {
    const fs::path folder = fs::path(testing::TempDir()) / name;
    fs::remove_all(folder);
    return folder;
}

// A 64 x 64 PNG of noise: each seed another picture, so another copy of about the same size.
TextureSource noisePicture(const fs::path& folder, int seed) {
    fs::create_directories(folder);
    const fs::path path = folder / ("noise" + std::to_string(seed) + ".png");
    OIIO::ImageBuf noise(OIIO::ImageSpec(64, 64, 3, OIIO::TypeDesc::UINT8));
    OIIO::ImageBufAlgo::noise(noise, "uniform", 0.0f, 1.0f, false, seed);
    EXPECT_TRUE(noise.write(path.string()));
    TextureSource source;
    source.path = path.string();
    return source;
}

// The names in the copies' folder of the tx cache `folder`, sorted.
std::vector<std::string> namesIn(const fs::path& folder) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(folder / kTxCopiesFolder))
        names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

std::uintmax_t copiesSize(const fs::path& folder) {
    std::uintmax_t total = 0;
    for (const auto& entry : fs::directory_iterator(folder / kTxCopiesFolder))
        if (entry.path().extension() == ".tx" && !entry.path().filename().string().starts_with("."))
            total += entry.file_size();
    return total;
}

// A temporary folder as a maker left it, with a file in it, last changed `age` ago.
fs::path leftTemporary(const fs::path& folder, const std::string& name, std::chrono::minutes age) {
    const fs::path temporary = folder / name;
    fs::create_directories(temporary);
    std::ofstream(temporary / "half.tx") << "half a copy";
    const auto then = fs::file_time_type::clock::now() - age;
    fs::last_write_time(temporary / "half.tx", then);
    fs::last_write_time(temporary, then);
    return temporary;
}

}  // namespace

TEST(TiledTextures, TemporariesOfDeadMakersUnchangedForLongAreRemoved) {
    const fs::path folder = freshFolder("tx-stale"), sources = freshFolder("tx-stale-sources");
    const fs::path copies = folder / kTxCopiesFolder;
    fs::create_directories(copies);
    const std::string dead = "4194305", alive = std::to_string(getpid());  // above Linux's largest PID
    const fs::path stale = leftTemporary(copies, ".old-0123.rt-tmp-" + dead + "-0.tx", std::chrono::minutes(60));
    // Kept: a dead maker's recent one (maybe another machine's, where the id means another
    // process), and a live process's old one.
    const fs::path recent = leftTemporary(copies, ".new-0123.rt-tmp-" + dead + "-1.tx", std::chrono::minutes(1));
    const fs::path running = leftTemporary(copies, ".run-0123.rt-tmp-" + alive + "-2.tx", std::chrono::minutes(60));
    const TiledCopy copy = tiledCopy(folder.string(), noisePicture(sources, 1));
    EXPECT_FALSE(fs::exists(stale));
    EXPECT_TRUE(fs::exists(recent));
    EXPECT_TRUE(fs::exists(running));
    EXPECT_TRUE(fs::exists(copy.path()));
}

TEST(TiledTextures, TheCacheKeepsWithinItsBoundRemovingTheLeastRecentlyUsedCopy) {
    const fs::path folder = freshFolder("tx-bound"), sources = freshFolder("tx-bound-sources");
    const TextureSource a = noisePicture(sources, 1), b = noisePicture(sources, 2), c = noisePicture(sources, 3);
    std::string pathA, pathB;
    { pathA = tiledCopy(folder.string(), a).path(); }
    const std::uint64_t bound = fs::file_size(pathA) * 5 / 2;  // room for two copies, not three
    // The file system's clock ticks every few milliseconds: uses in one tick are not ordered.
    const auto nextTick = [] { std::this_thread::sleep_for(std::chrono::milliseconds(50)); };
    nextTick();
    { pathB = tiledCopy(folder.string(), b, bound).path(); }
    nextTick();
    { EXPECT_EQ(tiledCopy(folder.string(), a, bound).path(), pathA); }  // reused: now b is the least recent
    const TiledCopy copyC = tiledCopy(folder.string(), c, bound);
    EXPECT_TRUE(fs::exists(pathA));
    EXPECT_FALSE(fs::exists(pathB));
    EXPECT_TRUE(fs::exists(copyC.path()));
    EXPECT_LE(copiesSize(folder), bound);
}

TEST(TiledTextures, ACopyInUseIsNotRemoved) {
    const fs::path folder = freshFolder("tx-in-use"), sources = freshFolder("tx-in-use-sources");
    const TiledCopy inUse = tiledCopy(folder.string(), noisePicture(sources, 1));
    const TiledCopy added = tiledCopy(folder.string(), noisePicture(sources, 2), 1);  // a bound nothing fits in
    EXPECT_TRUE(fs::exists(inUse.path()));
    EXPECT_TRUE(fs::exists(added.path()));  // the new copy is kept too, even beyond the bound
    std::string released;
    { released = tiledCopy(folder.string(), noisePicture(sources, 3), 1).path(); }
    const TiledCopy next = tiledCopy(folder.string(), noisePicture(sources, 4), 1);
    EXPECT_FALSE(fs::exists(released));
    EXPECT_TRUE(fs::exists(inUse.path()));
}

TEST(TiledTextures, MakersOfTheSameCopyAtTheSameTimeAllSucceedWithOneCopy) {
    const fs::path folder = freshFolder("tx-concurrent"), sources = freshFolder("tx-concurrent-sources");
    const TextureSource picture = noisePicture(sources, 1);
    std::vector<std::future<std::string>> makers;
    for (int i = 0; i < 4; ++i)
        makers.push_back(std::async(std::launch::async, [&] { return tiledCopy(folder.string(), picture).path(); }));
    std::vector<std::string> paths;
    for (auto& maker : makers) ASSERT_NO_THROW(paths.push_back(maker.get()));
    for (const std::string& path : paths) EXPECT_EQ(path, paths[0]);
    EXPECT_EQ(namesIn(folder),
              (std::vector<std::string>{".lock", ".rt-tx-cache", fs::path(paths[0]).filename().string()}));
    OIIO::ImageBuf copy(paths[0]);
    ASSERT_TRUE(copy.init_spec(paths[0], 0, 0));
    EXPECT_EQ(copy.nmiplevels(), 7);  // 64 texels a side down to 1
}
