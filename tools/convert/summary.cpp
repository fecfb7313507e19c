#include "summary.h"

#include <cstdio>

namespace rt::convert {
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

std::string jsonString(const std::string& s) {
    std::string out = "\"";
    for (const char ch : s) {
        const auto c = static_cast<unsigned char>(ch);
        if (c == '"' || c == '\\') {
            out += '\\';
            out += ch;
        } else if (c < 0x20) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\u%04x", c);
            out += buf;
        } else {
            out += ch;
        }
    }
    return out + "\"";
}

}  // namespace

void printSummary(std::ostream& out, const Summary& s) {
    const Scene& scene = s.result->scene;
    const ImportReport& r = s.result->report;
    const Counts c = countTriangles(scene);
    out << "rt-convert: " << s.input << " (" << r.format << ")" << (s.output.empty() ? "" : " -> " + s.output) << "\n"
        << "  meshes     " << r.meshes << " placed, " << scene.models.size() << " models (one RAW each)\n"
        << "  triangles  " << c.modelTriangles << " in the models, " << c.sceneTriangles << " in the scene\n"
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
    out << "{\"input\": " << jsonString(s.input)
        << ", \"output\": " << (s.output.empty() ? "null" : jsonString(s.output))
        << ", \"format\": " << jsonString(r.format) << ", \"meshes\": " << r.meshes
        << ", \"models\": " << scene.models.size() << ", \"modelTriangles\": " << c.modelTriangles
        << ", \"sceneTriangles\": " << c.sceneTriangles << ", \"instances\": " << scene.instances.size()
        << ", \"materials\": " << scene.materials.size() << ", \"cameras\": {\"inFile\": " << r.camerasInFile
        << ", \"used\": " << (r.cameraGenerated ? "null" : jsonString(r.cameraUsed))
        << ", \"generated\": " << std::boolalpha << r.cameraGenerated
        << "}, \"lights\": {\"inFile\": " << r.lightsInFile << ", \"written\": " << scene.lights.size()
        << ", \"generated\": " << r.lightGenerated << "}, \"dropped\": {\"points\": " << r.droppedPoints
        << ", \"lines\": " << r.droppedLines << ", \"degenerate\": " << r.droppedDegenerate
        << ", \"degenerateInScene\": " << r.droppedDegenerateInScene << "}, \"notes\": [";
    for (std::size_t i = 0; i < r.notes.size(); ++i) out << (i ? ", " : "") << jsonString(r.notes[i]);
    out << "]}\n";
}

}  // namespace rt::convert
