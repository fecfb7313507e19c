#include "os/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

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

TEST_F(AtomicFile, UnwritableFolderIsAnError) {
    EXPECT_THROW(writeFileAtomically((dir / "missing" / "a.txt").string(), [](std::ostream& os) { os << "x"; }),
                 std::runtime_error);
}

// Writes a scene-like pair: `name` in the file, and a file `name`.raw in the folder.
void writePair(const fs::path& dir, const std::string& name) {
    commitFileAndFolderAtomically((dir / "scene.xml").string(), (dir / "scene").string(),
                                  [&](const std::string& file, const std::string& folder) {
                                      std::ofstream(file) << name;
                                      std::ofstream(fs::path(folder) / (name + ".raw")) << name;
                                      return true;
                                  });
}

TEST_F(AtomicFile, FolderIsReplacedWholeWithItsFile) {
    writePair(dir, "old");
    writePair(dir, "new");
    EXPECT_EQ(slurp(dir / "scene.xml"), "new");
    EXPECT_EQ(slurp(dir / "scene" / "new.raw"), "new");
    EXPECT_FALSE(fs::exists(dir / "scene" / "old.raw")) << "nothing stale from the earlier output";
    EXPECT_EQ(entries(), 2u) << "no temporary left";
}

TEST_F(AtomicFile, FailedFolderWriteLeavesTheOldFolderAndFile) {
    writePair(dir, "old");
    const auto xml = (dir / "scene.xml").string(), folder = (dir / "scene").string();
    EXPECT_THROW(commitFileAndFolderAtomically(xml, folder,
                                               [](const std::string& file, const std::string& temp) -> bool {
                                                   std::ofstream(file) << "half";
                                                   std::ofstream(fs::path(temp) / "old.raw") << "half";
                                                   throw std::runtime_error("disk full");
                                               }),
                 std::runtime_error);
    const auto refuse = [](const std::string&, const std::string&) { return false; };
    EXPECT_THROW(commitFileAndFolderAtomically(xml, folder, refuse), std::runtime_error);
    EXPECT_EQ(slurp(xml), "old");
    EXPECT_EQ(slurp(fs::path(folder) / "old.raw"), "old");
    EXPECT_EQ(entries(), 2u);
}

TEST_F(AtomicFile, AFileWhereTheFolderGoesIsAnError) {
    const auto path = (dir / "scene").string();
    std::ofstream(path) << "mine";
    EXPECT_THROW(writePair(dir, "new"), std::runtime_error);
    EXPECT_EQ(slurp(path), "mine");
    EXPECT_EQ(entries(), 1u);
}

// Concurrent writers of the same pair take turns: the file always names a file of the folder.
TEST_F(AtomicFile, ConcurrentWritersPublishWholePairs) {
    for (int round = 0; round < 20; ++round) {
        std::thread a([&] { writePair(dir, "a"); }), b([&] { writePair(dir, "b"); });
        a.join();
        b.join();
        const std::string name = slurp(dir / "scene.xml");
        EXPECT_TRUE(fs::exists(dir / "scene" / (name + ".raw"))) << "round " << round << ": " << name;
        EXPECT_EQ(entries(), 2u);
    }
}

// A device, a FIFO or a socket is written in place, never replaced by a regular file.
TEST_F(AtomicFile, DevicesAreWrittenInPlace) {
    if (::geteuid() != 0) GTEST_SKIP() << "making device nodes needs root";
    const fs::path full = dir / "full", null = dir / "null";
    ASSERT_EQ(::mknod(full.c_str(), S_IFCHR | 0666, makedev(1, 7)), 0) << "mknod: " << std::strerror(errno);
    ASSERT_EQ(::mknod(null.c_str(), S_IFCHR | 0666, makedev(1, 3)), 0);
    try {
        writeFileAtomically(full.string(), [](std::ostream& os) { os << "text"; });
        ADD_FAILURE() << "writing to a full device succeeded";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("No space left on device"), std::string::npos) << e.what();
    }
    writeFileAtomically(null.string(), [](std::ostream& os) { os << "text"; });
    EXPECT_TRUE(fs::is_character_file(full));
    EXPECT_TRUE(fs::is_character_file(null));
    prepareOutputFile(null.string());
    EXPECT_EQ(entries(), 2u);
}

TEST_F(AtomicFile, AFifosReaderGetsTheText) {
    const fs::path fifo = dir / "fifo";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    // Opened read-write and non-blocking, the reader's end neither waits for the writer nor
    // hangs the test if the FIFO were replaced.
    const int reader = ::open(fifo.c_str(), O_RDWR | O_NONBLOCK);
    ASSERT_GE(reader, 0);
    writeFileAtomically(fifo.string(), [](std::ostream& os) { os << "through the pipe"; });
    char got[64] = {};
    const ssize_t n = ::read(reader, got, sizeof got - 1);
    ::close(reader);
    EXPECT_EQ(std::string(got, std::size_t(std::max<ssize_t>(n, 0))), "through the pipe");
    EXPECT_TRUE(fs::is_fifo(fifo));
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

TEST_F(AtomicFile, ATemporaryFolderPublishesItsFileAndLeavesNothingElse) {
    const std::string path = (dir / "copy.tx").string();
    {
        const TemporaryFolder temporary(path);
        const fs::path file = temporary.file();
        EXPECT_EQ(file.filename(), "copy.tx");
        EXPECT_TRUE(file.parent_path().filename().string().starts_with(".copy.rt-tmp-")) << file;
        std::ofstream(file) << "made";
        std::ofstream(file.string() + ".temp") << "a library's own temporary";
        temporary.commit();
        EXPECT_EQ(slurp(path), "made");
    }
    EXPECT_EQ(entries(), 1u);
}

TEST_F(AtomicFile, StaleTemporariesOfDeadProcessesAreRemoved) {
    // PID 2^22 + 1 is above Linux's largest PID, so no process runs under it.
    const fs::path dead = dir / ".a.rt-tmp-4194305-0.png";
    const fs::path alive = dir / (".a.rt-tmp-" + std::to_string(::getpid()) + "-7.png");
    const fs::path other = dir / ".b.rt-tmp-4194305-0.png", deadFolder = dir / ".models.rt-tmp-4194305-0";
    for (const fs::path& p : {dead, alive, other}) std::ofstream(p) << "x";
    fs::create_directories(deadFolder / "inside");
    writeFileAtomically((dir / "a.png").string(), [](std::ostream& os) { os << "new"; });
    EXPECT_FALSE(fs::exists(dead));
    EXPECT_TRUE(fs::exists(alive)) << "a running process's temporary";
    EXPECT_TRUE(fs::exists(other)) << "another target's temporary";
    const auto emptyPair = [](const std::string& file, const std::string&) { return bool(std::ofstream(file)); };
    commitFileAndFolderAtomically((dir / "models.xml").string(), (dir / "models").string(), emptyPair);
    EXPECT_FALSE(fs::exists(deadFolder));
}
