// What a material lets through (rt extension, docs/scene-format.md): the transmitted ray of
// Whitted's 1980 model, which the thesis left out (2.1, step 5). The renderer's side is
// render/refraction.h; the importers map glTF's KHR_materials_transmission, _ior and _volume,
// MTL's d/Tr/Ni/illum and Assimp's opacity onto it (docs/conversion.md).
#pragma once

#include <cstdint>
#include <limits>
#include <optional>

#include "core/color.h"

namespace rt {

struct Transmission {
    // k_t, 0-1: the share of the light not reflected at the surface (Schlick's Fresnel term
    // with `ior` splits the two) that passes through it. 0: opaque, as every thesis material.
    float weight = 0;
    Color color{1, 1, 1};  // tints the light that passes, as a coloured glass does
    float ior = 1.5f;      // index of refraction of the inside relative to the outside
    // A sheet with no inside (glTF's thin-walled material, MTL's dissolve): light passes
    // straight on, without bending or absorption; Fresnel still reflects by `ior`.
    bool thin = false;
    // Beer-Lambert absorption inside (KHR_materials_volume): white light that has travelled
    // attenuationDistance inside has become attenuationColor. Infinite: no absorption.
    Color attenuationColor{1, 1, 1};
    float attenuationDistance = std::numeric_limits<float>::infinity();
    // KHR_materials_transmission's transmissionTexture (XML's transmission_texture), an index in
    // Scene::textures: its red channel, read as data, scales `weight` per hit.
    std::optional<std::uint32_t> texture{};

    bool passesLight() const { return weight > 0; }
    bool absorbs() const { return !thin && attenuationDistance < std::numeric_limits<float>::infinity(); }
};

// The largest index of refraction a reader takes: every material's is below 5 (germanium's, 4.0);
// an ior of 1e300 became an infinite float and a NaN Fresnel term.
inline constexpr double kMaxIor = 100;

}  // namespace rt
