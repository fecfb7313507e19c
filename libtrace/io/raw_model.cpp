#include "io/raw_model.h"

#include <bit>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <istream>
#include <stdexcept>
#include <streambuf>
#include <vector>

#include "core/error.h"
#include "os/atomic_file.h"
#include "os/input_file.h"

namespace rt {
namespace {

constexpr char kMagic[5] = {'r', 'a', 'w', '3', 'd'};
constexpr std::size_t kTriangleFloats = 9;
constexpr std::size_t kSphereFloats = 4;
constexpr std::size_t kTagBytes = 4;

// The rt extension: per-corner data of the triangles after them, each section a 4-byte tag
// and count x floatsPerTriangle float32 (docs/scene-format.md).
struct RawSection {
    char tag[kTagBytes];
    std::vector<float> Model::*array;
    std::size_t floatsPerTriangle;
    const char* what;
};
constexpr RawSection kSections[] = {
    {{'v', 'n', 'r', 'm'}, &Model::vertexNormals, 9, "vertex normals"},
    {{'v', 't', 'e', 'x'}, &Model::vertexUvs, 6, "texture coordinates"},
    {{'v', 'c', 'o', 'l'}, &Model::vertexColors, 9, "vertex colours"},
    {{'v', 't', 'a', 'n'}, &Model::vertexTangents, 12, "tangents"},
};

// What the 10-byte header says: which array the data goes to and how many floats follow.
struct RawHeader {
    char type = 'T';
    std::uint32_t count = 0;
    std::size_t floats() const { return std::size_t(count) * (type == 'T' ? kTriangleFloats : kSphereFloats); }
    std::string dataNamed(std::uint64_t bytes, const char* what) const {
        return std::to_string(bytes) + " bytes of " + what + " for " + std::to_string(count) +
               (type == 'T' ? " triangle" : " sphere") + (count == 1 ? "" : "s");
    }
};

std::uint32_t readUint32LE(const std::uint8_t* p) {
    return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 | std::uint32_t(p[3]) << 24;
}

// A stream over bytes in memory, so that files and inline data are read by one parser.
class MemoryBuffer : public std::streambuf {
public:
    explicit MemoryBuffer(std::span<const std::uint8_t> bytes) {
        char* begin = const_cast<char*>(reinterpret_cast<const char*>(bytes.data()));
        setg(begin, begin, begin + bytes.size());
    }
};

// Reads RAW data of known total size from `in`. Every size is checked against what the
// file holds before anything is allocated: a count can claim up to 4 G primitives.
class RawReader {
public:
    RawReader(std::istream& in, std::uint64_t totalBytes, const std::string& name)
        : in_(in), total_(totalBytes), name_(name) {}
    Model read();

private:
    RawHeader readHeader();
    void readSection(Model& model, const RawHeader& h);
    // Reads `floats` float32 into `values`, checking that they are there and finite.
    void readFloats(std::vector<float>& values, std::size_t floats, const RawHeader& h, const char* what);
    void readBytes(void* to, std::size_t n);
    std::uint64_t left() const { return total_ - at_; }

