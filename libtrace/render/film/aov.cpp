#include "render/film/aov.h"

#include <algorithm>
#include <sstream>

#include "core/error.h"
#include "render/render_stats.h"
#include "render/surface.h"
#include "scene/scene.h"

namespace rt {

const std::vector<AovLayer>& aovLayers() {
    static const std::vector<AovLayer> layers{
        {Aov::Z, "Z", {"Z"}, false},
        {Aov::N, "N", {"N.X", "N.Y", "N.Z"}, false},
        {Aov::Ng, "Ng", {"Ng.X", "Ng.Y", "Ng.Z"}, false},
        {Aov::P, "P", {"P.X", "P.Y", "P.Z"}, false},
        {Aov::Albedo, "albedo", {"albedo.R", "albedo.G", "albedo.B"}, false},
        {Aov::Id, "id", {"id.material", "id.primitive"}, true},
        {Aov::Cost, "cost", {"cost.steps", "cost.tests", "cost.allSteps", "cost.allTests"}, false},
        {Aov::Variance, "variance", {"variance.R", "variance.G", "variance.B"}, false},
        {Aov::Samples, "samples", {"samples.count"}, false},
    };
    return layers;
}

const char* aovName(Aov aov) {
    const auto& layers = aovLayers();
    return std::find_if(layers.begin(), layers.end(), [aov](const AovLayer& l) { return l.aov == aov; })->name;
}

std::vector<Aov> parseAovList(const std::string& list) {
    std::vector<bool> wanted(aovLayers().size(), list == "all");
    std::istringstream items(list == "all" ? "" : list);
    for (std::string name; std::getline(items, name, ',');) {
        const auto& layers = aovLayers();
        const auto it = std::find_if(layers.begin(), layers.end(), [&](const AovLayer& l) { return name == l.name; });
        if (it == layers.end())
            throw InputError("--aov: unknown AOV '" + name +
                             "' (Z, N, Ng, P, albedo, id, cost, variance, samples or all)");
        wanted[std::size_t(it - layers.begin())] = true;
    }
    std::vector<Aov> aovs;
    for (std::size_t i = 0; i < wanted.size(); ++i)
        if (wanted[i]) aovs.push_back(aovLayers()[i].aov);
    return aovs;
}

// Ng is the primitive's own normal, not turned to the ray.
void AovSums::addHit(const Scene& scene, const SurfacePoint& s, const Hit& hit, const Color& albedo) {
    const Vec3 ng = scene.primitives.normal(hit.prim, s.point);
    for (int c = 0; c < 3; ++c) {
        sum_.p[c] += float(s.point[c]);
        sum_.n[c] += float(s.shadingNormal[c]);
        sum_.ng[c] += float(ng[c]);
    }
    sum_.z += float(hit.t);
    sum_.albedo += albedo;
    ++hits_;
    if (samples_ > 0) return;
    sum_.material = scene.primitives.material(hit.prim);
    sum_.primitive = hit.prim;
}

void AovSums::finishSample(const RenderCounters& before, const RenderCounters& after) {
    steps_ += after.camera.traversalSteps - before.camera.traversalSteps;
    tests_ += after.camera.intersectionTests - before.camera.intersectionTests;
    const RayCounters all = after.total(), allBefore = before.total();
    allSteps_ += all.traversalSteps - allBefore.traversalSteps;
    allTests_ += all.intersectionTests - allBefore.intersectionTests;
    ++samples_;
}

PixelAovs AovSums::mean(const Color& varianceOfMean) const {
    PixelAovs a = sum_;
    const float perHit = hits_ > 0 ? 1.0f / float(hits_) : 0.0f;
    for (int c = 0; c < 3; ++c) {
        a.p[c] *= perHit;
        a.n[c] *= perHit;
        a.ng[c] *= perHit;
    }
    a.albedo *= perHit;
    a.z = hits_ > 0 ? a.z * perHit : kInfinity;
    const float perSample = samples_ > 0 ? 1.0f / float(samples_) : 0.0f;
    a.steps = float(steps_) * perSample;
    a.tests = float(tests_) * perSample;
    a.allSteps = float(allSteps_) * perSample;
    a.allTests = float(allTests_) * perSample;
    a.variance = varianceOfMean;
    a.samples = float(samples_);
    return a;
}

std::vector<float> aovValues(const PixelAovs& a, Aov aov) {
    switch (aov) {
        case Aov::Z:
            return {a.z};
        case Aov::N:
            return {a.n[0], a.n[1], a.n[2]};
        case Aov::Ng:
            return {a.ng[0], a.ng[1], a.ng[2]};
        case Aov::P:
            return {a.p[0], a.p[1], a.p[2]};
        case Aov::Albedo:
            return {a.albedo.r, a.albedo.g, a.albedo.b};
        case Aov::Cost:
            return {a.steps, a.tests, a.allSteps, a.allTests};
        case Aov::Variance:
            return {a.variance.r, a.variance.g, a.variance.b};
        case Aov::Samples:
            return {a.samples};
        case Aov::Id:
            break;
    }
    return {};
}

}  // namespace rt
