#include "io/load_scene.h"

#include <string_view>

#include "core/error.h"
#include "core/text.h"
#include "io/mesh_data.h"
#include "io/model_file.h"
#include "io/xml_loader.h"
#include "os/input_file.h"

namespace rt {
namespace {

// --set fills $NAME in XML scenes only: given for a model file, it would silently do nothing.
void requireNoParameters(const std::string& path, const ImportOptions& options) {
    if (!options.parameters.empty())
        throw InputError(path + ": --set " + options.parameters.begin()->first +
                         ": parameters fill $NAME in XML scenes, and this is a model file");
}

Scene flattenedScene(ImportResult imported) {
    Scene scene = std::move(imported.scene);
    scene.warnings.insert(scene.warnings.end(), imported.report.notes.begin(), imported.report.notes.end());
    scene.droppedDegenerate = imported.report.droppedDegenerateInScene + scene.flatten();
    return scene;
}

// ImportOptions::camera picks one of an XML scene's named cameras, as the importers pick one of a
// model's; doubleSided makes its materials two-sided as it does a model's.
Scene withOptions(Scene scene, const ImportOptions& options) {
    if (!options.camera.empty()) scene.selectCamera(options.camera);
    if (options.doubleSided) makeDoubleSided(scene);
    return scene;
}

// Whether `bytes` can be an XML document: '<' first, after blanks and a UTF-8 byte order mark.
bool looksLikeXml(std::string_view bytes) {
    if (bytes.starts_with("\xEF\xBB\xBF")) bytes.remove_prefix(3);
    const std::size_t first = bytes.find_first_not_of(" \t\r\n");
    return first != std::string_view::npos && bytes[first] == '<';
}

// Standard input holds an XML scene or a glTF 2.0 model (GLB or JSON), told apart by content;
// anything else (an OBJ piped in) is named as such rather than reported as broken XML.
Scene loadStandardInput(const ImportOptions& options) {
    const std::string bytes = readStandardInput();
    if (looksLikeGltf(bytes)) {
        requireNoParameters("<stdin>", options);
        return flattenedScene(importGltfFromStandardInput(bytes, options));
    }
    if (!looksLikeXml(bytes))
        throw InputError(
            "<stdin>: standard input takes an rt XML scene or a glTF 2.0 model (binary GLB or JSON), "
            "and this is neither; give other model files by name");
    return withOptions(loadSceneXmlFromString(bytes, "<stdin>", ".", options.parameters), options);
}

}  // namespace

Scene loadScene(const std::string& path, const ImportOptions& options) {
    if (path == "-") return loadStandardInput(options);
    if (lowerCaseExtension(path) == ".xml") return withOptions(loadSceneXml(path, options.parameters), options);
    requireNoParameters(path, options);
    return flattenedScene(importScene(path, options));
}

}  // namespace rt
