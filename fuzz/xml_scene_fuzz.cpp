// The XML scene loader (scene/xml_loader.h) with inline RAW models (base64), as rt-render reads
// a scene from standard input: model files resolve against a folder that does not exist.
#include "fuzz_input.h"
#include "io/xml_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string xml(reinterpret_cast<const char*>(data), size);
    return rt::fuzz::expectInputErrorOnly([&] { rt::loadSceneXmlFromString(xml, "fuzz.xml", "/nonexistent-rt-fuzz"); });
}
