#include "render/surface.h"

#include <cmath>

#include "accel/kdtree.h"
#include "render/renderer.h"
#include "render_test_scenes.h"
#include "test_util.h"

using namespace rt;

namespace {

// One triangle in the plane z = 0, facing +z, with its hit at barycentric (u, v) from +z.
struct TriangleAt {
    Primitives prims;
    Hit hit;
    Ray ray;
    TriangleAt(Real u, Real v) {
        const Triangle t{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
        prims.add<Triangle>(t, 0);
        const Vec3 p = t.p0 + (t.p1 - t.p0) * u + (t.p2 - t.p0) * v;
        ray = {p + Vec3{0, 0, 2}, {0, 0, -1}};
        hit = {2, 0, u, v};
    }
};

CornerNormals normals(const Vec3& a, const Vec3& b, const Vec3& c) {
    CornerNormals n;
    const Vec3 corners[3] = {normalize(a), normalize(b), normalize(c)};
    for (int i = 0; i < 9; ++i) n.values[i] = float(corners[i / 3][i % 3]);
    return n;
}

}  // namespace

TEST(Surface, WithoutVertexDataTheShadingNormalIsTheGeometricOne) {
    TriangleAt t(0.25, 0.25);
    const SurfacePoint s = surfaceAt(t.prims, t.ray, t.hit);
    EXPECT_EQ(s.shadingNormal, s.geometricNormal);
    EXPECT_EQ(s.geometricNormal, (Vec3{0, 0, 1}));
    EXPECT_EQ(s.shadowOrigin, s.point);
    EXPECT_EQ(s.tint, (Color{1, 1, 1}));
    // Seen from below, both face the ray.
    t.ray = {t.ray.at(2) - Vec3{0, 0, 2}, {0, 0, 1}};
    EXPECT_EQ(surfaceAt(t.prims, t.ray, t.hit).shadingNormal, (Vec3{0, 0, -1}));
}

TEST(Surface, VertexDataIsInterpolatedWithTheHitsBarycentrics) {
    TriangleAt t(0.5, 0.25);
    t.prims.triangleShading().normals.set(0, normals({1, 0, 1}, {0, 1, 1}, {0, 0, 1}));
    CornerUvs uvs;
    uvs.values = {0, 0, 1, 0, 0, 2};
    t.prims.triangleShading().uvs.set(0, uvs);
    CornerColors colors;
    colors.values = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    t.prims.triangleShading().colors.set(0, colors);
    const SurfacePoint s = surfaceAt(t.prims, t.ray, t.hit);
    const Real w = 0.25;  // the weight of p0
    const Vec3 n = normalize(Vec3{1, 0, 1}) * w + normalize(Vec3{0, 1, 1}) * Real(0.5) + Vec3{0, 0, 1} * Real(0.25);
    expectNear(s.shadingNormal, normalize(n), 1e-6);
    EXPECT_EQ(s.geometricNormal, (Vec3{0, 0, 1}));
    EXPECT_NEAR(s.u, 0.5, 1e-6);
    EXPECT_NEAR(s.v, 0.5, 1e-6);
    EXPECT_NEAR(s.tint.r, 0.25f, 1e-6);
    EXPECT_NEAR(s.tint.g, 0.5f, 1e-6);
    EXPECT_NEAR(s.tint.b, 0.25f, 1e-6);
    // From below, the shading normal turns with the geometric one.
    t.ray = {t.ray.at(2) - Vec3{0, 0, 2}, {0, 0, 1}};
    expectNear(surfaceAt(t.prims, t.ray, t.hit).shadingNormal, -normalize(n), 1e-6);
}

TEST(Surface, TrianglesWithoutDataReadTheNeutralValues) {
    TriangleAt t(0.25, 0.25);
    t.prims.add<Triangle>({{0, 0, 5}, {1, 0, 5}, {0, 1, 5}}, 0);
    t.prims.triangleShading().colors.set(1, CornerColors{});  // only the second has data
    const SurfacePoint s = surfaceAt(t.prims, t.ray, t.hit);
    EXPECT_EQ(s.tint, (Color{1, 1, 1}));
    EXPECT_EQ(s.shadingNormal, s.geometricNormal);
    EXPECT_EQ(t.prims.triangleShading().normals.find(0), nullptr);
}

TEST(Surface, ShadowOriginMovesOntoTheSmoothSurface) {
    // Normals leaning outward, as on a sphere: the flat facet lies below the smooth surface,
    // so the point moves up (+z); where the normals equal the face's, nothing moves.
    const Triangle tri{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    const Vec3 outward[3] = {normalize(Vec3{-1, -1, 2}), normalize(Vec3{1, -0.2, 2}), normalize(Vec3{-0.2, 1, 2})};
    const Vec3 p{0.3, 0.3, 0};
    const Vec3 moved = offsetToSmoothSurface(p, tri, outward, 0.3, 0.3);
    EXPECT_GT(moved.z, 0);
    const Vec3 flat[3] = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    EXPECT_EQ(offsetToSmoothSurface(p, tri, flat, 0.3, 0.3), p);
    // At a vertex it stays on the vertex: the vertex lies on its own tangent plane.
    expectNear(offsetToSmoothSurface(tri.p1, tri, outward, 1, 0), tri.p1);
}

// A unit sphere as a mesh of `rings` x `segments` quads with its exact normals.
Model sphereMesh(int rings, int segments) {
    Model m;
    const auto at = [&](int i, int j) {
        const double theta = kPi * i / rings, phi = 2 * kPi * j / segments;
        return std::array<float, 3>{float(std::sin(theta) * std::cos(phi)), float(std::cos(theta)),
                                    float(std::sin(theta) * std::sin(phi))};
    };
    const auto corner = [&](int i, int j) {
        const auto p = at(i, j);
        m.triangleVertices.insert(m.triangleVertices.end(), p.begin(), p.end());
        const Vec3 n = normalize(Vec3{p[0], p[1], p[2]});
        for (int a = 0; a < 3; ++a) m.vertexNormals.push_back(float(n[a]));
    };
    for (int i = 0; i < rings; ++i)
        for (int j = 0; j < segments; ++j) {
            if (i > 0) corner(i, j), corner(i + 1, j), corner(i, j + 1);
            if (i + 1 < rings) corner(i, j + 1), corner(i + 1, j), corner(i + 1, j + 1);
        }
    return m;
}

TEST(Surface, SmoothSphereMeshShadesLikeTheAnalyticSphere) {
    // Issue 12: a 20,000-triangle sphere with vertex normals within 2/255 of the sphere, with
    // shadows on and the light from the side, so that the terminator crosses the picture.
    const Material white{
        .name = "white", .color = {1, 1, 1}, .phong = {.ambient = 0.05f, .diffuse = 0.9f, .specular = 0.3f}};
    Scene analytic = test::sphereSeenFromMinusZ(white, 16);
    Scene mesh = analytic;
    mesh.looseObjects = Primitives();
    mesh.models.push_back(sphereMesh(100, 102));
    mesh.instances.push_back({0, 0, Transform()});
    ASSERT_GE(mesh.models[0].triangleCount(), 20000u);
    for (Scene* s : {&analytic, &mesh}) {
        s->lights.push_back({{-10, 3, -2}, {1, 1, 1}, 0});
        s->flatten();
    }
    RenderSettings settings = test::picture(96, 96);
    settings.shadows = true;
    const auto picture = [&](const Scene& s) {
        const auto accel = buildKdTree(s.primitives, KdSettings{});
        RenderStats stats;
        return render(s, *accel, settings, stats);
    };
    const Framebuffer want = picture(analytic), got = picture(mesh);
    const auto onSphere = [&](int x, int y) {  // not within a pixel of the silhouette in either picture
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx)
                for (const Framebuffer* f : {&want, &got})
                    if (f->at(x + dx, y + dy) == analytic.background) return false;
        return true;
    };
    float worst = 0;
    int compared = 0;
    for (int y = 1; y + 1 < 96; ++y)
        for (int x = 1; x + 1 < 96; ++x) {
            if (!onSphere(x, y)) continue;
            ++compared;
            const Color a = want.at(x, y), b = got.at(x, y);
            worst = std::max({worst, std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
        }
    EXPECT_GT(compared, 3000);
    EXPECT_LE(worst, 2.0f / 255) << "over " << compared << " pixels";
}

namespace {

// How far above the surface (along ng) the mirror direction of toViewer about n points.
Real reflectionHeight(const Vec3& n, const Vec3& ng, const Vec3& toViewer) {
    return dot(n * (2 * dot(n, toViewer)) - toViewer, ng);
}

Vec3 tiltedFromZ(Real degrees, Real towardsX = 1) {
    const Real a = degrees * kPi / 180;
    return {towardsX * std::sin(a), 0, std::cos(a)};
}

}  // namespace

// Issue 18 (NormalTangentMirrorTest's black rings): a shading normal tilted so far that the view
// mirrors into the surface is turned back towards the geometric normal just far enough that the
// mirror direction clears it by min(0.9 cos, 0.01), in the plane of the two normals.
TEST(Surface, AShadingNormalThatMirrorsTheViewInsideIsTurnedBackJustEnough) {
    const Vec3 ng{0, 0, 1};
    struct Case {
        Vec3 n, toViewer;
    };
    // head-on under a 60-degree slope; 80 degrees off the normal under a slope of 10 away
    // from the viewer; a normal map's texel below the surface
    for (const Case& c : {Case{tiltedFromZ(60), ng}, Case{tiltedFromZ(10), tiltedFromZ(80, -1)},
                          Case{normalize(Vec3{1, 0, -0.2}), tiltedFromZ(30)}}) {
        ASSERT_LT(reflectionHeight(c.n, ng, c.toViewer), 0) << "the case sends the reflection inside";
        const Vec3 bent = keepReflectionAbove(c.n, ng, c.toViewer);
        const Real least = std::min(Real(0.9) * dot(c.toViewer, ng), Real(0.01));
        EXPECT_NEAR(reflectionHeight(bent, ng, c.toViewer), least, 1e-5);
        EXPECT_NEAR(length(bent), 1, 1e-5);
        EXPECT_NEAR(bent.y, 0, 1e-6) << "in the plane of the two normals";
        EXPECT_GT(bent.x, 0) << "turned towards ng, not past it";
        EXPECT_GT(dot(bent, ng), dot(c.n, ng)) << "turned towards ng";
        EXPECT_GT(dot(bent, c.toViewer), 0) << "the viewer is above the turned normal";
    }
}

// Where the mirror direction already leaves the surface the shading normal stays as it is, bit
// for bit: flat surfaces (the thesis's scenes, n = ng) at any angle, and gentle slopes.
TEST(Surface, AShadingNormalThatMirrorsTheViewOutsideIsKept) {
    const Vec3 ng{0, 0, 1};
    for (const Real viewer : {0.0, 45.0, 89.0, 89.999})
        EXPECT_EQ(keepReflectionAbove(ng, ng, tiltedFromZ(viewer)), ng) << viewer << " degrees";
    for (const Vec3& n : {tiltedFromZ(30), tiltedFromZ(60), tiltedFromZ(10, -1)}) {
        ASSERT_GT(reflectionHeight(n, ng, tiltedFromZ(50)), 0.01) << "the case's reflection leaves the surface";
        EXPECT_EQ(keepReflectionAbove(n, ng, tiltedFromZ(50)), n);
    }
}
