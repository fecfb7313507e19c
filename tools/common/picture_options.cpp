#include "picture_options.h"

#include "command_line.h"

namespace rt::tool {

void addPictureOptions(CLI::App& app, RenderSettings& s) {
    const char* rendering = "Rendering options";
    app.add_option("-x,--width", s.width, "Image width in pixels")
        ->check(numberIn(1, kMaxImageSide))
        ->capture_default_str()
        ->group(rendering);
    app.add_option("-y,--height", s.height, "Image height in pixels")
        ->check(numberIn(1, kMaxImageSide))
        ->capture_default_str()
        ->group(rendering);
    app.add_option("-d,--depth", s.reflectionDepth, "Reflection depth: reflections that may follow a camera ray")
        ->check(numberIn(0, kMaxReflectionDepth))
        ->capture_default_str()
        ->group(rendering);
    app.add_flag("-s,--shadows", s.shadows, "Shadows: a shadow ray to each light")->group(rendering);

    const char* quality = "Image quality options";
    app.add_option("-S,--supersample,--spp", s.pixelSamples,
                   "Stochastic supersampling: rays (the path tracer's paths) per pixel on a jittered grid")
        ->check(numberIn(1, kMaxSamples))
        ->group(quality);
    app.add_option_function<std::string>(
           "-D,--distributed",
           [&s](const std::string& kind) {
               s.softShadows = kind != "d";
               s.shadows = s.shadows || s.softShadows;
               s.glossyReflections = kind != "s";
           },
           "Distributed ray tracing: s soft shadows, d diffuse (glossy) reflections, b both")
        ->check(CLI::IsMember({"s", "d", "b"}))
        ->group(quality);
    app.add_option("-r,--distributed-samples", s.distributedSamples, "Rays per distributed bundle")
        ->check(numberIn(1, kMaxSamples))
        ->capture_default_str()
        ->group(quality);
}

}  // namespace rt::tool
