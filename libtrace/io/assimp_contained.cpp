#include "io/assimp_contained.h"

#include <assimp/scene.h>

#include "io/assimp_reply.h"
#include "os/contained.h"

namespace rt {
namespace {

// Generous for real files, tight for small broken ones (a tool answers those within 10 s): the
// shared models read in milliseconds and a few megabytes; Assimp's PLY reader, the hungriest,
// holds some 30 bytes for each byte of an ASCII file.
ContainmentLimits limitsFor(std::uint64_t inputBytes) {
    ContainmentLimits limits;
    limits.cpuSeconds = 2 + 2 * double(inputBytes) / 1e6;
    limits.wallSeconds = 2 * limits.cpuSeconds;
    limits.memoryBytes = (std::uint64_t(512) << 20) + 64 * inputBytes;
    limits.replyBytes = (std::uint64_t(256) << 20) + 64 * inputBytes;
    return limits;
}

}  // namespace

std::unique_ptr<aiScene> readContained(const std::string& path, std::uint64_t inputBytes,
                                       const std::function<const aiScene*(Assimp::Importer&)>& read) {
    const std::string reply = runContained(
        path, "Assimp",
        [&] {
            Assimp::Importer reader;
            return writeAssimpReply(*read(reader), path);
        },
        limitsFor(inputBytes));
    return readAssimpReply(reply, path);
}

}  // namespace rt
