#include "render/aov.h"

#include <algorithm>
#include <sstream>

#include "core/error.h"

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
            throw InputError("--aov: unknown AOV '" + name + "' (Z, N, Ng, P, albedo, id, cost, variance or all)");
        wanted[std::size_t(it - layers.begin())] = true;
    }
    std::vector<Aov> aovs;
    for (std::size_t i = 0; i < wanted.size(); ++i)
        if (wanted[i]) aovs.push_back(aovLayers()[i].aov);
    return aovs;
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
        case Aov::Id:
            break;
    }
    return {};
}

}  // namespace rt
