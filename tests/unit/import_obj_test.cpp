// OBJ import through tinyobjloader's streaming API (libtrace/import/obj_import.*): the shared
// OBJ models against Assimp's figures in MANIFEST.md, materials, polygons, and every way a
// file can be broken, each reported at its line.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <string>

#include "core/error.h"
#include "import_test_util.h"
#include "io/import.h"
#include "io/line_tracking_file.h"
#include "io/polygon.h"
#include "test_util.h"

namespace rt {
namespace {

using test::sharedModels;
using test::TempDir;

const char* const kSquare = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";

// The square's faces `faces` with the materials of `mtl` (m.mtl in `dir`).
ImportResult importSquare(const TempDir& dir, const std::string& mtl, const std::string& faces) {
    dir.write("m.mtl", mtl);
    return importScene(dir.write("m.obj", std::string("mtllib m.mtl\n") + kSquare + faces));
}

const Material& materialNamed(const ImportResult& r, const std::string& name) {
    return r.scene.materials[r.scene.findMaterial(name).value()];
}

// The message of the InputError that importing `text` as an OBJ throws ("" if none).
std::string objError(const TempDir& dir, const std::string& text) {
    const std::string path = dir.write("m.obj", text);
    return inputErrorOf([&] { importScene(path); });
}

double triangleArea(const Triangle& t) { return length(cross(t.p1 - t.p0, t.p2 - t.p0)) / 2; }

TEST(ImportObj, TriangleCountsMatchTheManifest) {
    SKIP_WITHOUT_SHARED_MODELS();
    const std::size_t files = test::expectManifestTriangleCounts({"obj"}, [](const ImportResult& r) {
        EXPECT_EQ(r.scene.models.size(), r.scene.instances.size());  // OBJ does not instance
        EXPECT_EQ(r.report.format, "Wavefront OBJ");
    });
    EXPECT_EQ(files, test::manifestModelFolders("obj"));
}

// spider.obj: 56 of its 1368 triangles have no area in float (Assimp's FindDegenerates finds the same ones here).
TEST(ImportObj, DegenerateTrianglesOfSpider) {
    SKIP_WITHOUT_SHARED_MODELS();
    const ImportResult r = importScene(sharedModels() + "/obj/spider/spider.obj");
    EXPECT_EQ(test::modelTriangles(r.scene), 1312u);
    EXPECT_EQ(r.report.droppedDegenerate, 56u);
}

// spider.mtl writes `map_Kd .\\SpiderTex.jpg` (Windows) and test1.3ds names CWALL02.JPG for
// CWALL02.jpg: each texture is found on disk, not left for the render to replace with white.
TEST(ImportObj, WindowsPathsAndOtherCaseFindTheTextures) {
    SKIP_WITHOUT_SHARED_MODELS();
    for (const char* model : {"/obj/spider/spider.obj", "/3ds/test1/test1.3ds",
                              "/3ds/cube_with_diffuse_texture/cube_with_diffuse_texture.3DS"}) {
        const ImportResult r = importScene(sharedModels() + model);
        EXPECT_FALSE(r.scene.textures.empty()) << model;
        for (const Texture& t : r.scene.textures)
            EXPECT_TRUE(std::filesystem::is_regular_file(t.path)) << model << ": " << t.path;
    }
}

// CornellBox-Original.mtl: the right wall is Kd 0.14 0.45 0.091 (green) with Ns 10 and no Ks.
TEST(ImportObj, MaterialsKeepTheirDiffuseColourAndNames) {
    SKIP_WITHOUT_SHARED_MODELS();
    const ImportResult r = importScene(sharedModels() + "/obj/CornellBox-Original/CornellBox-Original.obj");
    const std::optional<std::uint32_t> green = r.scene.findMaterial("rightWall");
    ASSERT_TRUE(green) << "materials keep their .mtl names";
    const Material& m = r.scene.materials[*green];
    EXPECT_NEAR(m.color.r, 0.14f, 1e-6);
    EXPECT_NEAR(m.color.g, 0.45f, 1e-6);
    EXPECT_NEAR(m.color.b, 0.091f, 1e-6);
    EXPECT_FLOAT_EQ(m.phong.specular, 0);
    EXPECT_FLOAT_EQ(m.phong.shininess, 10);
}

// Ks becomes the specular coefficient; illum 3 (ray-traced reflection) makes it a mirror too.
TEST(ImportObj, SpecularAndReflectionComeFromKsAndIllum) {
    TempDir dir;
    dir.write("m.mtl", "newmtl shiny\nKd 1 0 0\nKs 0.5 0.5 0.5\nNs 80\nillum 3\nnewmtl matte\nKd 0 0 1\nillum 2\n");
    const ImportResult r = importScene(
        dir.write("m.obj", std::string("mtllib m.mtl\n") + kSquare + "usemtl shiny\nf 1 2 3\nusemtl matte\nf 1 3 4\n"));
    ASSERT_EQ(r.scene.instances.size(), 2u);
    const Material& shiny = r.scene.materials[r.scene.instances[0].material];
    const Material& matte = r.scene.materials[r.scene.instances[1].material];
    EXPECT_EQ(shiny.name, "shiny");
    EXPECT_FLOAT_EQ(shiny.phong.specular, 0.5f);
    EXPECT_FLOAT_EQ(shiny.phong.shininess, 80);
    EXPECT_FLOAT_EQ(shiny.phong.reflection, 0.5f);
    EXPECT_EQ(matte.name, "matte");
    EXPECT_FLOAT_EQ(matte.color.b, 1);
    EXPECT_FLOAT_EQ(matte.phong.reflection, 0);
}

// illum 6 and 7 are glass of index Ni; d below 1 (or Tr above 0) lets 1 - d through straight,
// fading the surface's own light; illum 4 and 5 mirror as illum 3 does (docs/conversion.md).
TEST(ImportObj, TransparencyComesFromDTrNiAndIllum) {
    TempDir dir;
    dir.write("m.mtl",
              "newmtl glass\nKd 0.01 0.01 0.01\nKs 0.3 0.3 0.3\nNi 2.5\nillum 7\n"
              "newmtl veil\nKd 1 0 0\nd 0.25\nillum 2\n"
              "newmtl tr\nKd 1 1 1\nTr 0.4\n"
              "newmtl mirror\nKs 0.8 0.8 0.8\nillum 5\n"
              "newmtl plain\nKd 1 1 1\nNi 1.5\nillum 2\n");
    std::string obj = std::string("mtllib m.mtl\n") + kSquare;
    for (const char* name : {"glass", "veil", "tr", "mirror", "plain"})
        obj += std::string("usemtl ") + name + "\nf 1 2 3\n";
    const ImportResult r = importScene(dir.write("m.obj", obj));
    ASSERT_EQ(r.scene.instances.size(), 5u);
    const auto material = [&](int i) { return r.scene.materials[r.scene.instances[std::size_t(i)].material]; };
    const Transmission glass = material(0).transmission;
    EXPECT_EQ(glass.weight, 1.0f);
    EXPECT_EQ(glass.ior, 2.5f);
    EXPECT_FALSE(glass.thin);
    EXPECT_EQ(material(0).phong.reflection, 0.0f) << "the Fresnel term reflects";
    const Material veil = material(1);
    EXPECT_FLOAT_EQ(veil.transmission.weight, 0.75f);
    EXPECT_TRUE(veil.transmission.thin);
    EXPECT_EQ(veil.transmission.ior, 1.0f);
    EXPECT_FLOAT_EQ(veil.phong.diffuse, 0.9f * 0.25f);
    EXPECT_FLOAT_EQ(veil.phong.ambient, 0.1f * 0.25f);
    EXPECT_FLOAT_EQ(material(2).transmission.weight, 0.4f);
    EXPECT_FLOAT_EQ(material(3).phong.reflection, 0.8f);
    EXPECT_FALSE(material(3).transmission.passesLight());
    EXPECT_FALSE(material(4).transmission.passesLight()) << "Ni alone makes no glass";
}

// One model per run of object, group and material; going back to a pair adds to its model.
TEST(ImportObj, ModelsFollowObjectsGroupsAndMaterials) {
    TempDir dir;
    const ImportResult r = importSquare(dir, "newmtl a\nKd 1 1 1\nnewmtl b\nKd 0 0 0\n",
                                        "g left\nusemtl a\nf 1 2 3\nusemtl b\nf 1 3 4\n"
                                        "g right\nf 1 2 4\ng left\nusemtl a\nf 2 3 4\n");
    ASSERT_EQ(r.scene.models.size(), 3u);
    EXPECT_EQ(r.scene.models[0].name, "left");
    EXPECT_EQ(r.scene.models[0].triangleCount(), 2u);  // both "left" faces with material a
    EXPECT_EQ(r.scene.models[1].name, "left_2");
    EXPECT_EQ(r.scene.models[2].name, "right");
    EXPECT_EQ(r.scene.materials.size(), 2u);
}

// Negative indices count back from the last vertex defined; quads and pentagons give n - 2.
TEST(ImportObj, RelativeIndicesAndPolygons) {
    TempDir dir;
    const ImportResult r =
        importScene(dir.write("m.obj", std::string(kSquare) + "f -4 -3 -2 -1\nv 0.5 2 0\nf 1 2 3 5 4\n"));
    ImportResult copy = r;
    copy.scene.flatten();
    ASSERT_EQ(copy.scene.primitives.count<Triangle>(), 5u);
    double area = 0;
    for (std::size_t i = 0; i < 5; ++i) area += triangleArea(copy.scene.primitives.all<Triangle>()[i]);
    EXPECT_NEAR(area, 1 + 1.5, 1e-6);  // the unit square, then the square with a roof
}

// An L-shaped hexagon whose fan from corner 0 would leave the polygon.
TEST(ImportObj, ConcavePolygonsAreEarClipped) {
    const std::vector<std::array<float, 3>> l = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}};
    std::vector<std::array<float, 3>> rotated = l;  // the reflex corner first: a fan from it fails
    std::rotate(rotated.begin(), rotated.begin() + 4, rotated.end());
    std::vector<std::uint32_t> tris;
    EXPECT_TRUE(triangulatePolygon(rotated, tris));
    ASSERT_EQ(tris.size(), 12u);
    double area = 0;
    for (std::size_t t = 0; t < tris.size(); t += 3) {
        const auto& a = rotated[tris[t]];
        const auto& b = rotated[tris[t + 1]];
        const auto& c = rotated[tris[t + 2]];
        const double signedArea = ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])) / 2;
        EXPECT_GT(signedArea, 0) << "every triangle keeps the polygon's orientation";
        area += signedArea;
        const double cx = (a[0] + b[0] + c[0]) / 3, cy = (a[1] + b[1] + c[1]) / 3;
        EXPECT_FALSE(cx > 1 && cy > 1) << "a triangle lies in the notch";
    }
    EXPECT_NEAR(area, 3, 1e-9);
}

