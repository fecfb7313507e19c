// Scenes built in code for the rt-inspect tests.
#pragma once

#include "scene/scene.h"

namespace rt {

// The camera at the origin looking down +z with +y up (so +x is to the left of the
// picture, the world being right-handed), one default material, nothing else.
inline Scene sceneLookingDownZ(Real fovDegrees = 60) {
    Scene scene;
    scene.camera.origin = {0, 0, 0};
    scene.camera.destination = {0, 0, 1};
    scene.camera.fovDegrees = fovDegrees;
    scene.materials.push_back({});
    return scene;
}

// n^3 spheres `spacing` apart, the first centred on `corner`, with material 0.
inline void addSphereCluster(Scene& scene, const Vec3& corner, int n, Real spacing, Real radius) {
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < n; ++k)
                scene.looseObjects.add<Sphere>({corner + Vec3(Real(i), Real(j), Real(k)) * spacing, radius}, 0);
}

}  // namespace rt
