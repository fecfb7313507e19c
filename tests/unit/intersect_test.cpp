// Ray-sphere (thesis 2.1.2) and ray-triangle (Moller-Trumbore) against hand-computed hits.
#include "geometry/primitives.h"

#include <limits>

#include "test_util.h"

using namespace rt;

namespace {
const Sphere kUnitSphere{{0, 0, 0}, 1};
const Triangle kTriangle{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};  // in the plane z = 0, normal +z
}  // namespace

TEST(Sphere, HitFromOutside) {
    Real t = 0;
    ASSERT_TRUE(intersectSphere(kUnitSphere, {{0, 0, -5}, {0, 0, 1}}, kInfinity, t));
    EXPECT_NEAR(t, 4, kTol);
    const Vec3 p = Ray{{0, 0, -5}, {0, 0, 1}}.at(t);
    expectNear(kUnitSphere.normal(p), {0, 0, -1});
}

TEST(Sphere, NormalsAreUnitOnSmallSpheresFarFromTheOrigin) {
    // A computed hit point lies off the surface by the rounding of its coordinates, which far
    // from the origin is large beside a radius of 0.006 (the balls scene's smallest): dividing
    // by the radius instead of normalising gave normals up to 2.4 long after a few bounces.
    const Real unitRounding = 8 * std::numeric_limits<Real>::epsilon();
    for (const Vec3 centre : {Vec3{40, -25, 60}, Vec3{Real(1.3), Real(0.7), Real(-0.4)}, Vec3{-300, 150, 20}}) {
        const Sphere s{centre, Real(0.006)};
        for (int i = 0; i < 200; ++i) {
            // Rays from 0.05 away towards points spread over the sphere, aimed at 0.9 of its radius.
            const Real a = Real(0.1) * Real(i), b = Real(0.37) * Real(i);
            const Vec3 from = centre + Vec3{std::cos(a) * std::sin(b), std::sin(a) * std::sin(b), std::cos(b)} * Real(0.05);
            const Vec3 aim = centre + Vec3{std::sin(b), std::cos(a), std::sin(a)} * Real(0.9 * 0.006 / std::sqrt(2.0));
            const Ray ray{from, normalize(aim - from)};
            Real t = 0;
            ASSERT_TRUE(intersectSphere(s, ray, kInfinity, t)) << centre << " ray " << i;
            const Vec3 n = s.normal(ray.at(t));
            EXPECT_NEAR(length(n), 1, unitRounding) << centre << " ray " << i;
            EXPECT_GT(dot(n, -ray.direction), 0) << centre << " ray " << i;  // faces the ray that came from outside
        }
    }
}

TEST(Sphere, OffCentreHit) {
    // Ray along z at x = 0.6: enters at z = -0.8.
    Real t = 0;
    ASSERT_TRUE(intersectSphere(kUnitSphere, {{Real(0.6), 0, -5}, {0, 0, 1}}, kInfinity, t));
    EXPECT_NEAR(t, Real(4.2), kTol);
}

TEST(Sphere, MissBesideAndBehind) {
    Real t = 0;
    EXPECT_FALSE(intersectSphere(kUnitSphere, {{Real(1.01), 0, -5}, {0, 0, 1}}, kInfinity, t));
    EXPECT_FALSE(intersectSphere(kUnitSphere, {{0, 0, 5}, {0, 0, 1}}, kInfinity, t));
}

TEST(Sphere, GrazingRayTouchesTheSilhouette) {
    Real t = 0;
    ASSERT_TRUE(intersectSphere(kUnitSphere, {{1, 0, -5}, {0, 0, 1}}, kInfinity, t));
    EXPECT_NEAR(t, 5, Real(1e-3));
}

TEST(Sphere, FromInsideHitsTheFarSide) {
    Real t = 0;
    ASSERT_TRUE(intersectSphere(kUnitSphere, {{0, 0, Real(0.5)}, {0, 0, 1}}, kInfinity, t));
    EXPECT_NEAR(t, Real(0.5), kTol);
    ASSERT_TRUE(intersectSphere(kUnitSphere, {{0, 0, Real(0.5)}, {0, 0, -1}}, kInfinity, t));
    EXPECT_NEAR(t, Real(1.5), kTol);
}

TEST(Sphere, RespectsTMax) {
    Real t = 0;
    EXPECT_FALSE(intersectSphere(kUnitSphere, {{0, 0, -5}, {0, 0, 1}}, 3, t));
}

