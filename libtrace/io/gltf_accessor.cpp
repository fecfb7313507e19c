#include "io/gltf_accessor.h"

#include <tiny_gltf.h>

#include <cmath>
#include <cstring>

#include "core/error.h"

namespace rt {
namespace {

std::size_t componentBytes(int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return 1;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return 2;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        case TINYGLTF_COMPONENT_TYPE_FLOAT:
            return 4;
        default:
            return 0;  // INT and DOUBLE are not glTF 2.0 accessor types
    }
}

int componentsOf(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR:
            return 1;
        case TINYGLTF_TYPE_VEC2:
            return 2;
        case TINYGLTF_TYPE_VEC3:
            return 3;
        case TINYGLTF_TYPE_VEC4:
            return 4;
        default:
            return 0;  // matrices are never geometry
    }
}

template <class T>
T load(const unsigned char* p) {
    T value;
    std::memcpy(&value, p, sizeof(T));  // glTF data is little-endian, as is every host we build for
    return value;
}

// One component as a number; normalized integers map to [0, 1] or [-1, 1] (glTF 3.11).
double decode(const unsigned char* p, int componentType, bool normalized) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE: {
            const double v = load<std::int8_t>(p);
            return normalized ? std::max(v / 127.0, -1.0) : v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
            const double v = load<std::uint8_t>(p);
            return normalized ? v / 255.0 : v;
        }
        case TINYGLTF_COMPONENT_TYPE_SHORT: {
            const double v = load<std::int16_t>(p);
            return normalized ? std::max(v / 32767.0, -1.0) : v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            const double v = load<std::uint16_t>(p);
            return normalized ? v / 65535.0 : v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
            return load<std::uint32_t>(p);
        default:
            return load<float>(p);
    }
}

std::string typeName(int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
            return "BYTE";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return "UNSIGNED_BYTE";
        case TINYGLTF_COMPONENT_TYPE_SHORT:
            return "SHORT";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return "UNSIGNED_SHORT";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
            return "UNSIGNED_INT";
        case TINYGLTF_COMPONENT_TYPE_FLOAT:
            return "FLOAT";
        default:
            return "component type " + std::to_string(componentType);
    }
}

bool isIndexType(int componentType) {
    return componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
           componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
           componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
}

}  // namespace

// `count` elements of `components` components each, `stride` bytes apart from `data`;
// data == nullptr stands for an accessor without a bufferView, whose elements are all zero.
struct GltfAccessorReader::Elements {
    const unsigned char* data = nullptr;
    std::size_t stride = 0;
    std::size_t count = 0;
    int componentType = 0;
    int components = 0;
    bool normalized = false;

    double at(std::size_t element, int component) const {
        if (!data) return 0;
        const std::size_t bytes = componentBytes(componentType);
        return decode(data + element * stride + std::size_t(component) * bytes, componentType, normalized);
    }
};

void GltfAccessorReader::fail(const std::string& what, const std::string& message) const {
    throw InputError(file_ + ": " + what + ": " + message);
}

namespace {

// The start of `count` elements of `elementBytes` each, `stride` apart, at `offset` in
// bufferView `viewIndex`; nullptr and a message when any of it lies outside the data.
const unsigned char* checkedRange(const tinygltf::Model& gltf, int viewIndex, std::size_t offset, std::size_t count,
                                  std::size_t elementBytes, std::size_t stride, std::string& error) {
    if (viewIndex < 0 || std::size_t(viewIndex) >= gltf.bufferViews.size()) {
        error = "bufferView " + std::to_string(viewIndex) + " does not exist (the file has " +
                std::to_string(gltf.bufferViews.size()) + ")";
        return nullptr;
    }
    const tinygltf::BufferView& view = gltf.bufferViews[std::size_t(viewIndex)];
    const std::string viewName = "bufferView " + std::to_string(viewIndex);
    if (view.buffer < 0 || std::size_t(view.buffer) >= gltf.buffers.size()) {
        error = viewName + " names buffer " + std::to_string(view.buffer) + ", which does not exist";
        return nullptr;
    }
    const std::vector<unsigned char>& data = gltf.buffers[std::size_t(view.buffer)].data;
    if (view.byteLength > data.size() || view.byteOffset > data.size() - view.byteLength) {
        error = viewName + " (bytes " + std::to_string(view.byteOffset) + " + " + std::to_string(view.byteLength) +
                ") runs past the end of buffer " + std::to_string(view.buffer) + " (" + std::to_string(data.size()) +
                " bytes)";
        return nullptr;
    }
    if (count == 0) return data.data() + view.byteOffset;
    // The last element must end inside the view: offset + (count - 1) * stride + elementBytes <= length,
    // written without overflow.
    const bool fits = elementBytes <= view.byteLength && offset <= view.byteLength - elementBytes &&
                      count - 1 <= (view.byteLength - elementBytes - offset) / stride;
    if (!fits) {
        error = std::to_string(count) + " elements of " + std::to_string(elementBytes) + " bytes, " +
                std::to_string(stride) + " apart, from byte " + std::to_string(offset) + " do not fit in " + viewName +
                " (" + std::to_string(view.byteLength) + " bytes)";
        return nullptr;
    }
    return data.data() + view.byteOffset + offset;
}

std::size_t totalBufferBytes(const tinygltf::Model& gltf) {
    std::size_t total = 0;
    for (const tinygltf::Buffer& b : gltf.buffers) total += b.data.size();
    return total;
}

}  // namespace

