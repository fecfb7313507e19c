// Everything rt-render's command line sets, gathered by main.cpp (the only file that
// sees CLI11) and carried out by runRender.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "accel/settings.h"
#include "command_line.h"
#include "core/vec3.h"
#include "image/image_output.h"
#include "image/mip_map.h"
#include "io/import.h"
#include "progress.h"
#include "render/render_settings.h"

namespace rt::tool::render {

// --on-interrupt: what the first SIGINT or SIGTERM does to a render (docs/rt-render.md, "Interrupted
// renders"): discard it, writing nothing (as always), or end it after the pass under way and write that.
enum class OnInterrupt { Discard, Write };
inline constexpr NamedValues<OnInterrupt, 2> kOnInterruptNames{
    {{"discard", OnInterrupt::Discard}, {"write", OnInterrupt::Write}}};

inline constexpr NamedValues<TextureFilter, 4> kTextureFilterNames{{{"nearest", TextureFilter::Nearest},
                                                                    {"bilinear", TextureFilter::Bilinear},
                                                                    {"trilinear", TextureFilter::Trilinear},
                                                                    {"anisotropic", TextureFilter::Anisotropic}}};

struct RenderOptions {
    std::string scenePath;                        // a file, or "-" for standard input
    std::optional<std::string> outputType;        // -o: null png exr tga text; else from -f's extension
    std::vector<std::string> outputPaths;         // -f, any number: one render, each file written from it
    ExrPixelType exrPixels = ExrPixelType::Half;  // --exr-pixels half|float
    int pngBits = 8;                              // --png-bits 8|16
    int tiffBits = 8;                             // --tiff-bits 8|16|32
    int jpegQuality = 90;                         // --jpeg-quality 1-100
    std::string exrCompression = "zip";           // --exr-compression
    ColorSettings color;
    RenderSettings render;
    AccelSettings accel;                         // kind Kd unless -B or --accel says otherwise
    std::optional<std::string> region;           // --region x0,y0,x1,y1 (x1, y1 exclusive)
    std::optional<std::string> tiles;            // --tiles CxR: the farm's grid of tiles
    std::optional<std::string> tile;             // --tile I/N: render tile I of the N = C x R
    bool skipExisting = false;                   // --skip-existing: a complete output exits 0 at once
    bool quiet = false;                          // -q (implies --progress none)
    ProgressMode progress = ProgressMode::Auto;  // --progress auto|bar|lines|none
    bool statsLine = false;                      // -b
    bool preprocessOnly = false;                 // -p
    std::optional<std::string> statsJson;        // --stats-json FILE ("-" is standard output)
    std::optional<bool> alpha;                   // --alpha on|off; default on where the format has alpha
    std::optional<std::string> aovs;             // --aov LIST: AOV layers in the EXR (render/film/aov.h)
    // The camera: --camera NAME|INDEX, then --look-from, --look-at, --up (X,Y,Z), --fov, --frame.
    std::optional<std::string> camera;
    std::optional<std::string> lookFrom, lookAt, up;
    std::optional<double> fov;
    bool frame = false;
    int orbit = 0;                        // --orbit N: N frames around the look-at point; 0 is one picture
    std::optional<std::string> frames;    // --frames A..B: only frames A to B (inclusive) of the orbit
    ImportOptions import;                 // --flat, for a model file read directly; --double-sided
    std::vector<std::string> parameters;  // --set NAME=VALUE, any number: $NAME in the XML scene
    // For --stats-json: the command line as given, and every option's value (given or default).
    std::vector<std::string> arguments;
    OptionValues optionValues;
    std::optional<double> maxMemoryGb;        // --max-memory GB; default: rt::defaultMemoryLimit()
    std::optional<std::string> environment;   // --environment FILE: the sky image (light and background)
    std::vector<std::string> lights;          // --light TYPE:NUMBERS, any number (light_option.h)
    bool noDefaultLight = false;              // --no-default-light: the scene's headlight is removed
    std::vector<std::string> ignoredOptions;  // given, but not read by the integrator: noted on stderr
    TextureFilter textureFilter = TextureFilter::Anisotropic;  // --texture-filter
    // Options of the texture cache rt no longer has (--texture-cache, --tx-cache, --tx-cache-size),
    // given: accepted, so that scripts keep working, and noted on stderr as ignored.
    std::vector<std::string> retiredOptions;
    // --on-interrupt discard|write
    OnInterrupt onInterrupt = OnInterrupt::Discard;
};

// "X,Y,Z" for the option `option`; throws rt::InputError if it is not three finite numbers.
Vec3 parseVector(const std::string& option, const std::string& text);

// The frames --orbit N with --frames A..B renders: first..last, inclusive.
struct FrameRange {
    int first = 0, last = 0;
};
FrameRange parseFrames(const std::optional<std::string>& frames, int orbit);

// The output path of one frame: the last run of '#' in `path` replaced by the frame number,
// padded with zeros to its length (Blender's convention: out_####.png, frame 7: out_0007.png).
std::string framePath(const std::string& path, int frame);

// "x0,y0,x1,y1" with x1 and y1 exclusive; throws rt::InputError if it is not four integers.
PixelWindow parseRegion(const std::string& text);

// The window of "--tiles CxR --tile I/N"; throws rt::InputError if either is malformed or N is not C x R.
PixelWindow parseTile(const std::string& tiles, const std::string& tile, int width, int height);

// Loads the scene, builds the accelerator, renders and writes what the options ask for.
// Returns the exit code (3: --time-limit left no whole picture, nothing written); throws
// rt::InputError for bad input (exit 2), others for failures (exit 1).
int runRender(RenderOptions options);

// After a render that a SIGINT or SIGTERM ended and that was written (--on-interrupt write), ends
// the process by that signal, as an interrupted process ends (exit status 130 or 143), so that a
// shell loop stops as after any Ctrl-C. Returns when no interrupt asked for the end.
void endAsInterrupted();

}  // namespace rt::tool::render
