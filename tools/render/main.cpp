// rt-render: the ray tracer of the thesis (appendix B), with EXR, PNG, TGA and text output.
// This file only declares the command line; runRender (render_command.cpp) does the work.
#include <CLI/CLI.hpp>

#include "render_command.h"
#include "accel_options.h"
#include "command_line.h"
#include "picture_options.h"
#include "tool.h"

namespace {

using rt::render_tool::RenderOptions;

void addRenderingOptions(CLI::App& app, RenderOptions& o, std::string& accelName) {
    const char* group = "Rendering options";
    app.add_option("-o,--output", o.outputType,
                   "Output type: null png exr tga text (default: -f's extension; neither -o nor -f: null)")
        ->check(CLI::IsMember({"null", "png", "exr", "tga", "text"}))->group(group);
    app.add_option("-f,--file", o.outputPath, "Output file; - for standard output")->group(group);
    auto* bsp = app.add_flag_callback("-B,--bsp", [&] { accelName = "bsp"; }, "Use the BSP tree")->group(group);
    auto* kd = app.add_flag_callback("-K,--kd", [&] { accelName = "kd"; }, "Use the KD tree")->group(group);
    bsp->excludes(kd);
    app.add_option("--accel", accelName, "Ray-scene intersection: naive, bsp or kd")
        ->check(CLI::IsMember({"naive", "bsp", "kd"}))->excludes(bsp)->excludes(kd)->capture_default_str()
        ->group(group);
    app.add_option("--region", o.region, "Render only pixels x0,y0 to x1,y1 (x1, y1 exclusive) of the image")
        ->group(group);
    rt::tool::addMaxInputOption(app)->group(group);
    app.add_option("--max-memory", o.maxMemoryGb,
                   "Refuse to start a render estimated to need more memory than this, in GB [default: 3/4 of the "
                   "machine's]")
        ->check(rt::tool::numberIn(0.01, 1e6))->group(group);
    rt::tool::addThreadsOption(app, o.render.threads)->group(group);
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
    app.add_option("--exr-pixels", o.exrPixels, "EXR pixel type: half or float")
        ->check(CLI::IsMember({"half", "float"}))->capture_default_str()->group(group);
    app.add_option("--png-bits", o.pngBits, "PNG bits per channel: 8 or 16")->check(CLI::IsMember({8, 16}))
        ->capture_default_str()->group(group);
}

void addOtherOptions(CLI::App& app, RenderOptions& o) {
    const char* group = "Other options";
    app.add_flag("-q,--quiet", o.quiet, "Quiet: no progress or summary on standard error")->group(group);
    app.add_option("--progress", o.progress,
                   "Progress on standard error: bar, lines (for logs: every 10 % or 10 s), none, or auto "
                   "(the bar on a terminal, else lines)")
        ->check(CLI::IsMember({"auto", "bar", "lines", "none"}))->capture_default_str()->group(group);
    app.add_flag("-b,--batch-stats", o.statsLine,
                 "Print 'preprocessing render objects lights nodes tests-per-ray' on standard output")->group(group);
    app.add_flag("-p,--preprocess-only", o.preprocessOnly, "Build the tree and render nothing (implies -o null)")
        ->group(group);
    app.add_option("--stats-json", o.statsJson, "Write every statistic as JSON to FILE (- for standard output)")
        ->group(group);
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Renders a scene by ray tracing (thesis appendix B)."};
    app.set_version_flag("-v,--version", rt::tool::versionLine("rt-render"));
    RenderOptions options;
    std::string accelName = "kd";  // the thesis's program used the naive list unless -B or -K
    app.add_option("scene", options.scenePath, "Scene: rt XML (- reads standard input) or any model rt-convert reads")->required();
    rt::tool::addPictureOptions(app, options.render);
    addRenderingOptions(app, options, accelName);
    rt::tool::addAccelOptions(app, options.accel);
    addImageOptions(app, options);
    addOtherOptions(app, options);
    if (const std::optional<int> exitCode = rt::tool::parseCommandLine(app, "rt-render", argc, argv)) return *exitCode;
    options.accel.kind = *rt::parseAccelKind(accelName);
    return rt::tool::run("rt-render", [&] { return rt::render_tool::runRender(options); });
}
