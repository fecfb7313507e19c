// 3DS cameras read from the file's own camera chunks (libtrace/import/camera_3ds.*): the
// expected numbers are the chunk's bytes, decoded here, not Assimp's values.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <fstream>
#include <iterator>

#include "core/error.h"
#include "import_test_util.h"
#include "io/camera_3ds.h"
#include "io/import.h"
#include "io/scene_defaults.h"
#include "test_util.h"

namespace rt {
namespace {

using test::sharedModels;
using test::ThreeDsFixture;

// A little-endian float32 written as 8 hex digits, as `xxd` shows the file.
float floatFromHex(const std::string& hex) {
    std::uint32_t bits = 0;
    for (int i = 3; i >= 0; --i)
        bits = bits << 8 | std::uint32_t(std::stoul(hex.substr(std::size_t(2 * i), 2), nullptr, 16));
    return std::bit_cast<float>(bits);
}

std::string fileHex(const std::string& path, std::size_t offset, std::size_t bytes) {
    std::ifstream in(path, std::ios::binary);
    const std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::string hex;
    for (std::size_t i = offset; i < offset + bytes && i < data.size(); ++i) {
        static const char* digits = "0123456789abcdef";
        hex += digits[std::uint8_t(data[i]) >> 4];
        hex += digits[std::uint8_t(data[i]) & 15];
    }
    return hex;
}

// 3D Studio's Z-up file axes in rt's Y-up world (Assimp's 3DS root turn): (x, y, z) -> (x, z, -y).
Vec3 fromFile(float x, float y, float z) { return {x, z, -y}; }

struct ChunkCamera {
    const char* file;
    std::size_t offset;  // of the 0x4700 chunk's 32 data bytes
    const char* hex[8];  // position xyz, target xyz, bank (degrees), lens (mm)
};

// `xxd -s 829 -l 32 -c 4` on each file (the camera chunk 0x4700 of object "Camera01" starts
// at byte 823; its 6-byte header is followed by the eight float32). Both files also carry a
// keyframe FOV key (chunk 0xB023) of 00003442 = 45.0 degrees for lens 53.333 mm = 2400 / 45.
const ChunkCamera kTargetCamera{
    "3ds/TargetCameraAnim/TargetCameraAnim.3ds",
    829,
    {"44bc83c2", "70f88041", "80331bc0", "f2d1c842", "28bae141", "00000000", "00000000", "55555542"}};
const ChunkCamera kRollCamera{
    "3ds/CameraRollAnim/CameraRollAnim.3ds",
    829,
    {"bd1319c3", "88685140", "9338b641", "60e914c2", "43c461be", "9338b641", "00000000", "55555542"}};

void expectCameraFromChunk(const ChunkCamera& expected) {
    const std::string path = sharedModels() + "/" + expected.file;
    std::string hex;
    for (const char* h : expected.hex) hex += h;
    ASSERT_EQ(fileHex(path, expected.offset, 32), hex) << "the documented bytes are the file's";
    float v[8];
    for (int i = 0; i < 8; ++i) v[i] = floatFromHex(expected.hex[i]);

    const ImportResult r = importScene(path);
    EXPECT_EQ(r.report.cameraUsed, "Camera01");
    const Camera& c = r.scene.camera;
    expectNear(c.origin, fromFile(v[0], v[1], v[2]), 1e-3);
    expectNear(c.destination, fromFile(v[3], v[4], v[5]), 1e-3);
    // Bank 0: the up is the file's +Z (rt's +Y) made perpendicular to the view, no roll.
    const Vec3 view = normalize(c.destination - c.origin);
    expectNear(c.up, normalize(Vec3(0, 1, 0) - view * view.y), 1e-6);
    ASSERT_TRUE(c.fovDegrees);
    EXPECT_NEAR(*c.fovDegrees, 2400 / v[7], 1e-4);
    EXPECT_NEAR(*c.fovDegrees, floatFromHex("00003442"), 1e-4);  // the camera's own FOV key
}

TEST(Import3dsCamera, TargetCameraIsTheFilesCameraChunk) {
    SKIP_WITHOUT_SHARED_MODELS();
    expectCameraFromChunk(kTargetCamera);
}

TEST(Import3dsCamera, RollCameraIsTheFilesCameraChunk) {
    SKIP_WITHOUT_SHARED_MODELS();
    expectCameraFromChunk(kRollCamera);
}

// The model is in view: the view cone of the horizontal fov meets the model's bounding sphere.
TEST(Import3dsCamera, CameraLooksTowardsTheModel) {
    SKIP_WITHOUT_SHARED_MODELS();
    for (const ChunkCamera* file : {&kTargetCamera, &kRollCamera}) {
        const ImportResult r = importScene(sharedModels() + "/" + file->file);
        SCOPED_TRACE(file->file);
        const Camera& c = r.scene.camera;
        const Aabb bounds = sceneBounds(r.scene);
        const Vec3 toModel = bounds.center() - c.origin;
        const double distance = length(toModel), radius = length(bounds.diagonal()) / 2;
        ASSERT_GT(distance, radius) << "the camera is outside the model";
        const double cosine = dot(normalize(c.destination - c.origin), toModel / Real(distance));
        const double angle = std::acos(std::clamp(cosine, -1.0, 1.0)) - std::asin(radius / distance);
        EXPECT_LT(angle * 180 / kPi, *c.fovDegrees / 2);
    }
}

TEST(Import3dsCamera, AutoIgnoresTheFilesCameras) {
    SKIP_WITHOUT_SHARED_MODELS();
    ImportOptions o;
    o.camera = kFramingCamera;
    const ImportResult r = importScene(sharedModels() + "/" + kTargetCamera.file, o);
    EXPECT_EQ(r.report.camerasInFile, 1u);
    EXPECT_TRUE(r.report.cameraUsed.empty());
    EXPECT_TRUE(r.report.cameraGenerated);
    EXPECT_NE(std::find_if(r.report.notes.begin(), r.report.notes.end(),
                           [](const std::string& n) { return n.starts_with("--camera auto: made one"); }),
              r.report.notes.end());
}

// A bank of 90 degrees rolls the camera counter-clockwise as seen from behind it: its up
// becomes its left. A camera looking straight down Z takes -X as its up (lib3ds).
TEST(Import3dsCamera, BankAngleRollsTheUpVector) {
    const Camera3ds looksAlongY{"c", Vec3(0, 0, 0), Vec3(0, 5, 0), 90, 50};
    const Camera level = cameraFrom3ds({"c", Vec3(0, 0, 0), Vec3(0, 5, 0), 0, 50}, Transform());
    expectNear(level.up, Vec3(0, 0, 1), 1e-6);
    expectNear(cameraFrom3ds(looksAlongY, Transform()).up, Vec3(-1, 0, 0), 1e-6);
    expectNear(cameraFrom3ds({"c", Vec3(0, 0, 9), Vec3(0, 0, 0), 0, 50}, Transform()).up, Vec3(-1, 0, 0), 1e-6);
    EXPECT_DOUBLE_EQ(*level.fovDegrees, 48);
}

TEST(Import3dsCamera, BankAngleReachesTheSceneCamera) {
    TempDir dir;
    const auto bytes = ThreeDsFixture::file({ThreeDsFixture::mesh("tri", {-1, 5, -1, 1, 5, -1, 0, 5, 1}),
                                             ThreeDsFixture::camera("Cam", {0, 0, 0, 0, 5, 0, 90, 50})});
    const ImportResult r = importScene(ThreeDsFixture::write(dir, bytes));
    EXPECT_EQ(r.report.cameraUsed, "Cam");
    expectNear(r.scene.camera.up, fromFile(-1, 0, 0), 1e-6);
    expectNear(r.scene.camera.destination, fromFile(0, 5, 0), 1e-6);
}

std::vector<std::uint8_t> cameraFile(const std::vector<float>& numbers) {
    return ThreeDsFixture::file({ThreeDsFixture::camera("Cam", numbers)});
}

TEST(Import3dsCamera, ChunkReaderReadsEveryNumber) {
    const std::vector<Camera3ds> cams = read3dsCameras(cameraFile({1, 2, 3, 4, 5, 6, 7, 8}), "f");
    ASSERT_EQ(cams.size(), 1u);
    EXPECT_EQ(cams[0].name, "Cam");
    EXPECT_EQ(cams[0].position, Vec3(1, 2, 3));
    EXPECT_EQ(cams[0].target, Vec3(4, 5, 6));
    EXPECT_EQ(cams[0].bankDegrees, 7);
    EXPECT_EQ(cams[0].lensMm, 8);
}

void expectByteError(const std::vector<std::uint8_t>& bytes, const std::string& where) {
    try {
        read3dsCameras(bytes, "f.3ds");
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(where), std::string::npos) << e.what();
    }
}

// Layout of cameraFile: main header at 0, editor header at 6, object header at 12, name
// "Cam\0" at 18, camera header at 22, its numbers at 28..60.
TEST(Import3dsCamera, MalformedChunksAreInputErrorsWithTheirByte) {
    const std::vector<std::uint8_t> good = cameraFile({1, 2, 3, 4, 5, 6, 7, 8});
    ASSERT_EQ(good.size(), 60u);
    std::vector<std::uint8_t> b = good;
    b.resize(40);  // cut inside the camera numbers: the main chunk runs past the file
    expectByteError(b, "byte 0");
    b = good;
    b[24] = 20;  // the camera chunk claims 20 bytes: 14 numbers' bytes instead of 32
    b[14] = std::uint8_t(b[14] - 18), b[8] = std::uint8_t(b[8] - 18), b[2] = std::uint8_t(b[2] - 18);
    b.resize(42);
    expectByteError(b, "byte 28");
    b = good;
    b[14] = 200;  // the object runs past the editor
    expectByteError(b, "byte 12");
    b = good;
    std::fill(b.begin() + 21, b.end(), 'x');  // no zero after the name inside the object
    expectByteError(b, "byte 18");
    b = cameraFile({1, 2, 3, 4, std::nanf(""), 6, 7, 8});
    expectByteError(b, "byte 44");
    // Any cut or any byte set to 0 or 255: an error or a result, never a read past the end
    // (the asan preset checks that).
    std::vector<std::vector<std::uint8_t>> mutants;
    for (std::size_t size = 0; size < good.size(); ++size)
        mutants.emplace_back(good.begin(), good.begin() + std::ptrdiff_t(size));
    for (std::size_t at = 0; at < good.size(); ++at)
        for (const std::uint8_t value : {0, 255}) {
            mutants.push_back(good);
            mutants.back()[at] = value;
        }
    for (const std::vector<std::uint8_t>& mutant : mutants) {
        try {
            EXPECT_LE(read3dsCameras(mutant, "f").size(), 1u);
        } catch (const InputError&) {}
    }
}

}  // namespace
}  // namespace rt