TEST(ImportObj, TooManyCornersForEarClippingFallBackToAFan) {
    std::vector<std::array<float, 3>> star;
    for (std::size_t i = 0; i < 2 * kMaxEarClippedCorners; ++i) {
        const double angle = 2 * kPi * double(i) / double(2 * kMaxEarClippedCorners);
        const float radius = i % 2 ? 1.0f : 2.0f;
        star.push_back({radius * float(std::cos(angle)), radius * float(std::sin(angle)), 0});
    }
    std::vector<std::uint32_t> tris;
    EXPECT_FALSE(triangulatePolygon(star, tris));
    EXPECT_EQ(tris.size(), 3 * (star.size() - 2));
}

TEST(ImportObj, ZUpModelsAreTurnedToYUp) {
    SKIP_WITHOUT_SHARED_MODELS();
    const std::string path = sharedModels() + "/obj/box/box.obj";
    ImportResult plain = importScene(path);
    ImportOptions o;
    o.upAxis = UpAxis::Z;
    ImportResult turned = importScene(path, o);
    plain.scene.flatten();
    turned.scene.flatten();
    ASSERT_EQ(plain.scene.primitives.count<Triangle>(), turned.scene.primitives.count<Triangle>());
    const Triangle a = plain.scene.primitives.all<Triangle>()[0], b = turned.scene.primitives.all<Triangle>()[0];
    expectNear(b.p0, {a.p0.x, a.p0.z, -a.p0.y}, Real(1e-5));  // (x, y, z) -> (x, z, -y)
}

