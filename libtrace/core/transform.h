// Affine 4x4 transforms (thesis 2.2): translation, scale and rotation about the axes,
// composed by matrix product. Points carry w = 1, vectors w = 0, and normals use the
// inverse transpose so they stay perpendicular to surfaces under non-uniform scale.
#pragma once

#include <array>

#include "core/vec3.h"

namespace rt {

class Transform {
public:
    using Matrix = std::array<std::array<Real, 4>, 4>;

    Transform();  // identity
    // From a row-major matrix whose last row is (0, 0, 0, 1); throws std::invalid_argument if singular.
    explicit Transform(const Matrix& m);

    static Transform translate(const Vec3& t);
    static Transform scale(const Vec3& s);
    // Right-handed rotations by an angle in radians (thesis 2.2.3: R_x and R_z as printed;
    // R_y with the signs of its sines the other way round, which is the right-handed one).
    static Transform rotateX(Real radians);
    static Transform rotateY(Real radians);
    static Transform rotateZ(Real radians);

    // (a * b) applies b first, then a (thesis 2.2: x' = C * (B * (A * x))).
    friend Transform operator*(const Transform& a, const Transform& b);

    Vec3 point(const Vec3& p) const;
    Vec3 vector(const Vec3& v) const;
    Vec3 normal(const Vec3& n) const;  // not normalized

    Transform inverse() const;
    const Matrix& matrix() const { return m_; }
    bool isIdentity() const;
    // Largest factor by which the transform stretches a length, in any direction: the largest
    // singular value of its 3x3 part (for sphere radii).
    Real maxScale() const;
    bool operator==(const Transform& o) const { return m_ == o.m_; }

private:
    Transform(const Matrix& m, const Matrix& inv) : m_(m), inv_(inv) {}
    Matrix m_;
    Matrix inv_;
};

}  // namespace rt
