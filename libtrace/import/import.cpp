#include "import/import.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

#include "core/error.h"
#include "import/assimp_import.h"
#include "import/gltf_import.h"
#include "import/obj_import.h"
#include "import/scene_defaults.h"

namespace rt {
namespace {

void checkOptions(const ImportOptions& options) {
    if (!(options.scale > 0) || !std::isfinite(options.scale)) throw InputError("--scale must be a positive number");
    if (!(options.aspect > 0) || !std::isfinite(options.aspect)) throw InputError("--aspect must be a positive number");
}

void noteDrops(ImportReport& r) {
    if (r.droppedPoints || r.droppedLines)
        r.notes.push_back("skipped " + std::to_string(r.droppedPoints) + " point and " +
                          std::to_string(r.droppedLines) + " line primitive(s): rt renders triangles");
    if (r.droppedDegenerate)
        r.notes.push_back("dropped " + std::to_string(r.droppedDegenerate) + " degenerate (zero-area) triangle(s)");
}

}  // namespace

std::string lowerCaseExtension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

bool isGltfPath(const std::string& path) {
    const std::string ext = lowerCaseExtension(path);
    return ext == ".gltf" || ext == ".glb";
}

Transform rootTransform(const ImportOptions& options) {
    // Z-up to Y-up: a right-handed quarter turn about x takes +Z to +Y (and +Y to -Z).
    const Transform up = options.upAxis == UpAxis::Z ? Transform::rotateX(-kPi / 2) : Transform();
    const Real s = Real(options.scale);
    return Transform::scale(Vec3(s, s, s)) * up;
}

ImportResult importScene(const std::string& path, const ImportOptions& options) {
    checkOptions(options);
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) throw InputError(path + ": is a directory");
    if (!std::filesystem::is_regular_file(path, ec)) throw InputError(path + ": no such file");
    const Transform root = rootTransform(options);
    ImportResult result = isGltfPath(path) || hasGlbMagic(path) ? importGltf(path, options, root)
                          : lowerCaseExtension(path) == ".obj" ? importObj(path, options, root)
                                                               : importAssimp(path, options, root);
    if (result.scene.instances.empty()) throw InputError(path + ": nothing to convert: the scene places no triangles");
    noteDrops(result.report);
    addMissingCameraAndLight(result, options.aspect);
    return result;
}

}  // namespace rt
