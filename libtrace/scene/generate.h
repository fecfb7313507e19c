// Procedural test scenes: a given number of random triangles, spheres, cylinders, cones and disks in the cube
// [-1, 1]^3, spread evenly or gathered in clusters, seen by a camera from outside and lit
// by two lights. The tree tests, the benchmarks and the tools all use them, so a scene is
// fully determined by its recipe (own generator, no std:: distributions whose output
// differs between standard libraries).
#pragma once

#include <cstdint>

#include "scene/scene.h"

namespace rt {

enum class Placement {
    Uniform,    // centres uniform in the cube
    Clustered,  // centres in Gaussian clusters around cbrt(N) random points: the uneven
                // scenes on which the thesis's BSP tree does poorly (Table 4.2, "tree")
};

struct SceneRecipe {
    std::size_t triangles = 0;
    std::size_t spheres = 0;
    Placement placement = Placement::Uniform;
    std::uint64_t seed = 1;
    std::size_t cylinders = 0;  // random axes, length about the size of a triangle
    std::size_t cones = 0;      // frusta, some coming to a point
    std::size_t disks = 0;      // random normals, radius about a sphere's
};

// Sizes shrink with the count (edge about the mean spacing, cbrt(8 / N)), so every
// scene is about equally crowded. The result is flattened: scene.primitives is ready.
Scene generateScene(const SceneRecipe& recipe);

}  // namespace rt
