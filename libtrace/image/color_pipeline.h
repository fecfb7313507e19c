// Colour management through OpenColorIO: the rendered linear values are scene-referred;
// files meant for a screen (PNG, TGA, text) pass through an OCIO display/view transform.
//
// Which config: --color-config FILE, else $OCIO (as every OCIO tool), else the config rt
// ships (config/ocio/config.ocio in the source tree, share/rt/ocio/config.ocio when
// installed), found next to the running executable. Debian's OCIO 2.1 has no built-in configs.
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace rt {

struct ColorSettings {
    std::string configPath;  // --color-config; empty: $OCIO, then the shipped config
    std::string colorspace;  // --colorspace: the space of the rendered values; empty: the scene_linear role
    std::string display;     // --display; empty: the config's default display
    std::string view;        // --view; empty: the display's default view
    std::string look;        // --look; empty: none (several may be given as "a,b")
};

// The shipped config found from the executable's location, or "" if it is not there.
std::string shippedColorConfigPath();

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

    const std::string& configPath() const { return configPath_; }  // "" means $OCIO
    const std::string& colorspace() const { return colorspace_; }   // resolved name of the linear space
    const std::string& display() const { return display_; }
    const std::string& view() const { return view_; }

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    std::string configPath_, colorspace_, display_, view_;
};

}  // namespace rt
