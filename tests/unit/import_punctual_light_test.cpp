// Lights of imported files placed as rt lights (libtrace/import/punctual_light.*): what each type
// needs is checked for that type alone.
#include <gtest/gtest.h>

#include <limits>

#include "core/error.h"
#include "io/punctual_light.h"

namespace rt {
namespace {

PunctualLight withZeroDirection(Light::Type type) {
    PunctualLight light;
    light.type = type;
    light.position = {1, 2, 3};
    light.direction = {0, 0, 0};  // Assimp's omni lights come so
    return light;
}

TEST(PunctualLight, PointLightNeedsNoDirection) {
    const Light light = placeLight(withZeroDirection(Light::Type::Point), Transform(), 1, "omni");
    EXPECT_EQ(light.type, Light::Type::Point);
    EXPECT_EQ(light.position, Vec3(1, 2, 3));
}

TEST(PunctualLight, PointLightAtTheOriginIsPlaced) {
    PunctualLight origin;
    origin.position = {0, 0, 0};
    EXPECT_EQ(placeLight(origin, Transform(), 1, "point").position, Vec3(0, 0, 0));
}

TEST(PunctualLight, SpotAndDirectionalLightsNeedADirection) {
    for (const Light::Type type : {Light::Type::Spot, Light::Type::Directional})
        EXPECT_THROW(placeLight(withZeroDirection(type), Transform(), 1, "light"), InputError);
}

TEST(PunctualLight, NonFinitePositionIsRefused) {
    PunctualLight light;
    light.position = {0, std::numeric_limits<Real>::quiet_NaN(), 0};
    EXPECT_THROW(placeLight(light, Transform(), 1, "light"), InputError);
    light.type = Light::Type::Directional;
    light.position = {0, std::numeric_limits<Real>::infinity(), 0};  // a directional light has no position
    EXPECT_EQ(placeLight(light, Transform(), 1, "sun").type, Light::Type::Directional);
}

}  // namespace
}  // namespace rt
