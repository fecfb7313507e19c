#include "core/atomic_file.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/error.h"
#include "test_util.h"

using namespace rt;
namespace fs = std::filesystem;

namespace {

std::string slurp(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

struct AtomicFile : ::testing::Test {
    fs::path dir = fs::temp_directory_path() / ("rt-atomic-" + std::to_string(::getpid()));
    void SetUp() override { fs::create_directories(dir); }
    void TearDown() override { fs::remove_all(dir); }
    std::size_t entries() const { return std::distance(fs::directory_iterator(dir), fs::directory_iterator()); }
};

}  // namespace

TEST_F(AtomicFile, WritesTheWholeFile) {
    const auto path = (dir / "a.txt").string();
    writeFileAtomically(path, [](std::ostream& os) { os << "hello"; });
    EXPECT_EQ(slurp(path), "hello");
    EXPECT_EQ(entries(), 1u);
}

TEST_F(AtomicFile, FailedWriteLeavesThePreviousFileAndNoTemporary) {
    const auto path = (dir / "a.txt").string();
    writeFileAtomically(path, [](std::ostream& os) { os << "old"; });
    EXPECT_THROW(writeFileAtomically(path,
                                     [](std::ostream& os) {
                                         os << "half";
                                         throw std::runtime_error("interrupted");
                                     }),
                 std::runtime_error);
    EXPECT_EQ(slurp(path), "old");
    EXPECT_EQ(entries(), 1u);
}

TEST_F(AtomicFile, CommitKeepsTheExtensionOfTheTarget) {
    const auto path = (dir / "image.exr").string();
    std::string seen;
    commitFileAtomically(path, [&](const std::string& temp) {
        seen = temp;
        std::ofstream(temp) << "x";
        return true;
    });
    EXPECT_EQ(fs::path(seen).extension(), ".exr");
    EXPECT_EQ(slurp(path), "x");
    EXPECT_THROW(commitFileAtomically(path, [](const std::string&) { return false; }), std::runtime_error);
    EXPECT_EQ(slurp(path), "x");
    EXPECT_EQ(entries(), 1u);
}

TEST_F(AtomicFile, UnwritableFolderIsAnError) {
    EXPECT_THROW(writeFileAtomically((dir / "missing" / "a.txt").string(), [](std::ostream& os) { os << "x"; }),
                 std::runtime_error);
}

TEST_F(AtomicFile, FolderIsReplacedWhole) {
    const auto folder = (dir / "models").string();
    commitFolderAtomically(folder, [](const std::string& temp) {
        std::ofstream(fs::path(temp) / "old.raw") << "old";
        return true;
    });
    commitFolderAtomically(folder, [](const std::string& temp) {
        std::ofstream(fs::path(temp) / "new.raw") << "new";
        return true;
    });
    EXPECT_EQ(slurp(fs::path(folder) / "new.raw"), "new");
    EXPECT_FALSE(fs::exists(fs::path(folder) / "old.raw")) << "nothing stale from the earlier output";
    EXPECT_EQ(entries(), 1u) << "no temporary folder left";
}

TEST_F(AtomicFile, FailedFolderWriteLeavesTheOldFolder) {
    const auto folder = (dir / "models").string();
    commitFolderAtomically(folder, [](const std::string& temp) {
        std::ofstream(fs::path(temp) / "a.raw") << "old";
        return true;
    });
    EXPECT_THROW(commitFolderAtomically(folder,
                                        [](const std::string& temp) -> bool {
                                            std::ofstream(fs::path(temp) / "a.raw") << "half";
                                            throw std::runtime_error("disk full");
                                        }),
                 std::runtime_error);
    EXPECT_THROW(commitFolderAtomically(folder, [](const std::string&) { return false; }), std::runtime_error);
    EXPECT_EQ(slurp(fs::path(folder) / "a.raw"), "old");
    EXPECT_EQ(entries(), 1u);
}

TEST_F(AtomicFile, AFileWhereTheFolderGoesIsAnError) {
    const auto path = (dir / "models").string();
    std::ofstream(path) << "mine";
    EXPECT_THROW(commitFolderAtomically(path, [](const std::string&) { return true; }), std::runtime_error);
    EXPECT_EQ(slurp(path), "mine");
    EXPECT_EQ(entries(), 1u);
}

TEST_F(AtomicFile, PrepareCreatesMissingFoldersAndRejectsWhatCannotBeWritten) {
    prepareOutputFile((dir / "new" / "deeper" / "a.png").string());
    EXPECT_TRUE(fs::is_directory(dir / "new" / "deeper"));
    EXPECT_TRUE(fs::is_empty(dir / "new" / "deeper")) << "the probe file was not removed";
    EXPECT_THROW(prepareOutputFile(dir.string()), InputError);  // a folder
    std::ofstream(dir / "plain") << "x";
    EXPECT_THROW(prepareOutputFile((dir / "plain" / "a.png").string()), InputError);  // a file where a folder goes
    prepareOutputFile("-");
}

TEST_F(AtomicFile, StaleTemporariesOfDeadProcessesAreRemoved) {
    // PID 2^22 + 1 is above Linux's largest PID, so no process runs under it.
    const fs::path dead = dir / ".a.rt-tmp-4194305-0.png";
    const fs::path alive = dir / (".a.rt-tmp-" + std::to_string(::getpid()) + "-7.png");
    const fs::path other = dir / ".b.rt-tmp-4194305-0.png", deadFolder = dir / ".models.rt-tmp-4194305-0";
    for (const fs::path& p : {dead, alive, other}) std::ofstream(p) << "x";
    fs::create_directories(deadFolder / "inside");
    commitFileAtomically((dir / "a.png").string(), [](const std::string& temp) {
        std::ofstream(temp) << "new";
        return true;
    });
    EXPECT_FALSE(fs::exists(dead));
    EXPECT_TRUE(fs::exists(alive)) << "a running process's temporary";
    EXPECT_TRUE(fs::exists(other)) << "another target's temporary";
    commitFolderAtomically((dir / "models").string(), [](const std::string&) { return true; });
    EXPECT_FALSE(fs::exists(deadFolder));
}