TEST(Sphere, BoundsAndDegenerate) {
    EXPECT_EQ(kUnitSphere.bounds(), (Aabb{{-1, -1, -1}, {1, 1, 1}}));
    EXPECT_TRUE((Sphere{{0, 0, 0}, 0}).degenerate());
    EXPECT_TRUE((Sphere{{0, 0, 0}, -1}).degenerate());
    EXPECT_FALSE(kUnitSphere.degenerate());
}

TEST(Triangle, HitInsideWithBarycentrics) {
    Real t = 0, u = 0, v = 0;
    ASSERT_TRUE(intersectTriangle(kTriangle, {{Real(0.25), Real(0.5), 2}, {0, 0, -1}}, kInfinity, t, u, v));
    EXPECT_NEAR(t, 2, kTol);
    EXPECT_NEAR(u, Real(0.25), kTol);
    EXPECT_NEAR(v, Real(0.5), kTol);
    expectNear(kTriangle.normal(), {0, 0, 1});
}

TEST(Triangle, HitFromBehind) {
    Real t = 0, u = 0, v = 0;
    ASSERT_TRUE(intersectTriangle(kTriangle, {{Real(0.2), Real(0.2), -3}, {0, 0, 1}}, kInfinity, t, u, v));
    EXPECT_NEAR(t, 3, kTol);
}

TEST(Triangle, MissOutsideTheEdges) {
    Real t = 0, u = 0, v = 0;
    EXPECT_FALSE(intersectTriangle(kTriangle, {{Real(0.6), Real(0.6), 2}, {0, 0, -1}}, kInfinity, t, u, v));
    EXPECT_FALSE(intersectTriangle(kTriangle, {{-Real(0.1), Real(0.5), 2}, {0, 0, -1}}, kInfinity, t, u, v));
}

TEST(Triangle, RayParallelToThePlaneMisses) {
    Real t = 0, u = 0, v = 0;
    EXPECT_FALSE(intersectTriangle(kTriangle, {{-1, Real(0.2), 0}, {1, 0, 0}}, kInfinity, t, u, v));
    EXPECT_FALSE(intersectTriangle(kTriangle, {{-1, Real(0.2), 1}, {1, 0, 0}}, kInfinity, t, u, v));
}

TEST(Triangle, BehindTheOriginMisses) {
    Real t = 0, u = 0, v = 0;
    EXPECT_FALSE(intersectTriangle(kTriangle, {{Real(0.2), Real(0.2), 1}, {0, 0, 1}}, kInfinity, t, u, v));
}

TEST(Triangle, SharedEdgeIsHitByBothNeighbours) {
    const Triangle other{{1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    const Ray ray{{Real(0.5), Real(0.5), 1}, {0, 0, -1}};  // exactly on the shared diagonal
    Real t = 0, u = 0, v = 0;
    EXPECT_TRUE(intersectTriangle(kTriangle, ray, kInfinity, t, u, v));
    EXPECT_TRUE(intersectTriangle(other, ray, kInfinity, t, u, v));
}

TEST(Triangle, DegenerateTriangles) {
    EXPECT_TRUE((Triangle{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}}).degenerate());  // collinear
    EXPECT_TRUE((Triangle{{0, 0, 0}, {0, 0, 0}, {0, 1, 0}}).degenerate());
    EXPECT_TRUE((Triangle{{0, 0, 0}, {1, 0, 0}, {0, kInfinity, 0}}).degenerate());
    EXPECT_FALSE(kTriangle.degenerate());
}

TEST(Primitives, IdsRunOverTrianglesThenSpheres) {
    Primitives prims;
    prims.add<Sphere>(kUnitSphere, 7);
    prims.add<Triangle>(kTriangle, 3);
    ASSERT_EQ(prims.size(), 2u);
    EXPECT_EQ(prims.visit(0, [](const auto& p) { return std::string(p.kName); }), "triangle");
    EXPECT_EQ(prims.visit(1, [](const auto& p) { return std::string(p.kName); }), "sphere");
    EXPECT_EQ(prims.material(0), 3u);
    EXPECT_EQ(prims.material(1), 7u);
    EXPECT_EQ(prims.bounds(), (Aabb{{-1, -1, -1}, {1, 1, 1}}));
}

TEST(Primitives, StoreUnderHundredBytesPerTriangle) {
    Primitives prims;
    prims.reserve<Triangle>(1000);
    for (int i = 0; i < 1000; ++i) prims.add<Triangle>(kTriangle, 0);
    EXPECT_LT(prims.memoryBytes() / prims.size(), 100u);
}
