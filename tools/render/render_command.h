// Everything rt-render's command line sets, gathered by main.cpp (the only file that
// sees CLI11) and carried out by runRender.
#pragma once

#include <optional>
#include <string>

#include "accel/settings.h"
#include "image/image_output.h"
#include "progress.h"
#include "render/render_settings.h"

namespace rt::tool::render {

struct RenderOptions {
    std::string scenePath;                // a file, or "-" for standard input
    std::optional<std::string> outputType;  // -o: null png exr tga text; else from -f's extension
    std::optional<std::string> outputPath;  // -f
    ExrPixelType exrPixels = ExrPixelType::Half;  // --exr-pixels half|float
    int pngBits = 8;                      // --png-bits 8|16
    ColorSettings color;
    RenderSettings render;
    AccelSettings accel;                  // kind Kd unless -B or --accel says otherwise
    std::optional<std::string> region;    // --region x0,y0,x1,y1 (x1, y1 exclusive)
    std::optional<std::string> tiles;     // --tiles CxR: the farm's grid of tiles
    std::optional<std::string> tile;      // --tile I/N: render tile I of the N = C x R
    bool skipExisting = false;            // --skip-existing: a complete output exits 0 at once
    bool quiet = false;                   // -q (implies --progress none)
    ProgressMode progress = ProgressMode::Auto;  // --progress auto|bar|lines|none
    bool statsLine = false;               // -b
    bool preprocessOnly = false;          // -p
    std::optional<std::string> statsJson;  // --stats-json FILE ("-" is standard output)
};

// "x0,y0,x1,y1" with x1 and y1 exclusive; throws rt::InputError if it is not four integers.
PixelWindow parseRegion(const std::string& text);

// The window of "--tiles CxR --tile I/N"; throws rt::InputError if either is malformed or N is not C x R.
PixelWindow parseTile(const std::string& tiles, const std::string& tile, int width, int height);

// Loads the scene, builds the accelerator, renders and writes what the options ask for.
// Returns the exit code; throws rt::InputError for bad input (exit 2), others for failures (exit 1).
int runRender(RenderOptions options);

}  // namespace rt::tool::render
