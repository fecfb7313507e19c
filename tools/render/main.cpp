// rt-render: the Whitted ray tracer of the thesis, with EXR and PNG output.
#include <CLI/CLI.hpp>

#include "tool.h"

int main(int argc, char** argv) {
    CLI::App app{"Renders an rt scene by ray tracing."};
    app.set_version_flag("-v,--version", rt::tool::versionLine("rt-render"));
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e) == 0 ? rt::tool::kExitOk : rt::tool::kExitBadInput;
    }
    return rt::tool::run("rt-render", [] {
        throw std::runtime_error("rendering is not implemented yet");
        return 0;
    });
}
