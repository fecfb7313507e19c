// Colour management through OpenColorIO: the rendered linear values are scene-referred;
// files meant for a screen (PNG, TGA, text) pass through an OCIO display/view transform.
//
// Which config: --color-config FILE, else $OCIO (as every OCIO tool), else rt's own
// config/ocio/config.ocio, built into the library at build time (Debian's OCIO 2.1 has no
// built-in configs), so that a tool copied anywhere still finds it.
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace rt {

struct ColorSettings {
    std::string configPath;  // --color-config; empty: $OCIO, then the built-in config
    std::string colorspace;  // --colorspace: the space of the rendered values; empty: the scene_linear role
    std::string display;     // --display; empty: the config's default display
    std::string view;        // --view; empty: the display's default view
    std::string look;        // --look; empty: none (several may be given as "a,b")
    double exposure = 0;     // --exposure: stops (2^exposure times the linear values) before the looks and the view
};

// How errors and EXR headers name the built-in config.
inline constexpr const char* kBuiltinColorConfigName = "rt's built-in colour configuration (config/ocio/config.ocio)";

class ColorPipeline {
public:
    // Loads the config and builds the display transform. Throws rt::InputError for a missing
    // or invalid config or an unknown colour space, display, view or look.
    explicit ColorPipeline(const ColorSettings& settings);
    ~ColorPipeline();
    ColorPipeline(const ColorPipeline&) = delete;
    ColorPipeline& operator=(const ColorPipeline&) = delete;

    // Applies the display/view transform in place to packed RGB floats.
    void toDisplay(std::vector<float>& rgb) const;

    // The config in use: its file (with "(from $OCIO)" if $OCIO named it) or kBuiltinColorConfigName.
    const std::string& configName() const { return configName_; }
    const std::string& colorspace() const { return colorspace_; }  // resolved name of the linear space
    const std::string& display() const { return display_; }
    const std::string& view() const { return view_; }

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    std::string configName_, colorspace_, display_, view_;
};

}  // namespace rt
