// Import of the Assimp formats shared/models has no files for (PLY, STL, Collada, NFF, OFF):
// tiny files written here, so that each checks where the file puts its vertices, how many
// triangles it has, and for Collada that a mesh placed by two nodes stays one model.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.h"
#include "import_test_util.h"
#include "io/import.h"
#include "io/raw_model.h"
#include "test_util.h"

namespace rt {
namespace {

using test::TempDir;

// Twice the area of every triangle of every model, summed: the winding and the way a
// polygon was split do not change it, the vertices do.
double doubleArea(const Scene& scene) {
    double sum = 0;
    for (const Model& m : scene.models) {
        const std::vector<float>& v = m.triangleVertices;
        for (std::size_t t = 0; t + 9 <= v.size(); t += 9) {
            const Vec3 a(v[t], v[t + 1], v[t + 2]), b(v[t + 3], v[t + 4], v[t + 5]), c(v[t + 6], v[t + 7], v[t + 8]);
            sum += double(length(cross(b - a, c - a)));
        }
    }
    return sum;
}

// Every triangle corner of every model is one of `points`: nothing moved, nothing invented.
void expectCornersAmong(const Scene& scene, const std::vector<Vec3>& points) {
    for (const Model& m : scene.models) {
        for (std::size_t i = 0; i + 3 <= m.triangleVertices.size(); i += 3) {
            const Vec3 p(m.triangleVertices[i], m.triangleVertices[i + 1], m.triangleVertices[i + 2]);
            const bool found =
                std::any_of(points.begin(), points.end(), [&](const Vec3& q) { return length(p - q) < Real(1e-6); });
            EXPECT_TRUE(found) << "corner (" << p.x << ", " << p.y << ", " << p.z << ") is not a vertex of the file";
        }
    }
}

// The message of the rt::InputError importing `path` throws; empty (and a failure) if it throws none.
std::string importErrorOf(const std::string& path) {
    try {
        importScene(path);
    } catch (const InputError& e) {
        return e.what();
    }
    ADD_FAILURE() << path << " imported without an error";
    return "";
}

// The unit square z = 0 split by Triangulate, and a triangle above it at z = 1.
const char* const kPlyQuadAndTriangle = R"(ply
format ascii 1.0
element vertex 7
property float x
property float y
property float z
element face 2
property list uchar int vertex_indices
end_header
0 0 0
2 0 0
2 1 0
0 1 0
0 0 1
1 0 1
0 3 1
4 0 1 2 3
3 4 5 6
)";

TEST(ImportFormats, AsciiPlyQuadAndTriangle) {
    TempDir dir;
    const ImportResult r = importScene(dir.write("quad.ply", kPlyQuadAndTriangle));
    EXPECT_EQ(test::modelTriangles(r.scene), 3u);  // the quad as two triangles
    EXPECT_NEAR(doubleArea(r.scene), 2 * 2 + 3, 1e-5);
    expectCornersAmong(r.scene, {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 3, 1}});
}

TEST(ImportFormats, PlyFaceIndexOutOfRangeIsAnInputError) {
    TempDir dir;
    const std::string bad = dir.write("bad.ply", test::replaceOnce(kPlyQuadAndTriangle, "3 4 5 6", "3 4 5 7"));
    EXPECT_NE(importErrorOf(bad).find("out of range"), std::string::npos);  // Assimp's validation finds it
}

TEST(ImportFormats, AsciiStlTwoFacets) {
    TempDir dir;
    const ImportResult r = importScene(dir.write("two.stl", R"(solid two
facet normal 0 0 1
  outer loop
    vertex 0 0 0
    vertex 1 0 0
    vertex 0 1 0
  endloop
endfacet
facet normal 1 0 0
  outer loop
    vertex 5 0 0
    vertex 5 2 0
    vertex 5 0 2
  endloop
endfacet
endsolid two
)"));
    EXPECT_EQ(test::modelTriangles(r.scene), 2u);
    EXPECT_NEAR(doubleArea(r.scene), 1 + 4, 1e-5);
    expectCornersAmong(r.scene, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 0, 0}, {5, 2, 0}, {5, 0, 2}});
}

