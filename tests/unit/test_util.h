// Helpers shared by the unit tests.
#pragma once

#include <gtest/gtest.h>

#include "core/vec3.h"

// Tolerance that suits both the float and the double build.
constexpr rt::Real kTol = sizeof(rt::Real) == sizeof(float) ? rt::Real(1e-4) : rt::Real(1e-9);

inline void expectNear(const rt::Vec3& a, const rt::Vec3& b, rt::Real tol = kTol) {
    EXPECT_NEAR(a.x, b.x, tol) << a << " vs " << b;
    EXPECT_NEAR(a.y, b.y, tol) << a << " vs " << b;
    EXPECT_NEAR(a.z, b.z, tol) << a << " vs " << b;
}
