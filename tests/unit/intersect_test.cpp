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
            const Vec3 from =
                centre + Vec3{std::cos(a) * std::sin(b), std::sin(a) * std::sin(b), std::cos(b)} * Real(0.05);
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

// A cylinder of radius 1 along z from 0 to 2, and a cone from radius 1 at z = 0 to a point at z = 2.
const Cylinder kCylinder{{{0, 0, 0}, {0, 0, 2}, 1, 1}};
const Cone kCone{{{0, 0, 0}, {0, 0, 2}, 1, 0}};

TEST(Frustum, HitsTheSideAtTheExactDistance) {
    Hit hit;
    ASSERT_TRUE(intersect(kCylinder, {{-5, 0, 1}, {1, 0, 0}}, kInfinity, hit));
    EXPECT_NEAR(hit.t, 4, 1e-5);
    EXPECT_NEAR(hit.u, 0.5, 1e-5);
    expectNear(kCylinder.normal({-1, 0, 1}), {-1, 0, 0});
    ASSERT_TRUE(intersect(kCone, {{-5, 0, 1}, {1, 0, 0}}, kInfinity, hit));  // radius 0.5 at z = 1
    EXPECT_NEAR(hit.t, 4.5, 1e-5);
    expectNear(kCone.normal({-0.5f, 0, 1}), normalize(Vec3{-1, 0, 0.5f}));
}

TEST(Frustum, HitsTheCapsAndFromInsideTheFarSide) {
    Hit hit;
    ASSERT_TRUE(intersect(kCylinder, {{0.5f, 0, -3}, {0, 0, 1}}, kInfinity, hit));  // base cap
    EXPECT_NEAR(hit.t, 3, 1e-5);
    expectNear(kCylinder.normal({0.5f, 0, 0}), {0, 0, -1});
    ASSERT_TRUE(intersect(kCylinder, {{0.5f, 0, 5}, {0, 0, -1}}, kInfinity, hit));  // top cap
    EXPECT_NEAR(hit.t, 3, 1e-5);
    expectNear(kCylinder.normal({0.5f, 0, 2}), {0, 0, 1});
    ASSERT_TRUE(intersect(kCylinder, {{0, 0, 1}, {1, 0, 0}}, kInfinity, hit));  // from inside
    EXPECT_NEAR(hit.t, 1, 1e-5);
    ASSERT_TRUE(intersect(kCone, {{0.25f, 0, -1}, {0, 0, 1}}, kInfinity, hit));  // base cap of the cone
    EXPECT_NEAR(hit.t, 1, 1e-5);
}

TEST(Frustum, MissesBesideBeyondAndBehind) {
    Hit hit;
    EXPECT_FALSE(intersect(kCylinder, {{-5, 0, 2.5f}, {1, 0, 0}}, kInfinity, hit));  // above the top
    EXPECT_FALSE(intersect(kCylinder, {{-5, 1.5f, 1}, {1, 0, 0}}, kInfinity, hit));  // beside
    EXPECT_FALSE(intersect(kCylinder, {{-5, 0, 1}, {1, 0, 0}}, 3, hit));             // beyond tMax
    EXPECT_FALSE(intersect(kCylinder, {{5, 0, 1}, {1, 0, 0}}, kInfinity, hit));      // behind
    EXPECT_FALSE(intersect(kCone, {{-5, 0.75f, 1}, {1, 0, 0}}, kInfinity, hit));     // outside the narrowing side
    EXPECT_FALSE(intersectsAny(kCone, {{-5, 0.75f, 1}, {1, 0, 0}}, kInfinity));
}

TEST(Frustum, BoundsAreTightForAnyAxis) {
    const Aabb b = kCylinder.bounds();
    expectNear(b.lo, {-1, -1, 0}, Real(1e-5));
    expectNear(b.hi, {1, 1, 2}, Real(1e-5));
    // Along the diagonal every surface point lies inside the bounds, and the bounds reach no
    // further than the extreme surface points.
    const Cone tilted{{{0, 0, 0}, {1, 2, 3}, Real(0.5), Real(0.2)}};
    const Aabb t = tilted.bounds();
    Aabb reached;
    for (int i = 0; i <= 64; ++i)
        for (int j = 0; j < 256; ++j) {
            const Vec3 p = tilted.surfacePoint(Real(i) / 64, Real(j) / 256);
            EXPECT_TRUE(intersection(t, {p, p}) == (Aabb{p, p})) << p;
            reached.extend(p);
        }
    expectNear(reached.lo, t.lo, Real(1e-3));
    expectNear(reached.hi, t.hi, Real(1e-3));
}

TEST(Frustum, OverlapNeverMissesTheSurfaceAndSkipsBoxesInside) {
    const Cone tilted{{{0, 0, 0}, {1, 2, 3}, Real(0.5), Real(0.2)}};
    EXPECT_FALSE(overlaps(
        tilted, {Vec3{0.5f, 1, 1.5f} - Vec3{0.05f, 0.05f, 0.05f}, Vec3{0.5f, 1, 1.5f} + Vec3{0.05f, 0.05f, 0.05f}}));
    EXPECT_FALSE(overlaps(tilted, {{2, 2, 2}, {3, 3, 3}}));
    for (int i = 0; i <= 32; ++i)
        for (int j = 0; j < 32; ++j) {
            const Vec3 p = tilted.surfacePoint(Real(i) / 32, Real(j) / 32);
            const Aabb box{p - Vec3{0.01f, 0.02f, 0.03f}, p + Vec3{0.03f, 0.01f, 0.02f}};
            EXPECT_TRUE(overlaps(tilted, box)) << p;
            const Aabb clipped = clippedBounds(tilted, box);
            EXPECT_TRUE(intersection(clipped, {p, p}) == (Aabb{p, p})) << p;
        }
}

TEST(Frustum, DegenerateWithoutLengthOrRadius) {
    EXPECT_TRUE((Cylinder{{{0, 0, 0}, {0, 0, 0}, 1, 1}}).degenerate());
    EXPECT_TRUE((Cone{{{0, 0, 0}, {0, 0, 1}, 0, 0}}).degenerate());
    EXPECT_TRUE((Cone{{{0, 0, 0}, {0, 0, 1}, -1, 1}}).degenerate());
    EXPECT_FALSE(kCone.degenerate());
    EXPECT_NEAR(kCylinder.area(), 2 * kPi * 2 + 2 * kPi, 1e-4);
}
