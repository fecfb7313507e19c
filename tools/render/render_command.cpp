#include "render_command.h"

#include <charconv>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <vector>

#include "accel/build.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "import/load_scene.h"
#include "progress.h"
#include "render/memory_estimate.h"
#include "render/renderer.h"
#include "stats_report.h"
#include "version.h"

namespace rt::render_tool {

PixelWindow parseRegion(const std::string& text) {
    // from_chars, not sscanf: a number beyond int is an error here, where %d wrapped
    // 4294967306 to 10 and rendered a region nobody asked for.
    const InputError bad("--region: expected x0,y0,x1,y1 (pixels, x1 and y1 exclusive), got '" + text + "'");
    int corners[4];
    const char* at = text.data();
    const char* const end = at + text.size();
    for (int i = 0; i < 4; ++i) {
        if (i > 0 && (at == end || *at++ != ',')) throw bad;
        const auto [next, ec] = std::from_chars(at, end, corners[i]);
        if (ec != std::errc()) throw bad;
        at = next;
    }
    if (at != end) throw bad;
    return {corners[0], corners[1], corners[2], corners[3]};
}

namespace {

// The format follows -o and -f (chooseImageFormat); -p renders nothing, so it writes nothing.
ImageOutputSettings outputSettings(const RenderOptions& o) {
    ImageOutputSettings s;
    s.color = o.color;
    s.exrHalf = o.exrPixels == "half";
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
    return render(scene, accel, settings, stats,
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
    validate(o.render);
    const ImageOutputSettings output = outputSettings(o);
    prepareOutputs(o, output);
    const ProgressMode progress = progressMode(o.progress, o.quiet);

    const std::uint64_t memoryLimit = o.maxMemoryGb ? std::uint64_t(*o.maxMemoryGb * 1e9) : defaultMemoryLimit();
    checkMemoryLimit(estimateRenderMemory(o.render, 0, !o.preprocessOnly), memoryLimit);  // before the scene loads

    Scene scene = loadScene(o.scenePath);
    scene.dropDescription();
    checkMemoryLimit(estimateRenderMemory(o.render, scene.primitives.size(), !o.preprocessOnly), memoryLimit);
    RenderStats stats;
    const std::unique_ptr<Accelerator> accel = buildAnnounced(scene, o.accel, progress, stats);
    const AccelStats accelStats = accel->stats();
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
        const std::string json = statsJson(o.scenePath, o.render, accelStats, stats);
        writeFileAtomically(*o.statsJson, [&](std::ostream& os) { os << json; });
    }
    return 0;
}

}  // namespace rt::render_tool
