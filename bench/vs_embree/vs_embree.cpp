// rt's KD tree against Intel Embree 3 on the same scenes and the same rays (issue 14).
//
//   build/release/bench/vs_embree            all scenes, about a minute on 2 cores
//   build/release/bench/vs_embree --quick    two small scenes, one pass: a smoke test
//   build/release/bench/vs_embree --kd-intersection-cost 1.5    another KD tree (rt-render's --kd-* options)
//   build/release/bench/vs_embree --accel bvh    rt's wide BVH instead of its KD tree (or bsp, naive)
//   build/release/bench/vs_embree --scene model.glb --look-from 0,2,5 --look-at 0,1,0 --fov 60
//                                         any scene rt-render reads, from its camera or another
//
// Scenes: the five thesis scenes (rt::thesisScene), 10k/100k/1M uniform random triangles
// and the "teapot in a stadium" (bench_scenes.h); with --scene, files read as rt-render reads
// them (import/load_scene.h: thesis XML, glTF, OBJ, 3DS, ...), with the file's camera and lights
// (a headlight at the camera where the file has none) and rt-render's camera options. Rays, all made once with rt's KD
// tree: the 480,000 camera rays of an 800x600 view, one per pixel through its centre; a shadow ray from each visible
// point to each light it faces, and a mirror reflection ray from each visible point, both made as rt-render's Tracer
// makes them (offset off the surface by Tracer::epsilon). Every surface is treated as a mirror, so that every scene has
// a set of incoherent reflection rays.
//
// Both sides trace single rays on this one thread (rt: Accelerator::intersect/occluded;
// Embree: rtcIntersect1/rtcOccluded1), and both also trace the camera rays as packets of 8
// neighbouring pixels (4x2; rt: Accelerator::intersectPacket, Embree: rtcIntersect8) and the
// shadow rays as rt-render groups them: for each run of 8 pixels of a row and each light, the
// rays of the run's visible points that face it (rt: Accelerator::occludedPacket, Embree:
// rtcOccluded8, both with each ray's own tMax). rt's single rays also count the primitive tests
// per ray (RayCounters), the figure thesis Table 4.3 reports. Rays per second are per thread
// CPU second, the best of several passes taken in turn, so that other processes on a busy machine disturb the ratio
// little. Builds run on 2 threads (rt: OpenMP; Embree: RTC_BUILD_QUALITY_HIGH with threads=2) and are timed on the wall
// clock and in process CPU time. --builds measures the builds only.
//
// Agreement: a ray agrees when both miss, or both hit the same primitive at distances
// within kRelativeTolerance of the hit point's distance from the world origin (Embree sees
// the rays and triangles rounded to float, whose error grows with the coordinates), or,
// for shadow rays, both say occluded or both say not. Disagreeing rays are counted per set and the first
// few are listed on stderr; more than kMaxDisagreement of a set fails the run (exit 1).
// rt's packets must give exactly the single rays' answers (the same primitive and t, bit for
// bit); any ray that does not is listed and fails the run. The tables go to stdout as Markdown.
#include <omp.h>
#include <time.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <iostream>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "accel/build.h"
#include "accel_options.h"
#include "bench_scenes.h"
#include "command_line.h"
#include "core/simd.h"
#include "core/stopwatch.h"
#include "embree_scene.h"
#include "io/load_scene.h"
#include "render/camera_rays.h"
#include "render/integrators/tracer.h"
#include "render/materials/phong.h"
#include "render_command.h"
#include "scene/thesis_scenes.h"
#include "tool.h"

using namespace rt;
using rt::bench::EmbreeScene;

