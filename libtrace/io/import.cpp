#include "io/import.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <string_view>
#include <vector>

#include "core/error.h"
#include "core/text.h"
#include "io/assimp_import.h"
#include "io/gltf_import.h"
#include "io/mesh_data.h"
#include "io/obj_import.h"
#include "io/raw_model.h"
#include "io/scene_defaults.h"
#include "os/input_file.h"
#include "os/sandbox.h"

namespace rt {
namespace {

void checkOptions(const ImportOptions& options) {
    if (!(options.scale > 0) || !std::isfinite(options.scale)) throw InputError("--scale must be a positive number");
    if (!(options.aspect > 0) || !std::isfinite(options.aspect)) throw InputError("--aspect must be a positive number");
}

// A thesis RAW model (appendix D) is a scene of one model placed once under the root, with
// rt's default material; the caller adds the camera and light.
ImportResult importRaw(const std::string& path, const ImportOptions& options) {
    ImportResult result;
    result.report.format = "thesis RAW model";
    Model model = readRawFile(path);
    if (model.triangleCount() + model.sphereCount() == 0) return result;
    model.name = std::filesystem::path(path).stem().string();
    result.scene.models.push_back(std::move(model));
    result.scene.materials.push_back(Material{});
    result.scene.materials.back().name = "default";
    result.scene.instances.push_back({0, 0, rootTransform(options)});
    result.report.meshes = 1;
    return result;
}

void noteDrops(ImportReport& r) {
    if (r.droppedPoints || r.droppedLines)
        r.notes.push_back("skipped " + std::to_string(r.droppedPoints) + " point and " +
                          std::to_string(r.droppedLines) + " line primitive(s): rt renders triangles");
    if (r.droppedDegenerate)
        r.notes.push_back("dropped " + std::to_string(r.droppedDegenerate) + " degenerate (zero-area) triangle(s)");
}

// Inverted winding is not an error (two-sided materials draw it well), but single-sided ones
// show such a mesh inside out: said once, naming the first few models.
void noteWindingAgainstNormals(ImportReport& r) {
    const std::vector<std::string>& models = r.modelsFacingAway;
    if (models.empty()) return;
    constexpr std::size_t kNamed = 3;
    std::string names;
    for (std::size_t i = 0; i < std::min(models.size(), kNamed); ++i) names += (i ? ", " : "") + models[i];
    if (models.size() > kNamed) names += " and " + std::to_string(models.size() - kNamed) + " more";
    r.notes.push_back(std::to_string(models.size()) +
                      " mesh(es) with most triangles facing away from their vertex normals (inverted winding: "
                      "single-sided materials show them inside out; --double-sided draws both sides): " +
                      names);
}

// The importers by format: the first entry whose extensions hold the file's (in lower case)
// or whose signature starts the file reads it; Assimp reads everything else. glTF comes first
// so that a GLB is read as one under any name.
struct FormatImporter {
    std::vector<std::string_view> extensions;  // lower case, with the dot
    std::string_view signature;                // the file's first bytes, whatever its name; empty: none
    ImportResult (*read)(const std::string& path, const ImportOptions& options);
};

const FormatImporter kFormatImporters[] = {
    {{".gltf", ".glb"}, kGlbMagic, importGltf},
    {{".obj"}, {}, importObj},
    {{".raw"}, "raw3d", importRaw},
};

bool reads(const FormatImporter& importer, const std::string& path, const std::string& extension) {
    return std::find(importer.extensions.begin(), importer.extensions.end(), extension) != importer.extensions.end() ||
           (!importer.signature.empty() && fileStartsWith(path, importer.signature));
}

ImportResult importByFormat(const std::string& path, const ImportOptions& options) {
    const std::string extension = lowerCaseExtension(path);
    for (const FormatImporter& importer : kFormatImporters)
        if (reads(importer, path, extension)) return importer.read(path, options);
    return importAssimp(path, options);
}

// Extensions of the pictures OpenImageIO reads that no importer does: given as a scene, such a
// file is a slip (an environment map for the model), which Assimp would call an unknown format.
constexpr std::string_view kImageExtensions[] = {".exr", ".hdr", ".png",  ".jpg", ".jpeg", ".tif", ".tiff", ".tga",
                                                 ".tx",  ".bmp", ".webp", ".pfm", ".gif",  ".psd", ".dds"};

bool isImageFile(const std::string& path) {
    const std::string extension = lowerCaseExtension(path);
    return std::find(std::begin(kImageExtensions), std::end(kImageExtensions), extension) != std::end(kImageExtensions);
}

// What every import ends with: something to render, its drops noted, a camera and a light.
ImportResult finishImport(ImportResult result, const std::string& name, const ImportOptions& options) {
    if (result.scene.instances.empty()) throw InputError(name + ": nothing to convert: the scene places no triangles");
    noteDrops(result.report);
    noteWindingAgainstNormals(result.report);
    if (options.doubleSided) makeDoubleSided(result.scene);
    addMissingCameraAndLight(result, options);
    return result;
}

}  // namespace

Transform rootTransform(const ImportOptions& options, UpAxis importerUp) {
    // Z-up to Y-up is a right-handed quarter turn about x: +Z to +Y (and +Y to -Z). The file's
    // axis is turned up, after undoing the turn the importer made.
    const UpAxis fileUp = options.upAxis.value_or(importerUp);
    const Real turns = Real(fileUp == UpAxis::Z) - Real(importerUp == UpAxis::Z);
    const Real s = Real(options.scale);
    return Transform::scale(Vec3(s, s, s)) * Transform::rotateX(-turns * kPi / 2);
}

bool fileStartsWith(const std::string& path, std::string_view magic) {
    std::ifstream in(path, std::ios::binary);
    std::string head(magic.size(), '\0');
    return in.read(head.data(), std::streamsize(head.size())) && head == magic;
}

bool looksLikeGltf(std::string_view bytes) {
    const std::size_t first = bytes.find_first_not_of(" \t\r\n");
    return bytes.starts_with(kGlbMagic) || (first != std::string_view::npos && bytes[first] == '{');
}

ImportResult importScene(const std::string& path, const ImportOptions& options) {
    if (path == "-") return importGltfFromStandardInput(readStandardInput(), options);
    checkOptions(options);
    requireInsideSandbox(path, "the model", path);
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) throw InputError(path + ": is a directory, not a model file");
    if (!std::filesystem::is_regular_file(path, ec)) throw InputError(path + ": no such file");
    if (isImageFile(path))
        throw InputError(path +
                         ": is an image, not a model or scene (an environment map goes to rt-render "
                         "--environment; a texture is named by the model's materials)");
    inputFileSize(path);  // refuses a file beyond --max-input before any parser sees it
    return finishImport(importByFormat(path, options), path, options);
}

ImportResult importGltfFromStandardInput(const std::string& bytes, const ImportOptions& options) {
    const std::string name = "<stdin>";
    checkOptions(options);
    if (!looksLikeGltf(bytes))
        throw InputError(
            name + ": standard input takes a glTF 2.0 model (binary GLB or JSON); give other model files by name");
    return finishImport(importGltfBytes(bytes, name, options), name, options);
}

std::vector<std::string> unreadableTextureNotes(const Scene& scene) {
    std::vector<std::string> notes;
    std::set<std::string> checked;
    for (const Texture& t : scene.textures) {
        if (t.kind != Texture::Kind::Image || t.embedded || !checked.insert(t.path).second) continue;
        std::error_code ec;
        std::string why;
        if (std::filesystem::is_directory(t.path, ec))
            why = "is a directory";
        else if (std::ifstream(t.path, std::ios::binary).fail())
            why = std::string("cannot read it (") + std::strerror(errno) + ")";
        if (!why.empty()) notes.push_back("texture file " + t.path + ": " + why + ": renders white");
    }
    return notes;
}

}  // namespace rt
