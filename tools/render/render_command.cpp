#include "render_command.h"

#include <chrono>
#include <cstdio>
#include <iostream>
#include <vector>

#include "accel/build.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "import/load_scene.h"
#include "image/image_check.h"
#include "progress.h"
#include "render/renderer.h"
#include "render/tiles.h"
#include "stats_report.h"
#include "version.h"

namespace rt::tool::render {

PixelWindow parseRegion(const std::string& text) {
    PixelWindow w;
    int used = -1;
    if (std::sscanf(text.c_str(), "%d,%d,%d,%d%n", &w.x0, &w.y0, &w.x1, &w.y1, &used) != 4 ||
        used != int(text.size()))
        throw InputError("--region: expected x0,y0,x1,y1 (pixels, x1 and y1 exclusive), got '" + text + "'");
    return w;
}

PixelWindow parseTile(const std::string& tiles, const std::string& tile, int width, int height) {
    TileGrid grid;
    int index = -1, count = -1, used = -1;
    if (std::sscanf(tiles.c_str(), "%dx%d%n", &grid.columns, &grid.rows, &used) != 2 || used != int(tiles.size()))
        throw InputError("--tiles: expected CxR (columns x rows, e.g. 4x4), got '" + tiles + "'");
    if (std::sscanf(tile.c_str(), "%d/%d%n", &index, &count, &used) != 2 || used != int(tile.size()))
        throw InputError("--tile: expected I/N (tile I of N, from 0), got '" + tile + "'");
    if (count != grid.count())
        throw InputError("--tile " + tile + ": --tiles " + tiles + " makes " + std::to_string(grid.count()) + " tiles");
    return tileWindow(width, height, grid, index);
}

namespace {

// The format follows -o and -f (chooseImageFormat); -p renders nothing, so it writes nothing.
ImageOutputSettings outputSettings(const RenderOptions& o) {
    ImageOutputSettings s;
    s.color = o.color;
    s.exrPixels = o.exrPixels;
    s.pngBits = o.pngBits;
    s.path = o.outputPath.value_or("");
    if (o.preprocessOnly) return s;
    if (o.outputPath) checkNotDirectory(*o.outputPath);  // before its extension is looked at
    s.format = chooseImageFormat(o.outputType, o.outputPath);
    if (s.format == ImageFormat::Text && !o.outputPath) s.path = std::string(1, '-');  // text goes to the terminal
    if (s.format != ImageFormat::Null && s.path.empty())
        throw InputError(std::string(imageFormatName(s.format)) + " output needs -f FILE");
    return s;
}

// Two outputs on standard output would be concatenated into one unusable stream.
void checkOneStandardOutput(const RenderOptions& o, const ImageOutputSettings& output) {
    std::vector<std::string> users;
    if (output.format != ImageFormat::Null && output.path == "-") users.push_back("the image");
    if (o.statsLine) users.push_back("-b");
    if (o.statsJson == "-") users.push_back("--stats-json -");
    if (users.size() > 1)
        throw InputError(users[0] + " and " + users[1] + " would both write to standard output; send one to a file");
}

// Every problem with the outputs is found before the scene is loaded: bad colour names
// (whatever the output type), a file that cannot be written; missing folders are created.
void prepareOutputs(const RenderOptions& o, const ImageOutputSettings& output) {
    checkOneStandardOutput(o, output);
    ColorPipeline check(output.color);
    if (output.format != ImageFormat::Null) prepareOutputFile(output.path);
    if (o.statsJson) prepareOutputFile(*o.statsJson);
}

// --skip-existing: the output a task wrote before it was requeued is kept if it reads back whole.
bool outputIsComplete(const RenderOptions& o, const ImageOutputSettings& output, ProgressMode progress) {
    if (!o.skipExisting || output.format == ImageFormat::Null || output.path == "-") return false;
    const std::string why = whyNotCompleteImage(output.path, o.render.width, o.render.height, o.render.window());
    if (why.empty()) announce(progress, output.path + " is complete: nothing to render (--skip-existing)");
    else if (why != "missing") announce(progress, "rendering " + output.path + " again: " + why);
    return why.empty();
}

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::unique_ptr<Accelerator> buildAnnounced(const Scene& scene, const AccelSettings& settings, ProgressMode progress,
                                            RenderStats& stats) {
    announce(progress, std::string("building the ") + accelKindName(settings.kind) + " tree over " +
                           std::to_string(scene.primitives.size()) + " objects");
    const auto start = std::chrono::steady_clock::now();
    std::unique_ptr<Accelerator> accel = buildAccelerator(scene.primitives, settings);
    stats.preprocessSeconds = secondsSince(start);
    char done[160];
    std::snprintf(done, sizeof done, "%s tree built: %llu nodes in %.3f s", accel->stats().name.c_str(),
                  static_cast<unsigned long long>(accel->stats().nodes), stats.preprocessSeconds);
    announce(progress, done);
    return accel;
}

// The bar's line ends (its destructor) before anything else is printed.
Framebuffer renderShowingProgress(const Scene& scene, const Accelerator& accel, const RenderSettings& settings,
                                  ProgressMode mode, RenderStats& stats) {
    Progress progress(mode);
    return rt::render(scene, accel, settings, stats,
                  [&progress](std::uint64_t done, std::uint64_t total) { progress.update(done, total); });
}

// What a run without -f or -o did, so that nobody waits for a picture that never comes.
std::string outputNote(const RenderOptions& o, const ImageOutputSettings& output) {
    if (output.format != ImageFormat::Null) return output.path == "-" ? "" : "wrote " + output.path + "\n";
    if (o.outputType || o.preprocessOnly) return "";
    return "nothing written: without -f or -o the output is null (as in the thesis); "
           "write the picture with -f out.png or -f out.exr\n";
}

}  // namespace

int runRender(RenderOptions o) {
    if (o.region) o.render.region = parseRegion(*o.region);
    if (o.tile) o.render.region = parseTile(o.tiles.value_or(""), *o.tile, o.render.width, o.render.height);
    validate(o.render);
    const ImageOutputSettings output = outputSettings(o);
    const ProgressMode progress = progressMode(o.progress, o.quiet);
    if (outputIsComplete(o, output, progress)) return 0;
    prepareOutputs(o, output);

    Scene scene = loadScene(o.scenePath);
    scene.dropDescription();
    RenderStats stats;
    const std::unique_ptr<Accelerator> accel = buildAnnounced(scene, o.accel, progress, stats);
    const TreeReport tree{o.accel, accel->stats(), std::uint32_t(scene.primitives.size()), {}, {}};
    const AccelStats& accelStats = tree.stats;
    stats.treeNodes = accelStats.nodes;
    stats.objects = scene.primitives.size();
    stats.lights = scene.lights.size();

    if (!o.preprocessOnly) {
        const Framebuffer image = renderShowingProgress(scene, *accel, o.render, progress, stats);
        const ImageMetadata meta{std::string("rt-render ") + kVersion, o.scenePath, o.render.pixelSamples,
                                 stats.renderSeconds};
        writeImage(image, output, meta);
        std::cerr << nonFiniteWarning(stats);  // even with -q: a replaced sample is never silent
    }

    if (!o.quiet) {
        for (const std::string& w : scene.warnings) std::cerr << "rt-render: warning: " << w << '\n';
        std::cerr << statsSummary(o.render, accelStats, stats, !o.preprocessOnly) << outputNote(o, output);
    }
    if (o.statsLine) std::cout << thesisStatsLine(stats) << std::endl;
    if (o.statsJson) {
        const SceneSummary summary = summarizeScene(o.scenePath, scene);
        writeFileAtomically(*o.statsJson, [&](std::ostream& out) { writeStatsJson(out, summary, o.render, tree, stats); });
    }
    return 0;
}

}  // namespace rt::tool::render
