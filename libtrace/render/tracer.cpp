#include "render/tracer.h"

#include <algorithm>
#include <cmath>

#include "render/light_sample.h"
#include "render/phong.h"

namespace rt {

namespace {

// Secondary rays start this far off the surface, relative to the scene's size: the error
// of a computed hit point grows with the magnitude of its coordinates, so a fixed offset
// is too small for a city and too large for a teapot.
constexpr Real kRelativeEpsilon = sizeof(Real) == sizeof(float) ? Real(1e-4) : Real(1e-7);

Real sceneEpsilon(const Primitives& prims) {
    const Aabb box = prims.bounds();
    if (box.empty()) return kRelativeEpsilon;
    Real scale = std::max(length(box.diagonal()), Real(1e-3));
    for (int a = 0; a < 3; ++a) scale = std::max({scale, std::abs(box.lo[a]), std::abs(box.hi[a])});
    return kRelativeEpsilon * scale;
}

const Material& materialOf(const Scene& scene, std::uint32_t prim) {
    static const Material fallback;  // scenes built in code may give no materials
    const std::uint32_t id = scene.primitives.material(prim);
    return id < scene.materials.size() ? scene.materials[id] : fallback;
}

// A point on the disc of radius r around c facing along `axis` (unit): the light as the
// shading point sees it. Uniform in area: radius r sqrt(u1), angle 2 pi u2.
Vec3 pointOnDisc(const Vec3& c, const Vec3& axis, Real r, SampleRng& rng) {
    Vec3 t, b;
    orthonormalBasis(axis, t, b);
    const Real radius = r * std::sqrt(rng.uniform());
    const Real angle = 2 * kPi * rng.uniform();
    return c + t * (radius * std::cos(angle)) + b * (radius * std::sin(angle));
}

}  // namespace

Tracer::Tracer(const Scene& scene, const Accelerator& accel, const RenderSettings& settings,
               const ImageTextures* images)
    : scene_(scene),
      accel_(accel),
      settings_(settings),
      camera_(scene.camera, settings.width, settings.height),
      epsilon_(sceneEpsilon(scene.primitives)),
      images_(images) {
    // Thesis 2.1.3: i_a is the sum of the lights' intensities. The colour of a light with the
    // inverse-square falloff is what it gives at distance 1, no irradiance: it adds nothing.
    for (const Light& light : scene.lights)
        if (light.falloff == Light::Falloff::None) ambientLight_ += light.color;
}

Color Tracer::pixel(int x, int y, RenderCounters& counters, float& coverage, PixelAovs* aovs) const {
    const int n = settings_.pixelSamples;
    const RenderCounters before = counters;
    Color sum;
    int hits = 0;
    for (int i = 0; i < n; ++i) {
        SampleRng rng{std::uint32_t(x), std::uint32_t(y), std::uint32_t(i), settings_.seed};
        Real sx = Real(0.5), sy = Real(0.5);
        if (n > 1) jitteredGridSample(i, n, rng, sx, sy);
        ++counters.camera.rays;
        // trace() at depth 0, keeping whether the camera ray hit (alpha)
        const Ray ray = camera_.at(Real(x) + sx, Real(y) + sy);
        Hit hit;
        const bool seen = accel_.intersect(ray, kInfinity, hit, counters.camera);
        hits += seen;
        if (aovs && seen) addHit(*aovs, ray, hit, i == 0);
        const Color sample = seen ? shade(ray, hit, 0, false, rng, counters) : scene_.background;
        if (isFinite(sample))
            sum += sample;
        else
            counters.nonFinite.add(x, y);  // counts as black, and the tool says so
    }
    coverage = float(hits) / float(n);
    if (aovs) average(*aovs, n, hits, before, counters);
    return n == 1 ? sum : sum * (1.0f / float(n));
}

// Sums what a camera ray that hit shows into the pixel's AOVs; average() divides.
void Tracer::addHit(PixelAovs& a, const Ray& ray, const Hit& hit, bool first) const {
    const Vec3 p = ray.at(hit.t);
    const Vec3 ng = scene_.primitives.normal(hit.prim, p);
    const Vec3 n = dot(ng, ray.direction) > 0 ? -ng : ng;  // as shade() lights it: facing the ray
    for (int c = 0; c < 3; ++c) {
        a.p[c] += float(p[c]);
        a.n[c] += float(n[c]);
        a.ng[c] += float(ng[c]);
    }
    a.z += float(hit.t);
    a.albedo += materialOf(scene_, hit.prim).color;
    if (!first) return;
    a.material = scene_.primitives.material(hit.prim);
    a.primitive = hit.prim;
}

void Tracer::average(PixelAovs& a, int samples, int hits, const RenderCounters& before, const RenderCounters& after) {
    const float perHit = hits > 0 ? 1.0f / float(hits) : 0.0f;
    for (int c = 0; c < 3; ++c) {
        a.p[c] *= perHit;
        a.n[c] *= perHit;
        a.ng[c] *= perHit;
    }
    a.albedo *= perHit;
    a.z = hits > 0 ? a.z * perHit : kInfinity;
    const float perSample = 1.0f / float(samples);
    a.steps = float(after.camera.traversalSteps - before.camera.traversalSteps) * perSample;
    a.tests = float(after.camera.intersectionTests - before.camera.intersectionTests) * perSample;
    const RayCounters all = after.total(), allBefore = before.total();
    a.allSteps = float(all.traversalSteps - allBefore.traversalSteps) * perSample;
    a.allTests = float(all.intersectionTests - allBefore.intersectionTests) * perSample;
}

Color Tracer::trace(const Ray& ray, int depth, bool inBundle, SampleRng& rng, RenderCounters& counters) const {
    Hit hit;
    RayCounters& work = depth == 0 ? counters.camera : counters.reflection;
    if (!accel_.intersect(ray, kInfinity, hit, work)) return scene_.background;
    return shade(ray, hit, depth, inBundle, rng, counters);
}

Color Tracer::shade(const Ray& ray, const Hit& hit, int depth, bool inBundle, SampleRng& rng,
                    RenderCounters& counters) const {
    const SurfacePoint s = surfaceAt(scene_.primitives, ray, hit);
    const Material& m = materialOf(scene_, hit.prim);
    const Color color = surfaceColor(m, s);
    const Vec3 toViewer = -ray.direction;

    Color c = phongAmbient(color, m, ambientLight_) + emitted(m, s);
    for (const Light& light : scene_.lights) {
        const LightIncidence in = lightIncidence(light, s.point);
        // The light is behind the surface, or the point outside its cone or range: no shadow ray needed.
        if (dot(s.shadingNormal, in.toLight) <= 0 || in.color == Color{}) continue;
        const float seen = visibility(s, light, in.toLight, inBundle, rng, counters);
        if (seen > 0) c += phongLight(m, color, s.shadingNormal, in.toLight, toViewer, in.color) * seen;
    }
    // Thesis 2.1, step 6: the reflected intensity is added to the local one.
    if (m.reflection > 0 && depth < settings_.reflectionDepth)
        c += reflection(s, ray.direction, m, depth, inBundle, rng, counters) * m.reflection;
    return c;
}

Color Tracer::surfaceColor(const Material& m, const SurfacePoint& s) const {
    const Color c = m.color * s.tint;
    return m.colorTexture ? c * textureColor(scene_, *m.colorTexture, s, images_) : c;
}

// Whitted's model has no light transport from surfaces: an emitter is seen (directly, in
// mirrors), but lights nothing else.
Color Tracer::emitted(const Material& m, const SurfacePoint& s) const {
    return m.emissionTexture ? m.emission * textureColor(scene_, *m.emissionTexture, s, images_) : m.emission;
}

float Tracer::visibility(const SurfacePoint& s, const Light& light, const Vec3& toLight, bool inBundle, SampleRng& rng,
                         RenderCounters& counters) const {
    if (!settings_.shadows) return 1;
    const Vec3 origin = s.shadowOrigin + s.geometricNormal * epsilon_;
    if (light.type == Light::Type::Directional) {  // infinitely far: anything along the way shadows
        ++counters.shadow.rays;
        return accel_.occluded({origin, toLight}, kInfinity, counters.shadow) ? 0.0f : 1.0f;
    }
    const bool area = settings_.softShadows && light.size > 0;
    const int samples = area && !inBundle ? settings_.distributedSamples : 1;
    const Vec3 axis = area ? normalize(light.position - origin) : Vec3{};  // only area lights need it
    int visible = 0;
    for (int i = 0; i < samples; ++i) {
        const Vec3 target = area ? pointOnDisc(light.position, axis, light.size, rng) : light.position;
        const Vec3 d = target - origin;
        const Real distance = length(d);
        ++counters.shadow.rays;
        if (!accel_.occluded({origin, d / distance}, distance, counters.shadow)) ++visible;
    }
    return samples == 1 ? float(visible) : float(visible) / float(samples);
}

Color Tracer::reflection(const SurfacePoint& s, const Vec3& dir, const Material& m, int depth, bool inBundle,
                         SampleRng& rng, RenderCounters& counters) const {
    const Vec3 origin = s.point + s.geometricNormal * epsilon_;
    Vec3 r = mirror(dir, s.shadingNormal);
    if (dot(r, s.geometricNormal) <= 0) r = mirror(r, s.geometricNormal);  // a shading normal can send it inside
    if (!settings_.glossyReflections || !(m.spread > 0)) {
        ++counters.reflection.rays;
        return trace({origin, r}, depth + 1, inBundle, rng, counters);
    }
    // Glossy: directions around r, offset in the plane across r by a 2-D normal
    // distribution with sigma = spread (about the angle in radians, for small spreads).
    Vec3 t, b;
    orthonormalBasis(r, t, b);
    const int samples = inBundle ? 1 : settings_.distributedSamples;
    Color sum;
    for (int i = 0; i < samples; ++i) {
        Real g1, g2;
        rng.normalPair(g1, g2);
        Vec3 d = normalize(r + (t * g1 + b * g2) * Real(m.spread));
        if (dot(d, s.geometricNormal) <= 0) d = mirror(d, s.geometricNormal);  // below the surface: fold it back above
        ++counters.reflection.rays;
        sum += trace({origin, d}, depth + 1, true, rng, counters);
    }
    return samples == 1 ? sum : sum * (1.0f / float(samples));
}

}  // namespace rt
