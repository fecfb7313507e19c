#include "image/color_pipeline.h"

#include <OpenColorIO/OpenColorIO.h>

#include <cstdlib>
#include <sstream>

#include "builtin_color_config.h"
#include "core/error.h"

namespace OCIO = OCIO_NAMESPACE;

namespace rt {

namespace {

// Which config a pipeline uses: --color-config, else $OCIO, else the built-in one.
struct ConfigSource {
    std::string file;  // "" for the built-in config
    std::string name;  // as errors and the EXR header name it
};

ConfigSource configSource(const std::string& configPath) {
    if (!configPath.empty()) return {configPath, configPath};
    const char* env = std::getenv("OCIO");
    if (env && *env) return {env, std::string(env) + " (from $OCIO)"};
    return {"", kBuiltinColorConfigName};
}

OCIO::ConstConfigRcPtr loadConfig(const ConfigSource& source) {
    if (!source.file.empty()) return OCIO::Config::CreateFromFile(source.file.c_str());
    std::istringstream text(kBuiltinColorConfig);
    return OCIO::Config::CreateFromStream(text);
}

bool hasView(const OCIO::Config& config, const std::string& display, const std::string& view) {
    for (int i = 0; i < config.getNumViews(display.c_str()); ++i)
        if (view == config.getView(display.c_str(), i)) return true;
    return false;
}

bool hasDisplay(const OCIO::Config& config, const std::string& display) {
    for (int i = 0; i < config.getNumDisplays(); ++i)
        if (display == config.getDisplay(i)) return true;
    return false;
}

// Looks may be given as "a,b" or "+a,-b" (OCIO's look syntax); each must exist.
void checkLooks(const OCIO::Config& config, const std::string& looks) {
    std::stringstream list(looks);
    std::string name;
    while (std::getline(list, name, ',')) {
        if (!name.empty() && (name[0] == '+' || name[0] == '-')) name.erase(0, 1);
        if (!config.getLook(name.c_str())) throw InputError("the colour configuration has no look '" + name + "'");
    }
}

}  // namespace

struct ColorPipeline::Impl {
    OCIO::ConstCPUProcessorRcPtr cpu;
};

ColorPipeline::ColorPipeline(const ColorSettings& s) : impl_(std::make_unique<Impl>()) {
    const ConfigSource source = configSource(s.configPath);
    configName_ = source.name;
    const std::string where = source.file.empty() ? configName_ : "colour configuration " + configName_;
    try {
        const OCIO::ConstConfigRcPtr config = loadConfig(source);
        const std::string wanted = s.colorspace.empty() ? std::string(OCIO::ROLE_SCENE_LINEAR) : s.colorspace;
        const OCIO::ConstColorSpaceRcPtr space = config->getColorSpace(wanted.c_str());
        if (!space) throw InputError(where + " has no colour space '" + wanted + "'");
        colorspace_ = space->getName();

        display_ = s.display.empty() ? config->getDefaultDisplay() : s.display;
        if (!hasDisplay(*config, display_)) throw InputError(where + " has no display '" + display_ + "'");
        view_ = s.view.empty() ? config->getDefaultView(display_.c_str()) : s.view;
        if (!hasView(*config, display_, view_))
            throw InputError(where + " has no view '" + view_ + "' for display '" + display_ + "'");

        OCIO::DisplayViewTransformRcPtr displayView = OCIO::DisplayViewTransform::Create();
        displayView->setSrc(colorspace_.c_str());
        displayView->setDisplay(display_.c_str());
        displayView->setView(view_.c_str());
        OCIO::GroupTransformRcPtr group = OCIO::GroupTransform::Create();
        // Exposure in the scene-linear space, as Blender's Color Management and ociodisplay's
        // exposure slider apply it: the display-referred outputs only, the linear files keep the render.
        if (s.exposure != 0) {
            OCIO::ExposureContrastTransformRcPtr exposure = OCIO::ExposureContrastTransform::Create();
            exposure->setStyle(OCIO::EXPOSURE_CONTRAST_LINEAR);
            exposure->setExposure(s.exposure);
            group->appendTransform(exposure);
        }
        if (!s.look.empty()) {
            checkLooks(*config, s.look);
            OCIO::LookTransformRcPtr look = OCIO::LookTransform::Create();
            look->setSrc(colorspace_.c_str());
            look->setDst(colorspace_.c_str());
            look->setLooks(s.look.c_str());
            group->appendTransform(look);
        }
        group->appendTransform(displayView);
        impl_->cpu = config->getProcessor(group)->getDefaultCPUProcessor();
    } catch (const OCIO::Exception& e) {
        throw InputError(where + ": " + e.what());
    }
}

ColorPipeline::~ColorPipeline() = default;

void ColorPipeline::toDisplay(std::vector<float>& rgb) const {
    if (rgb.empty()) return;
    OCIO::PackedImageDesc desc(rgb.data(), long(rgb.size() / 3), 1, 3);
    impl_->cpu->apply(desc);
}

}  // namespace rt
