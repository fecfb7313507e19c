#include "io/raw_model.h"

#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>

#include "scene_test_files.h"

using namespace rt;

namespace {

std::string rawBytes(const Model& m) {
    std::ostringstream out;
    writeRaw(out, m);
    return out.str();
}

// A header by hand: magic, type, little-endian count.
std::string header(char type, std::uint32_t count) {
    std::string h = "raw3d";
    h += type;
    for (int i = 0; i < 4; ++i) h += char(count >> (8 * i) & 0xff);
    return h;
}

std::string floatBytes(std::initializer_list<float> values) {
    std::string s;
    for (float f : values) {
        char b[4];
        std::memcpy(b, &f, 4);  // the test machine is little-endian, like the format
        s.append(b, 4);
    }
    return s;
}

Model fromBytes(const std::string& bytes) {
    return readRawBytes({reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()}, "m.raw");
}

}  // namespace

TEST(RawModel, WritesTheAppendixDLayout) {
    const std::string bytes = rawBytes(rawModel({1, 2, 3, 4, 5, 6, 7, 8, 9}));
    EXPECT_EQ(bytes, header('T', 1) + floatBytes({1, 2, 3, 4, 5, 6, 7, 8, 9}));
    EXPECT_EQ(rawBytes(rawModel({}, {1, 2, 3, 0.5f})), header('S', 1) + floatBytes({1, 2, 3, 0.5f}));
    EXPECT_EQ(rawBytes(rawModel({})), header('T', 0));
}

TEST(RawModel, TrianglesRoundTripThroughAFile) {
    TempDir dir;
    const Model m = rawModel(
        {0.1f, -2.5f, 3e7f, 4, 5, 6, 7, 8, std::numeric_limits<float>::denorm_min(), 1, 1, 1, 2, 2, 2, 3, 3, 3.25f});
    writeRawFile(dir.path("t.raw"), m);
    const Model back = readRawFile(dir.path("t.raw"));
    EXPECT_EQ(back.triangleVertices, m.triangleVertices);  // bit-identical floats
    EXPECT_TRUE(back.sphereData.empty());
    EXPECT_EQ(back.triangleCount(), 2u);
}

TEST(RawModel, SpheresRoundTripThroughAFile) {
    TempDir dir;
    const Model m = rawModel({}, {0, 0, 0, 1, -1.5f, 2.25f, 1e-3f, 0.125f});
    writeRawFile(dir.path("s.raw"), m);
    const Model back = readRawFile(dir.path("s.raw"));
    EXPECT_EQ(back.sphereData, m.sphereData);
    EXPECT_TRUE(back.triangleVertices.empty());
    EXPECT_EQ(back.sphereCount(), 2u);
}

TEST(RawModel, ReadsFromMemory) {
    const Model m = fromBytes(header('S', 1) + floatBytes({1, 2, 3, 4}));
    EXPECT_EQ(m.sphereData, (std::vector<float>{1, 2, 3, 4}));
    EXPECT_EQ(fromBytes(header('T', 0)).triangleCount(), 0u);
}

TEST(RawModel, BadFilesNameTheByteOffset) {
    const std::string tri = floatBytes({1, 2, 3, 4, 5, 6, 7, 8, 9});
    EXPECT_EQ(inputErrorOf([&] { fromBytes("raw3"); }), "m.raw: byte 4: truncated RAW header (4 of 10 bytes)");
    EXPECT_EQ(inputErrorOf([&] { fromBytes("RAW3dT" + std::string(4, '\0')); }),
              "m.raw: byte 0: not a RAW model (the file must start with \"raw3d\")");
    EXPECT_EQ(inputErrorOf([&] { fromBytes(header('Q', 0)); }),
              "m.raw: byte 5: unknown RAW model type (expected 'T' or 'S')");
    EXPECT_EQ(inputErrorOf([&] { fromBytes(header('T', 2) + tri); }),
              "m.raw: byte 46: truncated RAW data: 72 bytes of data for 2 triangles, the file has 36");
    EXPECT_EQ(inputErrorOf([&] { fromBytes(header('S', 1) + tri); }),
              "m.raw: byte 26: 20 bytes after the 16 bytes of data for 1 sphere");
    EXPECT_EQ(inputErrorOf([&] { fromBytes(header('T', 1) + tri.substr(0, 35)); }),
              "m.raw: byte 45: truncated RAW data: 36 bytes of data for 1 triangle, the file has 35");
}

TEST(RawModel, HugeCountIsRejectedBeforeAllocating) {
    // 4 G triangles would be 154 GB: the size check must come before any reservation.
    EXPECT_EQ(inputErrorOf([&] {
                  fromBytes(header('T', 0xffffffffu) + floatBytes({1, 2, 3}));
              }),
              "m.raw: byte 22: truncated RAW data: 154618822620 bytes of data for 4294967295 triangles, "
              "the file has 12");
}

