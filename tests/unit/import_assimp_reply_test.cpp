// The reply of the contained Assimp read (import/assimp_reply.h): what the child writes reads
// back as the same scene, and bytes that are not an honest reply (cut short, counts beyond the
// bytes, indices out of range, a tree too deep, more than the budget) are one rt::InputError.
#include "io/assimp_reply.h"

#include <assimp/postprocess.h>
#include <gtest/gtest.h>

#include <assimp/Importer.hpp>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>

#include "core/error.h"
#include "os/input_file.h"
#include "test_util.h"

namespace rt {
namespace {

// A quad with normals, UVs and colours, as Assimp's PLY reader gives it.
const char* const kPly = R"(ply
format ascii 1.0
element vertex 4
property float x
property float y
property float z
property float nx
property float ny
property float nz
property float s
property float t
property uchar red
property uchar green
property uchar blue
element face 1
property list uchar int vertex_indices
end_header
0 0 0 0 0 1 0 0 255 0 0
1 0 0 0 0 1 1 0 0 255 0
1 1 0 0 0 1 1 1 0 0 255
0 1 0 0 0 1 0 1 255 255 255
4 0 1 2 3
)";

std::string replyOf(const std::string& bytes, const char* hint) {
    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFileFromMemory(bytes.data(), bytes.size(),
                                                       aiProcess_Triangulate | aiProcess_ValidateDataStructure, hint);
    if (!scene) ADD_FAILURE() << importer.GetErrorString();
    return scene ? writeAssimpReply(*scene, "model") : "";
}

// The message of the rt::InputError reading `reply` throws; empty (and a failure) if none.
std::string replyErrorOf(const std::string& reply) {
    try {
        readAssimpReply(reply, "model.ply");
    } catch (const InputError& e) {
        return e.what();
    }
    ADD_FAILURE() << "the reply read without an error";
    return "";
}

void putU32(std::string& s, std::size_t at, std::uint32_t v) { std::memcpy(&s[at], &v, 4); }
std::uint32_t getU32(const std::string& s, std::size_t at) {
    std::uint32_t v;
    std::memcpy(&v, &s[at], 4);
    return v;
}

// Where the first mesh's material index is in a reply: after the header and the mesh count.
constexpr std::size_t kFirstMeshMaterial = 12;
void appendU32(std::string& s, std::uint32_t v) { s.append(reinterpret_cast<const char*>(&v), 4); }

// A reply of no meshes, materials, cameras or lights, whose node tree `nodes` writes.
std::string replyWithNodes(const std::string& nodes) {
    std::string r = "rtAR";
    for (int i = 0; i < 5; ++i) appendU32(r, i == 0 ? 1 : 0);  // version, then four counts of 0
    return r + nodes;
}

// An unnamed node with the identity transform, no meshes and `children` children.
std::string node(std::uint32_t children) {
    std::string n;
    appendU32(n, 0);
    for (int i = 0; i < 16; ++i) {
        const float v = i % 5 == 0 ? 1.0f : 0.0f;
        n.append(reinterpret_cast<const char*>(&v), 4);
    }
    appendU32(n, 0);
    appendU32(n, children);
    return n;
}

TEST(AssimpReply, ReadsBackWhatTheChildWrote) {
    const std::string reply = replyOf(kPly, "ply");
    const auto scene = readAssimpReply(reply, "quad.ply");
    ASSERT_EQ(scene->mNumMeshes, 1u);
    const aiMesh& mesh = *scene->mMeshes[0];
    ASSERT_EQ(mesh.mNumVertices, 4u);
    EXPECT_EQ(mesh.mNumFaces, 2u);  // triangulated in the child
    ASSERT_TRUE(mesh.mNormals && mesh.mTextureCoords[0] && mesh.mColors[0]);
    EXPECT_FLOAT_EQ(mesh.mVertices[2].y, 1);
    EXPECT_FLOAT_EQ(mesh.mNormals[3].z, 1);
    EXPECT_FLOAT_EQ(mesh.mTextureCoords[0][1].x, 1);
    EXPECT_FLOAT_EQ(mesh.mColors[0][2].b, 1);
    EXPECT_EQ(writeAssimpReply(*scene, "quad.ply"), reply);  // nothing lost or changed on the way
}

// Every shared 3DS model (meshes, materials with textures and wrap modes, cameras, node trees)
// comes back as the same reply: the reader keeps all the writer sends.
TEST(AssimpReply, SharedModelsComeBackWhole) {
    SKIP_WITHOUT_SHARED_MODELS();
    int models = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(RT_SHARED_DIR "/models/3ds")) {
        const std::string ext = entry.path().extension().string();
        if (ext != ".3ds" && ext != ".3DS") continue;
        const std::string reply = replyOf(readInputFile(entry.path().string()), "3ds");
        EXPECT_EQ(writeAssimpReply(*readAssimpReply(reply, "m.3ds"), "m.3ds"), reply) << entry.path();
        ++models;
    }
    EXPECT_GE(models, 8);
}

