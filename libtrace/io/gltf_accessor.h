// Reading glTF accessors with every index and byte range checked first (glTF 2.0
// specification, section 3.6): accessor -> bufferView -> buffer indices, component type and
// element type, byteStride, and that the last element ends inside the bufferView and the
// bufferView inside the buffer. Sparse accessors are applied over their base data. Nothing
// is allocated before the data it describes is known to exist, so a forged count cannot
// cause a huge allocation. Every failure is an rt::InputError naming the file and accessor.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "io/mesh_data.h"

namespace tinygltf {
class Model;
}

namespace rt {

class GltfAccessorReader {
public:
    GltfAccessorReader(const tinygltf::Model& gltf, std::string file) : gltf_(gltf), file_(std::move(file)) {}

    // A VEC3 accessor of floats (or normalized integers, KHR_mesh_quantization) as points.
    // Throws if any value is NaN or infinite. `what` names the accessor's use in messages.
    std::vector<Point3f> points(int accessor, const std::string& what) const;

    // A per-vertex attribute (NORMAL, TEXCOORD_0, COLOR_0, TANGENT) of `components` floats per vertex,
    // from a VEC2, VEC3 or VEC4 accessor of floats or normalized integers; a VEC4 colour
    // loses its alpha. Throws if a value is NaN or infinite or the type does not fit.
    std::vector<float> attribute(int accessor, int components, const std::string& what) const;

    // A SCALAR accessor of unsigned bytes, shorts or ints; throws if a value is not below
    // vertexCount.
    std::vector<std::uint32_t> indices(int accessor, std::size_t vertexCount, const std::string& what) const;

    // The element count of an accessor (after checking the index).
    std::size_t count(int accessor, const std::string& what) const;

private:
    struct Elements;  // a checked byte range of one accessor's data
    Elements locate(int accessor, const std::string& what) const;
    std::vector<double> readAll(int accessor, int wantType, const std::string& what) const;
    [[noreturn]] void fail(const std::string& what, const std::string& message) const;

    const tinygltf::Model& gltf_;
    std::string file_;
};

}  // namespace rt
