// rt-inspect: statistics, dumps and heat maps of the KD and BSP trees.
#include <CLI/CLI.hpp>

#include "tool.h"

int main(int argc, char** argv) {
    CLI::App app{"Shows how the KD and BSP trees of a scene look and perform."};
    app.set_version_flag("-v,--version", rt::tool::versionLine("rt-inspect"));
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e) == 0 ? rt::tool::kExitOk : rt::tool::kExitBadInput;
    }
    return rt::tool::run("rt-inspect", [] {
        throw std::runtime_error("inspection is not implemented yet");
        return 0;
    });
}