TEST(ImportObj, BrokenFilesAreInputErrorsAtTheirLine) {
    TempDir dir;
    const std::string m = dir.path("m.obj");
    const std::string badVertex = ": vertex coordinates are not three finite numbers: ";
    EXPECT_EQ(objError(dir, "v 0 0 0\nv nan 0 0\n"), m + ":2" + badVertex + "\"v nan 0 0\"");
    EXPECT_EQ(objError(dir, "# big\nv 1e39 0 0\n"), m + ":2" + badVertex + "\"v 1e39 0 0\"");  // beyond float
    for (const char* v : {"v 1e 0 0", "v 1e99999999999 0 0", "v 1.5.5 0 0", "v 1 0", "v 1 2 3x", "v 0x1 0 0"})
        EXPECT_EQ(objError(dir, std::string(v) + "\n"), m + ":1" + badVertex + "\"" + v + "\"");
    const std::string badFace =
        ": face corners are not v, v/t, v//n or v/t/n with vertex numbers of at most 9 digits: ";
    for (const char* f : {"f 1 2 x", "f 1-5 2 3", "f 4294967297 2 3", "f 1 2 3 # a comment", "f 1/2/ 2 3"})
        EXPECT_EQ(objError(dir, std::string(kSquare) + "\n\n" + f + "\n"), m + ":7" + badFace + "\"" + f + "\"");
    EXPECT_EQ(objError(dir, std::string(kSquare) + "f 0 1 2\n"),
              m + ":5: face refers to vertex 0, but OBJ counts vertices from 1 (or from -1 backwards)");
    EXPECT_EQ(objError(dir, std::string(kSquare) + "f 1 2 5\nv 0 0 1\n"),
              m + ":5: face refers to vertex 5, but 4 vertices are defined before it");
    EXPECT_EQ(objError(dir, "v 0 0 0\r\nv 1 0 0\r\nf 1 2 -3\r\n"),
              m + ":3: face refers to vertex -3, but 2 vertices are defined before it");
    EXPECT_EQ(objError(dir, "v 0 0 0\n# " + std::string(std::size_t(1) << 21, 'x') + "\n"),
              m + ":2: line longer than 1 MiB");
    EXPECT_EQ(objError(dir, ""), m + ": nothing to convert: the scene places no triangles");
    EXPECT_EQ(objError(dir, "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\nf 1 2\nf 3\n"),
              m + ": nothing to convert: the scene places no triangles");
    ImportOptions camera;
    camera.camera = "0";
    const std::string path = dir.write("ok.obj", std::string(kSquare) + "f 1 2 3\n");
    EXPECT_THROW(importScene(path, camera), InputError);
}

