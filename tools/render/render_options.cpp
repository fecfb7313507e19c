#include "render_options.h"

#include <algorithm>
#include <array>

#include "accel_options.h"
#include "command_line.h"
#include "picture_options.h"
#include "progress.h"

namespace rt::tool::render {
namespace {

using rt::AccelKind;
using rt::tool::addNamedOption;
using rt::tool::numberIn;

// The texture cache's options (rt-render.md, "Textures"): rt reads textures into memory now.
constexpr std::array<const char*, 3> kRetiredTextureOptions{"--texture-cache", "--tx-cache", "--tx-cache-size"};

// -o's check: one of outputNames(). A file name there is the usual slip (rt-convert's -o is a file,
// as in most tools), so it is answered with the option that takes one.
CLI::Validator outputTypeCheck() {
    const std::vector<std::string> names = outputNames();
    return CLI::Validator(
        [names](std::string& type) -> std::string {
            if (std::find(names.begin(), names.end(), type) != names.end()) return {};
            const std::string valid = "{" + CLI::detail::join(names, ",") + "}";
            if (!rt::imageFormatFromPath(type)) return type + " not in " + valid;
            return type + " is a file name, and -o takes an output type " + valid + ": did you mean -f " + type + "?";
        },
        "{" + CLI::detail::join(names, ",") + "}");
}

void addRenderingOptions(CLI::App& app, RenderOptions& o) {
    const char* group = "Rendering options";
    app.add_option("-o,--output", o.outputType,
                   "Output type (default: -f's extension; neither -o nor -f: null); sdl: a window, beside any -f")
        ->check(outputTypeCheck())
        ->group(group);
    app.add_option("-f,--file", o.outputPaths,
                   "Output file; - for standard output; several -f write each from one render")
        ->allow_extra_args(false)
        ->group(group);
    AccelKind& kind = o.accel.kind;  // the KD tree; the thesis's program used the naive list unless -B or -K
    auto* bsp = app.add_flag_callback(
                       "-B,--bsp", [&kind] { kind = AccelKind::Bsp; }, "Use the BSP tree")
                    ->group(group);
    auto* kd = app.add_flag_callback(
                      "-K,--kd", [&kind] { kind = AccelKind::Kd; }, "Use the KD tree")
                   ->group(group);
    bsp->excludes(kd);
    addNamedOption(app, "--accel", kind, rt::kAccelKindNames,
                   "Ray-scene intersection: the naive list or a tree (default: kd, and bvh for --integrator path)")
        ->excludes(bsp)
        ->excludes(kd)
        ->group(group);
    auto* region =
        app.add_option("--region", o.region, "Render only pixels x0,y0 to x1,y1 (x1, y1 exclusive) of the image")
            ->group(group);
    auto* tiles =
        app.add_option("--tiles", o.tiles, "A farm's grid of tiles, CxR (columns x rows), for --tile")->group(group);
    auto* tile = app.add_option("--tile", o.tile, "Render only tile I of the N of --tiles (I/N, from 0, row by row)")
                     ->needs(tiles)
                     ->excludes(region)
                     ->group(group);
    tiles->needs(tile);
    app.add_flag("--skip-existing", o.skipExisting,
                 "Exit 0 at once if -f already holds this render, complete (read back: size, window, pixels)")
        ->group(group);
    rt::tool::addMaxInputOption(app)->group(group);
    rt::tool::addSandboxOption(app)->group(group);
    rt::tool::addMaxMemoryOption(app, o.maxMemoryGb)->group(group);
    addNamedOption(app, "--texture-filter", o.textureFilter, kTextureFilterNames,
                   "How image textures are filtered over a pixel's footprint: one texel, four, two MIP levels, or "
                   "up to 8 trilinear probes along the footprint")
        ->capture_default_str()
        ->group(group);
    // The texture cache's options, kept so that scripts that give them still run (noted as ignored).
    for (const char* retired : kRetiredTextureOptions)
        app.add_option_function<std::string>(
               retired, [](const std::string&) {},
               "No longer used: textures are read into memory, no copies are made (ignored)")
            ->group(group);
    rt::tool::addThreadsOption(app, o.render.threads)->group(group);
    app.add_option("--time-limit", o.render.timeLimitSeconds,
                   "Stop after this many seconds: the path tracer writes its whole passes, else nothing (exit 3)")
        ->check(rt::tool::numberIn(0.0, rt::kMaxTimeLimit))
        ->group(group);
    addNamedOption(app, "--on-interrupt", o.onInterrupt, kOnInterruptNames,
                   "The first SIGINT (Ctrl-C) or SIGTERM: discard the render, writing nothing; write: end after the "
                   "path tracer's pass under way and write the passes done, then exit 130 or 143 (SIGUSR1 always "
                   "does, exit 0)")
        ->group(group);
    app.add_option("--seed", o.render.seed,
                   "Random seed of the samples: another seed, independent noise (default 0, always the same)")
        ->capture_default_str()
        ->group(group);
    addNamedOption(app, "--packets", o.render.packets, rt::kOnOffNames,
                   "Camera rays of one-sample Whitted renders traced eight at a time (on) or one by one (off): "
                   "the same picture")
        ->group(group);
    app.add_flag("--flat", o.import.flat, rt::tool::kFlatHelp)->group(group);
    app.add_flag("--double-sided", o.import.doubleSided, rt::tool::kDoubleSidedHelp)->group(group);
    app.add_option("--set", o.parameters,
                   "NAME=VALUE: fills $NAME, ${NAME} and ${NAME:-default} in the XML scene's attributes; repeatable")
        ->allow_extra_args(false)
        ->group(group);
}

void addLightOptions(CLI::App& app, RenderOptions& o) {
    const char* group = "Light options (applied after the camera options)";
    app.add_option("--light", o.lights,
                   "Add a light, replacing the default headlight: point:X,Y,Z[,R,G,B[,W]], "
                   "spot:X,Y,Z,TX,TY,TZ[,CONE[,R,G,B[,W]]] or sun:DX,DY,DZ[,R,G,B[,W]]; repeatable")
        ->allow_extra_args(false)
        ->group(group);
    app.add_flag("--no-default-light", o.noDefaultLight,
                 "Remove the headlight a model without lights gets (the white point light at the camera)")
        ->group(group);
    app.add_option("--environment", o.environment,
                   "Equirectangular image (any format OpenImageIO reads), +y up: the sky the path tracer is lit "
                   "by, and the background both integrators show")
        ->group(group);
}

void addPathTracingOptions(CLI::App& app, RenderOptions& o) {
    const char* group = "Path tracing options (docs/path-tracing.md)";
    addNamedOption(app, "--integrator", o.render.integrator, rt::kIntegratorNames,
                   "whitted: the thesis's ray tracer; path: path tracing, -S paths per pixel")
        ->group(group);
    app.add_option("--max-bounces", o.render.maxBounces, "Surface bounces a path may take after the camera ray")
        ->check(numberIn(0, rt::kMaxBounces))
        ->capture_default_str()
        ->group(group);
    app.add_option("--clamp", o.render.clampRadiance,
                   "Cap indirect samples at this value, trading bias for fewer fireflies (default 0: off)")
        ->check(CLI::NonNegativeNumber)
        ->group(group);
    addNamedOption(app, "--light-sampler", o.render.lightSampler, rt::kLightSamplerNames,
                   "How next-event estimation picks a light: tree (by what each can send to the point, "
                   "the default) or power")
        ->group(group);
    app.add_option("--noise-threshold", o.render.noiseThreshold,
                   "Stop sampling a pixel once the relative standard error of its mean luminance is below this, "
                   "e.g. 0.02; -S is then the most a pixel takes (default 0: off)")
        ->check(rt::tool::numberIn(0.0, 1e30))
        ->group(group);
    app.add_option("--adaptive-min-samples", o.render.adaptiveMinSamples,
                   "Samples every pixel takes before --noise-threshold may stop it (default 0: from the threshold, "
                   "as Cycles chooses: max(4, 16 / threshold^0.3))")
        ->check(numberIn(0, rt::kMaxSamples))
        ->group(group);
}

// Adaptive subsampling (thesis 2.3): only rt-render, whose pictures are all the colour it interpolates.
void addAdaptiveOptions(CLI::App& app, rt::RenderSettings& s) {
    const char* quality = "Image quality options";
    // A flag with a value (--adaptive=4): a separate value would be taken for the scene.
    app.add_flag("--adaptive{8}", s.adaptiveGrid,
                 "Adaptive subsampling (--adaptive or --adaptive=GRID, default 8): trace the corners of GRID x GRID "
                 "pixel cells, interpolate where they agree, split the others")
        ->check(CLI::IsMember({2, 4, 8, 16, 32, 64, 128, 256}))
        ->group(quality);
    app.add_option("--adaptive-threshold", s.adaptiveThreshold,
                   "Largest difference of linear colour (and alpha) between corners that --adaptive interpolates")
        ->check(rt::tool::numberIn(0.0, 1e30))
        ->capture_default_str()
        ->group(quality);
}

void addCameraOptions(CLI::App& app, RenderOptions& o) {
    const char* group = "Camera options (applied in this order)";
    app.add_option("--camera", o.camera, "The scene's camera to render: its name or number (0 is the first)")
        ->group(group);
    app.add_option("--look-from", o.lookFrom, "Camera origin X,Y,Z (the lens stays)")->group(group);
    app.add_option("--look-at", o.lookAt, "Camera destination X,Y,Z")->group(group);
    app.add_option("--up", o.up, "Camera up vector X,Y,Z")->group(group);
    app.add_option("--fov", o.fov, "Horizontal field of view in degrees (replaces f and zoom)")
        ->check(rt::tool::numberIn(0.0, 180.0))
        ->group(group);
    app.add_flag("--frame", o.frame, "Move the camera along its view to fit the scene's bounding sphere")->group(group);
    app.add_option("--orbit", o.orbit, "Render N frames around the look-at point to -f out_####.png")
        ->check(numberIn(1, 1000000))
        ->group(group);
    app.add_option("--frames", o.frames, "Render only frames A..B of --orbit (both included)")->group(group);
}

void addImageOptions(CLI::App& app, RenderOptions& o) {
    const char* group = "Colour and file options";
    app.add_option("--color-config", o.color.configPath, "OpenColorIO config (default: $OCIO, then rt's own)")
        ->group(group);
    app.add_option("--colorspace", o.color.colorspace, "Colour space of the rendered values (default: scene_linear)")
        ->group(group);
    app.add_option("--display", o.color.display, "OCIO display for PNG, TGA and text (default: the config's)")
        ->group(group);
    app.add_option("--view", o.color.view, "OCIO view (default: the display's default, Standard)")->group(group);
    app.add_option("--look", o.color.look, "OCIO look(s) applied before the view, e.g. Contrast")->group(group);
    app.add_option("--exposure", o.color.exposure,
                   "Stops of exposure for PNG, TGA, JPEG, WebP, TIFF, text and the window: 2^EV times the linear "
                   "values before the looks and the view (EXR, HDR, PFM and float TIFF keep the render's values)")
        ->check(rt::tool::numberIn(-64.0, 64.0))
        ->group(group);
    addNamedOption(app, "--exr-pixels", o.exrPixels, rt::kExrPixelTypeNames, "EXR pixel type")->group(group);
    app.add_option_function<std::string>(
           "--alpha", [&o](const std::string& name) { o.alpha = rt::parseNamed(rt::kOnOffNames, name); },
           "Alpha channel (coverage): on or off (default: on where the format has alpha; EXR and float TIFF "
           "premultiplied, the others straight)")
        ->check(CLI::IsMember(rt::namesOf(rt::kOnOffNames)))
        ->group(group);
    app.add_option("--aov", o.aovs,
                   "AOV layers written into the EXR after the colour: a list of Z, N, Ng, P, albedo, id, cost, "
                   "variance, samples, or all")
        ->group(group);
    app.add_option("--png-bits", o.pngBits, "PNG bits per channel: 8 or 16")
        ->check(CLI::IsMember(rt::kPngBits))
        ->capture_default_str()
        ->group(group);
    app.add_option("--tiff-bits", o.tiffBits, "TIFF bits per channel: 8 or 16 (display-referred), 32 (float, linear)")
        ->check(CLI::IsMember(rt::kTiffBits))
        ->capture_default_str()
        ->group(group);
    app.add_option("--jpeg-quality", o.jpegQuality, "JPEG quality, 1-100")
        ->check(numberIn(1, 100))
        ->capture_default_str()
        ->group(group);
    app.add_option("--exr-compression", o.exrCompression, "EXR compression")
        ->check(CLI::IsMember(std::vector<std::string>(rt::kExrCompressions.begin(), rt::kExrCompressions.end())))
        ->capture_default_str()
        ->group(group);
}

void addOtherOptions(CLI::App& app, RenderOptions& o) {
    const char* group = "Other options";
    app.add_flag("-q,--quiet", o.quiet, "Quiet: no progress or summary on standard error")->group(group);
    addNamedOption(app, "--progress", o.progress, rt::tool::render::kProgressModeNames,
                   "Progress on standard error: bar, lines (for logs: every 10 % or 10 s), none, or auto "
                   "(the bar on a terminal, else lines)")
        ->group(group);
    app.add_flag("-b,--batch-stats", o.statsLine,
                 "Print 'preprocessing render objects lights nodes tests-per-ray' on standard output")
        ->group(group);
    app.add_flag("-p,--preprocess-only", o.preprocessOnly, "Build the tree and render nothing (implies -o null)")
        ->group(group);
    app.add_option("--stats-json", o.statsJson, "Write every statistic as JSON to FILE (- for standard output)")
        ->group(group);
}

}  // namespace

// The outputs -o takes: the image formats and the window.
std::vector<std::string> outputNames() {
    std::vector<std::string> names = rt::imageFormatNames();
    names.push_back("sdl");
    return names;
}

namespace {

// Options only one integrator reads.
struct IntegratorOption {
    const char* name;
    Integrator readBy;
};
constexpr std::array<IntegratorOption, 9> kIntegratorOptions{{{"--depth", Integrator::Whitted},
                                                              {"--shadows", Integrator::Whitted},
                                                              {"--distributed", Integrator::Whitted},
                                                              {"--distributed-samples", Integrator::Whitted},
                                                              {"--packets", Integrator::Whitted},
                                                              {"--max-bounces", Integrator::Path},
                                                              {"--clamp", Integrator::Path},
                                                              {"--light-sampler", Integrator::Path},
                                                              {"--adaptive-min-samples", Integrator::Path}}};

}  // namespace

void chooseDefaultAccel(CLI::App& app, RenderOptions& options) {
    if (app.count("--accel") + app.count("--bsp") + app.count("--kd") != 0) return;
    options.accel.kind = defaultAccelKind(options.render.integrator);
    app.get_option("--accel")->default_str(accelKindName(options.accel.kind));  // as --stats-json records it
}

std::vector<std::string> retiredOptionsGiven(const CLI::App& app) {
    std::vector<std::string> given;
    for (const char* option : kRetiredTextureOptions)
        if (app.count(option) > 0) given.emplace_back(option);
    return given;
}

std::vector<std::string> optionsTheIntegratorIgnores(const CLI::App& app, Integrator integrator) {
    std::vector<std::string> ignored;
    for (const IntegratorOption& option : kIntegratorOptions)
        if (option.readBy != integrator && app.count(option.name) > 0) ignored.emplace_back(option.name);
    return ignored;
}

void addRenderOptions(CLI::App& app, RenderOptions& options) {
    app.option_defaults()->always_capture_default();  // so that --stats-json records every default
    app.add_option("scene", options.scenePath, rt::tool::kSceneHelp)->required();
    rt::tool::addPictureOptions(app, options.render);
    addRenderingOptions(app, options);
    addAdaptiveOptions(app, options.render);
    addCameraOptions(app, options);
    addLightOptions(app, options);
    addPathTracingOptions(app, options);
    rt::tool::addAccelOptions(app, options.accel);
    addImageOptions(app, options);
    addOtherOptions(app, options);
}

}  // namespace rt::tool::render
