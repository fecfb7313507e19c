// The RAW model reader (scene/raw_model.h, thesis appendix D).
#include <span>

#include "fuzz_input.h"
#include "io/raw_model.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return rt::fuzz::expectInputErrorOnly([&] { rt::readRawBytes(std::span(data, size), "fuzz.raw"); });
}