// Comments after coordinates, vertex colours, a '+' sign, blanks of every kind.
TEST(ImportObj, VertexLinesInTheFormsExportersWrite) {
    TempDir dir;
    const ImportResult r = importScene(
        dir.write("m.obj", "v 0 0 0 # origin\nv\t+1.0\t0\t0 1.0\nv 0 1 0 0.5 0.5 0.5\r\nf 1/1 2//2 3/3/3\n"));
    ASSERT_EQ(test::modelTriangles(r.scene), 1u);
    const std::vector<float>& v = r.scene.models[0].triangleVertices;
    EXPECT_EQ(std::vector<float>(v.begin(), v.end()), std::vector<float>({0, 0, 0, 1, 0, 0, 0, 1, 0}));
}

// Old Mac files end lines with a lone CR; errors still name the right line.
TEST(ImportObj, CarriageReturnLineEndings) {
    TempDir dir;
    const ImportResult r = importScene(dir.write("m.obj", "v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 3\r"));
    EXPECT_EQ(test::modelTriangles(r.scene), 1u);
    EXPECT_EQ(objError(dir, "v 0 0 0\rv 1 0 0\r\rv x 1 0\r"),
              dir.path("m.obj") + ":4: vertex coordinates are not three finite numbers: \"v x 1 0\"");
}

// A repeated corner is no corner: the concave pentagon f 1 2 2 3 4 is the quad 1 2 3 4,
// ear-clipped inside, and the repeat's triangle counts as a dropped degenerate one.
TEST(ImportObj, RepeatedCornersAreDropped) {
    TempDir dir;
    ImportResult r = importScene(dir.write("m.obj", "v 0 0 0\nv 2 1 0\nv 0 2 0\nv 1 1 0\nf 1 2 2 3 4\n"));
    EXPECT_EQ(r.report.droppedDegenerate, 1u);
    r.scene.flatten();
    ASSERT_EQ(r.scene.primitives.count<Triangle>(), 2u);
    double area = 0;
    for (std::size_t i = 0; i < 2; ++i) area += triangleArea(r.scene.primitives.all<Triangle>()[i]);
    EXPECT_NEAR(area, 1, 1e-6);  // the arrowhead's area, not more
}

TEST(ImportObj, GroupNamesStayApart) {
    TempDir dir;
    const ImportResult r = importScene(dir.write("m.obj", std::string(kSquare) + "g a b\nf 1 2 3\ng a_b\nf 1 3 4\n"));
    EXPECT_EQ(r.scene.models.size(), 2u);
}

