#include "render/camera_rays.h"

#include "core/error.h"
#include "test_util.h"

using namespace rt;

TEST(CameraRays, CentreRayLooksAtTheDestination) {
    Camera cam;
    cam.origin = {1, 2, 3};
    cam.destination = {1, 2, 10};
    const CameraRays rays(cam, 64, 48);
    const Ray r = rays.at(32, 24);
    expectNear(r.origin, cam.origin);
    expectNear(r.direction, {0, 0, 1});
}

TEST(CameraRays, FovIsTheHorizontalAngle) {
    Camera cam;
    cam.destination = {0, 0, -1};  // looking down -z, +x is to the right
    cam.fovDegrees = 90;
    const CameraRays rays(cam, 100, 50);
    // The left and right image edges are 45 degrees off the axis.
    expectNear(rays.at(100, 25).direction, normalize(Vec3{1, 0, -1}));
    expectNear(rays.at(0, 25).direction, normalize(Vec3{-1, 0, -1}));
    // Row 0 is the top of the image.
    EXPECT_GT(rays.at(50, 0).direction.y, 0);
}

TEST(CameraRays, FocalDistanceFallsBackToTheTargetDistanceAndZoomScalesIt) {
    Camera cam;
    cam.destination = {0, 0, -50};
    EXPECT_NEAR(cam.focalPixels(kReferenceWidth), 50, kTol);
    cam.zoom = 200;
    EXPECT_NEAR(cam.focalPixels(kReferenceWidth), 100, kTol);
    cam.focalDistance = 10;
    EXPECT_NEAR(cam.focalPixels(kReferenceWidth), 20, kTol);
}

TEST(CameraRays, DegenerateCamerasAreInputErrors) {
    Camera same;
    same.destination = same.origin;
    EXPECT_THROW(CameraRays(same, 10, 10), InputError);
    Camera parallel;
    parallel.destination = {0, 5, 0};
    EXPECT_THROW(CameraRays(parallel, 10, 10), InputError);
}

// Ray differentials (render/ray_differential.h): one pixel's footprint on a plane seen head-on at
// distance 10 is 10 / f across; tilted by 60 degrees it stretches by 1 / cos 60 along the tilt; a
// cone after a bounce grows by its spread per unit distance.
TEST(CameraRays, OnePixelsFootprintOnAPlane) {
    Camera cam;
    cam.destination = {0, 0, -1};
    cam.fovDegrees = 90;  // f = 50 pixels for a 100-pixel width
    const CameraRays rays(cam, 100, 100);
    const Ray centre = rays.at(50, 50);
    const RayDifferential d = rays.differentialAt(50, 50, centre, 1);
    Vec3 dpdx, dpdy;
    d.footprintAt(centre.direction, 10, {0, 0, 1}, dpdx, dpdy);
    EXPECT_NEAR(dpdx.x, 10.0 / 50, 1e-3);
    EXPECT_NEAR(dpdy.y, -10.0 / 50, 1e-3);  // row y + 1 is lower
    const Vec3 tilted{0, std::sin(kPi / 3), std::cos(kPi / 3)};
    d.footprintAt(centre.direction, 10, tilted, dpdx, dpdy);
    EXPECT_NEAR(length(dpdy), 10.0 / 50 / std::cos(kPi / 3), 1e-3);
    EXPECT_NEAR(length(dpdx), 10.0 / 50, 1e-3);
    const RayDifferential cone = RayDifferential::cone({0, 0, -1}, 0.5, 0.01);
    EXPECT_NEAR(cone.radiusAt(100), 1.5, 1e-5);
}
