#include "core/transform.h"

#include <cmath>
#include <stdexcept>

namespace rt {
namespace {

using Matrix = Transform::Matrix;

Matrix identityMatrix() {
    Matrix m{};
    for (int i = 0; i < 4; ++i) m[i][i] = 1;
    return m;
}

Matrix multiply(const Matrix& a, const Matrix& b) {
    Matrix r{};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            for (int k = 0; k < 4; ++k) r[i][j] += a[i][k] * b[k][j];
    return r;
}

// Inverse of an affine matrix: invert the 3x3 linear part by cofactors, then the translation.
Matrix invertAffine(const Matrix& m) {
    const Real c00 = m[1][1] * m[2][2] - m[1][2] * m[2][1];
    const Real c01 = m[1][2] * m[2][0] - m[1][0] * m[2][2];
    const Real c02 = m[1][0] * m[2][1] - m[1][1] * m[2][0];
    const Real det = m[0][0] * c00 + m[0][1] * c01 + m[0][2] * c02;
    if (det == 0 || !std::isfinite(det)) throw std::invalid_argument("transform matrix is singular");
    const Real s = 1 / det;
    Matrix r = identityMatrix();
    r[0][0] = c00 * s;
    r[0][1] = (m[0][2] * m[2][1] - m[0][1] * m[2][2]) * s;
    r[0][2] = (m[0][1] * m[1][2] - m[0][2] * m[1][1]) * s;
    r[1][0] = c01 * s;
    r[1][1] = (m[0][0] * m[2][2] - m[0][2] * m[2][0]) * s;
    r[1][2] = (m[0][2] * m[1][0] - m[0][0] * m[1][2]) * s;
    r[2][0] = c02 * s;
    r[2][1] = (m[0][1] * m[2][0] - m[0][0] * m[2][1]) * s;
    r[2][2] = (m[0][0] * m[1][1] - m[0][1] * m[1][0]) * s;
    for (int i = 0; i < 3; ++i)
        r[i][3] = -(r[i][0] * m[0][3] + r[i][1] * m[1][3] + r[i][2] * m[2][3]);
    return r;
}

Matrix rotation(int axis, Real radians) {
    const Real c = std::cos(radians), s = std::sin(radians);
    const int i = (axis + 1) % 3, j = (axis + 2) % 3;  // the plane the rotation acts in
    Matrix m = identityMatrix();
    m[i][i] = c;
    m[i][j] = -s;
    m[j][i] = s;
    m[j][j] = c;
    return m;
}

}  // namespace

Transform::Transform() : m_(identityMatrix()), inv_(identityMatrix()) {}

Transform::Transform(const Matrix& m) : m_(m), inv_(invertAffine(m)) {
    if (m[3][0] != 0 || m[3][1] != 0 || m[3][2] != 0 || m[3][3] != 1)
        throw std::invalid_argument("transform matrix is not affine (last row must be 0 0 0 1)");
}

Transform Transform::translate(const Vec3& t) {
    Matrix m = identityMatrix(), inv = identityMatrix();
    for (int i = 0; i < 3; ++i) {
        m[i][3] = t[i];
        inv[i][3] = -t[i];
    }
    return {m, inv};
}

Transform Transform::scale(const Vec3& s) {
    Matrix m = identityMatrix();
    for (int i = 0; i < 3; ++i) m[i][i] = s[i];
    return Transform(m);  // throws for a zero factor
}

// rotation(axis) builds R_x for axis 0 and R_z for axis 2 exactly as printed in the thesis;
// for axis 1 the cyclic order (z, x) gives the right-handed R_y.
Transform Transform::rotateX(Real radians) { return {rotation(0, radians), rotation(0, -radians)}; }
Transform Transform::rotateY(Real radians) { return {rotation(1, radians), rotation(1, -radians)}; }
Transform Transform::rotateZ(Real radians) { return {rotation(2, radians), rotation(2, -radians)}; }

Transform operator*(const Transform& a, const Transform& b) {
    return {multiply(a.m_, b.m_), multiply(b.inv_, a.inv_)};
}

Vec3 Transform::point(const Vec3& p) const {
    return {m_[0][0] * p.x + m_[0][1] * p.y + m_[0][2] * p.z + m_[0][3],
            m_[1][0] * p.x + m_[1][1] * p.y + m_[1][2] * p.z + m_[1][3],
            m_[2][0] * p.x + m_[2][1] * p.y + m_[2][2] * p.z + m_[2][3]};
}

Vec3 Transform::vector(const Vec3& v) const {
    return {m_[0][0] * v.x + m_[0][1] * v.y + m_[0][2] * v.z,
            m_[1][0] * v.x + m_[1][1] * v.y + m_[1][2] * v.z,
            m_[2][0] * v.x + m_[2][1] * v.y + m_[2][2] * v.z};
}

Vec3 Transform::normal(const Vec3& n) const {
    // Multiply by the transpose of the inverse.
    return {inv_[0][0] * n.x + inv_[1][0] * n.y + inv_[2][0] * n.z,
            inv_[0][1] * n.x + inv_[1][1] * n.y + inv_[2][1] * n.z,
            inv_[0][2] * n.x + inv_[1][2] * n.y + inv_[2][2] * n.z};
}

Transform Transform::inverse() const { return {inv_, m_}; }

bool Transform::isIdentity() const { return m_ == identityMatrix(); }

Real Transform::maxScale() const {
    Real best = 0;
    for (int axis = 0; axis < 3; ++axis) {
        Vec3 e;
        e[axis] = 1;
        best = std::max(best, length(vector(e)));
    }
    return best;
}

}  // namespace rt
