#include "inspect/tree_report.h"

#include <cstdio>
#include <functional>
#include <utility>

#include "accel/kdtree.h"
#include "core/json_writer.h"
#include "inspect/text_table.h"

namespace rt {

namespace {

// One statistic of a T (a TreeReport, or the RenderCounters of its rays): its label in the
// table, its key in JSON, how it is printed, and its value.
template <class T>
struct Statistic {
    const char* label;
    const char* key;
    int decimals;  // 0: an integer count
    std::function<double(const T&)> value;
};

double bytesPerPrimitive(const TreeReport& t) {
    return t.scenePrimitives ? double(t.stats.memoryBytes) / t.scenePrimitives : 0.0;
}

const std::vector<Statistic<TreeReport>>& treeStatistics() {
    static const std::vector<Statistic<TreeReport>> rows = {
        {"build time (s)", "buildSeconds", 3, [](const TreeReport& t) { return t.stats.buildSeconds; }},
        {"build threads", "buildThreads", 0, [](const TreeReport& t) { return double(t.stats.buildThreads); }},
        {"nodes", "nodes", 0, [](const TreeReport& t) { return double(t.stats.nodes); }},
        {"leaves", "leaves", 0, [](const TreeReport& t) { return double(t.stats.leaves); }},
        {"empty leaves", "emptyLeaves", 0, [](const TreeReport& t) { return double(t.stats.emptyLeaves); }},
        {"depth", "depth", 0, [](const TreeReport& t) { return double(t.stats.maxDepth); }},
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

const std::vector<Statistic<RenderCounters>>& rayStatistics() {
    using C = RenderCounters;
    static const std::vector<Statistic<C>> rows = {
        {"camera rays", "cameraRays", 0, [](const C& c) { return double(c.camera.rays); }},
        {"shadow rays", "shadowRays", 0, [](const C& c) { return double(c.shadow.rays); }},
        {"reflection rays", "reflectionRays", 0, [](const C& c) { return double(c.reflection.rays); }},
        {"rays", "rays", 0, [](const C& c) { return double(c.total().rays); }},
        {"traversal steps", "traversalSteps", 0, [](const C& c) { return double(c.total().traversalSteps); }},
        {"intersection tests", "intersectionTests", 0, [](const C& c) { return double(c.total().intersectionTests); }},
        {"traversal steps per ray", "traversalStepsPerRay", 2, [](const C& c) { return stepsPerRay(c.total()); }},
        {"intersection tests per ray", "intersectionTestsPerRay", 2, [](const C& c) { return testsPerRay(c.total()); }},
        {"traversal steps per camera ray", "cameraTraversalStepsPerRay", 2,
         [](const C& c) { return stepsPerRay(c.camera); }},
        {"intersection tests per camera ray", "cameraIntersectionTestsPerRay", 2,
         [](const C& c) { return testsPerRay(c.camera); }},
    };
    return rows;
}

// One row per statistic of what `subject` picks from each tree.
template <class T>
void addRows(TextTable& table, const std::vector<Statistic<T>>& statistics, const std::vector<TreeReport>& trees,
             const std::function<const T&(const TreeReport&)>& subject) {
    for (const Statistic<T>& s : statistics) {
        std::vector<std::string> cells{s.label};
        for (const TreeReport& t : trees) cells.push_back(formatFixed(s.value(subject(t)), s.decimals));
        table.addRow(std::move(cells));
    }
}

template <class T>
void writeMembers(JsonWriter& json, const std::vector<Statistic<T>>& statistics, const T& subject) {
    for (const Statistic<T>& s : statistics) {
        if (s.decimals == 0)
            json.member(s.key, std::uint64_t(s.value(subject)));
        else
            json.member(s.key, s.value(subject));
    }
}

void writeSettingsJson(JsonWriter& json, const AccelSettings& settings, std::uint32_t primitives) {
    json.beginObject();
    json.member("watertight", settings.triangles == TriangleTest::Watertight);
    if (settings.kind == AccelKind::Bsp) {
        json.member("maxDepth", settings.bsp.maxDepth);
        json.member("minPrimitives", settings.bsp.minPrimitives);
        json.member("roundRobin", settings.bsp.roundRobin);
    } else if (settings.kind == AccelKind::Kd) {
        json.member("traversalCost", settings.kd.traversalCost);
        json.member("intersectionCost", settings.kd.intersectionCost);
        json.member("emptyBonus", settings.kd.emptyBonus);
        json.member("maxDepth", kdMaxDepth(settings.kd, primitives));
        json.member("maxDepthAuto", !settings.kd.maxDepth.has_value());
        json.member("split", kdSplitMethodName(settings.kd.splitMethod));
        json.member("samples", settings.kd.samples);
        json.member("minimumGain", settings.kd.minimumGain);
    } else if (settings.kind == AccelKind::Bvh) {
        json.member("maxLeafPrimitives", settings.bvh.maxLeafPrimitives);
        json.member("traversalCost", settings.bvh.traversalCost);
        json.member("intersectionCost", settings.bvh.intersectionCost);
    }
    json.endObject();
}

}  // namespace

void printTreeTable(std::ostream& out, const std::vector<TreeReport>& trees) {
    std::vector<std::string> header{"statistic"};
    for (const TreeReport& t : trees) header.push_back(t.stats.name);
    TextTable table(std::move(header));
    addRows<TreeReport>(table, treeStatistics(), trees, [](const TreeReport& t) -> const TreeReport& { return t; });
    const bool withRays = !trees.empty() && trees.front().rays.has_value();
    if (withRays)
        addRows<RenderCounters>(table, rayStatistics(), trees,
                                [](const TreeReport& t) -> const RenderCounters& { return t.rays.value(); });
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

SceneSummary summarizeScene(const std::string& path, const Scene& scene) {
    return {path == "-" ? "<stdin>" : path, scene.primitives.countsPerKind(), std::uint32_t(scene.lights.size()),
            scene.primitives.bounds()};
}

std::string describeBounds(const Aabb& box) {
    if (box.empty()) return "empty";
    const auto point = [](const Vec3& p) {
        char text[96];
        std::snprintf(text, sizeof text, "(%g, %g, %g)", double(p.x), double(p.y), double(p.z));
        return std::string(text);
    };
    return point(box.lo) + " to " + point(box.hi) + ", centre " + point(box.center());
}

void writeBoundsJson(JsonWriter& json, const Aabb& box) {
    if (box.empty()) return json.null();
    json.beginObject();
    for (const auto& [key, p] :
         {std::pair{"min", box.lo}, std::pair{"max", box.hi}, std::pair{"centre", box.center()}}) {
        json.key(key);
        json.beginArray();
        for (int axis = 0; axis < 3; ++axis) json.value(double(p[axis]));
        json.endArray();
    }
    json.endObject();
}

void writeSceneJson(JsonWriter& json, const SceneSummary& scene) {
    json.beginObject();
    json.member("file", scene.file);
    for (const KindCount& k : scene.primitives) json.member(k.name, k.count);
    json.member("lights", scene.lights);
    json.key("bounds");
    writeBoundsJson(json, scene.bounds);
    json.endObject();
}

void writePictureJson(JsonWriter& json, const RenderSettings& picture) {
    const PixelWindow w = picture.window();
    json.beginObject();
    json.member("width", picture.width);
    json.member("height", picture.height);
    json.key("region");
    json.beginArray();
    for (const int corner : {w.x0, w.y0, w.x1, w.y1}) json.value(corner);
    json.endArray();
    json.member("pixelSamples", picture.pixelSamples);
    json.member("seed", picture.seed);
    json.member("reflectionDepth", picture.reflectionDepth);
    json.member("shadows", picture.shadows);
    json.member("softShadows", picture.softShadows);
    json.member("glossyReflections", picture.glossyReflections);
    json.member("distributedSamples", picture.distributedSamples);
    json.member("adaptiveGrid", picture.adaptiveGrid);  // 0: every pixel traced
    json.member("adaptiveThreshold", picture.adaptiveThreshold);
    json.member("noiseThreshold", picture.noiseThreshold);  // 0: every pixel -S samples
    json.member("adaptiveMinSamples", picture.adaptiveMinSamples);
    json.endObject();
}

void writeRaysJson(JsonWriter& json, const RenderCounters& rays) {
    json.beginObject();
    writeMembers(json, rayStatistics(), rays);
    json.endObject();
}

void writeTreeReportJson(JsonWriter& json, const TreeReport& tree) {
    json.beginObject();
    json.member("name", accelKindName(tree.settings.kind));
    json.member("structure", tree.stats.name);  // as the accelerator names itself, e.g. "kd-sweep"
    json.key("settings");
    writeSettingsJson(json, tree.settings, tree.scenePrimitives);
    writeMembers(json, treeStatistics(), tree);
    if (tree.rays) {
        json.key("rays");
        writeRaysJson(json, *tree.rays);
    }
    if (tree.depths) {
        json.key("depthHistogram");
        writeDepthHistogramJson(json, *tree.depths);
    }
    json.endObject();
}

void writeReportJson(std::ostream& out, const SceneSummary& scene, const std::optional<RenderSettings>& picture,
                     const std::vector<TreeReport>& trees) {
    JsonWriter json(out);
    json.beginDocument();
    json.key("scene");
    writeSceneJson(json, scene);
    if (picture) {
        json.key("picture");
        writePictureJson(json, *picture);
    }
    json.key("trees");
    json.beginArray();
    for (const TreeReport& t : trees) writeTreeReportJson(json, t);
    json.endArray();
    json.endObject();
}

}  // namespace rt