namespace {

constexpr int kWidth = 800, kHeight = 600;
constexpr int kBuildThreads = 2;
constexpr int kBuilds = 2;  // per scene and side; the best counts
constexpr double kRelativeTolerance = 1e-5;
constexpr int kListedDisagreements = 5;  // per ray set, on stderr
// More disagreeing rays than this fraction of a set fails the run (exit 1): edge and
// grazing hits, where float and double round to different sides, stay well below it.
constexpr double kMaxDisagreement = 1e-4;

// ---- Scenes and rays

// Where the scene comes from: a built-in name (a thesis scene or a generated one), or a file.
struct SceneSource {
    std::string name;  // as the tables name it: the built-in name, or the file's name
    std::string path;  // empty for a built-in scene
};

// rt-render's camera options, applied to a file's camera in the order rt-render applies them.
struct CameraOptions {
    std::optional<std::string> camera, lookFrom, lookAt, up;
    std::optional<double> fov;
};

// A file read as rt-render reads it (tools/render/render_command.cpp, loadWithCamera): the
// camera picked and overridden, the headlight moved to it.
Scene sceneFromFile(const std::string& path, const CameraOptions& o) {
    ImportOptions import;
    import.camera = o.camera.value_or("");
    import.cameraFromCommandLine = o.lookFrom || o.lookAt || o.fov;
    import.aspect = double(kWidth) / double(kHeight);
    Scene scene = rt::loadScene(path, import);
    CameraOverrides overrides;
    if (o.lookFrom) overrides.lookFrom = tool::render::parseVector("--look-from", *o.lookFrom);
    if (o.lookAt) overrides.lookAt = tool::render::parseVector("--look-at", *o.lookAt);
    if (o.up) overrides.up = tool::render::parseVector("--up", *o.up);
    if (o.fov) overrides.fovDegrees = Real(*o.fov);
    applyOverrides(scene.camera, overrides, scene.primitives.bounds(), Real(import.aspect));
    scene.placeHeadlights();
    return scene;
}

Scene loadScene(const SceneSource& source, const CameraOptions& camera) {
    if (!source.path.empty()) return sceneFromFile(source.path, camera);
    const auto& generated = bench::generatedRecipes();
    return generated.count(source.name) ? bench::generatedScene(source.name) : thesisScene(source.name);
}

struct RaySet {
    std::string name;     // camera, shadow, reflection
    bool anyHit = false;  // shadow rays ask only whether something is closer than tMax
    std::vector<Ray> rays;
    std::vector<Real> tMax;
    std::vector<int> packets;  // the sizes of the packets the rays come in, in order; none: single rays only

