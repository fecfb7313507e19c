#include "render/normal_map.h"

namespace rt {

namespace {

// The normal on the side the triangle's vertex normals (or, for a flat one, its winding) face,
// interpolated but not turned towards the ray: the side its tangent frame was built on.
Vec3 frontNormal(const Primitives& prims, std::uint32_t index, const Hit& hit, const Vec3& point) {
    if (const CornerNormals* normals = prims.triangleShading().normals.find(index)) {
        const auto n = normals->at(hit.u, hit.v);
        const Vec3 v{n[0], n[1], n[2]};
        if (length(v) > 0) return normalize(v);
    }
    return prims.normal(hit.prim, point);
}

// The texel as a tangent-space normal, x and y scaled.
Vec3 tangentSpaceNormal(const ShadingContext& context, const Material& m, const SurfacePoint& s) {
    const Color c = textureData(context, *m.normalMap.texture, s);
    return {(2 * c.r - 1) * m.normalMap.scale, (2 * c.g - 1) * m.normalMap.scale, 2 * c.b - 1};
}

}  // namespace

void applyNormalMap(const ShadingContext& context, const Material& m, const Hit& hit, SurfacePoint& s) {
    const std::optional<std::uint32_t>& texture = m.normalMap.texture;
    if (!texture || !context.images || context.scene.textures[*texture].kind != Texture::Kind::Image) return;
    const Primitives& prims = context.scene.primitives;
    const std::optional<std::uint32_t> index = prims.indexIn<Triangle>(hit.prim);
    const CornerTangents* tangents = index ? prims.triangleShading().tangents.find(*index) : nullptr;
    if (!tangents) return;
    const bool back = dot(frontNormal(prims, *index, hit, s.point), s.geometricNormal) < 0;
    const Vec3 n = back ? -s.shadingNormal : s.shadingNormal;
    const auto t = tangents->at(hit.u, hit.v);
    Vec3 tangent = Vec3{t[0], t[1], t[2]};
    tangent = tangent - n * dot(n, tangent);  // Gram-Schmidt against the interpolated normal
    if (!(length(tangent) > 0)) return;
    tangent = normalize(tangent);
    const Vec3 bitangent = cross(n, tangent) * (t[3] < 0 ? Real(-1) : Real(1));
    const Vec3 local = tangentSpaceNormal(context, m, s);
    const Vec3 perturbed = tangent * local.x + bitangent * local.y + n * local.z;
    if (!(length(perturbed) > 0)) return;
    s.shadingNormal = back ? -normalize(perturbed) : normalize(perturbed);
}

SurfacePoint shadedSurfaceAt(const ShadingContext& context, const Ray& ray, const Hit& hit,
                             const RayDifferential& differential) {
    const Scene& scene = context.scene;
    SurfacePoint s = surfaceAt(scene.primitives, ray, hit);
    if (context.images && differential != RayDifferential{})
        setUvDerivatives(scene.primitives, ray.direction, hit, differential, s);
    applyNormalMap(context, scene.materialOf(hit.prim), hit, s);
    s.shadingNormal = keepReflectionAbove(s.shadingNormal, s.geometricNormal, -ray.direction);
    return s;
}

}  // namespace rt
