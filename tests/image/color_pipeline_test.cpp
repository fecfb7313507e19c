#include "image/color_pipeline.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "core/error.h"

using namespace rt;

namespace {

// Sets $OCIO for one test and restores it.
class ScopedOcioEnv {
public:
    explicit ScopedOcioEnv(const std::string& value) {
        if (const char* old = std::getenv("OCIO")) old_ = old;
        setenv("OCIO", value.c_str(), 1);
    }
    ~ScopedOcioEnv() {
        if (old_.empty())
            unsetenv("OCIO");
        else
            setenv("OCIO", old_.c_str(), 1);
    }

private:
    std::string old_;
};

ColorSettings shipped() {
    ColorSettings s;
    s.configPath = RT_SOURCE_DIR "/config/ocio/config.ocio";
    return s;
}

float displayed(const ColorSettings& s, float linear) {
    std::vector<float> rgb{linear, linear, linear};
    ColorPipeline(s).toDisplay(rgb);
    return rgb[0];
}

}  // namespace

TEST(ColorPipeline, MiddleGreyGivesTheSrgbCodeValue) {
    const ColorPipeline pipeline(shipped());
    EXPECT_EQ(pipeline.colorspace(), "lin_rec709");
    EXPECT_EQ(pipeline.display(), "sRGB");
    EXPECT_EQ(pipeline.view(), "Standard");
    // The sRGB curve: 1.055 * 0.18^(1/2.4) - 0.055 = 0.46136, which 8-bit rounds to 118.
    EXPECT_NEAR(displayed(shipped(), 0.18f), 0.461356f, 1e-5);
    EXPECT_NEAR(displayed(shipped(), 0.0031308f), 0.04045f, 1e-5);  // the linear segment's end
    EXPECT_NEAR(displayed(shipped(), 1.0f), 1.0f, 1e-5);
}

TEST(ColorPipeline, AliasesViewsAndLooks) {
    ColorSettings s = shipped();
    s.colorspace = "Linear";  // what OpenImageIO calls EXR data
    EXPECT_EQ(ColorPipeline(s).colorspace(), "lin_rec709");
    s.view = "Raw";
    EXPECT_FLOAT_EQ(displayed(s, 0.18f), 0.18f);
    s.view = "Standard";
    s.look = "Brighter";  // one stop: 0.09 displays like 0.18
    EXPECT_NEAR(displayed(s, 0.09f), 0.461356f, 1e-5);
    s.look = "Contrast";
    EXPECT_GT(displayed(s, 0.5f), displayed(shipped(), 0.5f));
}

TEST(ColorPipeline, ExposureScalesTheLinearValuesBeforeTheLooksAndTheView) {
    ColorSettings s = shipped();
    s.exposure = 1;  // one stop: 0.09 displays like 0.18
    EXPECT_NEAR(displayed(s, 0.09f), 0.461356f, 1e-5);
    s.exposure = -2;  // two stops down: 0.72 displays like 0.18
    EXPECT_NEAR(displayed(s, 0.72f), 0.461356f, 1e-5);
    s.exposure = 1.5;
    EXPECT_NEAR(displayed(s, 0.18f / std::exp2(1.5f)), 0.461356f, 1e-5);
    s.exposure = 1;
    s.look = "Darker";  // and a look after it: the stops add up
    EXPECT_NEAR(displayed(s, 0.18f), 0.461356f, 1e-5);
    s.view = "Raw";
    s.look.clear();
    EXPECT_NEAR(displayed(s, 0.25f), 0.5f, 1e-6);
}

TEST(ColorPipeline, UnknownNamesAreInputErrors) {
    for (auto change : {+[](ColorSettings& s) { s.colorspace = "ACEScg"; }, +[](ColorSettings& s) { s.display = "P3"; },
                        +[](ColorSettings& s) { s.view = "Filmic"; }, +[](ColorSettings& s) { s.look = "Sepia"; },
                        +[](ColorSettings& s) { s.configPath = "/nonexistent/config.ocio"; }}) {
        ColorSettings s = shipped();
        change(s);
        EXPECT_THROW(ColorPipeline{s}, InputError);
    }
}

TEST(ColorPipeline, HonoursOcioEnvironmentVariable) {
    // A config whose only view is raw: with $OCIO pointing at it, nothing is encoded.
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "rt_color_pipeline_test";
    std::filesystem::create_directories(dir);
    const std::string path = (dir / "raw.ocio").string();
    std::ofstream(path) << "ocio_profile_version: 2\n"
                           "roles: {default: raw, scene_linear: raw, data: raw}\n"
                           "file_rules:\n  - !<Rule> {name: Default, colorspace: default}\n"
                           "displays:\n  Screen:\n    - !<View> {name: None, colorspace: raw}\n"
                           "colorspaces:\n  - !<ColorSpace> {name: raw, isdata: true}\n";
    {
        const ScopedOcioEnv env(path);
        const ColorPipeline pipeline{ColorSettings{}};
        EXPECT_EQ(pipeline.display(), "Screen");
        EXPECT_FLOAT_EQ(displayed(ColorSettings{}, 0.18f), 0.18f);
        EXPECT_NEAR(displayed(shipped(), 0.18f), 0.461356f, 1e-5);  // an explicit config wins over $OCIO
    }
    {
        const ScopedOcioEnv env((dir / "missing.ocio").string());
        EXPECT_THROW(ColorPipeline{ColorSettings{}}, InputError);
    }
    std::filesystem::remove_all(dir);
}

TEST(ColorPipeline, UsesTheBuiltInConfigWithoutOcio) {
    // The built-in config needs no file: the tools work wherever they are built or copied.
    const char* old = std::getenv("OCIO");
    const std::string saved = old ? old : "";
    unsetenv("OCIO");
    const ColorPipeline pipeline{ColorSettings{}};
    EXPECT_EQ(pipeline.configName(), kBuiltinColorConfigName);
    EXPECT_EQ(pipeline.colorspace(), "lin_rec709");
    EXPECT_EQ(pipeline.display(), "sRGB");
    for (const float linear : {0.0f, 0.0031308f, 0.18f, 0.5f, 1.0f, 4.0f})  // the same as the shipped file
        EXPECT_FLOAT_EQ(displayed(ColorSettings{}, linear), displayed(shipped(), linear)) << linear;
    ColorSettings s;
    s.view = "Filmic";
    try {
        ColorPipeline{s};
        ADD_FAILURE() << "an unknown view was accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()).find("$OCIO"), std::string::npos) << e.what();  // $OCIO is not in use
        EXPECT_NE(std::string(e.what()).find("built-in"), std::string::npos) << e.what();
    }
    if (old) setenv("OCIO", saved.c_str(), 1);
}

TEST(ColorPipeline, NamesTheConfigInUse) {
    EXPECT_EQ(ColorPipeline(shipped()).configName(), shipped().configPath);
    const ScopedOcioEnv env(shipped().configPath);
    EXPECT_NE(ColorPipeline{ColorSettings{}}.configName().find(shipped().configPath), std::string::npos);
}
