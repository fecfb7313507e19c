// Importing 3-D model files into an rt::Scene in memory (docs/conversion.md).
//
// glTF 2.0 (.gltf, .glb) goes through tinygltf, OBJ through tinyobjloader's streaming API,
// everything else through Assimp: Debian's Assimp 5.2.5 glTF loader aborts the process on some
// broken files, and its OBJ loader needs 14 times the memory of what it reads, so neither is used.
// The importers keep the file's structure: one Model per distinct mesh (glTF: per mesh
// primitive, which carries the material; Assimp: per aiMesh; OBJ: per object, group and
// material), one Instance per place a node puts it, with the node's world transform.
// Degenerate triangles are dropped and counted.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace rt {

enum class UpAxis { Y, Z };

struct ImportOptions {
    std::optional<int> scene;   // glTF scene index; default: the file's default scene, else 0
    std::string camera;         // camera name or index; empty: the first perspective camera placed
    double scale = 1;           // uniform factor applied at the root (units)
    UpAxis upAxis = UpAxis::Y;  // the file's up axis; Z-up files are turned so that +Z becomes +Y
    double aspect = 4.0 / 3.0;  // width/height used to turn a vertical fov into rt's horizontal
                                // one when the file gives no aspect ratio
};

// What an import kept, dropped and approximated; the tools print it as the summary.
struct ImportReport {
    std::string format;      // "glTF 2.0 binary", "Wavefront Object Importer", ...
    std::size_t meshes = 0;  // distinct meshes placed in the scene
    std::size_t camerasInFile = 0;
    std::size_t lightsInFile = 0;
    std::string cameraUsed;                    // name (or "#index") of the camera taken; empty if generated
    bool cameraGenerated = false;              // no usable camera: one framing the scene was made
    bool lightGenerated = false;               // no light: a default light was made
    std::size_t droppedPoints = 0;             // point primitives skipped
    std::size_t droppedLines = 0;              // line primitives skipped
    std::size_t droppedDegenerate = 0;         // zero-area triangles dropped from the models
    std::size_t droppedDegenerateInScene = 0;  // the same counted once per instance
    std::vector<std::string> notes;            // each drop or approximation in words
};

struct ImportResult {
    Scene scene;  // not flattened: models in their own space, instances with world transforms
    ImportReport report;
};

// The extension of a path in lower case, with its dot (".gltf"); empty if there is none.
std::string lowerCaseExtension(const std::string& path);

// True for the extensions that importScene reads through tinygltf (.gltf, .glb).
bool isGltfPath(const std::string& path);

// Reads any supported model file. Throws rt::InputError (naming the file) for a missing,
// unreadable, unknown or invalid file; never reads out of bounds or allocates more than the
// file's data can justify.
ImportResult importScene(const std::string& path, const ImportOptions& options = {});

// The root transform of the options: --up-axis, then --scale.
Transform rootTransform(const ImportOptions& options);

}  // namespace rt
