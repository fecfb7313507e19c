#include "import/load_scene.h"

#include "scene/xml_loader.h"

namespace rt {

Scene loadScene(const std::string& path, const ImportOptions& options) {
    if (path == "-" || lowerCaseExtension(path) == ".xml") return loadSceneXml(path);
    ImportResult imported = importScene(path, options);
    Scene scene = std::move(imported.scene);
    scene.warnings.insert(scene.warnings.end(), imported.report.notes.begin(), imported.report.notes.end());
    scene.droppedDegenerate = imported.report.droppedDegenerateInScene + scene.flatten();
    return scene;
}

}  // namespace rt
