#include "render_command.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <stdexcept>
#include <vector>

#include "accel/build.h"
#include "core/error.h"
#include "core/stopwatch.h"
#include "core/text.h"
#include "image/image_check.h"
#include "image/texture_files.h"
#include "io/load_scene.h"
#include "light_option.h"
#include "os/atomic_file.h"
#include "progress.h"
#include "render/film/tiles.h"
#include "render/lights/environment_light.h"
#include "render/material_filter.h"
#include "render/memory_estimate.h"
#include "render/renderer.h"
#include "sdl_window.h"
#include "stats_report.h"
#include "tool.h"
#include "version.h"

namespace rt::tool::render {

PixelWindow parseRegion(const std::string& text) {
    const auto corners = parseSeparated<int, 4>(text, ",");
    if (!corners) throw InputError("--region: expected x0,y0,x1,y1 (pixels, x1 and y1 exclusive), got '" + text + "'");
    const auto [x0, y0, x1, y1] = *corners;
    return {x0, y0, x1, y1};
}

Vec3 parseVector(const std::string& option, const std::string& text) {
    const auto v = parseSeparated<double, 3>(text, ",");
    if (!v || !std::all_of(v->begin(), v->end(), [](double x) { return std::isfinite(x); }))
        throw InputError(option + ": expected X,Y,Z (three numbers), got '" + text + "'");
    return {Real((*v)[0]), Real((*v)[1]), Real((*v)[2])};
}

FrameRange parseFrames(const std::optional<std::string>& frames, int orbit) {
    if (!frames) return {0, std::max(orbit, 1) - 1};
    if (orbit < 1) throw InputError("--frames needs --orbit N: it picks frames of the orbit");
    const auto one = parseSeparated<int, 1>(*frames, "..");  // --frames 7: that frame alone
    const auto range = one ? std::array<int, 2>{(*one)[0], (*one)[0]} : parseSeparated<int, 2>(*frames, "..");
    if (!range) throw InputError("--frames: expected A..B (frame numbers, both included), got '" + *frames + "'");
    const FrameRange r{(*range)[0], (*range)[1]};
    if (r.first < 0 || r.last < r.first || r.last >= orbit)
        throw InputError("--frames " + *frames + ": the orbit's frames are 0.." + std::to_string(orbit - 1) +
                         ", and A must not exceed B");
    return r;
}

std::string framePath(const std::string& path, int frame) {
    const std::size_t end = path.find_last_of('#');
    if (end == std::string::npos) return path;
    const std::size_t begin = path.find_last_not_of('#', end) + 1;  // npos + 1 == 0: all '#'
    std::string number = std::to_string(frame);
    if (number.size() < end + 1 - begin) number.insert(0, end + 1 - begin - number.size(), '0');
    return path.substr(0, begin) + number + path.substr(end + 1);
}

PixelWindow parseTile(const std::string& tiles, const std::string& tile, int width, int height) {
    const auto columnsRows = parseSeparated<int, 2>(tiles, "x");
    if (!columnsRows) throw InputError("--tiles: expected CxR (columns x rows, e.g. 4x4), got '" + tiles + "'");
    const auto indexOfCount = parseSeparated<int, 2>(tile, "/");
    if (!indexOfCount) throw InputError("--tile: expected I/N (tile I of N, from 0), got '" + tile + "'");
    const TileGrid grid{(*columnsRows)[0], (*columnsRows)[1]};
    const auto [index, count] = *indexOfCount;
    if (count != grid.count())
        throw InputError("--tile " + tile + ": --tiles " + tiles + " makes " + std::to_string(grid.count()) + " tiles");
    return tileWindow(width, height, grid, index);
}

namespace {

// One output: the format follows -o and -f (chooseImageFormat); -p renders nothing, so it writes nothing.
ImageOutputSettings outputSettings(const RenderOptions& o, const std::optional<std::string>& path) {
    ImageOutputSettings s;
    s.color = o.color;
    s.exrPixels = o.exrPixels;
    s.pngBits = o.pngBits;
    s.tiffBits = o.tiffBits;
    s.jpegQuality = o.jpegQuality;
    s.exrCompression = o.exrCompression;
    s.path = path.value_or("");
    if (o.preprocessOnly) return s;
    if (path) checkNotDirectory(*path);  // before its extension is looked at
    s.format = chooseImageFormat(o.outputType, path);
    if (s.format == ImageFormat::Text && !path) s.path = std::string(1, '-');  // text goes to the terminal
    if (s.format != ImageFormat::Null && s.path.empty())
        throw InputError(std::string(imageFormatName(s.format)) + " output needs -f FILE");
    s.alpha = o.alpha.value_or(imageFormatHasAlpha(s.format));
    if (s.alpha && !imageFormatHasAlpha(s.format) && s.format != ImageFormat::Null)
        throw InputError(std::string("--alpha on: ") + imageFormatName(s.format) + " output has no alpha channel");
    if (o.aovs && s.format == ImageFormat::Exr) s.aovs = parseAovList(*o.aovs);
    return s;
}

// Every -f, written from one render (or the one output -o alone gives, or null).
std::vector<ImageOutputSettings> outputSettings(const RenderOptions& o) {
    std::vector<ImageOutputSettings> outputs;
    if (o.outputPaths.empty()) outputs.push_back(outputSettings(o, std::nullopt));
    for (const std::string& path : o.outputPaths) outputs.push_back(outputSettings(o, path));
    const bool anyExr = std::any_of(outputs.begin(), outputs.end(),
                                    [](const ImageOutputSettings& s) { return s.format == ImageFormat::Exr; });
    if (o.aovs && !anyExr && !o.preprocessOnly) throw InputError("--aov needs an EXR output (-f out.exr)");
    return outputs;
}

// Every frame of a turntable needs a file of its own: the names carry the frame number.
void checkFrameNames(const RenderOptions& o, const ImageOutputSettings& output) {
    if (o.orbit < 1) return;
    const auto needsNumber = [](const std::string& path) { return path != "-" && path.find('#') == std::string::npos; };
    if (output.format != ImageFormat::Null && needsNumber(output.path))
        throw InputError("--orbit: -f " + output.path + " needs #### where the frame number goes (out_####.png)");
    if (o.statsJson && needsNumber(*o.statsJson))
        throw InputError("--orbit: --stats-json " + *o.statsJson + " needs #### where the frame number goes");
    if (output.format != ImageFormat::Null && output.path == "-" && o.orbit > 1)
        throw InputError("--orbit: several pictures cannot all go to standard output");
}

// Two outputs on standard output would be concatenated into one unusable stream.
void checkOneStandardOutput(const RenderOptions& o, const std::vector<ImageOutputSettings>& outputs) {
    std::vector<std::string> users;
    for (const ImageOutputSettings& output : outputs)
        if (output.format != ImageFormat::Null && output.path == "-") users.push_back("the image");
    if (o.statsLine) users.push_back("-b");
    if (o.statsJson == "-") users.push_back("--stats-json -");
    if (users.size() > 1)
        throw InputError(users[0] + " and " + users[1] + " would both write to standard output; send one to a file");
}

// Every AOV some output asks for, in aovLayers() order.
std::vector<Aov> wantedAovs(const std::vector<ImageOutputSettings>& outputs) {
    std::vector<Aov> aovs;
    for (const AovLayer& layer : aovLayers())
        if (std::any_of(outputs.begin(), outputs.end(), [&layer](const ImageOutputSettings& s) {
                return std::find(s.aovs.begin(), s.aovs.end(), layer.aov) != s.aovs.end();
            }))
            aovs.push_back(layer.aov);
    return aovs;
}

// Every problem with the outputs is found before the scene is loaded: bad colour names
// (whatever the output type), a file that cannot be written; missing folders are created.
void prepareOutputs(const RenderOptions& o, const std::vector<ImageOutputSettings>& outputs, int firstFrame) {
    checkOneStandardOutput(o, outputs);
    ColorPipeline check(o.color);
    for (const ImageOutputSettings& output : outputs) {
        checkFrameNames(o, output);
        if (output.format != ImageFormat::Null) prepareOutputFile(framePath(output.path, firstFrame));
    }
    if (o.statsJson) prepareOutputFile(framePath(*o.statsJson, firstFrame));
}

CameraOverrides cameraOverrides(const RenderOptions& o) {
    CameraOverrides c;
    if (o.lookFrom) c.lookFrom = parseVector("--look-from", *o.lookFrom);
    if (o.lookAt) c.lookAt = parseVector("--look-at", *o.lookAt);
    if (o.up) c.up = parseVector("--up", *o.up);
    if (o.fov) c.fovDegrees = Real(*o.fov);
    c.frame = o.frame;
    return c;
}

// --light adds lights that replace the headlight, as --no-default-light removes it.
void addCommandLineLights(const RenderOptions& o, Scene& scene) {
    std::vector<Light> lights;
    for (const std::string& text : o.lights) lights.push_back(parseLightOption(text));
    if (!lights.empty() || o.noDefaultLight) scene.dropHeadlights();
    scene.lights.insert(scene.lights.end(), lights.begin(), lights.end());
}

// The scene with the camera the options ask for: --camera picks one, the overrides change it,
// the headlight follows.
Scene loadWithCamera(const RenderOptions& o) {
    ImportOptions import = o.import;
    import.camera = o.camera.value_or("");
    import.cameraFromCommandLine = o.lookFrom || o.lookAt || o.fov;
    for (const std::string& assignment : o.parameters) {  // a later --set of the same name wins
        auto [name, value] = parseParameterAssignment(assignment);
        import.parameters.insert_or_assign(std::move(name), std::move(value));
    }
    import.aspect = double(o.render.width) / double(o.render.height);
    Scene scene = loadScene(o.scenePath, import);
    if (o.environment) setEnvironmentImage(scene, *o.environment);
    applyOverrides(scene.camera, cameraOverrides(o), scene.primitives.bounds(), Real(import.aspect));
    addCommandLineLights(o, scene);
    scene.placeHeadlights();  // at the camera the overrides made
    return scene;
}

// --skip-existing: the output a task wrote before it was requeued is kept if it reads back whole.
bool outputIsComplete(const RenderOptions& o, const ImageOutputSettings& output, ProgressMode progress) {
    if (output.path == "-") return false;
    const std::string why = whyNotCompleteImage(output, o.render.width, o.render.height, o.render.window());
    if (why.empty())
        announce(progress, output.path + " is complete: nothing to render (--skip-existing)");
    else if (why != "missing")
        announce(progress, "rendering " + output.path + " again: " + why);
    return why.empty();
}

// --skip-existing on a run of one picture (one frame): every file it writes is already complete.
bool outputsComplete(const RenderOptions& o, const std::vector<ImageOutputSettings>& outputs, const FrameRange& frames,
                     ProgressMode progress) {
    if (!o.skipExisting || frames.first != frames.last) return false;
    bool any = false;
    for (ImageOutputSettings output : outputs) {
        if (output.format == ImageFormat::Null) continue;
        output.path = framePath(output.path, frames.first);
        if (!outputIsComplete(o, output, progress)) return false;
        any = true;
    }
    return any;
}

std::unique_ptr<Accelerator> buildAnnounced(const Scene& scene, const AccelSettings& settings, ProgressMode progress,
                                            RenderStats& stats) {
    announce(progress, std::string("building the ") + accelKindName(settings.kind) + " tree over " +
                           std::to_string(scene.primitives.size()) + " objects");
    const Stopwatch stopwatch;
    std::unique_ptr<Accelerator> accel = buildAccelerator(scene.primitives, settings);
    stats.preprocessSeconds = stopwatch.seconds();
    char done[160];
    std::snprintf(done, sizeof done, "%s tree built: %llu nodes in %.3f s", accel->stats().name.c_str(),
                  static_cast<unsigned long long>(accel->stats().nodes), stats.preprocessSeconds);
    announce(progress, done);
    return accel;
}

// The bar's line ends (its destructor) before anything else is printed. A signal during the
// render says how far it got (noteWorkInProgress), even with -q: a farm's log then shows it.
Framebuffer renderShowingProgress(const Scene& scene, const Accelerator& accel, const RenderSettings& settings,
                                  ProgressMode mode, RenderStats& stats, const ImageTextures& images,
                                  const RenderWatch& watch) {
    Progress progress(mode);
    const PixelWindow w = settings.window();
    noteWorkInProgress("rt-render", "samples", 0,
                       std::uint64_t(w.width()) * std::uint64_t(w.height()) * std::uint64_t(settings.pixelSamples));
    RenderWatch endable = watch;
    endable.endAfterPass = [] { return workEndRequested() != 0; };
    Framebuffer image = rt::render(
        {scene, &images}, accel, settings, stats,
        [&progress](std::uint64_t done, std::uint64_t total) {
            progress.update(done, total);
            noteWorkInProgress("rt-render", "samples", done, total);
        },
        endable);
    noteWorkInProgress("rt-render", "samples", 0, 0);  // rendered: a signal now interrupts the writing
    return image;
}

// What a run without -f or -o did, so that nobody waits for a picture that never comes.
std::string outputNote(const RenderOptions& o, const ImageOutputSettings& output) {
    if (output.format != ImageFormat::Null) return output.path == "-" ? "" : "wrote " + output.path + "\n";
    if (o.outputType || o.preprocessOnly) return "";
    return "nothing written: without -f or -o the output is null (as in the thesis); "
           "write the picture with -f out.png or -f out.exr\n";
}

// The exit code of a render that --time-limit cut short with nothing written (docs/rt-render.md).
constexpr int kExitTimeLimit = 3;

// --time-limit ran out before the picture had one sample in every pixel: nothing is written.
class TimeLimitReached : public std::runtime_error {
    using std::runtime_error::runtime_error;
};

// SIGUSR1, and with --on-interrupt write the first SIGINT or SIGTERM, end the render after the
// pass under way and write it; what the signal's line on standard error says depends on whether
// the render has passes (the path tracer) or is one (the Whitted tracer).
void endRendersOnSignals(const RenderOptions& o) {
    endWorkOnSignals(o.onInterrupt == OnInterrupt::Write, "rt-render",
                     o.render.integrator == Integrator::Path
                         ? "ending after the pass under way and writing the passes done (SIGINT again: stop now, "
                           "writing nothing)"
                         : "finishing the picture (the Whitted tracer has one pass) and writing it (SIGINT again: "
                           "stop now, writing nothing)");
}

// Renders one picture (a turntable's frame `frame`) once and writes every output of it.
void renderFrame(const RenderOptions& o, const Scene& scene, const Accelerator& accel, const TreeReport& tree,
                 const ImageTextures& images, const std::vector<ImageOutputSettings>& outputs, int frame,
                 ProgressMode progress, RenderStats& stats, const RenderWatch& watch) {
    std::vector<ImageOutputSettings> frameOutputs = outputs;
    for (ImageOutputSettings& out : frameOutputs) out.path = framePath(out.path, frame);
    std::optional<RenderEstimate> estimate;
    if (o.preprocessOnly) {
        estimate = estimateRender({scene, &images}, accel, o.render);
        if (!o.quiet) std::cerr << estimateSummary(o.render, *estimate);
    } else {
        const Framebuffer image = renderShowingProgress(scene, accel, o.render, progress, stats, images, watch);
        if (watch.stop && *watch.stop) return;  // the window was closed: nothing is written
        if (stats.samplesPerPixel == 0) throw TimeLimitReached(timeLimitMessage(o.render));
        const ImageMetadata meta{std::string("rt-render ") + kVersion, o.scenePath, stats.samplesPerPixel,
                                 stats.renderSeconds};
        for (const ImageOutputSettings& out : frameOutputs)
            std::cerr << halfClipWarning(out.path, writeImage(image, out, meta));  // even with -q, as below
        std::cerr << nonFiniteWarning(stats);         // even with -q: a replaced sample is never silent
        std::cerr << timeLimitNote(o.render, stats);  // even with -q: the picture has fewer samples than asked
        std::cerr << endRequestNote(workEndRequested(), o.render, stats);
    }
    if (!o.quiet) {
        std::cerr << statsSummary(o.render, tree.stats, stats, !o.preprocessOnly);
        for (const ImageOutputSettings& out : frameOutputs) std::cerr << outputNote(o, out);
    }
    if (o.statsLine) std::cout << thesisStatsLine(stats) << std::endl;
    if (o.statsJson) {
        const SceneSummary summary = summarizeScene(o.scenePath, scene);
        const RunRecord run{o.arguments, o.optionValues, o.orbit > 0 ? std::optional<int>(frame) : std::nullopt};
        writeFileAtomically(framePath(*o.statsJson, frame), [&](std::ostream& out) {
            writeStatsJson(out, run, summary, o.render, tree, stats, estimate);
        });
    }
}

// -o sdl opens a window beside the files of -f (whose extensions then give their types); at once,
// before the scene loads, so that a missing display is found first.
std::optional<SdlWindow> openWindow(RenderOptions& o) {
    if (o.outputType != "sdl") return std::nullopt;
    o.outputType.reset();
    if (o.orbit > 0) throw InputError("-o sdl shows one picture: not with --orbit");
    if (o.preprocessOnly) return std::nullopt;
    return std::optional<SdlWindow>(std::in_place, o.render.window(), o.color, "rt-render " + o.scenePath);
}

// Everything runRender does but the exit code of --time-limit.
int renderAll(RenderOptions o) {
    if (o.region) o.render.region = parseRegion(*o.region);
    if (o.tile) o.render.region = parseTile(o.tiles.value_or(""), *o.tile, o.render.width, o.render.height);
    const FrameRange frames = parseFrames(o.frames, o.orbit);
    std::optional<SdlWindow> window = openWindow(o);
    const std::vector<ImageOutputSettings> outputs = outputSettings(o);
    o.render.aovs = wantedAovs(outputs);
    validate(o.render);  // with the AOVs the outputs ask for
    const ProgressMode progress = progressMode(o.progress, o.quiet);
    for (const std::string& option : o.ignoredOptions)
        if (!o.quiet)
            std::cerr << "rt-render: note: " << option << " is not used by --integrator "
                      << nameOf(kIntegratorNames, o.render.integrator) << ": ignored\n";
    for (const std::string& option : o.retiredOptions)
        if (!o.quiet)
            std::cerr << "rt-render: note: " << option
                      << " is no longer used: textures are read into memory, no copies are made: ignored\n";
    if (outputsComplete(o, outputs, frames, progress)) return 0;
    prepareOutputs(o, outputs, frames.first);

    const std::uint64_t memoryLimit = o.maxMemoryGb ? std::uint64_t(*o.maxMemoryGb * 1e9) : defaultMemoryLimit();
    checkMemoryLimit(estimateRenderMemory(o.render, 0, !o.preprocessOnly), memoryLimit);  // before the scene loads

    Scene scene = loadWithCamera(o);
    scene.dropDescription();
    MemoryEstimate memory = estimateRenderMemory(o.render, scene.primitives.size(), !o.preprocessOnly);
    memory.textures = estimateTextureMemory(scene);  // before any is read
    checkMemoryLimit(memory, memoryLimit);
    const TextureSettings textures{o.textureFilter, [progress](const std::string& step) { announce(progress, step); }};
    const TextureFiles images(scene, scene.warnings, textures);  // before the warnings are shown: it adds its own
    if (!o.quiet)
        for (const std::string& w : scene.warnings) std::cerr << "rt-render: warning: " << oneLine(w) << '\n';
    RenderStats stats;
    const std::unique_ptr<Accelerator> accel = buildAnnounced(scene, o.accel, progress, stats);  // once for every frame
    const std::unique_ptr<MaterialFilter> filter = materialFilter({scene, &images});  // cut-outs, single-sided
    accel->setHitFilter(filter.get());
    const TreeReport tree{o.accel, accel->stats(), std::uint32_t(scene.primitives.size()), {}, {}};
    const AccelStats& accelStats = tree.stats;
    stats.treeNodes = accelStats.nodes;
    stats.objects = scene.primitives.size();
    stats.lights = scene.lights.size();

    const Camera camera = scene.camera;
    const auto renderFrames = [&](const RenderWatch& watch) {
        for (int frame = frames.first; frame <= frames.last; ++frame) {
            if (o.orbit > 0) {
                scene.camera = orbited(camera, Real(360) * Real(frame) / Real(o.orbit));
                scene.placeHeadlights();
                announce(progress, "frame " + std::to_string(frame) + " of 0.." + std::to_string(o.orbit - 1));
            }
            renderFrame(o, scene, *accel, tree, images, outputs, frame, progress, stats, watch);
            if (workEndRequested()) break;  // the frame it ended is written; no other starts
        }
    };
    if (window) return showWhileRendering(*window, renderFrames);
    renderFrames({});
    return 0;
}

}  // namespace

int runRender(RenderOptions o) {
    endRendersOnSignals(o);
    try {
        return renderAll(std::move(o));
    } catch (const TimeLimitReached& e) {
        printError("rt-render", e.what());
        return kExitTimeLimit;
    }
}

void endAsInterrupted() {
    const int signal = workEndRequested();
    if (signal != SIGINT && signal != SIGTERM) return;
    std::signal(signal, SIG_DFL);
    std::raise(signal);
}

}  // namespace rt::tool::render
