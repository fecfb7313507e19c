// rt-render's command line: every option CLI11 parses into RenderOptions, declared here so that
// the tool and the option-parsing fuzz target (fuzz/render_options_fuzz.cpp) parse the same way.
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "render_command.h"

namespace rt::tool::render {

// The outputs -o takes: the image formats and the window.
std::vector<std::string> outputNames();

// Declares the scene argument and every option of rt-render on `app`, each storing into `options`.
void addRenderOptions(CLI::App& app, RenderOptions& options);

// The integrator's structure (render/render_settings.h, defaultAccelKind) unless -B, -K or --accel
// named one; after parsing, since the integrator may come after them on the command line.
void chooseDefaultAccel(CLI::App& app, RenderOptions& options);

// The options given on `app`'s command line that `integrator` does not use (--max-bounces with
// the Whitted tracer, -d with the path tracer, ...): runRender notes each on stderr.
std::vector<std::string> optionsTheIntegratorIgnores(const CLI::App& app, Integrator integrator);
// The options of the texture cache rt no longer has, as given on the command line.
std::vector<std::string> retiredOptionsGiven(const CLI::App& app);

}  // namespace rt::tool::render