TEST(RawModel, NonFiniteNumbersNameTheirOffset) {
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    EXPECT_EQ(inputErrorOf([&] {
                  fromBytes(header('S', 1) + floatBytes({1, nan, 3, 4}));
              }),
              "m.raw: byte 14: NaN in RAW data");
    EXPECT_EQ(inputErrorOf([&] {
                  fromBytes(header('S', 1) + floatBytes({1, 2, 3, -inf}));
              }),
              "m.raw: byte 22: infinite number in RAW data");
}

TEST(RawModel, FileErrorsNameTheFile) {
    TempDir dir;
    const std::string missing = dir.path("missing.raw");
    EXPECT_EQ(inputErrorOf([&] { readRawFile(missing); }), missing + ": cannot open: No such file or directory");
    const std::string truncated = dir.write("short.raw", header('T', 3));
    EXPECT_EQ(inputErrorOf([&] { readRawFile(truncated); }),
              truncated + ": byte 10: truncated RAW data: 108 bytes of data for 3 triangles, the file has 0");
    EXPECT_NE(inputErrorOf([&] { readRawFile(dir.path("")); }), "");  // a folder
}

TEST(RawModel, WriterRefusesMixedModels) {
    EXPECT_THROW(rawBytes(rawModel({1, 2, 3, 4, 5, 6, 7, 8, 9}, {0, 0, 0, 1})), std::invalid_argument);
}

// rt extension: per-corner sections after the triangles.
TEST(RawModel, VertexDataRoundTripsAsSectionsAfterTheTriangles) {
    Model m = rawModel({0, 0, 0, 1, 0, 0, 0, 1, 0});
    m.vertexNormals = {0, 0, 1, 0, 0.6f, 0.8f, 0, 0, -1};
    m.vertexUvs = {0, 0, 1, 0, 0.25f, 2};
    m.vertexColors = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    const std::string bytes = rawBytes(m);
    EXPECT_EQ(bytes, header('T', 1) + floatBytes({0, 0, 0, 1, 0, 0, 0, 1, 0}) + "vnrm" +
                         floatBytes({0, 0, 1, 0, 0.6f, 0.8f, 0, 0, -1}) + "vtex" + floatBytes({0, 0, 1, 0, 0.25f, 2}) +
                         "vcol" + floatBytes({1, 0, 0, 0, 1, 0, 0, 0, 1}));
    const Model back = fromBytes(bytes);
    EXPECT_EQ(back.triangleVertices, m.triangleVertices);
    EXPECT_EQ(back.vertexNormals, m.vertexNormals);
    EXPECT_EQ(back.vertexUvs, m.vertexUvs);
    EXPECT_EQ(back.vertexColors, m.vertexColors);
    // Any order, any subset; a thesis file has none.
    const Model uvsOnly = fromBytes(header('T', 1) + floatBytes({0, 0, 0, 1, 0, 0, 0, 1, 0}) + "vtex" +
                                    floatBytes({0, 0, 1, 0, 0.25f, 2}));
    EXPECT_TRUE(uvsOnly.vertexNormals.empty());
    EXPECT_EQ(uvsOnly.vertexUvs, m.vertexUvs);
    EXPECT_TRUE(rawModel({0, 0, 0, 1, 0, 0, 0, 1, 0}).vertexNormals.empty());
    EXPECT_EQ(rawBytes(rawModel({0, 0, 0, 1, 0, 0, 0, 1, 0})),
              header('T', 1) + floatBytes({0, 0, 0, 1, 0, 0, 0, 1, 0}));
}

TEST(RawModel, BadSectionsNameTheByteOffset) {
    const std::string tri = header('T', 1) + floatBytes({1, 2, 3, 4, 5, 6, 7, 8, 9});
    const std::string normals = floatBytes({0, 0, 1, 0, 0, 1, 0, 0, 1});
    EXPECT_EQ(inputErrorOf([&] { fromBytes(tri + "junk"); }),
              "m.raw: byte 46: 4 bytes after the triangles that are no section (vnrm, vtex, vcol or vtan)");
    EXPECT_EQ(inputErrorOf([&] { fromBytes(tri + "vn"); }),
              "m.raw: byte 46: 2 bytes after the triangles that are no section (vnrm, vtex, vcol or vtan)");
    EXPECT_EQ(inputErrorOf([&] { fromBytes(tri + "vnrm" + normals.substr(0, 8)); }),
              "m.raw: byte 58: truncated RAW data: 36 bytes of vertex normals for 1 triangle, the file has 8");
    EXPECT_EQ(inputErrorOf([&] { fromBytes(tri + "vnrm" + normals + "vnrm" + normals); }),
              "m.raw: byte 86: a second vertex normals section");
    const float nan = std::numeric_limits<float>::quiet_NaN();
    EXPECT_EQ(inputErrorOf([&] {
                  fromBytes(tri + "vcol" + floatBytes({1, 1, 1, nan, 1, 1, 1, 1, 1}));
              }),
              "m.raw: byte 62: NaN in RAW data");
    Model partial = rawModel({1, 2, 3, 4, 5, 6, 7, 8, 9, 1, 2, 3, 4, 5, 6, 7, 8, 9});
    partial.vertexUvs = {0, 0, 1, 0, 0, 1};  // one triangle of two
    EXPECT_THROW(rawBytes(partial), std::invalid_argument);
}
