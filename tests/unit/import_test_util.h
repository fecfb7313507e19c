// Helpers for the importer tests: the Assimp ground truth of shared/models/MANIFEST.md, and
// small glTF files written on the fly (buffers inline as base64) to probe one rule at a time.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <cctype>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "io/import.h"
#include "scene_test_files.h"

namespace rt::test {

inline std::string sharedModels() { return std::string(RT_SHARED_DIR) + "/models"; }

// One row of the manifest's tables: triangles in the mesh data and placed in the scene.
struct ManifestCounts {
    std::size_t meshTriangles = 0;
    std::size_t sceneTriangles = 0;
};

// The rows for files under `folder` ("gltf", "glb", "obj", "3ds"), keyed by relative path.
inline std::map<std::string, ManifestCounts> manifestRows(const std::string& folder) {
    std::ifstream in(sharedModels() + "/MANIFEST.md");
    std::map<std::string, ManifestCounts> rows;
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind("| `" + folder + "/", 0) != 0) continue;
        std::vector<std::string> cells;
        std::stringstream ss(line);
        for (std::string cell; std::getline(ss, cell, '|');) cells.push_back(cell);
        // Only the ground-truth tables have counts in columns 4 and 5 ("16 (+19 lines, 7 pts)").
        const auto startsWithDigit = [](const std::string& c) {
            const std::size_t at = c.find_first_not_of(' ');
            return at != std::string::npos && std::isdigit(static_cast<unsigned char>(c[at]));
        };
        if (cells.size() < 6 || !startsWithDigit(cells[4]) || !startsWithDigit(cells[5])) continue;
        const std::string file = cells[1].substr(cells[1].find('`') + 1, cells[1].rfind('`') - cells[1].find('`') - 1);
        rows.emplace(file, ManifestCounts{std::stoul(cells[4]), std::stoul(cells[5])});
    }
    return rows;
}

// The manifest's count of model folders under `folder` (its first table). Each folder holds one
// model with one row in the ground-truth tables, so that is how many rows manifestRows must find.
inline std::size_t manifestModelFolders(const std::string& folder) {
    std::ifstream in(sharedModels() + "/MANIFEST.md");
    const std::string row = "| `" + folder + "/` | ";
    for (std::string line; std::getline(in, line);)
        if (line.rfind(row, 0) == 0) return std::stoul(line.substr(row.size()));
    ADD_FAILURE() << "MANIFEST.md lists no folder " << folder << "/";
    return 0;
}

inline std::size_t modelTriangles(const Scene& scene) {
    std::size_t n = 0;
    for (const Model& m : scene.models) n += m.triangleCount();
    return n;
}

inline std::size_t sceneTriangles(const Scene& scene) {
    std::size_t n = 0;
    for (const Instance& i : scene.instances) n += scene.models[i.model].triangleCount();
    return n;
}

// Imports every manifest file under `folders` and checks that the triangles kept plus the
// degenerate ones dropped (zero area in float) give Assimp's counts, for the mesh data and
// for the scene with every instance; `more` checks anything else. Returns the file count.
template <class Check>
std::size_t expectManifestTriangleCounts(std::initializer_list<const char*> folders, Check more) {
    std::size_t files = 0;
    for (const std::string folder : folders) {
        for (const auto& [file, counts] : manifestRows(folder)) {
            SCOPED_TRACE(file);
            const ImportResult r = importScene(sharedModels() + "/" + file);
            EXPECT_EQ(modelTriangles(r.scene) + r.report.droppedDegenerate, counts.meshTriangles);
            EXPECT_EQ(sceneTriangles(r.scene) + r.report.droppedDegenerateInScene, counts.sceneTriangles);
            more(r);
            ++files;
        }
    }
    return files;
}

