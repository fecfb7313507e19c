#include "inspect/tree_report.h"

#include <functional>

#include "inspect/json_writer.h"
#include "inspect/text_table.h"

namespace rt {

namespace {

// One statistic: its label in the table, its key in JSON, how it is printed, and its value.
struct Statistic {
    const char* label;
    const char* key;
    int decimals;  // 0: an integer count
    std::function<double(const TreeReport&)> value;
};

double bytesPerPrimitive(const TreeReport& t) {
    return t.scenePrimitives ? double(t.stats.memoryBytes) / t.scenePrimitives : 0.0;
}

const std::vector<Statistic>& treeStatistics() {
    static const std::vector<Statistic> rows = {
        {"build time (s)", "buildSeconds", 3, [](const TreeReport& t) { return t.stats.buildSeconds; }},
        {"nodes", "nodes", 0, [](const TreeReport& t) { return double(t.stats.nodes); }},
        {"leaves", "leaves", 0, [](const TreeReport& t) { return double(t.stats.leaves); }},
        {"empty leaves", "emptyLeaves", 0, [](const TreeReport& t) { return double(t.stats.emptyLeaves); }},
        {"max depth", "maxDepth", 0, [](const TreeReport& t) { return double(t.stats.maxDepth); }},
        {"average leaf depth", "averageLeafDepth", 2, [](const TreeReport& t) { return t.stats.averageLeafDepth; }},
        {"primitives per non-empty leaf", "averagePrimitivesPerLeaf", 2,
         [](const TreeReport& t) { return t.stats.averagePrimitivesPerLeaf; }},
        {"primitive references", "primitiveReferences", 0,
         [](const TreeReport& t) { return double(t.stats.primitiveReferences); }},
        {"memory (bytes)", "memoryBytes", 0, [](const TreeReport& t) { return double(t.stats.memoryBytes); }},
        {"bytes per primitive", "bytesPerPrimitive", 2, bytesPerPrimitive},
        {"SAH cost", "sahCost", 2, [](const TreeReport& t) { return t.stats.sahCost; }},
    };
    return rows;
}

const std::vector<Statistic>& rayStatistics() {
    static const std::vector<Statistic> rows = {
        {"camera rays", "cameraRays", 0, [](const TreeReport& t) { return double(t.rays->camera.rays); }},
        {"shadow rays", "shadowRays", 0, [](const TreeReport& t) { return double(t.rays->shadow.rays); }},
        {"reflection rays", "reflectionRays", 0, [](const TreeReport& t) { return double(t.rays->reflection.rays); }},
        {"rays", "rays", 0, [](const TreeReport& t) { return double(t.rays->total().rays); }},
        {"traversal steps", "traversalSteps", 0,
         [](const TreeReport& t) { return double(t.rays->total().traversalSteps); }},
        {"intersection tests", "intersectionTests", 0,
         [](const TreeReport& t) { return double(t.rays->total().intersectionTests); }},
        {"traversal steps per ray", "traversalStepsPerRay", 2,
         [](const TreeReport& t) { return stepsPerRay(t.rays->total()); }},
        {"intersection tests per ray", "intersectionTestsPerRay", 2,
         [](const TreeReport& t) { return testsPerRay(t.rays->total()); }},
        {"traversal steps per camera ray", "cameraTraversalStepsPerRay", 2,
         [](const TreeReport& t) { return stepsPerRay(t.rays->camera); }},
        {"intersection tests per camera ray", "cameraIntersectionTestsPerRay", 2,
         [](const TreeReport& t) { return testsPerRay(t.rays->camera); }},
    };
    return rows;
}

void addRows(TextTable& table, const std::vector<Statistic>& statistics, const std::vector<TreeReport>& trees) {
    for (const Statistic& s : statistics) {
        std::vector<std::string> cells{s.label};
        for (const TreeReport& t : trees) cells.push_back(formatFixed(s.value(t), s.decimals));
        table.addRow(std::move(cells));
    }
}

void writeMembers(JsonWriter& json, const std::vector<Statistic>& statistics, const TreeReport& t) {
    for (const Statistic& s : statistics) {
        if (s.decimals == 0)
            json.member(s.key, std::uint64_t(s.value(t)));
        else
            json.member(s.key, s.value(t));
    }
}

void writeSettingsJson(JsonWriter& json, const AccelSettings& settings) {
    json.beginObject();
    if (settings.kind == AccelKind::Bsp) {
        json.member("maxDepth", settings.bsp.maxDepth);
        json.member("minPrimitives", settings.bsp.minPrimitives);
        json.member("roundRobin", settings.bsp.roundRobin);
    } else if (settings.kind == AccelKind::Kd) {
        json.member("traversalCost", settings.kd.traversalCost);
        json.member("intersectionCost", settings.kd.intersectionCost);
        json.member("emptyBonus", settings.kd.emptyBonus);
        json.key("maxDepth");
        if (settings.kd.maxDepth)
            json.value(*settings.kd.maxDepth);
        else
            json.value("auto");
        json.member("split", kdSplitMethodName(settings.kd.splitMethod));
        json.member("samples", settings.kd.samples);
    }
    json.endObject();
}

}  // namespace

void printTreeTable(std::ostream& out, const std::vector<TreeReport>& trees) {
    std::vector<std::string> header{"statistic"};
    for (const TreeReport& t : trees) header.push_back(t.stats.name);
    TextTable table(std::move(header));
    addRows(table, treeStatistics(), trees);
    const bool withRays = !trees.empty() && trees.front().rays.has_value();
    if (withRays) addRows(table, rayStatistics(), trees);
    table.print(out);
}

void printThesisTable43(std::ostream& out, const std::string& sceneName, const TreeReport& bsp, const TreeReport& kd) {
    out << "Table 4.3: tree quality (intersection tests per ray over all rays traced)\n";
    TextTable table({"scene", "BSP nodes", "KD nodes", "BSP tests/ray", "KD tests/ray"});
    table.addRow({sceneName, std::to_string(bsp.stats.nodes), std::to_string(kd.stats.nodes),
                  formatFixed(testsPerRay(bsp.rays.value().total()), 2),
                  formatFixed(testsPerRay(kd.rays.value().total()), 2)});
    table.print(out);
}

void writeReportJson(std::ostream& out, const SceneSummary& scene, const std::optional<RenderSettings>& picture,
                     const std::vector<TreeReport>& trees) {
    JsonWriter json(out);
    json.beginObject();
    json.key("scene");
    json.beginObject();
    json.member("file", scene.file);
    for (const KindCount& k : scene.primitives) json.member(k.name, k.count);
    json.member("lights", scene.lights);
    json.endObject();
    if (picture) {
        json.key("rays");
        json.beginObject();
        json.member("width", picture->width);
        json.member("height", picture->height);
        json.member("shadows", picture->shadows);
        json.member("reflectionDepth", picture->maxDepth);
        json.member("pixelSamples", picture->pixelSamples);
        json.member("softShadows", picture->softShadows);
        json.member("glossyReflections", picture->glossyReflections);
        json.member("distributedSamples", picture->distributedSamples);
        json.endObject();
    }
    json.key("trees");
    json.beginArray();
    for (const TreeReport& t : trees) {
        json.beginObject();
        json.member("name", accelKindName(t.settings.kind));
        json.member("structure", t.stats.name);  // as the accelerator names itself, e.g. "kd-sweep"
        json.key("settings");
        writeSettingsJson(json, t.settings);
        writeMembers(json, treeStatistics(), t);
        if (t.rays) {
            json.key("rays");
            json.beginObject();
            writeMembers(json, rayStatistics(), t);
            json.endObject();
        }
        if (t.depths) {
            json.key("depthHistogram");
            writeDepthHistogramJson(json, *t.depths);
        }
        json.endObject();
    }
    json.endArray();
    json.endObject();
}

}  // namespace rt
