#include "scene/raw_model.h"

#include <bit>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <vector>

#include "core/atomic_file.h"
#include "core/error.h"
#include "scene/input_file.h"

namespace rt {
namespace {

constexpr char kMagic[5] = {'r', 'a', 'w', '3', 'd'};
constexpr std::size_t kTriangleFloats = 9;
constexpr std::size_t kSphereFloats = 4;

// What the 10-byte header says: which array the data goes to and how many floats follow.
struct RawHeader {
    char type = 'T';
    std::uint32_t count = 0;
    std::size_t floats() const { return std::size_t(count) * (type == 'T' ? kTriangleFloats : kSphereFloats); }
};

std::uint32_t readUint32LE(const std::uint8_t* p) {
    return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 | std::uint32_t(p[3]) << 24;
}

// Checks the header and that the data fills the rest of the file exactly, before the
// caller allocates anything: a count can claim up to 4 G primitives.
RawHeader parseHeader(const std::uint8_t* header, std::uint64_t totalBytes, const std::string& name) {
    if (totalBytes < kRawHeaderBytes)
        throw inputErrorAtByte(name, totalBytes,
                               "truncated RAW header (" + std::to_string(totalBytes) + " of 10 bytes)");
    if (std::memcmp(header, kMagic, sizeof kMagic) != 0)
        throw inputErrorAtByte(name, 0, "not a RAW model (the file must start with \"raw3d\")");
    RawHeader h;
    h.type = char(header[5]);
    if (h.type != 'T' && h.type != 'S')
        throw inputErrorAtByte(name, 5, "unknown RAW model type (expected 'T' or 'S')");
    h.count = readUint32LE(header + 6);
    const std::uint64_t dataBytes = std::uint64_t(h.floats()) * sizeof(float);
    const std::uint64_t available = totalBytes - kRawHeaderBytes;
    const std::string what = std::to_string(dataBytes) + " bytes of data for " + std::to_string(h.count) +
                             (h.type == 'T' ? " triangle" : " sphere") + (h.count == 1 ? "" : "s");
    if (available < dataBytes)
        throw inputErrorAtByte(name, totalBytes, "truncated RAW data: " + what + ", the file has " +
                                                     std::to_string(available));
    if (available > dataBytes)
        throw inputErrorAtByte(name, kRawHeaderBytes + dataBytes,
                               std::to_string(available - dataBytes) + " bytes after the " + what);
    return h;
}

// The data was copied in as raw bytes: swap them on a big-endian host, then reject
// numbers that would poison every computation they touch.
void finishFloats(std::vector<float>& values, const std::string& name) {
    if constexpr (std::endian::native == std::endian::big) {
        for (float& f : values) {
            std::uint8_t b[4];
            std::memcpy(b, &f, 4);
            const std::uint32_t u = readUint32LE(b);
            std::memcpy(&f, &u, 4);
        }
    }
    for (std::size_t i = 0; i < values.size(); ++i)
        if (!std::isfinite(values[i]))
            throw inputErrorAtByte(name, kRawHeaderBytes + i * sizeof(float),
                                   std::isnan(values[i]) ? "NaN in RAW data" : "infinite number in RAW data");
}

std::vector<float>& arrayFor(Model& model, const RawHeader& h) {
    return h.type == 'T' ? model.triangleVertices : model.sphereData;
}

void writeUint32LE(std::ostream& out, std::uint32_t v) {
    const char b[4] = {char(v & 0xff), char(v >> 8 & 0xff), char(v >> 16 & 0xff), char(v >> 24 & 0xff)};
    out.write(b, 4);
}

}  // namespace

Model readRawFile(const std::string& path) {
    const std::uint64_t size = inputFileSize(path);
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path + ": cannot open: " + std::strerror(errno));
    std::uint8_t header[kRawHeaderBytes] = {};
    in.read(reinterpret_cast<char*>(header), std::streamsize(std::min<std::uint64_t>(size, kRawHeaderBytes)));
    const RawHeader h = parseHeader(header, size, path);
    Model model;
    std::vector<float>& values = arrayFor(model, h);
    values.resize(h.floats());
    in.read(reinterpret_cast<char*>(values.data()), std::streamsize(values.size() * sizeof(float)));
    if (!in) throw InputError(path + ": read error");
    finishFloats(values, path);
    return model;
}

Model readRawBytes(std::span<const std::uint8_t> bytes, const std::string& name) {
    const RawHeader h = parseHeader(bytes.data(), bytes.size(), name);
    Model model;
    std::vector<float>& values = arrayFor(model, h);
    values.resize(h.floats());
    if (!values.empty()) std::memcpy(values.data(), bytes.data() + kRawHeaderBytes, values.size() * sizeof(float));
    finishFloats(values, name);
    return model;
}

void writeRaw(std::ostream& out, const Model& model) {
    if (!model.triangleVertices.empty() && !model.sphereData.empty())
        throw std::invalid_argument("model '" + model.name + "' has triangles and spheres; a RAW file holds one kind");
    const bool spheres = !model.sphereData.empty();
    const std::size_t count = spheres ? model.sphereCount() : model.triangleCount();
    if (count > UINT32_MAX) throw std::invalid_argument("model '" + model.name + "' is too large for a RAW file");
    const std::vector<float>& values = spheres ? model.sphereData : model.triangleVertices;
    out.write(kMagic, sizeof kMagic);
    out.put(spheres ? 'S' : 'T');
    writeUint32LE(out, std::uint32_t(count));
    if constexpr (std::endian::native == std::endian::little) {
        out.write(reinterpret_cast<const char*>(values.data()), std::streamsize(values.size() * sizeof(float)));
    } else {
        for (float f : values) writeUint32LE(out, std::bit_cast<std::uint32_t>(f));
    }
}

void writeRawFile(const std::string& path, const Model& model) {
    writeFileAtomically(path, [&](std::ostream& out) { writeRaw(out, model); });
}

}  // namespace rt
