// scene/camera: the reference width of focal distances in pixels, the command line's
// overrides, --frame and the turntable orbit.
#include "scene/camera.h"

#include <cmath>

#include "core/error.h"
#include "render/camera_rays.h"
#include "scene/scene.h"
#include "test_util.h"

using namespace rt;

namespace {

Camera focalCamera(std::optional<Real> f) {
    Camera c;
    c.origin = {0, 0, -10};
    c.destination = {0, 0, 0};
    c.focalDistance = f;
    return c;
}

// Where p lands in an image w x h pixels seen by the camera (x right, y down), or NaN behind it.
void project(const Camera& c, int w, int h, const Vec3& p, Real& x, Real& y) {
    const Vec3 forward = normalize(c.destination - c.origin);
    const Vec3 right = normalize(cross(forward, c.up));
    const Vec3 up = cross(right, forward);
    const Vec3 d = p - c.origin;
    const Real depth = dot(d, forward);
    const Real f = c.focalPixels(w);
    x = depth > 0 ? Real(w) / 2 + f * dot(d, right) / depth : Real(NAN);
    y = depth > 0 ? Real(h) / 2 - f * dot(d, up) / depth : Real(NAN);
}

}  // namespace

TEST(Camera, FocalPixelsMeanPixelsAtTheReferenceWidth) {
    for (const std::optional<Real> f : {std::optional<Real>(700), std::optional<Real>()}) {
        const Camera c = focalCamera(f);
        const Real atReference = f.value_or(10);  // without f: the origin-destination distance
        EXPECT_EQ(c.focalPixels(kReferenceWidth), atReference) << "the thesis's own size must not change a bit";
        EXPECT_NEAR(c.focalPixels(kReferenceWidth / 2), atReference / 2, kTol);
        EXPECT_NEAR(c.focalPixels(kReferenceWidth * 3), atReference * 3, kTol * 10);
    }
}

TEST(Camera, EveryKindOfCameraKeepsItsFramingAtAnyWidth) {
    Camera fov = focalCamera(std::nullopt);
    fov.fovDegrees = 40;
    for (const Camera& c : {focalCamera(700), focalCamera(std::nullopt), fov}) {
        // The ray through the right edge of the picture points the same way at 200 and 1000 pixels.
        const Vec3 small = CameraRays(c, 200, 150).at(200, 75).direction;
        const Vec3 large = CameraRays(c, 1000, 750).at(1000, 375).direction;
        expectNear(small, large);
        EXPECT_NEAR(std::abs(std::atan2(small.x, small.z)) * 2 * 180 / kPi, c.horizontalFovDegrees(), 1e-3);
    }
}

TEST(Camera, OverridesReplaceThePartsGiven) {
    Camera c = focalCamera(700);
    c.zoom = 90;
    CameraOverrides o;
    o.lookFrom = Vec3(1, 2, 3);
    o.up = Vec3(0, 0, 1);
    o.fovDegrees = 35;
    applyOverrides(c, o, Aabb(), 4.0 / 3.0);
    EXPECT_EQ(c.origin, Vec3(1, 2, 3));
    EXPECT_EQ(c.destination, Vec3(0, 0, 0));
    EXPECT_EQ(c.up, Vec3(0, 0, 1));
    EXPECT_EQ(c.fovDegrees, Real(35));
    EXPECT_FALSE(c.focalDistance);
    EXPECT_EQ(c.zoom, 100);
    o.fovDegrees = 180;
    EXPECT_THROW(applyOverrides(c, o, Aabb(), 1), InputError);
}

TEST(Camera, MovingACameraWithoutFovOrFKeepsItsLens) {
    Camera c = focalCamera(std::nullopt);  // f = the distance: 10 pixels at 800 wide
    const Real before = c.horizontalFovDegrees();
    CameraOverrides o;
    o.lookFrom = Vec3(0, 0, -50);
    applyOverrides(c, o, Aabb(), 1);
    EXPECT_NEAR(c.horizontalFovDegrees(), before, 1e-9 * 180);
}

TEST(Camera, FramePutsTheBoundsInsideThePictureWithAMargin) {
    const Aabb box{{-3, 10, 4}, {5, 11, 6}};  // off-centre and flat
    for (const Real aspect : {Real(2), Real(0.5)}) {
        Camera c = focalCamera(std::nullopt);
        c.fovDegrees = 50;
        const Vec3 direction = normalize(c.destination - c.origin);
        frameBounds(c, box, aspect);
        expectNear(normalize(c.destination - c.origin), direction);  // seen from the same side
        expectNear(c.destination, box.center());
        const int w = 400, h = int(400 / aspect);
        Real largest = 0;
        for (int corner = 0; corner < 8; ++corner) {
            const Vec3 p((corner & 1) ? box.hi.x : box.lo.x, (corner & 2) ? box.hi.y : box.lo.y,
                         (corner & 4) ? box.hi.z : box.lo.z);
            Real x, y;
            project(c, w, h, p, x, y);
            EXPECT_GT(x, 0.02 * w) << corner;
            EXPECT_LT(x, 0.98 * w) << corner;
            EXPECT_GT(y, 0.02 * h) << corner;
            EXPECT_LT(y, 0.98 * h) << corner;
            largest = std::max({largest, std::abs(x - w / 2), std::abs(y - h / 2)});
        }
        EXPECT_GT(largest / (std::min(w, h) / 2), 0.7) << "the bounds should fill the picture, not sit small in it";
    }
    Camera c = focalCamera(std::nullopt);
    EXPECT_THROW(frameBounds(c, Aabb(), 1), InputError);
}

TEST(Camera, OrbitTurnsAboutTheUpAxisThroughTheDestination) {
    Camera c = focalCamera(std::nullopt);
    c.origin = {Real(0.3), 2, Real(-7.1)};
    c.destination = {Real(0.5), 1, Real(0.25)};
    const Camera same = orbited(c, 0);
    EXPECT_EQ(same.origin, c.origin) << "frame 0 is the plain render, bit for bit";
    const Camera quarter = orbited(c, 90);
    EXPECT_NEAR(length(quarter.origin - c.destination), length(c.origin - c.destination), kTol * 10);
    EXPECT_NEAR(quarter.origin.y, c.origin.y, kTol * 10);  // about +y: the height stays
    // Counter-clockwise seen from above (+y): -z turns to -x.
    EXPECT_NEAR(quarter.origin.x - c.destination.x, c.origin.z - c.destination.z, kTol * 10);
    expectNear(orbited(c, 360).origin, c.origin, kTol * 100);
    EXPECT_EQ(quarter.destination, c.destination);
    EXPECT_EQ(quarter.up, c.up);
}

TEST(Camera, SceneSelectsACameraByNameThenNumber) {
    Scene s;
    s.camera.name = "main";
    Camera numberLike = focalCamera(5);
    numberLike.name = "0";  // a name that looks like a number wins over the number
    s.extraCameras.push_back(numberLike);
    s.extraCameras.push_back(focalCamera(6));
    s.selectCamera("0");
    EXPECT_EQ(s.camera.focalDistance, Real(5));
    Scene t = s;
    t.selectCamera("2");
    EXPECT_EQ(t.camera.focalDistance, Real(6));
    try {
        s.selectCamera("side");
        FAIL() << "no camera is named side";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("0 \"0\", 1 \"main\", 2"), std::string::npos) << e.what();
    }
}