    void add(const Ray& ray, Real t) {
        rays.push_back(ray);
        tMax.push_back(t);
    }
};

// One ray per pixel, in 4x2 tiles so that each run of 8 rays is one rtcIntersect8 packet.
RaySet cameraRays(const Scene& scene) {
    static_assert(kPacketSize == 8 && kWidth % 4 == 0 && kHeight % 2 == 0);
    const CameraRays camera(scene.camera, kWidth, kHeight);
    RaySet set{"camera", false, {}, {}, {}};
    for (int y0 = 0; y0 < kHeight; y0 += 2)
        for (int x0 = 0; x0 < kWidth; x0 += 4) {
            for (int i = 0; i < kPacketSize; ++i)
                set.add(camera.at(Real(x0 + i % 4) + Real(0.5), Real(y0 + i / 4) + Real(0.5)), kInfinity);
            set.packets.push_back(kPacketSize);
        }
    return set;
}

// Where secondary rays leave the nearest hit of a camera ray: the point, its normal turned to
// face the ray, and the point moved off the surface along it by Tracer::epsilon.
struct Leaving {
    Vec3 point, normal, origin;
};

Leaving leaving(const Scene& scene, const Ray& ray, const Hit& hit, Real epsilon) {
    const Vec3 p = ray.at(hit.t);
    Vec3 n = scene.primitives.normal(hit.prim, p);
    if (dot(n, ray.direction) > 0) n = -n;
    return {p, n, p + n * epsilon};
}

Real epsilonOf(const Scene& scene, const Accelerator& kd) { return Tracer(scene, kd, RenderSettings{}).epsilon(); }

// The shadow rays from the camera rays' nearest hits to each light they face, made as
// Tracer::shade and visibility make them for point lights, and grouped as Tracer::pixelRun
// groups them: for each run of kPacketSize pixels of a row and each light, one packet.
RaySet shadowRays(const Scene& scene, const Accelerator& kd) {
    static_assert(kWidth % kPacketSize == 0);
    const CameraRays camera(scene.camera, kWidth, kHeight);
    const Real epsilon = epsilonOf(scene, kd);
    RaySet set{"shadow", true, {}, {}, {}};
    RayCounters counters;
    for (int y = 0; y < kHeight; ++y)
        for (int x0 = 0; x0 < kWidth; x0 += kPacketSize) {
            Leaving run[kPacketSize];
            int seen = 0;
            for (int i = 0; i < kPacketSize; ++i) {
                const Ray ray = camera.at(Real(x0 + i) + Real(0.5), Real(y) + Real(0.5));
                Hit hit;
                if (kd.intersect(ray, kInfinity, hit, counters)) run[seen++] = leaving(scene, ray, hit, epsilon);
            }
            for (const Light& light : scene.lights) {
                int size = 0;
                for (int k = 0; k < seen; ++k) {
                    if (dot(run[k].normal, light.position - run[k].point) <= 0) continue;  // behind the surface
                    const Vec3 d = light.position - run[k].origin;
                    const Real distance = length(d);
                    set.add({run[k].origin, d / distance}, distance);
                    ++size;
                }
                if (size != 0) set.packets.push_back(size);
            }
        }
    return set;
}

// A mirror reflection ray from each camera ray's nearest hit, made as Tracer::reflection makes them.
RaySet reflectionRays(const Scene& scene, const Accelerator& kd, const RaySet& camera) {
    const Real epsilon = epsilonOf(scene, kd);
    RaySet set{"reflection", false, {}, {}, {}};
    RayCounters counters;
    for (const Ray& ray : camera.rays) {
        Hit hit;
        if (!kd.intersect(ray, kInfinity, hit, counters)) continue;
        const Leaving from = leaving(scene, ray, hit, epsilon);
        set.add({from.origin, mirror(ray.direction, from.normal)}, kInfinity);
    }
    return set;
}

// ---- Tracing

struct Answers {
    std::vector<Hit> hits;
    std::vector<char> found;  // hit (or, for shadow rays, occluded)
    RayCounters counters;     // rt's, of the last pass; Embree counts nothing
};

using TraceAll = std::function<void(const RaySet&, Answers&)>;

TraceAll traceRt(const Accelerator& kd) {
    return [&kd](const RaySet& set, Answers& out) {
        RayCounters counters;
        for (std::size_t i = 0; i < set.rays.size(); ++i) {
            if (set.anyHit) {
                out.found[i] = kd.occluded(set.rays[i], set.tMax[i], counters);
            } else {
                Hit hit;
                out.found[i] = kd.intersect(set.rays[i], set.tMax[i], hit, counters);
                out.hits[i] = hit;
            }
        }
        out.counters = counters;
    };
}

// In the packets rt-render traces them in: the camera rays' nearest hits, the shadow rays' any hits.
TraceAll traceRtPackets(const Accelerator& kd) {
    return [&kd](const RaySet& set, Answers& out) {
        RayCounters counters;
        bool found[kPacketSize];
        std::size_t i = 0;
        for (const int size : set.packets) {
            if (set.anyHit)
                kd.occludedPacket(&set.rays[i], size, &set.tMax[i], found, counters);
            else
                kd.intersectPacket(&set.rays[i], size, kInfinity, &out.hits[i], found, counters);
            std::copy(found, found + size, &out.found[i]);
            i += std::size_t(size);
        }
    };
}

TraceAll traceEmbree(const EmbreeScene& embree) {
    return [&embree](const RaySet& set, Answers& out) {
        for (std::size_t i = 0; i < set.rays.size(); ++i) {
            if (set.anyHit) {
                out.found[i] = embree.occluded(set.rays[i], set.tMax[i]);
            } else {
                Hit hit;
                out.found[i] = embree.intersect(set.rays[i], set.tMax[i], hit);
                out.hits[i] = hit;
            }
        }
    };
}

// The packets traceRtPackets traces (camera rays are unbounded and come in whole packets).
TraceAll traceEmbree8(const EmbreeScene& embree) {
    return [&embree](const RaySet& set, Answers& out) {
        bool found[kPacketSize];
        std::size_t i = 0;
        for (const int size : set.packets) {
            if (set.anyHit)
                embree.occluded8(&set.rays[i], &set.tMax[i], size, found);
            else
                embree.intersect8(&set.rays[i], &out.hits[i], found);
            std::copy(found, found + size, &out.found[i]);
            i += std::size_t(size);
        }
    };
}

double threadCpuSeconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

// The best time of each tracer over `passes` passes, taken in turn; `answers` keeps the last pass's results.
std::vector<double> bestSeconds(const std::vector<TraceAll>& tracers, const RaySet& set, int passes,
                                std::vector<Answers>& answers) {
    std::vector<double> best(tracers.size(), std::numeric_limits<double>::infinity());
    answers.assign(tracers.size(), {std::vector<Hit>(set.rays.size()), std::vector<char>(set.rays.size()), {}});
    for (int pass = 0; pass < passes; ++pass) {
        for (std::size_t k = 0; k < tracers.size(); ++k) {
            const double start = threadCpuSeconds();
            tracers[k](set, answers[k]);
            best[k] = std::min(best[k], threadCpuSeconds() - start);
        }
    }
    return best;
}

// ---- Agreement

bool agree(const RaySet& set, const Answers& a, const Answers& b, std::size_t i) {
    if (a.found[i] != b.found[i]) return false;
    if (set.anyHit || !a.found[i]) return true;
    const Hit &x = a.hits[i], &y = b.hits[i];
    const Ray& r = set.rays[i];
    const Real scale =
        std::max({std::abs(r.origin.x), std::abs(r.origin.y), std::abs(r.origin.z)}) + std::max(x.t, y.t);
    return x.prim == y.prim && std::abs(x.t - y.t) <= kRelativeTolerance * scale;
}

std::size_t countDisagreements(const std::string& scene, const std::string& tracer, const RaySet& set,
                               const Answers& rtAnswers, const Answers& other) {
    std::size_t count = 0;
    for (std::size_t i = 0; i < set.rays.size(); ++i) {
        if (agree(set, rtAnswers, other, i)) continue;
        if (++count > kListedDisagreements) continue;
        const Hit &x = rtAnswers.hits[i], &y = other.hits[i];
        const Ray& r = set.rays[i];
        std::fprintf(
            stderr,
            "  differ %s %s %s ray %zu (o %.9g %.9g %.9g, d %.9g %.9g %.9g): rt %s prim %u t %.9g u %.3g v %.3g, "
            "Embree %s prim %u t %.9g u %.3g v %.3g\n",
            scene.c_str(), set.name.c_str(), tracer.c_str(), i, double(r.origin.x), double(r.origin.y),
            double(r.origin.z), double(r.direction.x), double(r.direction.y), double(r.direction.z),
            rtAnswers.found[i] ? "hit" : "miss", x.prim, double(x.t), double(x.u), double(x.v),
            other.found[i] ? "hit" : "miss", y.prim, double(y.t), double(y.u), double(y.v));
    }
    return count;
}

// ---- Report

std::string rate(double perSecond) {
    char text[32];
    if (perSecond >= 1e6)
        std::snprintf(text, sizeof text, "%.2fM", perSecond / 1e6);
    else
        std::snprintf(text, sizeof text, "%.0fk", perSecond / 1e3);
    return text;
}

std::string fixed(double value, int digits) {
    char text[32];
    std::snprintf(text, sizeof text, "%.*f", digits, value);
    return text;
}

std::string count(std::size_t n) {
    return n >= 1000000 ? fixed(double(n) / 1e6, 2) + "M"
           : n >= 1000  ? fixed(double(n) / 1e3, 1) + "k"
                        : std::to_string(n);
}

std::string disagreement(std::size_t differ, std::size_t rays) {
    return std::to_string(differ) + " (" + fixed(100.0 * double(differ) / double(std::max<std::size_t>(rays, 1)), 3) +
           " %)";
}

struct SceneReport {
    std::vector<std::string> rayRows;
    std::string buildRow;
    bool agreed = true;  // every ray set within kMaxDisagreement
};

// Rays whose packet answer is not bit for bit the single-ray answer, listed on stderr.
std::size_t countPacketDifferences(const std::string& scene, const RaySet& set, const Answers& single,
                                   const Answers& packets) {
    std::size_t count = 0;
    for (std::size_t i = 0; i < set.rays.size(); ++i) {
        const Hit &a = single.hits[i], &b = packets.hits[i];
        if (single.found[i] == packets.found[i] &&
            (set.anyHit || !single.found[i] || (a.prim == b.prim && std::memcmp(&a.t, &b.t, sizeof a.t) == 0)))
            continue;
        if (++count <= kListedDisagreements)
            std::fprintf(stderr, "  differ %s %s rt packets ray %zu: single prim %u t %.17g, packet prim %u t %.17g\n",
                         scene.c_str(), set.name.c_str(), i, a.prim, double(a.t), b.prim, double(b.t));
    }
    return count;
}

// One row of the ray table for a set: rt single rays, Embree single rays, and for camera and
// shadow rays rt packets and Embree packets.
std::string measureSet(const std::string& scene, std::size_t prims, const RaySet& set, const Accelerator& kd,
                       const EmbreeScene& embree, int passes, bool& agreed) {
    std::vector<TraceAll> tracers = {traceRt(kd), traceEmbree(embree)};
    const bool packets = !set.packets.empty();
    if (packets) tracers.insert(tracers.end(), {traceRtPackets(kd), traceEmbree8(embree)});
    std::vector<Answers> answers;
    const std::vector<double> seconds = bestSeconds(tracers, set, passes, answers);
    const double n = double(set.rays.size());
    std::string row = "| " + scene + " | " + count(prims) + " | " + set.name + " | " + count(set.rays.size()) + " | " +
                      rate(n / seconds[0]) + " | " + rate(n / seconds[1]) + " | " + fixed(seconds[1] / seconds[0], 2) +
                      " | ";
    std::size_t differ =
        countDisagreements(scene, set.anyHit ? "rtcOccluded1" : "rtcIntersect1", set, answers[0], answers[1]);
    if (packets) {
        row += rate(n / seconds[2]) + " | " + fixed(seconds[1] / seconds[2], 2) + " | " + rate(n / seconds[3]) + " | " +
               fixed(seconds[3] / seconds[2], 2) + " | ";
        differ = std::max(differ, countDisagreements(scene, set.anyHit ? "rtcOccluded8" : "rtcIntersect8", set,
                                                     answers[0], answers[3]));
        // Packets must give the single rays' bits: any difference fails the run.
        if (countPacketDifferences(scene, set, answers[0], answers[2]) != 0) agreed = false;
    } else {
        row += "- | - | - | - | ";
    }
    agreed = agreed && double(differ) <= kMaxDisagreement * n;
    const double testsPerRay = double(answers[0].counters.intersectionTests) / std::max(n, 1.0);
    return row + disagreement(differ, set.rays.size()) + " | " + fixed(testsPerRay, 2) + " |";
}

double processCpuSeconds() {
    timespec ts{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

// A build's wall clock time, and the CPU time of all the process's threads while it ran: on a
// machine shared with other work the CPU time moves less (it includes threads spinning idle).
struct BuildTime {
    double wall = std::numeric_limits<double>::infinity();
    double cpu = std::numeric_limits<double>::infinity();

    template <class F>
    void keepBest(F&& build) {
        const Stopwatch stopwatch;
        const double cpu0 = processCpuSeconds();
        build();
        cpu = std::min(cpu, processCpuSeconds() - cpu0);
        wall = std::min(wall, stopwatch.seconds());
    }
};

// One row of the build table; the SAH cost (thesis 2.5.1) shows that a faster build kept the tree's quality.
std::string buildRow(const std::string& name, const Primitives& prims, const Accelerator& kd, const BuildTime& kdTime,
                     const EmbreeScene& embree, const BuildTime& embreeTime) {
    const double n = double(prims.size());
    const double geometryBytes =
        double(prims.count<Triangle>() * sizeof(Triangle) + prims.count<Sphere>() * sizeof(Sphere));
    const AccelStats stats = kd.stats();
    return "| " + name + " | " + count(prims.size()) + " | " + fixed(kdTime.wall * 1e3, 0) + " / " +
           fixed(kdTime.cpu * 1e3, 0) + " ms | " + fixed(embreeTime.wall * 1e3, 0) + " / " +
           fixed(embreeTime.cpu * 1e3, 0) + " ms | " + fixed(kdTime.wall / embreeTime.wall, 2) + " / " +
           fixed(kdTime.cpu / embreeTime.cpu, 2) + " | " + fixed(stats.sahCost, 2) + " | " +
           fixed(double(stats.memoryBytes) / n, 1) + " + " + fixed(geometryBytes / n, 1) + " | " +
           fixed(double(embree.memoryBytes()) / n, 1) + " |";
}

SceneReport measureScene(const SceneSource& source, const CameraOptions& view, const AccelSettings& settings,
                         int passes, bool buildsOnly) {
    const std::string& name = source.name;
    std::cerr << "vs_embree: " << name << ": " << (source.path.empty() ? "generating" : "reading") << "\n";
    const Scene scene = loadScene(source, view);
    const Primitives& prims = scene.primitives;
    std::cerr << "vs_embree: " << name << ": building (" << prims.size() << " primitives)\n";
    std::unique_ptr<Accelerator> kd;
    // The best of kBuilds builds: the first may pay for starting threads. Embree's time
    // includes copying the geometry to its buffers.
    BuildTime kdTime, embreeTime;
    std::unique_ptr<EmbreeScene> embreeScene;
    for (int b = 0; b < kBuilds; ++b) {
        kd.reset();
        embreeScene.reset();
        kdTime.keepBest([&] { kd = buildAccelerator(prims, settings); });
        embreeTime.keepBest([&] { embreeScene = std::make_unique<EmbreeScene>(prims, kBuildThreads); });
    }
    const EmbreeScene& embree = *embreeScene;
    SceneReport report;
    report.buildRow = buildRow(name, prims, *kd, kdTime, embree, embreeTime);
    if (buildsOnly) return report;

    const RaySet camera = cameraRays(scene), shadow = shadowRays(scene, *kd),
                 reflection = reflectionRays(scene, *kd, camera);
    for (const RaySet* set : {&camera, &shadow, &reflection}) {
        std::cerr << "vs_embree: " << name << ": " << set->rays.size() << " " << set->name << " rays\n";
        report.rayRows.push_back(measureSet(name, prims.size(), *set, *kd, embree, passes, report.agreed));
    }
    return report;
}

// The built-in scenes named by --scenes, then the files of --scene, named by their file names.
std::vector<SceneSource> sceneSources(const std::vector<std::string>& names, const std::vector<std::string>& files) {
    std::vector<SceneSource> sources;
    for (const std::string& name : names) sources.push_back({name, ""});
    for (const std::string& file : files) {
        const std::size_t slash = file.find_last_of('/');
        sources.push_back({slash == std::string::npos ? file : file.substr(slash + 1), file});
    }
    return sources;
}

void addCameraOptions(CLI::App& app, CameraOptions& o) {
    const char* group = "Camera of --scene files (rt-render's options)";
    app.add_option("--camera", o.camera, "The file's camera: its name or number (0 is the first)")->group(group);
    app.add_option("--look-from", o.lookFrom, "Camera origin X,Y,Z")->group(group);
    app.add_option("--look-at", o.lookAt, "Camera destination X,Y,Z")->group(group);
    app.add_option("--up", o.up, "Camera up vector X,Y,Z")->group(group);
    app.add_option("--fov", o.fov, "Horizontal field of view in degrees")->check(CLI::Range(0.0, 180.0))->group(group);
}

// The structure measured as the tables name it: "KD", "BVH".
std::string structureName(AccelKind kind) {
    std::string name = accelKindName(kind);
    for (char& c : name) c = char(std::toupper(static_cast<unsigned char>(c)));
    return name;
}

void printRayTable(const std::vector<SceneReport>& reports, AccelKind kind) {
    std::cout << "\n### Rays per second, one thread (rt / Embree > 1: rt is faster)\n\n"
              << "| Scene | Primitives | Rays | Count | rt " << structureName(kind)
              << " | Embree 1 | rt / Embree 1 | rt packets | rt packets / "
                 "Embree 1 | Embree 8 | rt packets / Embree 8 | Differ | rt tests / ray |\n"
                 "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const SceneReport& r : reports)
        for (const std::string& row : r.rayRows) std::cout << row << "\n";
}

void printTables(const std::vector<SceneReport>& reports, AccelKind kind) {
    if (!reports.empty() && !reports.front().rayRows.empty()) printRayTable(reports, kind);
    std::cout << "\n### Builds on " << kBuildThreads << " threads and memory (rt / Embree > 1: rt takes longer)\n\n"
              << "| Scene | Primitives | rt " << structureName(kind)
              << " build (wall / CPU) | Embree build (wall / CPU) | rt / Embree (wall / CPU) "
                 "| rt SAH cost | rt bytes/prim (tree + "
                 "geometry) | Embree bytes/prim |\n|---|---|---|---|---|---|---|---|\n";
    for (const SceneReport& r : reports) std::cout << r.buildRow << "\n";
}

// The --kd-* options as given, else their defaults (tool::optionValues), to name the tree measured.
std::string kdOptions(const CLI::App& app) {
    std::string line;
    for (const tool::OptionValue& o : tool::optionValues(app))
        if (o.name.rfind("kd-", 0) == 0)
            line += " --" + o.name + " " + (o.values.empty() ? "(default)" : o.values.front());
    return line;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"rt's KD tree against Intel Embree 3: the same scenes and rays, rays per second and build times"};
    std::vector<std::string> scenes = {"balls",  "balls2",  "ships", "tree",       "pyramid5",
                                       "tri10k", "tri100k", "tri1M", "stadium100k"};
    std::vector<std::string> files;
    CameraOptions camera;
    int passes = 3;
    bool quick = false, buildsOnly = false;
    AccelSettings accel;  // rt-render's defaults unless --accel and the --kd-* options say otherwise
    auto* builtIn =
        app.add_option("--scenes", scenes, "Scenes to measure (thesis scenes and tri10k, tri100k, tri1M, stadium100k)");
    app.add_option("--scene", files,
                   "A scene file to measure, read as rt-render reads it (thesis XML, glTF, OBJ, ...); any number; "
                   "without --scenes, only these");
    app.add_option("--passes", passes, "Timed passes over each ray set; the best counts")->check(CLI::Range(1, 100));
    app.add_flag("--quick", quick, "Smoke test: ships and tri10k, one pass");
    app.add_flag("--builds", buildsOnly, "Builds only: no rays, only the build table");
    tool::addNamedOption(app, "--accel", accel.kind, kAccelKindNames, "rt's structure: kd, bvh, bsp or naive")
        ->capture_default_str();
    tool::addKdOptions(app, accel.kd);
    tool::addTriangleTestOption(app, accel);
    addCameraOptions(app, camera);
    CLI11_PARSE(app, argc, argv);
    if (quick) scenes = {"ships", "tri10k"}, passes = 1;
    if (!files.empty() && builtIn->count() == 0 && !quick) scenes.clear();

    omp_set_num_threads(kBuildThreads);
    std::vector<SceneReport> reports;
    // A bad scene file or camera option is exit 2, as in rt-render; any other failure exit 1.
    const int loaded = tool::run("vs_embree", [&] {
        for (const SceneSource& source : sceneSources(scenes, files))
            reports.push_back(measureScene(source, camera, accel, passes, buildsOnly));
        return tool::kExitOk;
    });
    if (loaded != tool::kExitOk) return loaded;
    std::cout << "rt (" << realTypeName() << ") against Embree " << RTC_VERSION_STRING << ", " << kWidth << "x"
              << kHeight << ", best of " << passes << " passes, rt on " << simdLevelName(simdLevel())
              << " lanes, single rays and packets (RT_SIMD=sse2|avx2|avx512 for another); rt's "
              << accelKindName(accel.kind) << (accel.kind == AccelKind::Kd ? kdOptions(app) : std::string())
              << (accel.triangles == TriangleTest::Watertight ? ", watertight triangles" : "") << "\n";
    printTables(reports, accel.kind);
    if (std::all_of(reports.begin(), reports.end(), [](const SceneReport& r) { return r.agreed; })) return 0;
    std::cerr << "vs_embree ERROR: rt and Embree disagree on more than " << 100 * kMaxDisagreement
              << " % of a ray set, or rt's packets differ from its single rays (the first rays are listed above)\n";
    return 1;
}
