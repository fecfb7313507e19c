// A point or direction in 3-D space, in the configured Real type.
#pragma once

#include <algorithm>
#include <cmath>
#include <ostream>

#include "core/real.h"

namespace rt {

struct Vec3 {
    Real x = 0, y = 0, z = 0;

    constexpr Vec3() = default;
    constexpr Vec3(Real x_, Real y_, Real z_) : x(x_), y(y_), z(z_) {}

    constexpr Real operator[](int axis) const { return axis == 0 ? x : (axis == 1 ? y : z); }
    constexpr Real& operator[](int axis) { return axis == 0 ? x : (axis == 1 ? y : z); }

    constexpr Vec3 operator-() const { return {-x, -y, -z}; }
    constexpr Vec3& operator+=(const Vec3& b) {
        x += b.x;
        y += b.y;
        z += b.z;
        return *this;
    }
    constexpr Vec3& operator-=(const Vec3& b) {
        x -= b.x;
        y -= b.y;
        z -= b.z;
        return *this;
    }
    constexpr Vec3& operator*=(Real s) {
        x *= s;
        y *= s;
        z *= s;
        return *this;
    }
    constexpr bool operator==(const Vec3&) const = default;
};

constexpr Vec3 operator+(const Vec3& a, const Vec3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
constexpr Vec3 operator-(const Vec3& a, const Vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
constexpr Vec3 operator*(const Vec3& a, Real s) { return {a.x * s, a.y * s, a.z * s}; }
constexpr Vec3 operator*(Real s, const Vec3& a) { return a * s; }
constexpr Vec3 operator/(const Vec3& a, Real s) { return a * (Real(1) / s); }
// Component-wise product, used for scale factors.
constexpr Vec3 mul(const Vec3& a, const Vec3& b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }

constexpr Real dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
constexpr Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline Real length(const Vec3& a) { return std::sqrt(dot(a, a)); }
inline Vec3 normalize(const Vec3& a) { return a / length(a); }

inline Vec3 min(const Vec3& a, const Vec3& b) { return {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)}; }
inline Vec3 max(const Vec3& a, const Vec3& b) { return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)}; }
// Unit length to within the rounding that normalising and mirroring leave: what the sphere test
// and the Phong model require of their directions (checked by assert in debug builds).
inline bool isUnitLength(const Vec3& a) {
    constexpr Real tolerance = sizeof(Real) == sizeof(float) ? Real(1e-4) : Real(1e-9);
    return std::abs(dot(a, a) - 1) <= tolerance;
}
inline bool isFinite(const Vec3& a) { return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z); }

inline std::ostream& operator<<(std::ostream& os, const Vec3& a) {
    return os << '(' << a.x << ", " << a.y << ", " << a.z << ')';
}

}  // namespace rt
