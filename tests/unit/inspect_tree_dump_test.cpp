// Leaf-box OBJ, DOT and the depth histogram of a hand-made tree, parsed back.
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "inspect/depth_histogram.h"
#include "inspect/leaf_boxes_obj.h"
#include "inspect/tree_dump.h"
#include "inspect_fixed_tree.h"
#include "test_util.h"

using namespace rt;

namespace {

struct ObjLines {
    std::vector<Vec3> vertices;
    std::vector<std::pair<long, long>> lines;
    int objects = 0;
};

ObjLines parseObj(const std::string& text) {
    ObjLines obj;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream l(line);
        std::string tag;
        l >> tag;
        if (tag.empty() || tag == "#") continue;
        if (tag == "v") {
            Vec3 v;
            l >> v.x >> v.y >> v.z;
            EXPECT_FALSE(l.fail()) << line;
            obj.vertices.push_back(v);
        } else if (tag == "l") {
            long a = 0, b = 0;
            l >> a >> b;
            EXPECT_FALSE(l.fail()) << line;
            obj.lines.emplace_back(a, b);
        } else if (tag == "o") {
            ++obj.objects;
        } else {
            ADD_FAILURE() << "unexpected OBJ statement: " << line;
        }
    }
    return obj;
}

std::string leafObj(const Accelerator& tree, const TreeCut& cut, std::size_t* boxes = nullptr) {
    std::ostringstream out;
    const std::size_t n = writeLeafBoxesObj(out, tree, cut);
    if (boxes) *boxes = n;
    return out.str();
}

// Every box is 8 vertices spanning a node's voxel and 12 edges of length equal to one side.
void expectBoxes(const ObjLines& obj, const std::vector<Aabb>& boxes) {
    ASSERT_EQ(obj.vertices.size(), 8 * boxes.size());
    ASSERT_EQ(obj.lines.size(), 12 * boxes.size());
    for (std::size_t b = 0; b < boxes.size(); ++b) {
        Aabb spanned;
        for (int i = 0; i < 8; ++i) spanned.extend(obj.vertices[8 * b + i]);
        EXPECT_EQ(spanned, boxes[b]);
        for (int e = 0; e < 12; ++e) {
            const auto [i, j] = obj.lines[12 * b + e];
            ASSERT_GE(i, long(8 * b + 1));
            ASSERT_LE(j, long(8 * b + 8));
            const Vec3 d = obj.vertices[j - 1] - obj.vertices[i - 1];
            const int axesChanged = (d.x != 0) + (d.y != 0) + (d.z != 0);
            EXPECT_EQ(axesChanged, 1) << "edge " << i << "-" << j << " is not along one axis";
        }
    }
}

}  // namespace

TEST(LeafBoxesObj, AllLeavesAreWireframeBoxes) {
    const FixedTree tree = FixedTree::sample();
    std::size_t boxes = 0;
    const ObjLines obj = parseObj(leafObj(tree, {}, &boxes));
    EXPECT_EQ(boxes, 3u);
    EXPECT_EQ(obj.objects, 1);
    expectBoxes(obj, {tree.node(1).bounds, tree.node(3).bounds, tree.node(4).bounds});
}

TEST(LeafBoxesObj, NonEmptyLeavesOnly) {
    const FixedTree tree = FixedTree::sample();
    TreeCut cut;
    cut.nonEmptyOnly = true;
    expectBoxes(parseObj(leafObj(tree, cut)), {tree.node(1).bounds, tree.node(4).bounds});
}

TEST(LeafBoxesObj, CutAtDepthShowsTheCutOffSubtreeAsOneBox) {
    const FixedTree tree = FixedTree::sample();
    TreeCut cut;
    cut.maxDepth = 1;
    expectBoxes(parseObj(leafObj(tree, cut)), {tree.node(1).bounds, tree.node(2).bounds});
    cut.maxDepth = 0;
    expectBoxes(parseObj(leafObj(tree, cut)), {tree.node(0).bounds});
}

TEST(TreeDot, NodesAndEdgesMatchTheTree) {
    const FixedTree tree = FixedTree::sample();
    std::ostringstream out;
    writeTreeDot(out, tree, {});
    const std::string dot = out.str();
    ASSERT_TRUE(std::regex_search(dot, std::regex(R"(^digraph "[^"]*" \{\n)"))) << dot;
    ASSERT_EQ(dot.substr(dot.size() - 2), "}\n");

    const std::regex nodeStatement(R"re(^  n(\d+) \[label="([^"]*)"[^\]]*\];$)re");
    const std::regex edgeStatement(R"(^  n(\d+) -> n(\d+);$)");
    std::map<int, std::string> labels;
    std::set<std::pair<int, int>> edges;
    std::istringstream in(dot);
    std::string line;
    std::getline(in, line);  // digraph
    std::getline(in, line);  // node defaults
    EXPECT_NE(line.find("node [shape=box"), std::string::npos);
    while (std::getline(in, line) && line != "}") {
        std::smatch m;
        if (std::regex_match(line, m, nodeStatement)) {
            labels[std::stoi(m[1])] = m[2];
        } else if (std::regex_match(line, m, edgeStatement)) {
            edges.emplace(std::stoi(m[1]), std::stoi(m[2]));
            EXPECT_TRUE(labels.count(std::stoi(m[1])) && labels.count(std::stoi(m[2])))
                << "edge before its nodes: " << line;
        } else {
            ADD_FAILURE() << "not a DOT statement this dump writes: " << line;
        }
    }
    EXPECT_EQ(labels.size(), 5u);
    EXPECT_EQ(edges, (std::set<std::pair<int, int>>{{0, 1}, {0, 2}, {2, 3}, {2, 4}}));
    EXPECT_NE(labels[0].find("x = 0"), std::string::npos) << labels[0];
    EXPECT_NE(labels[2].find("y = 1"), std::string::npos) << labels[2];
    EXPECT_NE(labels[4].find("3 primitives"), std::string::npos) << labels[4];
}

TEST(TreeDot, CutAtDepthMarksTheCutNode) {
    const FixedTree tree = FixedTree::sample();
    TreeCut cut;
    cut.maxDepth = 1;
    std::ostringstream out;
    writeTreeDot(out, tree, cut);
    const std::string dot = out.str();
    EXPECT_EQ(dot.find("n3"), std::string::npos);
    EXPECT_NE(dot.find("n2 [label=\"#2\\ny = 1\\n(cut off)\", style=dotted]"), std::string::npos) << dot;
}

TEST(DepthHistogram, CountsPerDepth) {
    const std::vector<DepthLevel> levels = depthHistogram(FixedTree::sample());
    ASSERT_EQ(levels.size(), 3u);
    EXPECT_EQ(levels[0].nodes, 1u);
    EXPECT_EQ(levels[0].leaves, 0u);
    EXPECT_EQ(levels[1].nodes, 2u);
    EXPECT_EQ(levels[1].leaves, 1u);
    EXPECT_EQ(levels[1].primitiveReferences, 2u);
    EXPECT_EQ(levels[2].leaves, 2u);
    EXPECT_EQ(levels[2].emptyLeaves, 1u);
    EXPECT_EQ(levels[2].primitiveReferences, 3u);
}
