// Everything rt-render's command line sets, gathered by main.cpp (the only file that
// sees CLI11) and carried out by runRender.
#pragma once

#include <optional>
#include <string>

#include "accel/settings.h"
#include "image/image_output.h"
#include "render/render_settings.h"

namespace rt::render_tool {

struct RenderOptions {
    std::string scenePath;                // a file, or "-" for standard input
    std::optional<std::string> outputType;  // -o: null png exr tga text; else from -f's extension
    std::optional<std::string> outputPath;  // -f
    std::string exrPixels = "half";       // --exr-pixels half|float
    int pngBits = 8;                      // --png-bits 8|16
    ColorSettings color;
    RenderSettings render;
    AccelSettings accel;                  // kind Kd unless -B or --accel says otherwise
    std::optional<std::string> region;    // --region x0,y0,x1,y1 (x1, y1 exclusive)
    bool quiet = false;                   // -q (implies --progress none)
    std::string progress = "auto";        // --progress auto|bar|lines|none
    bool statsLine = false;               // -b
    bool preprocessOnly = false;          // -p
    std::optional<std::string> statsJson;  // --stats-json FILE ("-" is standard output)
    std::optional<double> maxMemoryGb;    // --max-memory GB; default: rt::defaultMemoryLimit()
};

// "x0,y0,x1,y1" with x1 and y1 exclusive; throws rt::InputError if it is not four integers.
PixelWindow parseRegion(const std::string& text);

// Loads the scene, builds the accelerator, renders and writes what the options ask for.
// Returns the exit code; throws rt::InputError for bad input (exit 2), others for failures (exit 1).
int runRender(RenderOptions options);

}  // namespace rt::render_tool
