#include "import/assimp_contained.h"

#include <assimp/scene.h>

#include <assimp/Exporter.hpp>
#include <stdexcept>

#include "core/contained.h"
#include "core/error.h"

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

const aiScene* readContained(Assimp::Importer& importer, const std::string& path, std::uint64_t inputBytes,
                             const std::function<const aiScene*(Assimp::Importer&)>& read) {
    const std::string dump = runContained(
        path, "Assimp",
        [&] {
            Assimp::Importer reader;
            const aiScene* scene = read(reader);
            Assimp::Exporter exporter;
            const aiExportDataBlob* blob = exporter.ExportToBlob(scene, "assbin");
            if (!blob) throw std::runtime_error(exporter.GetErrorString());
            return std::string(static_cast<const char*>(blob->data), blob->size);
        },
        limitsFor(inputBytes));
    return readReply(importer, path, dump);
}

const aiScene* readReply(Assimp::Importer& importer, const std::string& path, const std::string& reply) {
    const aiScene* scene = importer.ReadFileFromMemory(reply.data(), reply.size(), 0, "assbin");
    if (!scene || !scene->mRootNode)
        throw std::runtime_error(
            path + ": the scene Assimp's process sent back does not read back: " + importer.GetErrorString());
    return scene;
}

}  // namespace rt