TEST(AssimpReply, EveryShortenedReplyIsAnInputError) {
    const std::string reply = replyOf(kPly, "ply");
    for (std::size_t length = 0; length < reply.size(); ++length)
        EXPECT_NE(replyErrorOf(reply.substr(0, length)).find("model.ply: byte "), std::string::npos) << length;
    EXPECT_NE(replyErrorOf(reply + "x").find("bytes follow the node tree"), std::string::npos);
}

TEST(AssimpReply, CountsBeyondTheBytesAreRefusedBeforeAnythingIsAllocated) {
    std::string reply = replyOf(kPly, "ply");
    putU32(reply, 8, 0xffffffffu);  // meshes
    EXPECT_NE(replyErrorOf(reply).find("mesh count: 4294967295, more than the"), std::string::npos);
    reply = replyOf(kPly, "ply");
    putU32(reply, kFirstMeshMaterial + 4, 0xfffffff0u);  // the mesh's vertices
    EXPECT_NE(replyErrorOf(reply).find("mesh 0 vertices: 4294967280"), std::string::npos);
}

TEST(AssimpReply, IndicesOutOfRangeAreRefused) {
    const std::string good = replyOf(kPly, "ply");
    std::string reply = good;
    // After the material, the vertex count, what they have and 4 vertices of 3 + 3 + 2 + 4 numbers:
    // the face count, the first face's corner count and its first corner.
    const std::size_t faces = kFirstMeshMaterial + 4 + 4 + 1 + 4 * (3 + 3 + 2 + 4) * 4;
    ASSERT_EQ(getU32(good, faces), 2u);
    putU32(reply, faces + 4 + 4, 4);
    EXPECT_NE(replyErrorOf(reply).find("mesh 0 face 0 names vertex 4 of 4"), std::string::npos);
    reply = good;
    putU32(reply, kFirstMeshMaterial, 7);
    EXPECT_NE(replyErrorOf(reply).find("mesh 0 names material 7 of 1"), std::string::npos);
}

TEST(AssimpReply, NodeTreesDeeperThanTheLimitAreRefused) {
    std::string chain;
    for (std::size_t i = 0; i < kMaxReplyNodeDepth; ++i) chain += node(1);
    EXPECT_NO_THROW(readAssimpReply(replyWithNodes(chain + node(0)), "deep.ply"));
    EXPECT_NE(replyErrorOf(replyWithNodes(chain + node(1) + node(0))).find("deeper than 1024 levels"),
              std::string::npos);
}

// Material entries cost the tool a whole aiMaterialProperty (over 1 KiB) for a few bytes.
TEST(AssimpReply, MoreThanTheReplyJustifiesIsRefused) {
    std::string reply = "rtAR";
    appendU32(reply, 1);
    appendU32(reply, 0);  // meshes
    appendU32(reply, 1);  // materials
    const std::uint32_t entries = 100000;
    appendU32(reply, entries);
    for (std::uint32_t e = 0; e < entries; ++e) {
        const float one = 1;
        reply += std::string("\0\1", 2);  // the diffuse colour, one number
        reply.append(reinterpret_cast<const char*>(&one), 4);
    }
    reply += std::string(8, '\0') + node(0);  // no cameras or lights
    EXPECT_NE(replyErrorOf(reply).find("MiB its length allows the tool to spend on it"), std::string::npos);
}

TEST(AssimpReply, OtherBytesAreNotAReply) {
    EXPECT_NE(replyErrorOf("").find("ends early"), std::string::npos);
    EXPECT_NE(replyErrorOf("assimp.binary-dump").find("does not start with rtAR"), std::string::npos);
}

}  // namespace
}  // namespace rt
