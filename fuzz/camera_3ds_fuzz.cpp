// The 3DS camera chunk reader (import/camera_3ds.h), and rt's camera made of what it found.
#include <span>

#include "fuzz_input.h"
#include "io/camera_3ds.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return rt::fuzz::expectInputErrorOnly([&] {
        for (const rt::Camera3ds& camera : rt::read3dsCameras(std::span(data, size), "fuzz.3ds"))
            rt::cameraFrom3ds(camera, rt::Transform());
    });
}
