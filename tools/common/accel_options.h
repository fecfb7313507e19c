// The tree parameters on the command line, shared by rt-render and rt-inspect so that
// a user can tune a tree with rt-inspect and render with the same flags. Defaults and
// meanings are those of rt::AccelSettings (libtrace/accel/settings.h).
#pragma once

#include <CLI/CLI.hpp>

#include "accel/settings.h"

namespace rt::tool {

// Adds --watertight and the --bsp-* and --kd-* options; they write into `settings` when the command
// line is parsed.
void addAccelOptions(CLI::App& app, AccelSettings& settings);
// --watertight alone (AccelSettings::triangles), for a program with its own tree options (bench/vs_embree).
void addTriangleTestOption(CLI::App& app, AccelSettings& settings);
// The --kd-* options alone, for a program that builds only KD trees (bench/vs_embree).
void addKdOptions(CLI::App& app, KdSettings& kd);

}  // namespace rt::tool
