// What every BSDF of the path tracer answers (render/materials/bsdf.h holds them), in the local
// frame of the shading normal (z up), wo towards the viewer:
//   Color evaluate(wo, wi)               f(wo, wi) |cos(wi)|, zero for a delta lobe
//   Real pdf(wo, wi)                     the density sample() draws wi with
//   optional<BsdfSample> sample(wo, u1, u2, u3)   u1 picks a lobe, (u2, u3) its direction
//   BsdfFlags flags()                    what kinds of scattering it has
// as pbrt-v4's BxDF interface does.
#pragma once

#include <cstdint>

#include "core/color.h"
#include "core/vec3.h"
#include "render/sampling.h"

namespace rt {

// The kinds of scattering a BSDF has (pbrt-v4's BxDFFlags): which side light leaves to, and how
// spread its lobes are. A BSDF that is only Specular is smooth: light samples cannot find what it
// scatters, so the path tracer sends none.
enum class BsdfFlags : std::uint8_t {
    None = 0,
    Reflection = 1 << 0,
    Transmission = 1 << 1,
    Diffuse = 1 << 2,
    Glossy = 1 << 3,
    Specular = 1 << 4,  // a delta: one direction, as a mirror or smooth glass
};

constexpr BsdfFlags operator|(BsdfFlags a, BsdfFlags b) { return BsdfFlags(std::uint8_t(a) | std::uint8_t(b)); }
constexpr bool has(BsdfFlags flags, BsdfFlags what) { return (std::uint8_t(flags) & std::uint8_t(what)) != 0; }
// Whether some of what it scatters is spread over directions, so that a light sample can find it.
constexpr bool isNonSpecular(BsdfFlags flags) { return has(flags, BsdfFlags::Diffuse | BsdfFlags::Glossy); }

struct BsdfSample {
    Vec3 wi;
    Color weight;  // f cos / pdf (for a specular direction: its share of the light)
    Real pdf = 0;
    bool specular = false;  // a delta direction: no light sample could have found it
};

// The BSDF's local frame at a surface point: tangent, bitangent, normal (its z).
struct ShadingFrame {
    Vec3 axes[3];

    explicit ShadingFrame(const Vec3& n) {
        orthonormalBasis(n, axes[0], axes[1]);
        axes[2] = n;
    }
    Vec3 toLocal(const Vec3& v) const { return {dot(v, axes[0]), dot(v, axes[1]), dot(v, axes[2])}; }
    Vec3 toWorld(const Vec3& v) const { return axes[0] * v.x + axes[1] * v.y + axes[2] * v.z; }
};

}  // namespace rt
