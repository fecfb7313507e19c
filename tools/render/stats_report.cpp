#include "stats_report.h"

#include <cstdio>
#include <sstream>

namespace rt::render_tool {

namespace {

std::string format(const char* fmt, auto... args) {
    char buffer[512];
    std::snprintf(buffer, sizeof buffer, fmt, args...);
    return buffer;
}

std::string jsonString(const std::string& s) {
    std::string out = "\"";
    for (const char c : s) {
        if (c == '"' || c == '\\')
            out += {'\\', c};
        else if (static_cast<unsigned char>(c) < 0x20)
            out += format("\\u%04x", unsigned(c));
        else
            out += c;
    }
    return out + '"';
}

std::string firstNonFinitePixel(const NonFiniteSamples& n) {
    return n.count ? format("[%d, %d]", n.firstX, n.firstY) : "null";
}

}  // namespace

std::string nonFiniteWarning(const RenderStats& s) {
    const NonFiniteSamples& n = s.counters.nonFinite;
    if (!n.count) return {};
    return format("rt-render: warning: %llu non-finite (NaN or infinite) samples, first at pixel (%d, %d); "
                  "written as black (0, 0, 0)\n",
                  static_cast<unsigned long long>(n.count), n.firstX, n.firstY);
}

std::string thesisStatsLine(const RenderStats& s) {
    return format("%.2f %.2f %llu %llu %llu %.2f", s.preprocessSeconds, s.renderSeconds,
                  static_cast<unsigned long long>(s.objects), static_cast<unsigned long long>(s.lights),
                  static_cast<unsigned long long>(s.treeNodes), s.testsPerRay());
}

std::string statsJson(const std::string& scene, const RenderSettings& settings, const AccelStats& accel,
                      const RenderStats& s) {
    const RenderCounters& c = s.counters;
    const PixelWindow w = settings.window();
    std::ostringstream o;
    o << "{\n"
      << "  \"scene\": " << jsonString(scene) << ",\n"
      << "  \"width\": " << settings.width << ",\n  \"height\": " << settings.height << ",\n"
      << "  \"region\": [" << w.x0 << ", " << w.y0 << ", " << w.x1 << ", " << w.y1 << "],\n"
      << "  \"samplesPerPixel\": " << settings.pixelSamples << ",\n"
      << "  \"seed\": " << settings.seed << ",\n"
      << "  \"maxDepth\": " << settings.maxDepth << ",\n"
      << "  \"shadows\": " << (settings.shadows ? "true" : "false") << ",\n"
      << "  \"accelerator\": " << jsonString(accel.name) << ",\n"
      << "  \"treeNodes\": " << s.treeNodes << ",\n  \"treeLeaves\": " << accel.leaves << ",\n"
      << "  \"treeMaxDepth\": " << accel.maxDepth << ",\n"
      << "  \"preprocessSeconds\": " << s.preprocessSeconds << ",\n"
      << "  \"renderSeconds\": " << s.renderSeconds << ",\n"
      << "  \"threads\": " << s.threads << ",\n"
      << "  \"objects\": " << s.objects << ",\n  \"lights\": " << s.lights << ",\n"
      << "  \"primaryRays\": " << c.camera.rays << ",\n  \"shadowRays\": " << c.shadow.rays << ",\n"
      << "  \"reflectionRays\": " << c.reflection.rays << ",\n  \"rays\": " << c.rays() << ",\n"
      << "  \"intersectionTests\": " << c.total().intersectionTests << ",\n"
      << "  \"traversalSteps\": " << c.total().traversalSteps << ",\n"
      << "  \"testsPerRay\": " << s.testsPerRay() << ",\n"
      << "  \"nonFiniteSamples\": " << c.nonFinite.count << ",\n"
      << "  \"firstNonFinitePixel\": " << firstNonFinitePixel(c.nonFinite) << ",\n"
      << "  \"raysPerSecond\": " << s.raysPerSecond() << "\n}\n";
    return o.str();
}

std::string statsSummary(const RenderSettings& settings, const AccelStats& accel, const RenderStats& s,
                         bool rendered) {
    std::string text = format("%llu objects, %llu lights; %s with %llu nodes built in %.3f s\n",
                              static_cast<unsigned long long>(s.objects), static_cast<unsigned long long>(s.lights),
                              accel.name.c_str(), static_cast<unsigned long long>(s.treeNodes), s.preprocessSeconds);
    if (!rendered) return text;
    const RenderCounters& c = s.counters;
    const PixelWindow w = settings.window();
    text += format("rendered %dx%d pixels in %.3f s on %d thread%s: %llu primary, %llu shadow, %llu reflection rays\n",
                   w.width(), w.height(), s.renderSeconds, s.threads, s.threads == 1 ? "" : "s",
                   static_cast<unsigned long long>(c.camera.rays),
                   static_cast<unsigned long long>(c.shadow.rays), static_cast<unsigned long long>(c.reflection.rays));
    text += format("%.2f M rays/s, %.2f intersection tests per ray\n", s.raysPerSecond() / 1e6, s.testsPerRay());
    return text;
}

}  // namespace rt::render_tool
