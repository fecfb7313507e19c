// The thesis's five test scenes (libtrace/scene/thesis_scenes.*): the counts of thesis
// Table 4.1, built the same way on every call, and the shapes they are made of.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "scene/thesis_scenes.h"
#include "test_util.h"

namespace {

struct Table41Row {
    const char* name;
    std::size_t triangles, spheres, lights;
};

// Thesis Table 4.1, "Charakteristiky testovacích scén".
constexpr Table41Row kTable41[] = {
    {"balls", 2, 7381, 3},  {"balls2", 2, 597871, 3},  {"ships", 1004, 13, 2},
    {"tree", 180182, 0, 7}, {"pyramid5", 18750, 0, 1},
};

TEST(ThesisScenes, HaveTheCountsOfTable41) {
    ASSERT_EQ(rt::thesisSceneNames().size(), std::size(kTable41));
    for (const Table41Row& row : kTable41) {
        SCOPED_TRACE(row.name);
        const rt::Scene scene = rt::thesisScene(row.name);
        EXPECT_EQ(scene.primitives.count<rt::Triangle>(), row.triangles);
        EXPECT_EQ(scene.primitives.count<rt::Sphere>(), row.spheres);
        EXPECT_EQ(scene.lights.size(), row.lights);
        EXPECT_EQ(scene.droppedDegenerate, 0u);
    }
}

TEST(ThesisScenes, AreTheSameOnEveryCall) {
    for (const auto name : {"ships", "pyramid5"}) {
        const rt::Scene a = rt::thesisScene(name), b = rt::thesisScene(name);
        ASSERT_EQ(a.primitives.size(), b.primitives.size());
        for (std::uint32_t i = 0; i < a.primitives.size(); ++i)
            ASSERT_EQ(a.primitives.bounds(i).lo, b.primitives.bounds(i).lo) << name << " primitive " << i;
    }
}

TEST(ThesisScenes, UnknownNameIsAnInputError) {
    EXPECT_THROW(rt::thesisScene("balls3"), rt::InputError);
    EXPECT_THROW(rt::thesisScene(""), rt::InputError);
}

// Haines's sphereflake: every child touches its parent and has a third of its radius, and
// the first sphere's nine children are three above its equator and six on it.
TEST(ThesisScenes, SphereflakeChildrenTouchTheirParent) {
    const rt::Scene scene = rt::thesisBalls();
    const auto& spheres = scene.primitives.all<rt::Sphere>();
    const rt::Sphere& root = spheres[0];
    EXPECT_NEAR(root.radius, 0.5, kTol);
    int above = 0, onEquator = 0;
    // Depth first: the root's children are spheres 1, 1 + 820, 1 + 2 * 820, ... (820 = 1 + 9 + 81 + 729).
    for (int child = 0; child < 9; ++child) {
        const rt::Sphere& s = spheres[1 + child * 820];
        EXPECT_NEAR(s.radius, 0.5 / 3, 1e-6);
        EXPECT_NEAR(rt::length(s.center - root.center), 0.5 + 0.5 / 3, 1e-6);
        const rt::Real height = s.center.z - root.center.z;
        above += height > 0.1;
        onEquator += std::abs(height) < 1e-6;
    }
    EXPECT_EQ(above, 3);
    EXPECT_EQ(onEquator, 6);
}

// The Sierpinski pyramid keeps the outline of the pyramid it grew from: a base of side 2
// and the height of a pyramid with equilateral sides, 2 / sqrt 2.
TEST(ThesisScenes, PyramidKeepsTheOuterShape) {
    const rt::Aabb box = rt::thesisPyramid5().primitives.bounds();
    expectNear(box.lo, {-1, 0, -1}, 1e-6);
    expectNear(box.hi, {1, rt::Real(std::sqrt(2.0)), 1}, 1e-6);
}

}  // namespace
