// Helpers shared by the unit tests.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <type_traits>
#include <vector>

#include "accel/accelerator.h"
#include "core/vec3.h"

// Tolerance that suits both the float and the double build.
constexpr rt::Real kTol = sizeof(rt::Real) == sizeof(float) ? rt::Real(1e-4) : rt::Real(1e-9);

inline void expectNear(const rt::Vec3& a, const rt::Vec3& b, rt::Real tol = kTol) {
    EXPECT_NEAR(a.x, b.x, tol) << a << " vs " << b;
    EXPECT_NEAR(a.y, b.y, tol) << a << " vs " << b;
    EXPECT_NEAR(a.z, b.z, tol) << a << " vs " << b;
}

// The same bits, not only equal values: a NaN equals nothing and -0 equals 0, but a render that
// must not depend on the thread count or region split has to give the very same bits.
template <class T>
requires std::is_trivially_copyable_v<T>
bool sameBits(const T& a, const T& b) { return std::memcmp(&a, &b, sizeof(T)) == 0; }

template <class T>
requires std::is_trivially_copyable_v<T>
bool sameBits(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

// Every node of a tree or BVH, in the order forEachNode visits them.
inline std::vector<rt::TreeNodeInfo> nodesOf(const rt::Accelerator& accel) {
    std::vector<rt::TreeNodeInfo> nodes;
    accel.forEachNode([&](const rt::TreeNodeInfo& n) { nodes.push_back(n); });
    return nodes;
}

namespace rt::test {

// The shared test models are not part of the repository: RT_SHARED_DIR (set when CMake
// configures, by default shared/ beside the checkout) may not hold them.
inline bool sharedModelsPresent() { return std::filesystem::is_directory(RT_SHARED_DIR "/models"); }

// RT_REQUIRE_SHARED_MODELS=1 (CI, where the models are present) turns the skip into a failure,
// so that a wrong path cannot quietly skip half of the suite.
inline bool sharedModelsRequired() {
    const char* required = std::getenv("RT_REQUIRE_SHARED_MODELS");
    return required && std::string(required) == "1";
}

inline std::string sharedModelsMissing() {
    return "needs the shared test models, not found in " RT_SHARED_DIR
           "/models: configure with -DRT_SHARED_DIR=/path/to/shared or put shared/ beside the checkout";
}

}  // namespace rt::test

// First statement of a test that reads RT_SHARED_DIR/models: skips the test when they are absent.
#define SKIP_WITHOUT_SHARED_MODELS()                                                         \
    do {                                                                                     \
        if (!rt::test::sharedModelsPresent()) {                                              \
            if (rt::test::sharedModelsRequired()) FAIL() << rt::test::sharedModelsMissing(); \
            GTEST_SKIP() << rt::test::sharedModelsMissing();                                 \
        }                                                                                    \
    } while (false)