// Binary STL: an 80-byte header, a little-endian uint32 facet count, then per facet a normal,
// three vertices (12 floats) and a 16-bit attribute word, 50 bytes.
std::string binaryStl(const std::string& header, const std::vector<std::vector<float>>& facets) {
    std::string out = header;
    out.resize(80, ' ');
    const std::uint32_t count = std::uint32_t(facets.size());
    const auto put = [&out](const void* p, std::size_t n) { out.append(static_cast<const char*>(p), n); };
    put(&count, 4);  // the test machines are little-endian, as the format
    for (const std::vector<float>& f : facets) {
        const float normal[3] = {0, 0, 1};
        put(normal, sizeof normal);
        put(f.data(), 9 * sizeof(float));
        const std::uint16_t attribute = 0;
        put(&attribute, 2);
    }
    return out;
}

const std::vector<std::vector<float>> kStlFacets{{0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 0, 3, 2, 0, 3, 0, 2, 3}};

// Many exporters start the binary header with "solid", which should announce ASCII; Assimp
// reads the file as binary when its size is exactly what the facet count says.
const char* const kStlHeaders[] = {"binary facets", "solid written by a careless exporter"};

TEST(ImportFormats, BinaryStl) {
    TempDir dir;
    for (const char* header : kStlHeaders) {
        SCOPED_TRACE(header);
        const ImportResult r = importScene(dir.write("two.stl", binaryStl(header, kStlFacets)));
        EXPECT_EQ(test::modelTriangles(r.scene), 2u);
        EXPECT_NEAR(doubleArea(r.scene), 1 + 4, 1e-5);
        expectCornersAmong(r.scene, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 3}, {2, 0, 3}, {0, 2, 3}});
    }
}

// The count promises two facets; the file ends 20 bytes into the second. Assimp then does not
// take it for binary; under a "solid" header it parses the bytes as ASCII and finds no vertex.
TEST(ImportFormats, TruncatedBinaryStlIsAnInputError) {
    TempDir dir;
    for (const char* header : kStlHeaders) {
        SCOPED_TRACE(header);
        const std::string whole = binaryStl(header, kStlFacets);
        EXPECT_FALSE(importErrorOf(dir.write("cut.stl", whole.substr(0, whole.size() - 30))).empty());
    }
}

// One geometry (a unit right triangle) placed by two nodes, each with a translate, and bound
// to a material whose Phong diffuse is orange.
const char* const kColladaTwoPlacements = R"(<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit name="meter" meter="1"/><up_axis>Y_UP</up_axis></asset>
  <library_effects>
    <effect id="orange-fx"><profile_COMMON><technique sid="common"><phong>
      <diffuse><color>1 0.5 0.25 1</color></diffuse>
    </phong></technique></profile_COMMON></effect>
  </library_effects>
  <library_materials>
    <material id="orange" name="orange"><instance_effect url="#orange-fx"/></material>
  </library_materials>
  <library_geometries>
    <geometry id="tri" name="tri"><mesh>
      <source id="tri-pos">
        <float_array id="tri-pos-array" count="9">0 0 0 1 0 0 0 1 0</float_array>
        <technique_common><accessor source="#tri-pos-array" count="3" stride="3">
          <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
        </accessor></technique_common>
      </source>
      <vertices id="tri-vtx"><input semantic="POSITION" source="#tri-pos"/></vertices>
      <triangles material="paint" count="1">
        <input semantic="VERTEX" source="#tri-vtx" offset="0"/>
        <p>0 1 2</p>
      </triangles>
    </mesh></geometry>
  </library_geometries>
  <library_visual_scenes>
    <visual_scene id="scene">
      <node id="left" name="left"><translate>-3 0 0</translate>
        <instance_geometry url="#tri"><bind_material><technique_common>
          <instance_material symbol="paint" target="#orange"/>
        </technique_common></bind_material></instance_geometry>
      </node>
      <node id="right" name="right"><translate>4 2 1</translate>
        <instance_geometry url="#tri"><bind_material><technique_common>
          <instance_material symbol="paint" target="#orange"/>
        </technique_common></bind_material></instance_geometry>
      </node>
    </visual_scene>
  </library_visual_scenes>
  <scene><instance_visual_scene url="#scene"/></scene>
