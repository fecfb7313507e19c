#include "io/camera_3ds.h"

#include <bit>
#include <cmath>

#include "core/error.h"
#include "os/input_file.h"

namespace rt {
namespace {

constexpr std::uint16_t kMainChunk = 0x4D4D;
constexpr std::uint16_t kEditorChunk = 0x3D3D;
constexpr std::uint16_t kNamedObjectChunk = 0x4000;
constexpr std::uint16_t kCameraChunk = 0x4700;
constexpr std::size_t kChunkHeaderBytes = 6;  // uint16 id, uint32 length (header included)
constexpr std::size_t kCameraBytes = 8 * 4;   // position, target, bank, lens: float32 each

// A chunk's contents: bytes [begin, end) after its header.
struct Chunk {
    std::uint16_t id;
    std::size_t begin;
    std::size_t end;
};

// Walks the chunk tree down to the camera chunks only; every other chunk is skipped by its length.
class CameraChunkReader {
public:
    CameraChunkReader(std::span<const std::uint8_t> bytes, const std::string& name) : bytes_(bytes), name_(name) {}

    std::vector<Camera3ds> read() {
        forEachChild(0, bytes_.size(), kMainChunk, [&](const Chunk& main) {
            forEachChild(main.begin, main.end, kEditorChunk, [&](const Chunk& editor) {
                forEachChild(editor.begin, editor.end, kNamedObjectChunk,
                             [&](const Chunk& object) { readObject(object); });
            });
        });
        return std::move(cameras_);
    }

private:
    [[noreturn]] void fail(std::size_t offset, const std::string& message) const {
        throw inputErrorAtByte(name_, offset, message);
    }

    std::uint32_t littleEndian(std::size_t at, int bytes) const {
        std::uint32_t value = 0;
        for (int i = bytes; i-- > 0;) value = value << 8 | bytes_[at + std::size_t(i)];
        return value;
    }

    // Calls visit for each child chunk with the given id in [begin, end). A tail shorter than a
    // chunk header is ignored, as Assimp does; a chunk that runs past its parent is an error.
    template <class Visit>
    void forEachChild(std::size_t begin, std::size_t end, std::uint16_t id, Visit visit) const {
        for (std::size_t at = begin; end - at >= kChunkHeaderBytes;) {
            const std::uint32_t length = littleEndian(at + 2, 4);
            if (length < kChunkHeaderBytes || length > end - at)
                fail(at, "chunk of " + std::to_string(length) + " bytes does not fit in the " +
                             std::to_string(end - at) + " bytes left of its parent");
            if (littleEndian(at, 2) == id) visit(Chunk{id, at + kChunkHeaderBytes, at + length});
            at += length;
        }
    }

    void readObject(const Chunk& object) {
        std::size_t nameEnd = object.begin;
        while (nameEnd < object.end && bytes_[nameEnd] != 0) ++nameEnd;
        if (nameEnd == object.end) fail(object.begin, "object name has no terminating zero inside its chunk");
        const std::string name(bytes_.begin() + std::ptrdiff_t(object.begin), bytes_.begin() + std::ptrdiff_t(nameEnd));
        forEachChild(nameEnd + 1, object.end, kCameraChunk, [&](const Chunk& camera) { readCamera(camera, name); });
    }

    void readCamera(const Chunk& chunk, const std::string& name) {
        if (chunk.end - chunk.begin < kCameraBytes)
            fail(chunk.begin, "camera chunk holds " + std::to_string(chunk.end - chunk.begin) + " bytes, fewer than " +
                                  std::to_string(kCameraBytes));
        double v[8];
        for (std::size_t i = 0; i < 8; ++i) {
            v[i] = std::bit_cast<float>(littleEndian(chunk.begin + 4 * i, 4));
            if (!std::isfinite(v[i])) fail(chunk.begin + 4 * i, "camera number is NaN or infinite");
        }
        cameras_.push_back(
            {name, Vec3(Real(v[0]), Real(v[1]), Real(v[2])), Vec3(Real(v[3]), Real(v[4]), Real(v[5])), v[6], v[7]});
    }

    std::span<const std::uint8_t> bytes_;
    const std::string& name_;
    std::vector<Camera3ds> cameras_;
};

}  // namespace

std::vector<Camera3ds> read3dsCameras(std::span<const std::uint8_t> bytes, const std::string& name) {
    return CameraChunkReader(bytes, name).read();
}

std::vector<Camera3ds> read3dsCamerasFromFile(const std::string& path) {
    const std::string data = readInputFile(path);
    return read3dsCameras({reinterpret_cast<const std::uint8_t*>(data.data()), data.size()}, path);
}

double fovDegreesFromLens(double lensMm) { return 2400 / lensMm; }

Camera cameraFrom3ds(const Camera3ds& camera, const Transform& fileToWorld) {
    const Vec3 forward = normalize(camera.target - camera.position);
    // 3D Studio's up is +Z; a camera looking straight along Z takes -X (lib3ds_matrix_camera).
    const Vec3 fileUp = forward.x == 0 && forward.y == 0 ? Vec3(-1, 0, 0) : Vec3(0, 0, 1);
    const Vec3 right = normalize(cross(forward, fileUp));
    const Vec3 up = cross(right, forward);
    const Real bank = Real(camera.bankDegrees * kPi / 180);
    Camera out;
    out.origin = fileToWorld.point(camera.position);
    out.destination = fileToWorld.point(camera.target);
    out.up = normalize(fileToWorld.vector(up * std::cos(bank) - right * std::sin(bank)));
    out.fovDegrees = Real(fovDegreesFromLens(camera.lensMm));
    return out;
}

}  // namespace rt
