#include "summary.h"

#include "core/json_writer.h"
#include "inspect/tree_report.h"
#include "io/scene_defaults.h"

namespace rt::tool::convert {
namespace {

struct Counts {
    std::size_t modelTriangles = 0;
    std::size_t sceneTriangles = 0;
};

Counts countTriangles(const Scene& scene) {
    Counts c;
    for (const Model& m : scene.models) c.modelTriangles += m.triangleCount();
    for (const Instance& i : scene.instances) c.sceneTriangles += scene.models[i.model].triangleCount();
    return c;
}

}  // namespace

void printSummary(std::ostream& out, const Summary& s) {
    const Scene& scene = s.result->scene;
    const ImportReport& r = s.result->report;
    const Counts c = countTriangles(scene);
    out << "rt-convert: " << s.input << " (" << r.format << ")" << (s.output.empty() ? "" : " -> " + s.output) << "\n"
        << "  meshes     " << r.meshes << " placed, " << scene.models.size() << " models (one RAW each)\n"
        << "  triangles  " << c.modelTriangles << " in the models, " << c.sceneTriangles << " in the scene\n"
        << "  bounds     " << describeBounds(sceneBounds(scene)) << "\n"
        << "  instances  " << scene.instances.size() << "\n"
        << "  materials  " << scene.materials.size() << "\n"
        << "  cameras    " << r.camerasInFile << " in the file, "
        << (r.cameraGenerated ? "one generated to frame the scene" : "using \"" + r.cameraUsed + "\"") << "\n"
        << "  lights     " << r.lightsInFile << " in the file, " << scene.lights.size() << " written"
        << (r.lightGenerated ? " (a default light)" : "") << "\n";
    for (const std::string& note : r.notes) out << "  note: " << note << "\n";
}

void printSummaryJson(std::ostream& out, const Summary& s) {
    const Scene& scene = s.result->scene;
    const ImportReport& r = s.result->report;
    const Counts c = countTriangles(scene);
    JsonWriter json(out);
    json.beginDocument();
    json.member("input", s.input);
    json.key("output");
    s.output.empty() ? json.null() : json.value(s.output);
    json.member("format", r.format);
    json.member("meshes", r.meshes);
    json.member("models", scene.models.size());
    json.member("modelTriangles", c.modelTriangles);
    json.member("sceneTriangles", c.sceneTriangles);
    json.key("bounds");
    writeBoundsJson(json, sceneBounds(scene));
    json.member("instances", scene.instances.size());
    json.member("materials", scene.materials.size());
    json.key("cameras");
    json.beginObject();
    json.member("inFile", r.camerasInFile);
    json.key("used");
    r.cameraGenerated ? json.null() : json.value(r.cameraUsed);
    json.member("generated", r.cameraGenerated);
    json.endObject();
    json.key("lights");
    json.beginObject();
    json.member("inFile", r.lightsInFile);
    json.member("written", scene.lights.size());
    json.member("generated", r.lightGenerated);
    json.endObject();
    json.key("dropped");
    json.beginObject();
    json.member("points", r.droppedPoints);
    json.member("lines", r.droppedLines);
    json.member("degenerate", r.droppedDegenerate);
    json.member("degenerateInScene", r.droppedDegenerateInScene);
    json.endObject();
    json.key("notes");
    json.beginArray();
    for (const std::string& note : r.notes) json.value(note);
    json.endArray();
    json.endObject();
}

}  // namespace rt::tool::convert
