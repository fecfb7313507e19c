// The generated scenes the benchmarks share (bench_accel, vs_embree): random triangles
// and spheres from generateScene, named by size, and one uneven scene.
#pragma once

#include <map>
#include <string>

#include "scene/generate.h"

namespace rt::bench {

inline const std::map<std::string, SceneRecipe>& generatedRecipes() {
    static const std::map<std::string, SceneRecipe> all = {
        {"tri10k", {10000, 0, Placement::Uniform, 1}},         {"tri100k", {100000, 0, Placement::Uniform, 1}},
        {"tri1M", {1000000, 0, Placement::Uniform, 1}},        {"spheres100k", {0, 100000, Placement::Clustered, 1}},
        {"stadium100k", {100000, 0, Placement::Clustered, 1}},
    };
    return all;
}

// "Teapot in a stadium": the clustered triangles on a floor 100 units wide, so that the
// scene's box is mostly empty, like the thesis's uneven scenes (Table 4.2, "tree"),
// where middle planes spend most of the BSP's depth limit on empty space.
inline Scene generatedScene(const std::string& name) {
    Scene scene = generateScene(generatedRecipes().at(name));
    if (name == "stadium100k") {
        constexpr Real kHalf = 50, kFloor = Real(-1.2);
        scene.looseObjects.add<Triangle>({{-kHalf, kFloor, -kHalf}, {kHalf, kFloor, kHalf}, {kHalf, kFloor, -kHalf}},
                                         0);
        scene.looseObjects.add<Triangle>({{-kHalf, kFloor, -kHalf}, {-kHalf, kFloor, kHalf}, {kHalf, kFloor, kHalf}},
                                         0);
        scene.flatten();
    }
    return scene;
}

}  // namespace rt::bench