</COLLADA>
)";

TEST(ImportFormats, ColladaMeshPlacedTwiceIsOneModelWithTwoInstances) {
    TempDir dir;
    ImportResult r = importScene(dir.write("two.dae", kColladaTwoPlacements));
    ASSERT_EQ(r.scene.models.size(), 1u);
    EXPECT_EQ(r.scene.models[0].triangleCount(), 1u);
    expectCornersAmong(r.scene, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    ASSERT_EQ(r.scene.instances.size(), 2u);
    std::vector<Vec3> origins;
    for (const Instance& i : r.scene.instances) {
        EXPECT_EQ(i.model, 0u);
        origins.push_back(i.transform.point(Vec3(0, 0, 0)));
        const Material& m = r.scene.materials.at(i.material);
        EXPECT_FLOAT_EQ(m.color.r, 1);
        EXPECT_FLOAT_EQ(m.color.g, 0.5f);
        EXPECT_FLOAT_EQ(m.color.b, 0.25f);
    }
    std::sort(origins.begin(), origins.end(), [](const Vec3& a, const Vec3& b) { return a.x < b.x; });
    expectNear(origins[0], {-3, 0, 0});
    expectNear(origins[1], {4, 2, 1});
    r.scene.flatten();
    EXPECT_EQ(r.scene.primitives.count<Triangle>(), 2u);
}

// A Collada file says its up axis itself, and Assimp applies it; --up-axis, when given, takes
// its place: Z_UP and --up-axis z turn the file once (not twice), --up-axis y keeps its axes.
TEST(ImportFormats, ColladaUpAxisIsTurnedOnce) {
    TempDir dir;
    const std::string path = dir.write("z.dae", test::replaceOnce(kColladaTwoPlacements, "Y_UP", "Z_UP"));
    const auto rightOrigin = [&](std::optional<UpAxis> up) {
        ImportOptions o;
        o.upAxis = up;
        Vec3 furthest(-1e9, 0, 0);
        for (const Instance& i : importScene(path, o).scene.instances)
            if (i.transform.point(Vec3()).x > furthest.x) furthest = i.transform.point(Vec3());
        return furthest;  // the node translated by (4, 2, 1) in the file
    };
    expectNear(rightOrigin(std::nullopt), {4, 1, -2});
    expectNear(rightOrigin(UpAxis::Z), {4, 1, -2});
    expectNear(rightOrigin(UpAxis::Y), {4, 2, 1});
}

// A thesis RAW model (appendix D) is read as one, not by Assimp's unrelated RAW reader: one
// model placed once, framed by the generated camera (spheres count in the bounds), under any
// name that starts with the RAW magic.
TEST(ImportFormats, ThesisRawModelIsOneInstance) {
    TempDir dir;
    Model ball;
    ball.sphereData = {10, 0, 0, 2};
    for (const char* name : {"ball.raw", "ball-without-extension"}) {
        SCOPED_TRACE(name);
        const std::string path = dir.path(name);
        writeRawFile(path, ball);
        const ImportResult r = importScene(path);
        EXPECT_EQ(r.report.format, "thesis RAW model");
        ASSERT_EQ(r.scene.models.size(), 1u);
        EXPECT_EQ(r.scene.models[0].sphereData, ball.sphereData);
        ASSERT_EQ(r.scene.instances.size(), 1u);
        EXPECT_TRUE(r.report.cameraGenerated);
        expectNear(r.scene.camera.destination - r.scene.camera.origin,
                   normalize(Vec3(10, 0, 0) - r.scene.camera.origin) *
                       length(r.scene.camera.destination - r.scene.camera.origin),
                   Real(1e-3));
    }
}

// The format table (import.cpp): the extension in any case, or a signature (GLB, RAW) under
// any name, picks the importer; Assimp reads the rest.
TEST(ImportFormats, TheExtensionInAnyCaseOrTheSignatureChoosesTheImporter) {
    TempDir dir;
    const std::string triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    EXPECT_EQ(importScene(dir.write("tri.OBJ", triangle)).report.format, "Wavefront OBJ");
    EXPECT_EQ(importScene(dir.write("tri.Obj", triangle)).report.format, "Wavefront OBJ");
    Model ball;
    ball.sphereData = {0, 0, 0, 1};
    for (const char* name : {"ball.RAW", "ball.stl"}) {
        writeRawFile(dir.path(name), ball);
        EXPECT_EQ(importScene(dir.path(name)).report.format, "thesis RAW model") << name;
    }
    test::GltfFixture gltf;
    gltf.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    gltf.indices = {0, 1, 2};
    EXPECT_EQ(importScene(dir.write("tri.GLTF", gltf.json())).report.format, "glTF 2.0");
    EXPECT_NE(importScene(dir.write("tri.stl",
                                    "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n"
                                    "vertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid t\n"))
                  .report.format.find("STL"),
              std::string::npos);
}

// An NFF polygon ("p", vertex count, then one vertex per line) after a fill colour
// ("f" red green blue Kd Ks shine transmittance index of refraction).
TEST(ImportFormats, NffPolygon) {
    TempDir dir;
    const ImportResult r = importScene(dir.write("quad.nff", R"(f 0.2 0.4 0.6 1 0 0 0 1
p 4
0 0 0
3 0 0
3 2 0
0 2 0
)"));
    EXPECT_EQ(test::modelTriangles(r.scene), 2u);
    EXPECT_NEAR(doubleArea(r.scene), 2 * 6, 1e-5);
    ASSERT_EQ(r.scene.materials.size(), 1u);
    EXPECT_FLOAT_EQ(r.scene.materials[0].color.r, 0.2f);
    EXPECT_FLOAT_EQ(r.scene.materials[0].color.g, 0.4f);
    EXPECT_FLOAT_EQ(r.scene.materials[0].color.b, 0.6f);
    expectCornersAmong(r.scene, {{0, 0, 0}, {3, 0, 0}, {3, 2, 0}, {0, 2, 0}});
}

// OFF: the counts (vertices, faces, edges), the vertices, then faces as a count and indices.
TEST(ImportFormats, OffQuadAndTriangle) {
    TempDir dir;
    const ImportResult r = importScene(dir.write("shape.off", R"(OFF
6 2 0
0 0 0
1 0 0
1 1 0
0 1 0
0 0 2
2 0 2
4 0 1 2 3
3 0 4 5
)"));
    EXPECT_EQ(test::modelTriangles(r.scene), 3u);
    EXPECT_NEAR(doubleArea(r.scene), 2 * 1 + 4, 1e-5);
    expectCornersAmong(r.scene, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 2}, {2, 0, 2}});
}

// One definition of a degenerate triangle for every importer (docs/conversion.md): its cross
// product, computed in double from its corners in float (as RAW stores them), is exactly zero.
// So collinear corners and repeated corners are dropped; a sliver one float step away from a
// line, and a tiny triangle, are kept.
TEST(ImportFormats, DegenerateTrianglesAreTheSameInEveryImporter) {
    const float step = std::nextafter(2.0f, 3.0f);
    const std::vector<float> corners{
        0, 0, 0, 1,     0, 0, 0, 1,     0,     // valid
        0, 0, 0, 1,     1, 1, 2, 2,     2,     // collinear
        0, 0, 0, 0,     0, 0, 0, 1,     0,     // a repeated corner
        0, 0, 0, 1,     1, 1, 2, 2,     step,  // a sliver, not collinear in float
        0, 0, 0, 1e-3f, 0, 0, 0, 1e-3f, 0,     // tiny
    };
    std::ostringstream vertices, obj, ply;
    vertices.precision(9);
    for (std::size_t i = 0; i < corners.size(); i += 3)
        vertices << corners[i] << ' ' << corners[i + 1] << ' ' << corners[i + 2] << '\n';
    std::istringstream lines(vertices.str());
    for (std::string line; std::getline(lines, line);) obj << "v " << line << '\n';
    ply << "ply\nformat ascii 1.0\nelement vertex 15\nproperty float x\nproperty float y\nproperty float z\n"
           "element face 5\nproperty list uchar int vertex_indices\nend_header\n"
        << vertices.str();
    for (int t = 0; t < 5; ++t) {
        obj << "f " << 3 * t + 1 << ' ' << 3 * t + 2 << ' ' << 3 * t + 3 << '\n';
        ply << "3 " << 3 * t << ' ' << 3 * t + 1 << ' ' << 3 * t + 2 << '\n';
    }
    test::GltfFixture gltf;
    gltf.positions = corners;
    gltf.indices.resize(15);
    for (std::uint16_t i = 0; i < 15; ++i) gltf.indices[i] = i;
    TempDir dir;
    for (const std::string& path :
         {dir.write("d.obj", obj.str()), dir.write("d.ply", ply.str()), dir.write("d.gltf", gltf.json())}) {
        SCOPED_TRACE(path);
        const ImportResult r = importScene(path);
        EXPECT_EQ(test::modelTriangles(r.scene), 3u);
        EXPECT_EQ(r.report.droppedDegenerate, 2u);
    }
}

// Collada lights through Assimp's aiLight: a spot with the pure quadratic attenuation keeps
// its falloff, cone and the node's -Z; a directional light its direction; a point light with a
// linear term is drawn without falloff, with a note.
TEST(ImportFormats, ColladaLightsKeepTheirKind) {
    TempDir dir;
    std::string dae = test::replaceOnce(kColladaTwoPlacements, "  <library_visual_scenes>", R"(  <library_lights>
    <light id="spot" name="spot"><technique_common><spot><color>1 1 1</color>
      <constant_attenuation>0</constant_attenuation><linear_attenuation>0</linear_attenuation>
      <quadratic_attenuation>1</quadratic_attenuation><falloff_angle>30</falloff_angle>
    </spot></technique_common></light>
    <light id="sun" name="sun"><technique_common><directional><color>0.5 0.5 0.5</color></directional>
    </technique_common></light>
    <light id="bulb" name="bulb"><technique_common><point><color>0.25 0.25 0.25</color>
      <linear_attenuation>1</linear_attenuation></point></technique_common></light>
  </library_lights>
  <library_visual_scenes>)");
    dae =
        test::replaceOnce(dae, "    </visual_scene>", R"(      <node id="lamp" name="lamp"><translate>0 5 0</translate>
        <rotate>1 0 0 -90</rotate><instance_light url="#spot"/></node>
      <node id="sky" name="sky"><instance_light url="#sun"/></node>
      <node id="desk" name="desk"><translate>1 1 1</translate><instance_light url="#bulb"/></node>
    </visual_scene>)");
    const ImportResult r = importScene(dir.write("lights.dae", dae));
    ASSERT_EQ(r.scene.lights.size(), 3u);
    std::map<Light::Type, Light> byType;
    for (const Light& l : r.scene.lights) byType[l.type] = l;
    const Light &spot = byType[Light::Type::Spot], &sun = byType[Light::Type::Directional],
                &bulb = byType[Light::Type::Point];
    expectNear(spot.position, {0, 5, 0}, 1e-6);
    expectNear(spot.direction, {0, -1, 0}, 1e-6);
    EXPECT_EQ(spot.falloff, Light::Falloff::InverseSquare);
    EXPECT_GT(spot.outerConeDegrees, 0);
    EXPECT_LE(spot.innerConeDegrees, spot.outerConeDegrees);
    EXPECT_FLOAT_EQ(spot.color.r, 1);
    expectNear(sun.direction, {0, 0, -1}, 1e-6);
    EXPECT_FLOAT_EQ(sun.color.r, 0.5f);
    expectNear(bulb.position, {1, 1, 1}, 1e-6);
    EXPECT_EQ(bulb.falloff, Light::Falloff::None);
    std::size_t notes = 0;
    for (const std::string& n : r.report.notes) notes += n.find("other than the inverse square") != std::string::npos;
    EXPECT_EQ(notes, 1u);
}

}  // namespace
}  // namespace rt
