// Importing 3-D model files into an rt::Scene in memory (docs/conversion.md).
//
// glTF 2.0 (.gltf, .glb) goes through tinygltf, OBJ through tinyobjloader's streaming API,
// everything else through Assimp: Debian's Assimp 5.2.5 glTF loader aborts the process on some
// broken files, and its OBJ loader needs 14 times the memory of what it reads, so neither is used.
// The importers keep the file's structure: one Model per distinct mesh (glTF: per mesh
// primitive, which carries the material; Assimp: per aiMesh; OBJ: per object, group and
// material), one Instance per place a node puts it, with the node's world transform.
// Degenerate triangles (a cross product of exactly zero from the float corners: repeated or
// collinear corners; mesh_data.h appendTriangle) are dropped and counted, the same in every importer:
// they share their scaffolding (scene_assembly.h) and are chosen by format in import.cpp.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/names.h"
#include "io/parameters.h"
#include "scene/crease_normals.h"
#include "scene/scene.h"

namespace rt {

enum class UpAxis { Y, Z };
inline constexpr NamedValues<UpAxis, 2> kUpAxisNames{{{"y", UpAxis::Y}, {"z", UpAxis::Z}}};

struct ImportOptions {
    std::optional<int> scene;  // glTF scene index; default: the file's default scene, else 0
    std::string camera;        // camera name or index; empty: the first perspective camera placed;
                               // kFramingCamera: none of the file's, the generated framing camera
    // rt-render --look-from, --look-at or --fov: the command line places the camera, so that a
    // camera generated for a file without one is no news (no note says so).
    bool cameraFromCommandLine = false;
    double scale = 1;  // uniform factor applied at the root (units)
    // The file's up axis as its author knows it (3DS and most CAD exports: Z), whatever the
    // importer does internally; the scene is turned so that it becomes rt's +Y. Unset: the
    // format's own convention (3DS: Z, a Collada file's <up_axis>, otherwise Y).
    std::optional<UpAxis> upAxis;
    double aspect = 4.0 / 3.0;  // width/height used to turn a vertical fov into rt's horizontal
                                // one when the file gives no aspect ratio
    // Meshes without vertex normals get them by crease angle (scene/crease_normals.h), unless
    // `flat` (rt-convert --flat): then they keep their facets.
    bool flat = false;
    double creaseDegrees = kDefaultCreaseDegrees;
    // rt-render --set: fills $NAME in an XML scene's attribute values (scene/parameters.h);
    // a model file has none, so parameters given for one are an error.
    SceneParameters parameters;
    // glTF buffers may be read from anywhere; by default only from the model's folder and below
    // (standard input: the working folder), so that a file cannot make rt copy /etc/passwd.
    bool filesOutsideModelFolder = false;
    // rt-convert and rt-render --double-sided: every material two-sided, whatever the file says
    // (glTF's doubleSided false), for models whose winding is inverted. loadScene applies it to
    // XML scenes too.
    bool doubleSided = false;
};

// ImportOptions::camera value (rt-convert --camera auto) that ignores the file's cameras.
inline constexpr const char* kFramingCamera = "auto";

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
    // The models most of whose triangles face away from their vertex normals (mesh_data.h
    // windingAgainstNormals): inverted winding, which single-sided materials show inside out.
    std::vector<std::string> modelsFacingAway;
    std::vector<std::string> notes;  // each drop or approximation in words
};

struct ImportResult {
    Scene scene;  // not flattened: models in their own space, instances with world transforms
    ImportReport report;
};

// True when the file at `path` starts with the bytes `magic` ("glTF", "raw3d").
bool fileStartsWith(const std::string& path, std::string_view magic);

// True for bytes that can only be glTF 2.0: the GLB magic "glTF", or a JSON object ('{' after
// blanks), which no XML scene starts with.
bool looksLikeGltf(std::string_view bytes);

// Reads any supported model file: glTF, OBJ, a thesis RAW model (appendix D, wrapped in a scene
// with one instance), everything else through Assimp; the format is told by the extension, or
// by the first bytes (GLB, RAW) under any name (import.cpp kFormatImporters). "-" reads standard input, which must hold
// a glTF 2.0 model (GLB or JSON). Throws rt::InputError (naming the file) for a missing,
// unreadable, unknown or invalid file; never reads out of bounds or allocates more than the
// file's data can justify.
ImportResult importScene(const std::string& path, const ImportOptions& options = {});

// importScene for a model held in memory, read from standard input: GLB or glTF JSON.
ImportResult importGltfFromStandardInput(const std::string& bytes, const ImportOptions& options);

// One note per image file that the scene's textures name and that cannot be read (missing, a
// folder, not readable), however many textures use it: what rendering will warn about, said
// by rt-convert before it writes a scene naming the file.
std::vector<std::string> unreadableTextureNotes(const Scene& scene);

// The root transform of the options: --up-axis, then --scale. `importerUp` is the up axis
// the importer already turned to +Y (Assimp's 3DS reader turns Z-up to Y-up, the others
// leave the file's axes alone), so that --up-axis describes the file, not the importer.
Transform rootTransform(const ImportOptions& options, UpAxis importerUp = UpAxis::Y);

}  // namespace rt
