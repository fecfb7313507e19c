// rt-convert: glTF, OBJ, 3DS and the rest of Assimp's formats to the thesis XML+RAW scene.
#include <CLI/CLI.hpp>

#include "tool.h"

int main(int argc, char** argv) {
    CLI::App app{"Converts a 3-D model (glTF, OBJ, 3DS, ...) to the rt XML+RAW scene format."};
    app.set_version_flag("-v,--version", rt::tool::versionLine("rt-convert"));
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e) == 0 ? rt::tool::kExitOk : rt::tool::kExitBadInput;
    }
    return rt::tool::run("rt-convert", [] {
        throw std::runtime_error("conversion is not implemented yet");
        return 0;
    });
}
