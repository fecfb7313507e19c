// The tool's side of the contained Assimp read (import/assimp_contained.h readReply): the assbin
// bytes the child sends back, read by Assimp's assbin reader in the tool's own process. A child
// that a hostile file took over could send anything, so the reader must answer any bytes with
// a scene or an error.
#include <stdexcept>

#include "fuzz_input.h"
#include "import/assimp_contained.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    Assimp::Importer importer;
    try {
        rt::readReply(importer, "fuzz.assbin", std::string(reinterpret_cast<const char*>(data), size));
    } catch (const std::runtime_error&) {}
    return 0;
}
