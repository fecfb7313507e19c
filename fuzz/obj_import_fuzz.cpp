// OBJ import through tinyobjloader's streaming API (import/obj_import.h), as rt-convert reads a
// .obj file; its mtllib lines find no file unless they name the input itself.
#include "fuzz_input.h"
#include "io/import.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string path = rt::fuzz::writeInputFile(data, size, "input.obj");
    return rt::fuzz::expectInputErrorOnly([&] { rt::importScene(path); });
}
