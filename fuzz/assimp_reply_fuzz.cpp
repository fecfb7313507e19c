// The tool's side of the contained Assimp read: the bytes the child sends back
// (import/assimp_reply.h readAssimpReply), read in the tool's own process, and the scene the
// importer builds from them (import/assimp_import.h importAssimpScene). A child that a hostile
// file took over could send anything, so any bytes must end in a scene or an rt::InputError.
#include <assimp/scene.h>

#include "fuzz_input.h"
#include "io/assimp_import.h"
#include "io/assimp_reply.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return rt::fuzz::expectInputErrorOnly([&] {
        const auto scene = rt::readAssimpReply(std::string(reinterpret_cast<const char*>(data), size), "fuzz.reply");
        // A format whose axes Assimp leaves alone, and not 3DS, whose cameras come from the file.
        rt::importAssimpScene(*scene, "fuzz.reply", "Stanford Polygon Library", rt::ImportOptions{});
    });
}
