// The options that decide which rays a picture needs (thesis appendix B: -x -y -d -s, and
// -S -D -r of distributed ray tracing), shared by rt-render and rt-inspect --rays so that
// the statistics rt-inspect reports are those of the picture rt-render would render.
#pragma once

#include <CLI/CLI.hpp>

#include "render/render_settings.h"

namespace rt::tool {

// Adds -x -y -d -s to the group "Rendering options" and -S -D -r to "Image quality options";
// they write into `settings` when the command line is parsed (-D s|d|b sets softShadows and
// glossyReflections; soft shadows are shadows, so -D s and b also set shadows).
void addPictureOptions(CLI::App& app, RenderSettings& settings);

}  // namespace rt::tool
