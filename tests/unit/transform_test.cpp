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

// Transform::maxScale is the largest singular value of the linear part; each case below
// has known singular values. Measuring only the images of the axes gave 1.58 for the first.
TEST(Transform, MaxScaleOfRotateThenScaleIsTheLargestScale) {
    const Transform m = Transform::scale({2, 1, 1}) * Transform::rotateZ(kPi / 4);  // rotate first
    EXPECT_NEAR(m.maxScale(), 2, kTol);
    // The diagonal that the rotation brought onto x is stretched by exactly that much.
    EXPECT_NEAR(length(m.vector(normalize(Vec3{1, -1, 0}))), 2, kTol);
}

TEST(Transform, MaxScaleOfScaleThenRotateIsTheLargestScale) {
    EXPECT_NEAR((Transform::rotateY(Real(0.4)) * Transform::scale({1, Real(0.5), Real(1.5)})).maxScale(), 1.5, kTol);
}

TEST(Transform, MaxScaleOfNonUniformScaleBetweenRotations) {
    // U S V^T with U, V rotations about every axis: the singular values are |S|'s diagonal.
    const Transform u = Transform::rotateX(Real(0.3)) * Transform::rotateY(Real(-1.2)) * Transform::rotateZ(Real(2.1));
    const Transform v = Transform::rotateZ(Real(0.7)) * Transform::rotateX(Real(1.9)) * Transform::rotateY(Real(0.5));
    const Transform translated = Transform::translate({5, -7, 100});
    EXPECT_NEAR((translated * u * Transform::scale({3, -2, Real(0.5)}) * v).maxScale(), 3, 4 * kTol);
    EXPECT_NEAR((u * Transform::scale({Real(0.25), Real(0.5), Real(-0.75)}) * v).maxScale(), 0.75, kTol);
    EXPECT_NEAR((u * Transform::scale({Real(1.5), Real(1.5), Real(1.5)}) * v).maxScale(), 1.5, kTol);
    EXPECT_NEAR((u * Transform::scale({2, 2, 1}) * v).maxScale(), 2, kTol);  // two equal singular values
}

TEST(Transform, MaxScaleOfAShearIsTheGoldenRatio) {
    // The shear x += y has singular values phi and 1/phi (and 1 along z).
    Transform::Matrix shear{};
    for (int i = 0; i < 4; ++i) shear[i][i] = 1;
    shear[0][1] = 1;
    EXPECT_NEAR(Transform(shear).maxScale(), (1 + std::sqrt(Real(5))) / 2, kTol);
}

TEST(Transform, MaxScaleOfQuarterTurnsIsOne) {
    // A^T A is the identity up to cos(90 degrees) rounding: in float its spread about the mean
    // is so small that its cube underflows, which once gave NaN.
    const Real quarter = kPi / 2;
    EXPECT_NEAR((Transform::rotateY(quarter) * Transform::rotateX(quarter)).maxScale(), 1, kTol);
    EXPECT_NEAR((Transform::rotateZ(quarter) * Transform::rotateY(quarter) * Transform::rotateX(quarter)).maxScale(), 1,
                kTol);
}
