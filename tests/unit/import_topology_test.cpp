// Strips and fans unrolled with the winding of the glTF specification (import/primitive_topology.*).
#include <gtest/gtest.h>

#include "io/primitive_topology.h"

namespace rt {
namespace {

using Corners = std::vector<std::uint32_t>;

TEST(ImportTopology, StripAlternatesTheWinding) {
    const Corners v{10, 11, 12, 13, 14};
    EXPECT_EQ(triangleCorners(Topology::Strip, v), (Corners{10, 11, 12, 11, 13, 12, 12, 13, 14}));
}

TEST(ImportTopology, FanTurnsAroundTheFirstVertex) {
    const Corners v{10, 11, 12, 13, 14};
    EXPECT_EQ(triangleCorners(Topology::Fan, v), (Corners{11, 12, 10, 12, 13, 10, 13, 14, 10}));
}

TEST(ImportTopology, TrianglesLoseAnIncompleteEnd) {
    const Corners v{1, 2, 3, 4, 5};
    EXPECT_EQ(triangleCorners(Topology::Triangles, v), (Corners{1, 2, 3}));
}

TEST(ImportTopology, TooFewVerticesGiveNothing) {
    const Corners v{1, 2};
    EXPECT_TRUE(triangleCorners(Topology::Strip, v).empty());
    EXPECT_TRUE(triangleCorners(Topology::Fan, v).empty());
    EXPECT_TRUE(triangleCorners(Topology::Triangles, v).empty());
}

}  // namespace
}  // namespace rt
