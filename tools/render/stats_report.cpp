#include "stats_report.h"

#include <charconv>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "core/json_writer.h"
#include "os/peak_memory.h"
#include "render/film/noise_threshold.h"
#include "version.h"

namespace rt::tool::render {

namespace {

std::string format(const char* fmt, auto... args) {
    char buffer[512];
    std::snprintf(buffer, sizeof buffer, fmt, args...);
    return buffer;
}

// Writes `text` as a Whole if it is all one, and says whether it was.
template <class Whole>
bool writeWhole(JsonWriter& json, const std::string& text) {
    Whole whole = 0;
    const char* end = text.data() + text.size();
    const auto [stop, error] = std::from_chars(text.data(), end, whole);
    if (error != std::errc() || stop != end) return false;
    json.value(whole);
    return true;
}

// An option's number as CLI11 read it: a whole number as an integer ("--seed 7": 7), else a double.
void writeNumber(JsonWriter& json, const std::string& text) {
    if (!writeWhole<std::int64_t>(json, text) && !writeWhole<std::uint64_t>(json, text))
        json.value(std::strtod(text.c_str(), nullptr));
}

// One option's value in its type: a number, a boolean or a string; a list is an array of strings.
void writeOptionValue(JsonWriter& json, const OptionValue& option) {
    if (option.type == OptionValue::Type::List) {
        json.beginArray();
        for (const std::string& v : option.values) json.value(v);
        json.endArray();
    } else if (option.values.empty()) {
        json.null();
    } else if (option.type == OptionValue::Type::Boolean) {
        json.value(option.values[0] == "true");
    } else if (const std::string& text = option.values[0]; option.type == OptionValue::Type::Number) {
        writeNumber(json, text);
    } else {
        json.value(text);
    }
}

// "options": {"width": 800, "shadows": false, "file": ["a.png", "a.exr"], "region": null}.
void writeOptionsJson(JsonWriter& json, const RunRecord& run) {
    json.beginObject();
    for (const OptionValue& option : run.options) {
        json.key(option.name);
        writeOptionValue(json, option);
    }
    json.endObject();
}

void writeRunJson(JsonWriter& json, const RunRecord& run) {
    json.member("rtVersion", kVersion);
    json.key("commandLine");
    json.beginArray();
    for (const std::string& argument : run.arguments) json.value(argument);
    json.endArray();
    json.key("options");
    writeOptionsJson(json, run);
    json.key("frame");  // the turntable's frame, or null
    if (run.frame)
        json.value(*run.frame);
    else
        json.null();
}

// The camera rays of a render that traces every pixel of the window -S times.
std::uint64_t fullRenderCameraRays(const RenderSettings& settings) {
    const PixelWindow w = settings.window();
    return std::uint64_t(w.width()) * std::uint64_t(w.height()) * std::uint64_t(settings.pixelSamples);
}

// What --adaptive saved: camera rays against a render that traces every pixel.
std::string adaptiveSummary(const RenderSettings& settings, const RenderCounters& c) {
    const double full = double(fullRenderCameraRays(settings));
    return format("adaptive %d: %llu pixels interpolated, %.1f %% of a full render's %.0f camera rays saved\n",
                  settings.adaptiveGrid, static_cast<unsigned long long>(c.interpolatedPixels),
                  100.0 * (full - double(c.camera.rays)) / full, full);
}

// What --noise-threshold saved: camera samples against every pixel's -S.
std::string noiseThresholdSummary(const RenderSettings& settings, const RenderStats& s) {
    const double full = double(fullRenderCameraRays(settings));
    return format("noise threshold %g (at least %d samples): %llu of %.0f samples taken, %.1f %% saved\n",
                  settings.noiseThreshold, NoiseThreshold(settings).minSamples(),
                  static_cast<unsigned long long>(s.samplesTaken), full,
                  100.0 * (full - double(s.samplesTaken)) / full);
}

void writeEstimateJson(JsonWriter& json, const std::optional<RenderEstimate>& e) {
    if (!e) {
        json.null();
        return;
    }
    json.beginObject();
    json.member("probePixels", e->probePixels);
    json.member("probeSeconds", e->probeSeconds);
    json.member("cameraSamples", e->cameraSamples);
    json.member("rays", e->rays);
    json.member("intersectionTests", e->intersectionTests);
    json.member("seconds", e->seconds);
    json.member("threads", e->threads);
    json.endObject();
}

}  // namespace

std::string nonFiniteWarning(const RenderStats& s) {
    const NonFiniteSamples& n = s.counters.nonFinite;
    if (!n.count) return {};
    return format(
        "rt-render: warning: %llu non-finite (NaN or infinite) samples, first at pixel (%d, %d); "
        "written as black (0, 0, 0)\n",
        static_cast<unsigned long long>(n.count), n.firstX, n.firstY);
}

std::string halfClipWarning(const std::string& path, std::uint64_t clipped) {
    if (!clipped) return {};
    return format(
        "rt-render: warning: %s: %llu values above half float's 65504 written as 65504 (--exr-pixels float "
        "keeps them)\n",
        path.c_str(), static_cast<unsigned long long>(clipped));
}

std::string timeLimitMessage(const RenderSettings& settings) {
    const std::string limit = format("--time-limit %g s", settings.timeLimitSeconds);
    if (settings.integrator == Integrator::Path)
        return limit + " ran out before the first pass (one sample of every pixel) was finished: nothing written";
    return limit +
           " ran out before the picture was finished: nothing written (the whitted integrator renders in one "
           "pass; --integrator path keeps the passes it finished)";
}

std::string timeLimitNote(const RenderSettings& settings, const RenderStats& stats) {
    if (!stats.timeLimitReached) return {};
    return format("rt-render: --time-limit %g s reached: %d of %d samples per pixel taken and written\n",
                  settings.timeLimitSeconds, stats.samplesPerPixel, settings.pixelSamples);
}

std::string endRequestNote(int signal, const RenderSettings& settings, const RenderStats& stats) {
    if (signal == 0 || stats.samplesPerPixel >= settings.pixelSamples) return {};
    const char* name = signal == SIGUSR1 ? "SIGUSR1" : signal == SIGINT ? "SIGINT" : "SIGTERM";
    return format("rt-render: %s: ended after %d of %d samples per pixel, written\n", name, stats.samplesPerPixel,
                  settings.pixelSamples);
}

std::string estimateSummary(const RenderSettings& settings, const RenderEstimate& e) {
    const PixelWindow w = settings.window();
    return format(
        "rt-render: estimate: %dx%d pixels x %d sample%s: %.3g rays, %.3g intersection tests, about %.3g s on %d "
        "thread%s (probe: %llu pixels traced in %.3g s)\n",
        w.width(), w.height(), settings.pixelSamples, settings.pixelSamples == 1 ? "" : "s", e.rays,
        e.intersectionTests, e.seconds, e.threads, e.threads == 1 ? "" : "s",
        static_cast<unsigned long long>(e.probePixels), e.probeSeconds);
}

std::string thesisStatsLine(const RenderStats& s) {
    return format("%.2f %.2f %llu %llu %llu %.2f", s.preprocessSeconds, s.renderSeconds,
                  static_cast<unsigned long long>(s.objects), static_cast<unsigned long long>(s.lights),
                  static_cast<unsigned long long>(s.treeNodes), s.testsPerRay());
}

void writeStatsJson(std::ostream& out, const RunRecord& run, const SceneSummary& scene, const RenderSettings& settings,
                    const TreeReport& tree, const RenderStats& s, const std::optional<RenderEstimate>& estimate) {
    const NonFiniteSamples& nonFinite = s.counters.nonFinite;
    JsonWriter json(out);
    json.beginDocument();
    writeRunJson(json, run);
    json.key("scene");
    writeSceneJson(json, scene);
    json.key("picture");
    writePictureJson(json, settings);
    json.key("tree");
    writeTreeReportJson(json, tree);
    json.key("rays");
    writeRaysJson(json, s.counters);
    json.member("renderSeconds", s.renderSeconds);
    json.member("threads", s.threads);
    json.member("raysPerSecond", s.raysPerSecond());
    json.member("peakMemoryBytes", peakMemoryBytes());
    json.member("nonFiniteSamples", nonFinite.count);
    json.member("interpolatedPixels", s.counters.interpolatedPixels);  // --adaptive
    json.member("fullRenderCameraRays", fullRenderCameraRays(settings));
    json.member("samplesPerPixel", s.samplesPerPixel);    // taken: fewer than -S if --time-limit ran out
    json.member("samplesTaken", s.samplesTaken);          // over all pixels: fewer with --noise-threshold
    json.member("timeLimitReached", s.timeLimitReached);  // --time-limit
    json.key("estimate");                                 // -p's prediction, else null
    writeEstimateJson(json, estimate);
    json.key("firstNonFinitePixel");  // [x, y], or null when every sample was finite
    if (nonFinite.count) {
        json.beginArray();
        json.value(nonFinite.firstX);
        json.value(nonFinite.firstY);
        json.endArray();
    } else {
        json.null();
    }
    json.endObject();
}

std::string statsSummary(const RenderSettings& settings, const AccelStats& accel, const RenderStats& s, bool rendered) {
    std::string text = format("%llu objects, %llu lights; %s with %llu nodes built in %.3f s\n",
                              static_cast<unsigned long long>(s.objects), static_cast<unsigned long long>(s.lights),
                              accel.name.c_str(), static_cast<unsigned long long>(s.treeNodes), s.preprocessSeconds);
    if (!rendered) return text;
    const RenderCounters& c = s.counters;
    const PixelWindow w = settings.window();
    text += format("rendered %dx%d pixels in %.3f s on %d thread%s: %llu camera, %llu shadow, %llu reflection rays\n",
                   w.width(), w.height(), s.renderSeconds, s.threads, s.threads == 1 ? "" : "s",
                   static_cast<unsigned long long>(c.camera.rays), static_cast<unsigned long long>(c.shadow.rays),
                   static_cast<unsigned long long>(c.reflection.rays));
    text += format("%.2f M rays/s, %.2f intersection tests per ray\n", s.raysPerSecond() / 1e6, s.testsPerRay());
    if (settings.adaptiveGrid) text += adaptiveSummary(settings, s.counters);
    if (settings.noiseThreshold > 0) text += noiseThresholdSummary(settings, s);
    return text;
}

}  // namespace rt::tool::render
