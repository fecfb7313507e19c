// rt-render: the ray tracer of the thesis (appendix B), with EXR, PNG, TGA and text output.
// The options are declared in render_options.cpp; runRender (render_command.cpp) does the work.
#include <CLI/CLI.hpp>

#include "command_line.h"
#include "render_command.h"
#include "render_options.h"
#include "sdl_window.h"
#include "tool.h"

namespace {

// The version line and, as the thesis's -v did, the outputs compiled in.
std::string versionText() {
    std::string outputs;
    for (const std::string& name : rt::tool::render::outputNames())
        if (name != "sdl" || rt::tool::render::SdlWindow::compiledIn()) outputs += " " + name;
    return rt::tool::versionLine("rt-render") + "\noutputs:" + outputs;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{
        "Renders a scene by ray tracing (thesis appendix B).\n"
        "Examples:\n"
        "  rt-render scenes/demo.xml -f demo.png           the demo scene as a PNG\n"
        "  rt-render model.glb -x 1280 -y 720 --integrator path --spp 64 -f model.exr\n"
        "  rt-render model.obj --look-from 0,2,5 --look-at 0,1,0 --fov 60 -f view.png\n"
        "  rt-render scene.xml --orbit 36 -f turn/frame_####.png   a turntable of 36 frames\n"
        "  rt-render scene.xml -p --stats-json stats.json  the tree and an estimate, no picture\n"};
    app.set_version_flag("-v,--version", versionText());
    rt::tool::render::RenderOptions options;
    rt::tool::render::addRenderOptions(app, options);
    if (const std::optional<int> exitCode = rt::tool::parseCommandLine(app, "rt-render", argc, argv)) return *exitCode;
    rt::tool::render::chooseDefaultAccel(app, options);
    options.arguments.assign(argv, argv + argc);
    options.optionValues = rt::tool::optionValues(app);
    options.ignoredOptions = rt::tool::render::optionsTheIntegratorIgnores(app, options.render.integrator);
    options.retiredOptions = rt::tool::render::retiredOptionsGiven(app);
    const int status = rt::tool::run("rt-render", [&] { return rt::tool::render::runRender(options); });
    if (status == rt::tool::kExitOk) rt::tool::render::endAsInterrupted();  // once standard output is flushed
    return status;
}
