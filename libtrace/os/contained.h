// Running a third-party parser where its failures cannot reach the tool. Assimp aborts on
// internal assertions, writes past its buffers, spins for ever and asks for tens of gigabytes
// on some broken files (docs/robustness.md); rt cannot fix it, so it reads in a child process
// with limits on CPU time, wall-clock time, memory and what it may send back. Whatever goes
// wrong there ends the child, and the caller gets one rt::InputError naming the file.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

namespace rt {

struct ContainmentLimits {
    double cpuSeconds = 4;                // then the kernel stops the child (RLIMIT_CPU)
    double wallSeconds = 8;               // then the parent kills it, for a child that waits
    std::uint64_t memoryBytes = 1 << 29;  // address space the child may add to what it inherits
    std::uint64_t replyBytes = 1 << 28;   // the most it may send back
};

// Runs `work` in a forked child under `limits` and returns the bytes it returned. An
// rt::InputError thrown by `work` is thrown here with its message; a crash, a signal, an
// exit, running out of time or memory, or a reply beyond the limit throw rt::InputError
// "`file`: `parser` ...", with the first line the child wrote to standard error (an
// assertion's message) appended. The child's standard output and error never reach the
// tool's. Throws std::runtime_error if no child process can be started.
std::string runContained(const std::string& file, const std::string& parser, const std::function<std::string()>& work,
                         const ContainmentLimits& limits);

}  // namespace rt