inline std::string base64(const std::vector<std::uint8_t>& bytes) {
    static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::uint32_t n = (std::uint32_t(bytes[i]) << 16) | (i + 1 < bytes.size() ? bytes[i + 1] << 8 : 0) |
                                (i + 2 < bytes.size() ? bytes[i + 2] : 0);
        out += table[(n >> 18) & 63];
        out += table[(n >> 12) & 63];
        out += i + 1 < bytes.size() ? table[(n >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? table[n & 63] : '=';
    }
    return out;
}

// A glTF with one mesh (accessor 0: POSITION, accessor 1: UNSIGNED_SHORT indices) placed by
// the nodes given. Tests edit the JSON text to break one thing at a time.
struct GltfFixture {
    std::vector<float> positions{0, 0, 0, 1, 0, 0, 0, 1, 0};
    std::vector<std::uint16_t> indices{0, 1, 2};
    int mode = 4;
    std::string nodes = R"([{"mesh": 0}])";
    std::string extra;  // more top-level members, each starting with a comma

    std::string json() const {
        const auto* p = reinterpret_cast<const std::uint8_t*>(positions.data());
        std::vector<std::uint8_t> bytes(p, p + positions.size() * sizeof(float));
        const std::size_t indexOffset = bytes.size();
        const auto* q = reinterpret_cast<const std::uint8_t*>(indices.data());
        bytes.insert(bytes.end(), q, q + indices.size() * sizeof(std::uint16_t));
        const std::string vertexCount = std::to_string(positions.size() / 3);
        std::ostringstream j;
        j << R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": )" << nodes
          << R"(, "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "mode": )" << mode << "}]}]"
          << R"(, "buffers": [{"byteLength": )" << bytes.size() << R"(, "uri": "data:application/octet-stream;base64,)"
          << base64(bytes) << R"("}], "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": )" << indexOffset
          << R"(}, {"buffer": 0, "byteOffset": )" << indexOffset << R"(, "byteLength": )" << indices.size() * 2
          << R"(}], "accessors": [{"bufferView": 0, "componentType": 5126, "count": )" << vertexCount
          << R"(, "type": "VEC3"}, {"bufferView": 1, "componentType": 5123, "count": )" << indices.size()
          << R"(, "type": "SCALAR"}])" << extra << "}";
        return j.str();
    }
};

// A 3DS file built chunk by chunk (uint16 id, uint32 length with the 6-byte header, little
// endian): main 0x4D4D > editor 0x3D3D > named objects 0x4000, holding a triangle mesh 0x4100
// (vertices 0x4110, faces 0x4120), a camera 0x4700 (position, target, bank, lens) or an omni
// light 0x4600 (position, then its colour in a float colour chunk 0x0010).
struct ThreeDsFixture {
    using Bytes = std::vector<std::uint8_t>;

    static void put(Bytes& out, std::uint32_t value, int bytes) {
        for (int i = 0; i < bytes; ++i) out.push_back(std::uint8_t(value >> (8 * i)));
    }
    static void putFloat(Bytes& out, float value) {
        std::uint32_t bits;
        std::memcpy(&bits, &value, 4);
        put(out, bits, 4);
    }
    static Bytes chunk(std::uint16_t id, const Bytes& contents) {
        Bytes out;
        put(out, id, 2);
        put(out, std::uint32_t(contents.size() + 6), 4);
        out.insert(out.end(), contents.begin(), contents.end());
        return out;
    }
    static Bytes object(const std::string& name, const Bytes& child) {
        Bytes out(name.begin(), name.end());
        out.push_back(0);
        out.insert(out.end(), child.begin(), child.end());
        return chunk(0x4000, out);
    }
    // One triangle.
    static Bytes mesh(const std::string& name, const std::vector<float>& corners) {
        Bytes vertices, faces;
        put(vertices, 3, 2);
        for (float v : corners) putFloat(vertices, v);
        put(faces, 1, 2);
        for (std::uint32_t i : {0u, 1u, 2u, 0u}) put(faces, i, 2);  // a, b, c, flags
        Bytes tri = chunk(0x4110, vertices);
        const Bytes f = chunk(0x4120, faces);
        tri.insert(tri.end(), f.begin(), f.end());
        return object(name, chunk(0x4100, tri));
    }
    static Bytes camera(const std::string& name, const std::vector<float>& numbers) {
        Bytes data;
        for (float v : numbers) putFloat(data, v);
        return object(name, chunk(0x4700, data));
    }
    static Bytes omniLight(const std::string& name, const std::vector<float>& position, const std::vector<float>& rgb) {
        Bytes data, color;
        for (float v : position) putFloat(data, v);
        for (float v : rgb) putFloat(color, v);
        const Bytes colorChunk = chunk(0x0010, color);
        data.insert(data.end(), colorChunk.begin(), colorChunk.end());
        return object(name, chunk(0x4600, data));
    }
    static Bytes file(const std::vector<Bytes>& objects) {
        Bytes editor;
        for (const Bytes& o : objects) editor.insert(editor.end(), o.begin(), o.end());
        return chunk(0x4D4D, chunk(0x3D3D, editor));
    }
    static std::string write(const ::TempDir& dir, const Bytes& bytes) {
        return dir.write("fixture.3ds", std::string(bytes.begin(), bytes.end()));
    }
};

using ::TempDir;  // scene_test_files.h

// `text` with the first `from` replaced by `to`; a test fails if `from` is not there.
inline std::string replaceOnce(std::string text, const std::string& from, const std::string& to) {
    const std::size_t at = text.find(from);
    if (at == std::string::npos) {
        ADD_FAILURE() << "fixture text has no \"" << from << "\"";
        return text;
    }
    return text.replace(at, from.size(), to);
}

}  // namespace rt::test
