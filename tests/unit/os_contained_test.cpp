// A parser run in a child process (os/contained.h): what it returns comes back; whatever it
// does wrong (an abort, a loop, a wait, a huge allocation, a flood of output) becomes one
// rt::InputError naming the file and the parser, in bounded time.
#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "core/error.h"
#include "os/contained.h"

namespace rt {
namespace {

ContainmentLimits quickLimits() {
    ContainmentLimits limits;
    limits.cpuSeconds = 1;
    limits.wallSeconds = 3;
    limits.memoryBytes = std::uint64_t(256) << 20;
    limits.replyBytes = std::uint64_t(1) << 20;
    return limits;
}

// The message of the InputError that `work` ends in, run contained.
std::string errorOf(const std::function<std::string()>& work, ContainmentLimits limits = quickLimits()) {
    try {
        runContained("model.ply", "Parser", work, limits);
    } catch (const InputError& e) {
        return e.what();
    }
    ADD_FAILURE() << "no rt::InputError";
    return "";
}

TEST(CoreContained, ReturnsWhatTheWorkReturnsWhateverItsBytes) {
    const std::string bytes("a\0b\nc", 5);
    EXPECT_EQ(runContained(
                  "f", "Parser", [&] { return bytes; }, quickLimits()),
              bytes);
    const std::string large(3 << 16, 'x');  // more than a pipe holds at once
    EXPECT_EQ(runContained(
                  "f", "Parser", [&] { return large; }, quickLimits()),
              large);
}

TEST(CoreContained, AnInputErrorKeepsItsMessage) {
    EXPECT_EQ(errorOf([]() -> std::string { throw InputError("model.ply: bad header"); }), "model.ply: bad header");
}

TEST(CoreContained, AnAbortIsAnErrorWithWhatTheChildSaid) {
    const std::string e = errorOf([]() -> std::string {
        std::fputs("assertion failed: numOut != 0\n", stderr);
        std::abort();
    });
    EXPECT_EQ(e.rfind("model.ply: Parser crashed reading the file (Aborted): assertion failed: numOut != 0", 0), 0u)
        << e;
}

TEST(CoreContained, ASpinningParserIsStoppedByItsCpuTime) {
    const auto start = std::chrono::steady_clock::now();
    const std::string e = errorOf([]() -> std::string {
        std::atomic<unsigned long> spins = 0;  // atomic: a loop without side effects may be assumed to end
        for (;;) spins.fetch_add(1, std::memory_order_relaxed);
    });
    EXPECT_NE(e.find("model.ply: Parser "), std::string::npos) << e;
    EXPECT_NE(e.find("; stopped"), std::string::npos) << e;
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(10));
}

TEST(CoreContained, AWaitingParserIsKilledAtTheWallClockLimit) {
    ContainmentLimits limits = quickLimits();
    limits.wallSeconds = 0.5;
    const std::string e = errorOf(
        []() -> std::string {
            sleep(60);
            return "";
        },
        limits);
    EXPECT_EQ(e, "model.ply: Parser did not finish reading the file in 1 s; stopped");
}

TEST(CoreContained, AReplyBeyondItsLimitIsStopped) {
    const std::string e = errorOf([] { return std::string(2 << 20, 'x'); });
    EXPECT_EQ(e.rfind("model.ply: Parser made more than", 0), 0u) << e;
}

#if !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)
// Sanitizers reserve terabytes of address space and report a failed allocation themselves.
TEST(CoreContained, AHugeAllocationIsAnErrorNotTheMachinesMemory) {
    const std::string e = errorOf([] {
        std::vector<char> huge(std::size_t(8) << 30);
        return std::string(huge.data(), 1);
    });
    EXPECT_EQ(e, "model.ply: Parser needed more than 0.3 GB of memory reading the file; stopped");
}
#endif

}  // namespace
}  // namespace rt
