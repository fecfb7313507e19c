// glTF 2.0 import through tinygltf (import/gltf_import.h), JSON and GLB, as rt-render reads a
// model from standard input; URIs resolve against the working folder.
#include "fuzz_input.h"
#include "io/import.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    return rt::fuzz::expectInputErrorOnly([&] { rt::importGltfFromStandardInput(bytes, rt::ImportOptions{}); });
}
