#include "scene/generate.h"

#include <cmath>
#include <vector>

#include "core/random.h"

namespace rt {

namespace {

// SplitMix64 (core/random.h): the same scene on every machine.
class Random {
public:
    explicit Random(std::uint64_t seed) : stream_(seed) {}

    std::uint64_t next() { return stream_.next(); }
    double uniform() { return stream_.uniform(); }  // [0, 1)
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
    Vec3 inCube(double half) {
        const Real x = Real(uniform(-half, half)), y = Real(uniform(-half, half)), z = Real(uniform(-half, half));
        return {x, y, z};
    }
    double gaussian() {
        const double u = 1 - uniform(), v = uniform();
        return boxMuller(u, v).first;
    }

private:
    SplitMix64 stream_;
};

class CentrePicker {
public:
    CentrePicker(Placement placement, std::size_t count, Random& random) : placement_(placement), random_(random) {
        if (placement_ != Placement::Clustered) return;
        const auto clusters = std::size_t(std::max(1.0, std::cbrt(double(count))));
        for (std::size_t i = 0; i < clusters; ++i) clusters_.push_back(random_.inCube(0.8));
    }

    Vec3 next() {
        if (placement_ == Placement::Uniform) return random_.inCube(1);
        const Vec3& c = clusters_[random_.next() % clusters_.size()];
        const auto spread = Real(0.08);
        Vec3 p{c.x + spread * Real(random_.gaussian()), c.y + spread * Real(random_.gaussian()),
               c.z + spread * Real(random_.gaussian())};
        return min(max(p, Vec3{-1, -1, -1}), Vec3{1, 1, 1});
    }

private:
    Placement placement_;
    Random& random_;
    std::vector<Vec3> clusters_;
};

}  // namespace

Scene generateScene(const SceneRecipe& recipe) {
    Scene scene;
    scene.background = {0.05f, 0.05f, 0.08f};
    scene.camera.origin = {Real(0.6), Real(1.2), Real(3.4)};
    scene.camera.destination = {0, 0, 0};
    scene.camera.fovDegrees = Real(60);
    scene.lights.push_back({{3, 4, 5}, {0.8f, 0.8f, 0.8f}, Real(0.2)});
    scene.lights.push_back({{-4, 3, 2}, {0.4f, 0.4f, 0.5f}, Real(0.2)});
    scene.materials.push_back({"triangles", {0.8f, 0.8f, 0.75f}});
    scene.materials.push_back({"spheres", {0.8f, 0.3f, 0.25f}, {0.1f, 0.7f, 0.3f, 40.0f, 0.2f}});

    const std::size_t total =
        std::max<std::size_t>(recipe.triangles + recipe.spheres + recipe.cylinders + recipe.cones + recipe.disks, 1);
    const double spacing = std::cbrt(8.0 / double(total));
    const double size = recipe.placement == Placement::Clustered ? spacing * 0.5 : spacing;
    Random random(recipe.seed);
    CentrePicker centres(recipe.placement, total, random);
    scene.looseObjects.reserve<Triangle>(recipe.triangles);
    while (scene.looseObjects.count<Triangle>() < recipe.triangles) {
        const Vec3 c = centres.next();
        const auto half = Real(size / 2);
        const Triangle t{c + random.inCube(half), c + random.inCube(half), c + random.inCube(half)};
        if (t.area() > Real(1e-3) * half * half) scene.looseObjects.add<Triangle>(t, 0);  // no slivers
    }
    for (std::size_t i = 0; i < recipe.spheres; ++i) {
        const Vec3 c = centres.next();
        scene.looseObjects.add<Sphere>({c, Real(size * random.uniform(0.2, 0.5))}, 1);
    }
    const auto frustum = [&](Real topRadiusFactor) {
        const Vec3 c = centres.next(), half = random.inCube(Real(size / 2));
        const Real r = Real(size * random.uniform(0.1, 0.3));
        return Frustum{c - half, c + half, r, r * topRadiusFactor};
    };
    for (std::size_t i = 0; i < recipe.cylinders; ++i) scene.looseObjects.add<Cylinder>({frustum(1)}, 1);
    for (std::size_t i = 0; i < recipe.cones; ++i)
        scene.looseObjects.add<Cone>({frustum(i % 2 ? 0 : Real(random.uniform(0.2, 0.8)))}, 1);
    for (std::size_t i = 0; i < recipe.disks; ++i) {
        const Vec3 c = centres.next(), n = random.inCube(1);
        if (length(n) > Real(0.1))
            scene.looseObjects.add<Disk>({c, normalize(n), Real(size * random.uniform(0.2, 0.5))}, 1);
    }
    scene.droppedDegenerate = scene.flatten();
    return scene;
}

}  // namespace rt
