#include "render_command.h"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <iostream>

#include "accel/build.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "import/load_scene.h"
#include "progress_bar.h"
#include "render/renderer.h"
#include "import/load_scene.h"
#include "stats_report.h"
#include "version.h"

namespace rt::render_tool {

PixelWindow parseRegion(const std::string& text) {
    PixelWindow w;
    int used = -1;
    if (std::sscanf(text.c_str(), "%d,%d,%d,%d%n", &w.x0, &w.y0, &w.x1, &w.y1, &used) != 4 ||
        used != int(text.size()))
        throw InputError("--region: expected x0,y0,x1,y1 (pixels, x1 and y1 exclusive), got '" + text + "'");
    return w;
}

namespace {

// -o wins; otherwise -f's extension decides; with neither, nothing is written (thesis: null).
ImageOutputSettings outputSettings(const RenderOptions& o) {
    ImageOutputSettings s;
    s.color = o.color;
    s.exrHalf = o.exrPixels == "half";
    s.pngBits = o.pngBits;
    s.path = o.outputPath.value_or("");
    if (o.preprocessOnly) return s;  // -p implies null output
    if (o.outputType) {
        s.format = *parseImageFormat(*o.outputType);  // CLI11 has checked the name
    } else if (o.outputPath) {
        const std::optional<ImageFormat> f = imageFormatFromPath(*o.outputPath);
        if (!f) throw InputError("-f " + *o.outputPath + ": cannot tell the type from the extension; give -o");
        s.format = *f;
    }
    if (s.format == ImageFormat::Text && !o.outputPath) s.path = std::string(1, '-');  // text goes to the terminal
    if (s.format != ImageFormat::Null && s.path.empty())
        throw InputError(std::string(imageFormatName(s.format)) + " output needs -f FILE");
    return s;
}

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int runRender(RenderOptions o) {
    if (o.region) o.render.region = parseRegion(*o.region);
    validate(o.render);
    const ImageOutputSettings output = outputSettings(o);
    if (output.format != ImageFormat::Null) ColorPipeline check(output.color);  // bad colour names fail before rendering

    Scene scene = loadScene(o.scenePath);
    scene.dropDescription();
    RenderStats stats;
    const auto buildStart = std::chrono::steady_clock::now();
    const std::unique_ptr<Accelerator> accel = buildAccelerator(scene.primitives, o.accel);
    stats.preprocessSeconds = secondsSince(buildStart);
    const AccelStats accelStats = accel->stats();
    stats.treeNodes = accelStats.nodes;
    stats.objects = scene.primitives.size();
    stats.lights = scene.lights.size();

    if (!o.preprocessOnly) {
        ProgressBar bar(!o.quiet && isatty(STDERR_FILENO));
        const Framebuffer image =
            render(scene, *accel, o.render, stats, [&bar](int done, int total) { bar.update(done, total); });
        const ImageMetadata meta{std::string("rt-render ") + kVersion, o.scenePath, o.render.pixelSamples,
                                 stats.renderSeconds};
        writeImage(image, output, meta);
        std::cerr << nonFiniteWarning(stats);  // even with -q: a replaced sample is never silent
    }

    if (!o.quiet) {
        for (const std::string& w : scene.warnings) std::cerr << "rt-render: warning: " << w << '\n';
        std::cerr << statsSummary(o.render, accelStats, stats, !o.preprocessOnly);
        if (output.format != ImageFormat::Null && output.path != "-") std::cerr << "wrote " << output.path << '\n';
    }
    if (o.statsLine) std::cout << thesisStatsLine(stats) << std::endl;
    if (o.statsJson) {
        const std::string json = statsJson(o.scenePath, o.render, accelStats, stats);
        writeFileAtomically(*o.statsJson, [&](std::ostream& os) { os << json; });
    }
    return 0;
}

}  // namespace rt::render_tool
