#include "core/transform.h"

#include "test_util.h"

using namespace rt;

TEST(Transform, TranslateMovesPointsNotVectors) {
    const Transform t = Transform::translate({1, 2, 3});
    expectNear(t.point({1, 1, 1}), {2, 3, 4});
    expectNear(t.vector({1, 1, 1}), {1, 1, 1});
}

TEST(Transform, ScaleByAxis) {
    const Transform s = Transform::scale({2, 3, -1});
    expectNear(s.point({1, 1, 1}), {2, 3, -1});
    EXPECT_NEAR(s.maxScale(), 3, kTol);
}

TEST(Transform, ZeroScaleIsRejected) { EXPECT_THROW(Transform::scale({1, 0, 1}), std::invalid_argument); }

TEST(Transform, RotationsAreRightHanded) {
    const Real quarter = kPi / 2;
    // Right-handed: a quarter turn about X takes Y to Z, about Y takes Z to X, about Z takes X to Y.
    expectNear(Transform::rotateX(quarter).point({0, 1, 0}), {0, 0, 1});
    expectNear(Transform::rotateY(quarter).point({0, 0, 1}), {1, 0, 0});
    expectNear(Transform::rotateZ(quarter).point({1, 0, 0}), {0, 1, 0});
}

TEST(Transform, RotationMatricesMatchTheThesis) {
    // Thesis 2.2.3 prints R_x with -sin in row 2 and R_z with -sin in row 1.
    const Real a = Real(0.3);
    const auto rx = Transform::rotateX(a).matrix();
    EXPECT_NEAR(rx[1][2], -std::sin(a), kTol);
    EXPECT_NEAR(rx[2][1], std::sin(a), kTol);
    const auto rz = Transform::rotateZ(a).matrix();
    EXPECT_NEAR(rz[0][1], -std::sin(a), kTol);
    EXPECT_NEAR(rz[1][0], std::sin(a), kTol);
    // R_y in its right-handed form: +sin in row 1, column 3.
    const auto ry = Transform::rotateY(a).matrix();
    EXPECT_NEAR(ry[0][2], std::sin(a), kTol);
    EXPECT_NEAR(ry[2][0], -std::sin(a), kTol);
}

TEST(Transform, CompositionAppliesRightOperandFirst) {
    // x' = T * (S * x): scale first, then translate (thesis 2.2).
    const Transform m = Transform::translate({10, 0, 0}) * Transform::scale({2, 2, 2});
    expectNear(m.point({1, 1, 1}), {12, 2, 2});
    const Transform n = Transform::scale({2, 2, 2}) * Transform::translate({10, 0, 0});
    expectNear(n.point({1, 1, 1}), {22, 2, 2});
}

TEST(Transform, InverseUndoes) {
    const Transform m = Transform::translate({1, -2, 3}) * Transform::rotateY(Real(0.7)) *
                        Transform::scale({2, Real(0.5), 3}) * Transform::rotateX(Real(-1.1));
    const Vec3 p{Real(0.3), Real(-4), Real(2.5)};
    expectNear(m.inverse().point(m.point(p)), p);
    expectNear((m * m.inverse()).point(p), p);
}

TEST(Transform, NormalsStayPerpendicularUnderNonUniformScale) {
    // The plane x + y = 0 has normal (1, 1, 0). Squashing y by 4 tilts the plane;
    // transforming the normal like a vector would leave it tilted the wrong way.
    const Transform s = Transform::rotateZ(Real(0.2)) * Transform::scale({1, Real(0.25), 1});
    const Vec3 n{1, 1, 0};
    const Vec3 inPlane1 = s.vector({1, -1, 0});
    const Vec3 inPlane2 = s.vector({0, 0, 1});
    const Vec3 tn = s.normal(n);
    EXPECT_NEAR(dot(tn, inPlane1), 0, kTol);
    EXPECT_NEAR(dot(tn, inPlane2), 0, kTol);
    EXPECT_GT(std::abs(dot(normalize(s.vector(n)), normalize(inPlane1))), Real(0.1));
}

TEST(Transform, GeneralMatrixMustBeAffineAndInvertible) {
    Transform::Matrix m{};
    m[0][0] = m[1][1] = m[2][2] = 1;
    EXPECT_THROW(Transform{m}, std::invalid_argument);  // last row is zero
    m[3][3] = 1;
    EXPECT_NO_THROW(Transform{m});
    m[1][1] = 0;
    EXPECT_THROW(Transform{m}, std::invalid_argument);
}