// A line of exactly 1 MiB is allowed; one byte more is not, and is never read cut short.
TEST(ImportObj, LineLengthLimit) {
    TempDir dir;
    const std::size_t mib = std::size_t(1) << 20;
    std::string exact = "v 0 0 0 #";
    exact += std::string(mib - exact.size(), 'x');
    const std::string tail = "\r\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    EXPECT_EQ(objError(dir, exact + tail), "");
    EXPECT_EQ(objError(dir, exact + "x" + tail), dir.path("m.obj") + ":1: line longer than 1 MiB");
    std::string longFace = std::string(kSquare) + "f ";
    while (longFace.size() < 2 * mib) longFace += "-1 ";
    EXPECT_EQ(objError(dir, longFace + "\n"), dir.path("m.obj") + ":5: line longer than 1 MiB");
}

TEST(ImportObj, LineNumbersHoldAcrossBufferRefills) {
    TempDir dir;
    std::string text;
    for (int i = 0; i < 30000; ++i) text += "v " + std::to_string(i) + " 0.25 -1.5e-3\n";  // ~750 KB
    text += "f 1 2 3\nf 1 2 30001\n";
    EXPECT_EQ(objError(dir, text),
              dir.path("m.obj") + ":30002: face refers to vertex 30001, but 30000 vertices are defined before it");
}

TEST(ImportObj, LineTrackingFileShowsTheLineReadLast) {
    TempDir dir;
    const std::string path = dir.write("t.txt", "first\nsecond line\r\nthird");
    LineTrackingFile file(path, 8);  // lines above 8 bytes are too long
    std::istream in(&file);
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(file.lineNumber(), 1u);
    EXPECT_EQ(file.lineText(), "first");
    std::getline(in, line);
    EXPECT_TRUE(file.tooLong());
    EXPECT_FALSE(file.readFailed());
}

TEST(ImportObj, MissingMaterialsFallBackToADefaultWithANote) {
    TempDir dir;
    dir.write("empty.mtl", "# no materials\n");
    const ImportResult r =
        importScene(dir.write("m.obj", std::string("mtllib absent.mtl empty.mtl\nmtllib /dev/zero\n") + kSquare +
                                           "usemtl red\nf 1 2 3\nusemtl red\nf 1 3 4\nusemtl \nf 2 3 4\n"));
    ASSERT_EQ(r.scene.materials.size(), 1u);
    EXPECT_EQ(r.scene.materials[0].name, "default");
    EXPECT_FLOAT_EQ(r.scene.materials[0].color.g, 1) << "rt's white default, not an unnamed black one";
    const auto& notes = r.report.notes;
    EXPECT_EQ(std::count_if(notes.begin(), notes.end(),
                            [](const std::string& n) { return n.find("\"red\" is not defined") != std::string::npos; }),
              1)
        << "each missing material is named once";
    for (const char* file : {"absent.mtl", "empty.mtl", "/dev/zero"})
        EXPECT_NE(std::find_if(notes.begin(), notes.end(),
                               [&](const std::string& n) { return n.find(file) != std::string::npos; }),
                  notes.end())
            << file;
}

// A triangle with a repeated vertex is dropped and counted; the rest converts.
TEST(ImportObj, DegenerateFacesAreDroppedAndCounted) {
    TempDir dir;
    const ImportResult r = importScene(dir.write("d.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 2\n"));
    EXPECT_EQ(test::modelTriangles(r.scene), 1u);
    EXPECT_EQ(r.report.droppedDegenerate, 1u);
}

TEST(ImportObj, NanVerticesOfTheSharedBadFileAreAnInputError) {
    SKIP_WITHOUT_SHARED_MODELS();
    EXPECT_THROW(importScene(sharedModels() + "/bad/obj-tinyobjloader/test-nan.obj"), InputError);
}

