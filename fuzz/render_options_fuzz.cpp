// rt-render's command line (tools/render/render_options.h) and the values runRender parses out
// of it before it reads the scene: region, tiles, frames, camera vectors, the render settings.
// The input is the arguments after the program's name, separated by NUL bytes. Each list must
// end in options, a CLI11 parse error (exit 2 in the tool) or an rt::InputError.
#include <vector>

#include "fuzz_input.h"
#include "render/render_settings.h"
#include "render_options.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::vector<std::string> arguments{"rt-render"};
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    for (std::size_t start = 0; start <= bytes.size() && arguments.size() <= 64;) {
        const std::size_t end = std::min(bytes.find('\0', start), bytes.size());
        arguments.push_back(bytes.substr(start, end - start));
        start = end + 1;
    }
    std::vector<char*> argv;
    for (std::string& argument : arguments) argv.push_back(argument.data());
    namespace render = rt::tool::render;
    render::RenderOptions o;
    CLI::App app;
    render::addRenderOptions(app, o);
    try {
        app.parse(int(argv.size()), argv.data());
    } catch (const CLI::ParseError&) {
        return 0;
    }
    return rt::fuzz::expectInputErrorOnly([&] {
        rt::validate(o.render);
        if (o.region) render::parseRegion(*o.region);
        if (o.tiles && o.tile) render::parseTile(*o.tiles, *o.tile, o.render.width, o.render.height);
        const render::FrameRange frames = render::parseFrames(o.frames, o.orbit);
        for (const std::string& path : o.outputPaths) render::framePath(path, frames.last);
        for (const auto* vector : {&o.lookFrom, &o.lookAt, &o.up})
            if (*vector) render::parseVector("--vector", **vector);
    });
}