    std::istream& in_;
    std::uint64_t total_;
    std::uint64_t at_ = 0;
    const std::string& name_;
};

Model RawReader::read() {
    const RawHeader h = readHeader();
    Model model;
    readFloats(h.type == 'T' ? model.triangleVertices : model.sphereData, h.floats(), h, "data");
    if (h.type == 'S' && left() > 0)
        throw inputErrorAtByte(name_, at_,
                               std::to_string(left()) + " bytes after the " +
                                   h.dataNamed(std::uint64_t(h.floats()) * sizeof(float), "data"));
    while (left() > 0) readSection(model, h);
    return model;
}

RawHeader RawReader::readHeader() {
    if (total_ < kRawHeaderBytes)
        throw inputErrorAtByte(name_, total_, "truncated RAW header (" + std::to_string(total_) + " of 10 bytes)");
    std::uint8_t header[kRawHeaderBytes];
    readBytes(header, kRawHeaderBytes);
    if (std::memcmp(header, kMagic, sizeof kMagic) != 0)
        throw inputErrorAtByte(name_, 0, "not a RAW model (the file must start with \"raw3d\")");
    RawHeader h;
    h.type = char(header[5]);
    if (h.type != 'T' && h.type != 'S')
        throw inputErrorAtByte(name_, 5, "unknown RAW model type (expected 'T' or 'S')");
    h.count = readUint32LE(header + 6);
    return h;
}

// One section of per-corner data after the triangles (rt extension).
void RawReader::readSection(Model& model, const RawHeader& h) {
    const std::uint64_t start = at_;
    char tag[kTagBytes] = {};
    if (left() >= kTagBytes) readBytes(tag, kTagBytes);
    for (const RawSection& section : kSections) {
        if (std::memcmp(tag, section.tag, kTagBytes) != 0) continue;
        std::vector<float>& values = model.*section.array;
        if (!values.empty()) throw inputErrorAtByte(name_, start, "a second " + std::string(section.what) + " section");
        readFloats(values, h.count * section.floatsPerTriangle, h, section.what);
        return;
    }
    throw inputErrorAtByte(name_, start,
                           std::to_string(total_ - start) + " bytes after the triangles that are no section " +
                               "(vnrm, vtex, vcol or vtan)");
}

void RawReader::readFloats(std::vector<float>& values, std::size_t floats, const RawHeader& h, const char* what) {
    const std::uint64_t bytes = std::uint64_t(floats) * sizeof(float);
    if (left() < bytes)
        throw inputErrorAtByte(
            name_, total_,
            "truncated RAW data: " + h.dataNamed(bytes, what) + ", the file has " + std::to_string(left()));
    const std::uint64_t first = at_;
    values.resize(floats);
    readBytes(values.data(), bytes);
    if constexpr (std::endian::native == std::endian::big) {
        for (float& f : values) {
            std::uint8_t b[4];
            std::memcpy(b, &f, 4);
            const std::uint32_t u = readUint32LE(b);
            std::memcpy(&f, &u, 4);
        }
    }
    // Numbers that would poison every computation they touch.
    for (std::size_t i = 0; i < values.size(); ++i)
        if (!std::isfinite(values[i]))
            throw inputErrorAtByte(name_, first + i * sizeof(float),
                                   std::isnan(values[i]) ? "NaN in RAW data" : "infinite number in RAW data");
}

void RawReader::readBytes(void* to, std::size_t n) {
    if (n > 0 && !in_.read(static_cast<char*>(to), std::streamsize(n))) throw InputError(name_ + ": read error");
    at_ += n;
}

void writeUint32LE(std::ostream& out, std::uint32_t v) {
    const char b[4] = {char(v & 0xff), char(v >> 8 & 0xff), char(v >> 16 & 0xff), char(v >> 24 & 0xff)};
    out.write(b, 4);
}

void writeFloats(std::ostream& out, const std::vector<float>& values) {
    if constexpr (std::endian::native == std::endian::little) {
        out.write(reinterpret_cast<const char*>(values.data()), std::streamsize(values.size() * sizeof(float)));
    } else {
        for (float f : values) writeUint32LE(out, std::bit_cast<std::uint32_t>(f));
    }
}

}  // namespace

Model readRawFile(const std::string& path) {
    const std::uint64_t size = inputFileSize(path);
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path + ": cannot open: " + std::strerror(errno));
    return RawReader(in, size, path).read();
}

Model readRawBytes(std::span<const std::uint8_t> bytes, const std::string& name) {
    MemoryBuffer buffer(bytes);
    std::istream in(&buffer);
    return RawReader(in, bytes.size(), name).read();
}

void writeRaw(std::ostream& out, const Model& model) {
    if (!model.triangleVertices.empty() && !model.sphereData.empty())
        throw std::invalid_argument("model '" + model.name + "' has triangles and spheres; a RAW file holds one kind");
    const bool spheres = !model.sphereData.empty();
    const std::size_t count = spheres ? model.sphereCount() : model.triangleCount();
    if (count > UINT32_MAX) throw std::invalid_argument("model '" + model.name + "' is too large for a RAW file");
    out.write(kMagic, sizeof kMagic);
    out.put(spheres ? 'S' : 'T');
    writeUint32LE(out, std::uint32_t(count));
    writeFloats(out, spheres ? model.sphereData : model.triangleVertices);
    for (const RawSection& section : kSections) {
        const std::vector<float>& values = model.*section.array;
        if (values.empty()) continue;
        if (spheres || values.size() != count * section.floatsPerTriangle)
            throw std::invalid_argument("model '" + model.name + "' has " + section.what + " for " +
                                        std::to_string(values.size() / section.floatsPerTriangle) + " of " +
                                        std::to_string(model.triangleCount()) + " triangles");
        out.write(section.tag, kTagBytes);
        writeFloats(out, values);
    }
}

void writeRawFile(const std::string& path, const Model& model) {
    writeFileAtomically(path, [&](std::ostream& out) { writeRaw(out, model); });
}

}  // namespace rt