// Data rt does not use is no note (tinyobjloader warns for each material with both d and Tr);
// data rt drops that changes the picture is one note per kind, with a count.
TEST(ImportObj, OneNotePerKindOfDroppedMaterialData) {
    TempDir dir;
    std::string mtl;
    for (const char* name : {"a", "b", "c"})
        mtl += std::string("newmtl ") + name + "\nKd 1 1 1\nd 0.5\nTr 0.5\nmap_Kd wood.png\nmap_Ks s.png\nKe 1 1 1\n";
    mtl += "newmtl plain\nKd 1 0 0\n";
    dir.write("m.mtl", mtl);
    const ImportResult r = importScene(dir.write("m.obj", std::string("mtllib m.mtl\n") + kSquare +
                                                              "usemtl a\nf 1 2 3\nusemtl b\nf 1 3 4\n"
                                                              "usemtl c\nf 1 2 4\nusemtl plain\nf 2 3 4\n"));
    const auto& notes = r.report.notes;
    const auto count = [&](const std::string& text) {
        return std::count_if(notes.begin(), notes.end(),
                             [&](const std::string& n) { return n.find(text) != std::string::npos; });
    };
    EXPECT_EQ(count("`Tr`"), 0) << "d wins over Tr, as documented: no warning about them";
    EXPECT_EQ(count("texture maps rt's material has no input for, ignored: map_Ks in 3 material(s)"), 1);
    EXPECT_EQ(count("material"), 1) << "one note per kind, not per material; transparency is used";
    // Ke is the emission, map_Kd the colour texture, beside the OBJ.
    const Material& a = r.scene.materials[r.scene.instances[0].material];
    EXPECT_EQ(a.emission.color, (Color{1, 1, 1}));
    ASSERT_TRUE(a.colorTexture);
    EXPECT_EQ(r.scene.textures[*a.colorTexture].path, dir.path("wood.png"));
}

// map_d is the cut-out's mask; without it map_Kd's alpha; without either no cut-out.
TEST(ImportObj, MapDAndTheAlphaOfMapKdCutOut) {
    TempDir dir;
    const ImportResult r = importSquare(dir,
                                        "newmtl fence\nmap_Kd wood.png\nmap_d fence.png\nnewmtl leaf\n"
                                        "map_Kd leaf.png\nnewmtl glass\nd 0.5\n",
                                        "usemtl fence\nf 1 2 3\nusemtl leaf\nf 1 3 4\nusemtl glass\nf 1 2 4\n");
    const Material &fence = materialNamed(r, "fence"), &leaf = materialNamed(r, "leaf");
    ASSERT_TRUE(fence.opacity.texture);
    EXPECT_EQ(r.scene.textures[*fence.opacity.texture].path, dir.path("fence.png"));
    EXPECT_EQ(fence.opacity.cutoff, std::optional<float>(0.5f));
    EXPECT_EQ(leaf.opacity.texture, leaf.colorTexture);
    EXPECT_EQ(leaf.opacity.cutoff, std::optional<float>(0.5f));
    EXPECT_FALSE(materialNamed(r, "glass").opacity.cutoff) << "a constant d is not a cut-out";
}

// norm, else map_bump (or bump), is the normal map; -bm its scale.
TEST(ImportObj, NormAndMapBumpAreNormalMaps) {
    TempDir dir;
    const ImportResult r =
        importSquare(dir, "newmtl a\nmap_bump -bm 0.5 a.png\nnewmtl b\nbump b.png\nnorm n.png\nnewmtl c\nKd 1 1 1\n",
                     "usemtl a\nf 1 2 3\nusemtl b\nf 1 3 4\nusemtl c\nf 1 2 4\n");
    const Material &a = materialNamed(r, "a"), &b = materialNamed(r, "b");
    ASSERT_TRUE(a.normalMap.texture && b.normalMap.texture);
    EXPECT_EQ(r.scene.textures[*a.normalMap.texture].path, dir.path("a.png"));
    EXPECT_EQ(a.normalMap.scale, 0.5f);
    EXPECT_EQ(r.scene.textures[*b.normalMap.texture].path, dir.path("n.png"));
    EXPECT_FALSE(materialNamed(r, "c").normalMap.texture);
}