std::size_t GltfAccessorReader::count(int accessor, const std::string& what) const {
    if (accessor < 0 || std::size_t(accessor) >= gltf_.accessors.size())
        fail(what, "accessor " + std::to_string(accessor) + " does not exist (the file has " +
                       std::to_string(gltf_.accessors.size()) + ")");
    return gltf_.accessors[std::size_t(accessor)].count;
}

GltfAccessorReader::Elements GltfAccessorReader::locate(int accessor, const std::string& what) const {
    count(accessor, what);  // checks the index
    const tinygltf::Accessor& acc = gltf_.accessors[std::size_t(accessor)];
    const std::string name = what + " (accessor " + std::to_string(accessor) + ")";
    Elements e;
    e.componentType = acc.componentType;
    e.components = componentsOf(acc.type);
    e.normalized = acc.normalized;
    e.count = acc.count;
    const std::size_t bytes = componentBytes(acc.componentType);
    if (bytes == 0) fail(name, "invalid component type " + std::to_string(acc.componentType));
    if (e.components == 0) fail(name, "invalid element type " + std::to_string(acc.type));
    const std::size_t elementBytes = bytes * std::size_t(e.components);
    if (acc.bufferView < 0) {
        // All zeros (normally the base of a sparse accessor). Its size is not backed by data,
        // so it is bounded by the data the file has, as no real file needs more.
        if (acc.count > totalBufferBytes(gltf_))
            fail(name, std::to_string(acc.count) + " elements without a bufferView are more than the file's data");
        return e;
    }
    const std::size_t viewStride = std::size_t(acc.bufferView) < gltf_.bufferViews.size()
                                       ? gltf_.bufferViews[std::size_t(acc.bufferView)].byteStride
                                       : 0;
    e.stride = viewStride ? viewStride : elementBytes;
    if (e.stride < elementBytes || e.stride % bytes != 0)
        fail(name, "byteStride " + std::to_string(e.stride) + " does not suit elements of " +
                       std::to_string(elementBytes) + " bytes");
    std::string error;
    e.data = checkedRange(gltf_, acc.bufferView, acc.byteOffset, acc.count, elementBytes, e.stride, error);
    if (!e.data) fail(name, error);
    return e;
}

