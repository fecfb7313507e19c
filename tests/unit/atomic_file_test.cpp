#include "core/atomic_file.h"

#include <filesystem>
#include <fstream>
#include <sstream>

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