// map_Ke is the emission's texture, times Ke; without Ke (or Ke 0) it glows at its own colour.
// map_Ks and map_Ns, which rt's material has no input for, are one note naming them.
TEST(ImportObj, MapKeIsTheEmissionTexture) {
    TempDir dir;
    const ImportResult r = importSquare(dir,
                                        "newmtl screen\nKd 0 0 0\nKe 1 0.5 0.25\nmap_Ke -clamp on -s 2 2 1 tv.png\n"
                                        "newmtl lamp\nmap_Ke shade.png\nmap_Ks s.png\nmap_Ns n.png\n"
                                        "newmtl plain\nKe 0.5 0.5 0.5\n",
                                        "usemtl screen\nf 1 2 3\nusemtl lamp\nf 1 3 4\nusemtl plain\nf 1 2 4\n");
    const Material &screen = materialNamed(r, "screen"), &lamp = materialNamed(r, "lamp");
    ASSERT_TRUE(screen.emission.texture && lamp.emission.texture);
    const Texture& tv = r.scene.textures[*screen.emission.texture];
    EXPECT_EQ(tv.path, dir.path("tv.png"));
    EXPECT_EQ(tv.wrapS, Texture::Wrap::Clamp);
    EXPECT_EQ(tv.scale, (std::array<float, 2>{2, 2}));
    EXPECT_EQ(screen.emission.color, (Color{1, 0.5f, 0.25f}));
    EXPECT_EQ(r.scene.textures[*lamp.emission.texture].path, dir.path("shade.png"));
    EXPECT_EQ(lamp.emission.color, (Color{1, 1, 1}));
    EXPECT_FALSE(materialNamed(r, "plain").emission.texture);
    EXPECT_EQ(materialNamed(r, "plain").emission.color, (Color{0.5f, 0.5f, 0.5f}));
    EXPECT_NE(std::find(r.report.notes.begin(), r.report.notes.end(),
                        "texture maps rt's material has no input for, ignored: map_Ks in 1 material(s), "
                        "map_Ns in 1 material(s)"),
              r.report.notes.end());
}

// A mesh whose faces mostly turn away from its vertex normals (inverted winding) is one note
// naming it; a mesh whose faces agree with them, or that has no normals, is not.
TEST(ImportObj, MeshesFacingAwayFromTheirNormalsAreNoted) {
    TempDir dir;
    const ImportResult r =
        importScene(dir.write("m.obj", std::string(kSquare) + "vn 0 0 -1\nvn 0 0 1\ng inside_out\nf 1//1 2//1 3//1\n"
                                                              "f 1//1 3//1 4//1\ng right\nf 1//2 2//2 3//2\n"
                                                              "g unsmoothed\nf 1 3 4\n"));
    const auto notes = std::count_if(r.report.notes.begin(), r.report.notes.end(), [](const std::string& n) {
        return n.find("facing away from their vertex normals") != std::string::npos;
    });
    EXPECT_EQ(notes, 1);
    EXPECT_EQ(r.report.modelsFacingAway, std::vector<std::string>{"inside_out"});
}

// vn and vt go with their corners; OBJ's v (up the image) becomes rt's (down).
TEST(ImportObj, NormalsAndTextureCoordinatesFollowTheirCorners) {
    TempDir dir;
    const ImportResult r = importScene(
        dir.write("m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0.25\nvn 0 0 2\nvn 0 1 1\nf 1/1/1 2/2/2 3/1/1\n"));
    ASSERT_EQ(r.scene.models.size(), 1u);
    const Model& m = r.scene.models[0];
    const float s = float(1 / std::sqrt(2.0));
    EXPECT_EQ(m.vertexNormals, std::vector<float>({0, 0, 1, 0, s, s, 0, 0, 1}));  // made unit length
    EXPECT_EQ(m.vertexUvs, std::vector<float>({0, 1, 1, 0.75f, 0, 1}));
    EXPECT_TRUE(m.vertexColors.empty());
}

// Without vn the mesh gets normals by crease angle, unless --flat; a vt or vn index that is
// not defined is ignored with a note.
TEST(ImportObj, MeshesWithoutNormalsAreSmoothedUnlessFlat) {
    TempDir dir;
    const std::string path = dir.write("m.obj", std::string(kSquare) + "v 2 0 0.1\nf 1 2 3 4\nf 2 5 3/7/9\n");
    const ImportResult smooth = importScene(path);
    ASSERT_EQ(smooth.scene.models.size(), 1u);
    EXPECT_EQ(smooth.scene.models[0].vertexNormals.size(), 27u);
    EXPECT_TRUE(smooth.scene.models[0].vertexUvs.empty());
    EXPECT_NE(std::find_if(smooth.report.notes.begin(), smooth.report.notes.end(),
                           [](const std::string& n) { return n.find("not defined: ignored") != std::string::npos; }),
              smooth.report.notes.end());
    ImportOptions flat;
    flat.flat = true;
    EXPECT_TRUE(importScene(path, flat).scene.models[0].vertexNormals.empty());
}

}  // namespace
}  // namespace rt