std::vector<double> GltfAccessorReader::readAll(int accessor, int wantType, const std::string& what) const {
    const Elements e = locate(accessor, what);
    const tinygltf::Accessor& acc = gltf_.accessors[std::size_t(accessor)];
    const std::string name = what + " (accessor " + std::to_string(accessor) + ")";
    if (acc.type != wantType)
        fail(name, "has " + std::to_string(e.components) + " components per element, expected " +
                       std::to_string(componentsOf(wantType)));
    std::vector<double> out(e.count * std::size_t(e.components));
    for (std::size_t i = 0; i < e.count; ++i)
        for (int c = 0; c < e.components; ++c) out[i * std::size_t(e.components) + std::size_t(c)] = e.at(i, c);
    if (!acc.sparse.isSparse) return out;

    // Sparse substitution (glTF 3.6.2.3): `count` indices and values, tightly packed.
    const std::size_t sparseCount = acc.sparse.count < 0 ? 0 : std::size_t(acc.sparse.count);
    if (sparseCount > e.count) fail(name, "has more sparse values than elements");
    const int indexType = acc.sparse.indices.componentType;
    if (!isIndexType(indexType)) fail(name, "sparse indices of type " + typeName(indexType));
    if (acc.sparse.indices.byteOffset < 0 || acc.sparse.values.byteOffset < 0) fail(name, "negative sparse byteOffset");
    std::string error;
    const unsigned char* idx =
        checkedRange(gltf_, acc.sparse.indices.bufferView, std::size_t(acc.sparse.indices.byteOffset), sparseCount,
                     componentBytes(indexType), componentBytes(indexType), error);
    if (!idx) fail(name + " sparse indices", error);
    const std::size_t elementBytes = componentBytes(e.componentType) * std::size_t(e.components);
    Elements values = e;
    values.count = sparseCount;
    values.stride = elementBytes;
    values.data = checkedRange(gltf_, acc.sparse.values.bufferView, std::size_t(acc.sparse.values.byteOffset),
                               sparseCount, elementBytes, elementBytes, error);
    if (!values.data) fail(name + " sparse values", error);
    for (std::size_t j = 0; j < sparseCount; ++j) {
        const double target = decode(idx + j * componentBytes(indexType), indexType, false);
        if (target >= double(e.count))
            fail(name, "sparse index " + std::to_string(std::uint64_t(target)) + " is out of range");
        for (int c = 0; c < e.components; ++c)
            out[std::size_t(target) * std::size_t(e.components) + std::size_t(c)] = values.at(j, c);
    }
    return out;
}

std::vector<Point3f> GltfAccessorReader::points(int accessor, const std::string& what) const {
    const std::string name = what + " (accessor " + std::to_string(accessor) + ")";
    count(accessor, what);
    if (gltf_.accessors[std::size_t(accessor)].componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
        fail(name, "positions cannot be UNSIGNED_INT");
    const std::vector<double> values = readAll(accessor, TINYGLTF_TYPE_VEC3, what);
    std::vector<Point3f> out(values.size() / 3);
    for (std::size_t i = 0; i < out.size(); ++i) {
        for (std::size_t c = 0; c < 3; ++c) {
            const double v = values[3 * i + c];
            if (!std::isfinite(v) || !std::isfinite(float(v)))
                fail(name, "vertex " + std::to_string(i) + " has a NaN or infinite coordinate");
            out[i][c] = float(v);
        }
    }
    return out;
}

std::vector<float> GltfAccessorReader::attribute(int accessor, int components, const std::string& what) const {
    const std::string name = what + " (accessor " + std::to_string(accessor) + ")";
    count(accessor, what);
    const int type = gltf_.accessors[std::size_t(accessor)].type;
    const bool colorWithAlpha = components == 3 && type == TINYGLTF_TYPE_VEC4;
    const std::vector<double> values = readAll(accessor,
                                               colorWithAlpha || components == 4 ? TINYGLTF_TYPE_VEC4
                                               : components == 2                 ? TINYGLTF_TYPE_VEC2
                                                                                 : TINYGLTF_TYPE_VEC3,
                                               what);
    const std::size_t stride = colorWithAlpha ? 4 : std::size_t(components);
    std::vector<float> out;
    out.reserve(values.size() / stride * std::size_t(components));
    for (std::size_t i = 0; i < values.size(); i += stride)
        for (std::size_t c = 0; c < std::size_t(components); ++c) {
            const double v = values[i + c];
            if (!std::isfinite(v) || !std::isfinite(float(v)))
                fail(name, "vertex " + std::to_string(i / stride) + " has a NaN or infinite value");
            out.push_back(float(v));
        }
    return out;
}

std::vector<std::uint32_t> GltfAccessorReader::indices(int accessor, std::size_t vertexCount,
                                                       const std::string& what) const {
    const std::string name = what + " (accessor " + std::to_string(accessor) + ")";
    count(accessor, what);
    const tinygltf::Accessor& acc = gltf_.accessors[std::size_t(accessor)];
    if (!isIndexType(acc.componentType)) fail(name, "indices of type " + typeName(acc.componentType));
    const std::vector<double> values = readAll(accessor, TINYGLTF_TYPE_SCALAR, what);
    std::vector<std::uint32_t> out(values.size());
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (values[i] >= double(vertexCount))
            fail(name, "index " + std::to_string(std::uint64_t(values[i])) + " at position " + std::to_string(i) +
                           " is not below the vertex count " + std::to_string(vertexCount));
        out[i] = std::uint32_t(values[i]);
    }
    return out;
}

}  // namespace rt
