// What rt-inspect reports about each tree: its build statistics (AccelStats), optionally the
// work done for a picture's rays and the depth histogram; as an aligned table with one column
// per tree, as the thesis's Table 4.3 (BSP against KD), or as one JSON document.
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "accel/settings.h"
#include "core/aabb.h"
#include "core/json_writer.h"
#include "geometry/primitives.h"
#include "inspect/depth_histogram.h"
#include "inspect/ray_statistics.h"
#include "scene/scene.h"

namespace rt {

struct TreeReport {
    AccelSettings settings;  // the kind of tree and the parameters it was built with
    AccelStats stats;
    std::uint32_t scenePrimitives = 0;  // for bytes per primitive
    std::optional<RenderCounters> rays;
    std::optional<std::vector<DepthLevel>> depths;
};

struct SceneSummary {
    std::string file;
    std::vector<KindCount> primitives;  // per kind, in the list's order
    std::uint32_t lights = 0;
    Aabb bounds;  // of every primitive, in world space: where a camera can be put (empty: none)
};

// "(x0, y0, z0) to (x1, y1, z1), centre (x, y, z)", six significant digits, as `assimp info`
// gives a scene's extent; "empty" for an empty box.
std::string describeBounds(const Aabb& box);

// {"min": [x, y, z], "max": [x, y, z], "centre": [x, y, z]}, or null for an empty box.
void writeBoundsJson(JsonWriter& json, const Aabb& box);

// The summary of `scene`, read from `path` ("-" is reported as "<stdin>").
SceneSummary summarizeScene(const std::string& path, const Scene& scene);

// Every statistic in rows, one column per tree.
void printTreeTable(std::ostream& out, const std::vector<TreeReport>& trees);

// Thesis Table 4.3 for one scene: nodes and intersection tests per ray, BSP against KD.
// Both reports must have ray statistics.
void printThesisTable43(std::ostream& out, const std::string& sceneName, const TreeReport& bsp, const TreeReport& kd);

// The JSON of rt-inspect --json (docs/json.md): {"version", "scene", "picture" (when the
// rays were traced), "trees": [...]}.
void writeReportJson(std::ostream& out, const SceneSummary& scene, const std::optional<RenderSettings>& picture,
                     const std::vector<TreeReport>& trees);

// The objects rt-inspect --json and rt-render --stats-json share, so that a quantity has one
// name and one shape in both (docs/json.md):
// {"file", one count per primitive kind ("triangles", ...), "lights", "bounds"}
void writeSceneJson(JsonWriter& json, const SceneSummary& scene);
// {"width", "height", "region", "pixelSamples", "reflectionDepth", "shadows", "softShadows",
// "glossyReflections", "distributedSamples"}
void writePictureJson(JsonWriter& json, const RenderSettings& picture);
// {"name", "structure", "settings", the statistics, and "rays", "depthHistogram" when the report has them}
void writeTreeReportJson(JsonWriter& json, const TreeReport& tree);
// {"cameraRays", "shadowRays", ..., "cameraIntersectionTestsPerRay"}
void writeRaysJson(JsonWriter& json, const RenderCounters& rays);

}  // namespace rt
