#include "core/transform.h"

#include <algorithm>
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
    for (int i = 0; i < 3; ++i) r[i][3] = -(r[i][0] * m[0][3] + r[i][1] * m[1][3] + r[i][2] * m[2][3]);
    // A tiny determinant (a scale by 1e-104 in double) is not zero, yet its inverse overflows.
    for (const auto& row : r)
        for (const Real x : row)
            if (!std::isfinite(x)) throw std::invalid_argument("transform matrix is singular");
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

// The largest eigenvalue of a symmetric 3x3 matrix in closed form (Smith 1961, "Eigenvalues of a
// symmetric 3x3 matrix"): the eigenvalues are q + 2p cos(phi + 2 pi k / 3), where q is the mean of
// the diagonal, p the spread about it and phi a third of the angle whose cosine is det(S - qI)/(2p^3).
Real largestSymmetricEigenvalue(const Real (&s)[3][3]) {
    const Real offDiagonal = s[0][1] * s[0][1] + s[0][2] * s[0][2] + s[1][2] * s[1][2];
    if (offDiagonal == 0) return std::max({s[0][0], s[1][1], s[2][2]});  // already diagonal
    const Real q = (s[0][0] + s[1][1] + s[2][2]) / 3;
    const Real a = s[0][0] - q, b = s[1][1] - q, c = s[2][2] - q;
    const Real p = std::sqrt((a * a + b * b + c * c + 2 * offDiagonal) / 6);
    // S is qI to within rounding (a rotation in float): p^3 underflows, and q + 2p bounds every eigenvalue.
    if (!(p * p * p > 0)) return q + 2 * p;
    // det(S - qI) / (2 p^3), clamped: rounding can push it just outside [-1, 1].
    const Real det = a * (b * c - s[1][2] * s[1][2]) - s[0][1] * (s[0][1] * c - s[1][2] * s[0][2]) +
                     s[0][2] * (s[0][1] * s[1][2] - b * s[0][2]);
    const Real r = std::clamp(det / (2 * p * p * p), Real(-1), Real(1));
    return q + 2 * p * std::cos(std::acos(r) / 3);
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

Transform operator*(const Transform& a, const Transform& b) { return {multiply(a.m_, b.m_), multiply(b.inv_, a.inv_)}; }

Vec3 Transform::point(const Vec3& p) const {
    return {m_[0][0] * p.x + m_[0][1] * p.y + m_[0][2] * p.z + m_[0][3],
            m_[1][0] * p.x + m_[1][1] * p.y + m_[1][2] * p.z + m_[1][3],
            m_[2][0] * p.x + m_[2][1] * p.y + m_[2][2] * p.z + m_[2][3]};
}

Vec3 Transform::vector(const Vec3& v) const {
    return {m_[0][0] * v.x + m_[0][1] * v.y + m_[0][2] * v.z, m_[1][0] * v.x + m_[1][1] * v.y + m_[1][2] * v.z,
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

// The largest singular value of the linear part A: the square root of the largest eigenvalue
// of the symmetric matrix A^T A. Lengths of the axis images alone are not enough: rotating by
// 45 degrees and then scaling x by 2 stretches no axis by more than 1.58, but the diagonal by 2.
Real Transform::maxScale() const {
    Real s[3][3];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) s[i][j] = m_[0][i] * m_[0][j] + m_[1][i] * m_[1][j] + m_[2][i] * m_[2][j];
    return std::sqrt(largestSymmetricEigenvalue(s));
}

}  // namespace rt
