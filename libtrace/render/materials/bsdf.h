// The path tracer's BSDF at a surface point: one of the lobes of this folder, chosen for the
// material by bsdfAt, the one place that chooses (as pbrt-v4's Material::GetBxDF). The path
// tracer asks it only what lobe.h lists (evaluate, pdf, sample, flags), never which one it is.
//
// Adding a BSDF (docs/architecture.md, "Adding a BSDF"): its class in a file of its own here,
// with the interface of lobe.h and a test of its own; its type in Bsdf's list below; its rule in
// bsdfAt (bsdf.cpp); the material's fields it reads in scene/scene.h and the readers and writers
// that fill them.
#pragma once

#include <optional>
#include <utility>
#include <variant>

#include "render/materials/clearcoat_bsdf.h"
#include "render/materials/dielectric_bsdf.h"
#include "render/materials/lobe.h"
#include "render/materials/pbr_bsdf.h"
#include "render/texture.h"
#include "scene/scene.h"

namespace rt {

class Bsdf {
public:
    using Lobes = std::variant<PbrBsdf, DielectricBsdf, ClearcoatBsdf>;

    explicit Bsdf(Lobes lobes) : lobes_(std::move(lobes)) {}
    Color evaluate(const Vec3& wo, const Vec3& wi) const {
        return std::visit([&](const auto& b) { return b.evaluate(wo, wi); }, lobes_);
    }
    Real pdf(const Vec3& wo, const Vec3& wi) const {
        return std::visit([&](const auto& b) { return b.pdf(wo, wi); }, lobes_);
    }
    std::optional<BsdfSample> sample(const Vec3& wo, Real u1, Real u2, Real u3) const {
        return std::visit([&](const auto& b) { return b.sample(wo, u1, u2, u3); }, lobes_);
    }
    BsdfFlags flags() const {
        return std::visit([](const auto& b) { return b.flags(); }, lobes_);
    }

private:
    Lobes lobes_;
};

// The BSDF of material m at surface point s. A material that lets light through (transmission
// weight w at s: transmissionAt) is glass (dielectric_bsdf.h) for a share w of its paths and the
// metallic-roughness BRDF (pbr_bsdf.h) for the rest, under its clear coat if it has one
// (clearcoat_bsdf.h); `lobe`, a uniform number, makes the choice and is stretched back to [0, 1)
// for sample().
Bsdf bsdfAt(const ShadingContext& context, const Material& m, const SurfacePoint& s, Real& lobe);

}  // namespace rt
