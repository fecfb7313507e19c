#include "io/gltf_import.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <set>
#include <sstream>

#include "core/error.h"
#include "core/text.h"
#include "io/gltf_accessor.h"
#include "io/gltf_images.h"
#include "io/primitive_topology.h"
#include "io/punctual_light.h"
#include "io/scene_assembly.h"
#include "io/scene_defaults.h"
#include "os/input_file.h"
#include "os/sandbox.h"

namespace rt {
namespace {

// File access for tinygltf. Only regular files are read (its own reader sizes a directory
// as 2^64 - 1 bytes and throws std::bad_alloc), and image files are never opened: each reads
// as one placeholder byte, which keepDataUriImage ignores; OpenImageIO reads them when rendering.
bool isImagePath(const std::string& path) {
    const std::string ext = lowerCaseExtension(path);
    return ext == ".png" || ext == ".jpg" || ext == ".jpeg" || ext == ".ktx2" || ext == ".webp" || ext == ".dds";
}

bool isRegularFile(const std::string& path, void*) {
    std::error_code ec;
    return isImagePath(path) || std::filesystem::is_regular_file(path, ec);
}

std::string samePath(const std::string& path, void*) { return path; }

// The files a glTF may have read (its buffers): those in the model's folder or below, unless
// ImportOptions::filesOutsideModelFolder, and always inside --sandbox (scene/sandbox.h). A buffer
// URI "../../../etc/passwd" or "/etc/passwd" would otherwise copy any file the user can read
// into the scene and onto standard output.
struct FileAccess {
    std::filesystem::path folder;  // canonical
    bool anywhere = false;

    FileAccess(const std::string& modelPath, bool anywhereAllowed) : anywhere(anywhereAllowed) {
        std::error_code ec;
        folder = std::filesystem::weakly_canonical(std::filesystem::absolute(modelPath).parent_path(), ec);
    }
    // After symbolic links are resolved, so that a link in the folder cannot lead out of it.
    bool allows(const std::string& path) const {
        std::error_code ec;
        const std::filesystem::path relative =
            std::filesystem::weakly_canonical(std::filesystem::absolute(path), ec).lexically_relative(folder);
        return anywhere || (!ec && !relative.empty() && *relative.begin() != "..");
    }
};

bool readRegularFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* access) {
    out->assign(1, 0);
    if (isImagePath(path)) return true;
    if (const std::optional<std::string> why = sandboxRefusal(path, "buffer " + path)) {
        *err += *why + "\n";
        return false;
    }
    if (!static_cast<const FileAccess*>(access)->allows(path)) {
        *err += "outside the model's folder (rt-convert --allow-outside-files reads it)\n";
        return false;
    }
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) {
        *err += "not a file: " + path + "\n";
        return false;
    }
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (!ec && size > maxInputBytes()) {  // read whole before tinygltf compares it with byteLength
        *err += path + " is larger than the input limit (--max-input)\n";
        return false;
    }
    std::ifstream in(path, std::ios::binary);
    if (ec || !in) {
        *err += "cannot read " + path + "\n";
        return false;
    }
    out->resize(size);
    if (!in.read(reinterpret_cast<char*>(out->data()), std::streamsize(size))) {
        *err += "cannot read " + path + "\n";
        return false;
    }
    return true;
}

bool refuseWrite(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    *err += "rt never writes through tinygltf\n";
    return false;
}

// The first line of a tinygltf message, printable: JSON errors quote the offending bytes.
std::string firstLine(const std::string& text) {
    std::string line = text.substr(0, text.find('\n'));
    for (char& c : line)
        if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) c = '?';
    return line.empty() ? "not a valid glTF file" : line;
}

// `load(loader, model, error, warning)` reads the file or the bytes; `name` names them in messages.
template <class Load>
tinygltf::Model loadGltf(const std::string& name, bool binary, const FileAccess& access, ImportReport& report,
                         Load load) {
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(keepDataUriImage, nullptr);
    loader.SetFsCallbacks({isRegularFile, samePath, readRegularFile, refuseWrite, const_cast<FileAccess*>(&access)});
    tinygltf::Model gltf;
    std::string error, warning;
    report.format = binary ? "glTF 2.0 binary (.glb)" : "glTF 2.0";
    bool loaded = false;
    try {
        loaded = load(loader, gltf, error, warning);
    } catch (const std::bad_alloc&) {
        throw;
    } catch (const std::exception& e) {
        // tinygltf 2.8 indexes with at() where the file may not hold what it declares: a .glb
        // whose buffer 0 has byteLength 0 while its BIN chunk holds data threw std::out_of_range
        // (found by fuzz_gltf_import).
        throw InputError(name + ": tinygltf cannot read it (" + firstLine(e.what()) + ")");
    }
    if (!loaded) throw InputError(name + ": " + firstLine(error));
    for (std::size_t start = 0; start < warning.size();) {
        const std::size_t end = std::min(warning.find('\n', start), warning.size());
        if (end > start) report.notes.push_back("tinygltf: " + firstLine(warning.substr(start, end - start)));
        start = end + 1;
    }
    for (const std::string& ext : gltf.extensionsRequired)
        if (ext.find("compression") != std::string::npos)
            throw InputError(name + ": requires " + ext + ", which rt-convert does not decode");
    return gltf;
}

double finiteNumber(double v, const std::string& file, const std::string& what) {
    if (!std::isfinite(v)) throw InputError(file + ": " + what + " is not a finite number");
    return v;
}

// A number of the file within [lowest, highest]: rt's scenes hold each field within its range
// (docs/conversion.md), and a value beyond it (an ior of 1e300 made a NaN specular) is the
// file's error, named with its field, whether rt-convert or rt-render reads it.
double numberWithin(double v, double lowest, double highest, const std::string& file, const std::string& what) {
    finiteNumber(v, file, what);
    if (v >= lowest && v <= highest) return v;
    std::ostringstream message;
    message << file << ": " << what << " " << v << " is out of range (" << lowest << " to " << highest << ")";
    throw InputError(message.str());
}

// A number from an extension object, which tinygltf leaves as untyped JSON values.
double numberValue(const tinygltf::Value& v, const std::string& file, const std::string& what) {
    if (!v.IsNumber()) throw InputError(file + ": " + what + " is not a number");
    return finiteNumber(v.GetNumberAsDouble(), file, what);
}

// A node's local transform: its matrix (column-major), or T * R * S (glTF 3.5.2).
// Throws InputError for malformed values, std::invalid_argument for a singular matrix.
Transform nodeTransform(const tinygltf::Node& node, const std::string& file, const std::string& what) {
    auto check = [&](const std::vector<double>& v, std::size_t size, const char* field) {
        if (!v.empty() && v.size() != size)
            throw InputError(file + ": " + what + ": " + field + " has " + std::to_string(v.size()) + " numbers");
        for (double x : v) finiteNumber(x, file, what + " " + field);
    };
    check(node.matrix, 16, "matrix");
    check(node.translation, 3, "translation");
    check(node.rotation, 4, "rotation");
    check(node.scale, 3, "scale");
    Transform::Matrix m{};
    if (!node.matrix.empty()) {
        for (int col = 0; col < 4; ++col)
            for (int row = 0; row < 4; ++row) m[row][col] = Real(node.matrix[std::size_t(col * 4 + row)]);
        return Transform(m);
    }
    const std::vector<double> t = node.translation.empty() ? std::vector<double>{0, 0, 0} : node.translation;
    const std::vector<double> s = node.scale.empty() ? std::vector<double>{1, 1, 1} : node.scale;
    double x = 0, y = 0, z = 0, w = 1;
    if (!node.rotation.empty()) {
        const double n =
            std::sqrt(std::inner_product(node.rotation.begin(), node.rotation.end(), node.rotation.begin(), 0.0));
        if (!(n > 0)) throw InputError(file + ": " + what + ": rotation is a zero quaternion");
        x = node.rotation[0] / n, y = node.rotation[1] / n, z = node.rotation[2] / n, w = node.rotation[3] / n;
    }
    const double r[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
                            {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
                            {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}};
    for (int row = 0; row < 3; ++row) {
        for (int col = 0; col < 3; ++col) m[row][col] = Real(r[row][col] * s[std::size_t(col)]);
        m[row][3] = Real(t[std::size_t(row)]);
    }
    m[3][3] = 1;
    return Transform(m);
}

struct Placed {
    int index;  // camera or light
    Transform world;
};

class GltfSceneBuilder {
public:
    GltfSceneBuilder(const tinygltf::Model& gltf, const std::string& file, const ImportOptions& options,
                     ImportResult& out)
        : gltf_(gltf), file_(file), options_(options), out_(out), assembly_(out, options), reader_(gltf, file) {}

    void build(const Transform& root) {
        const tinygltf::Scene& scene = gltf_.scenes[chooseScene()];
        std::vector<std::pair<int, Transform>> stack;
        for (auto it = scene.nodes.rbegin(); it != scene.nodes.rend(); ++it) stack.emplace_back(*it, root);
        std::vector<char> visited(gltf_.nodes.size(), 0);
        while (!stack.empty()) {  // depth first, children in file order, without recursion
            auto [index, parent] = stack.back();
            stack.pop_back();
            if (index < 0 || std::size_t(index) >= gltf_.nodes.size())
                fail("node " + std::to_string(index) + " does not exist (the file has " +
                     std::to_string(gltf_.nodes.size()) + ")");
            if (visited[std::size_t(index)]++)
                fail("node " + std::to_string(index) + " is reached twice (a cycle, or a node with two parents)");
            std::optional<Transform> world = worldTransform(index, parent);
            if (!world) continue;
            placeNode(index, *world);
            const std::vector<int>& children = gltf_.nodes[std::size_t(index)].children;
            for (auto it = children.rbegin(); it != children.rend(); ++it) stack.emplace_back(*it, *world);
        }
        out_.report.meshes = meshesPlaced_.size();
        const Aabb bounds = sceneBounds(out_.scene);
        takeCamera(bounds);
        takeLights();
        noteTextures();
    }

private:
    [[noreturn]] void fail(const std::string& message) const { throw InputError(file_ + ": " + message); }

    std::size_t chooseScene() const {
        if (gltf_.scenes.empty()) fail("the file has no scene");
        const int chosen = options_.scene ? *options_.scene : std::max(gltf_.defaultScene, 0);
        if (chosen < 0 || std::size_t(chosen) >= gltf_.scenes.size())
            fail("scene " + std::to_string(chosen) + " does not exist (the file has " +
                 std::to_string(gltf_.scenes.size()) + ")");
        return std::size_t(chosen);
    }

    std::optional<Transform> worldTransform(int index, const Transform& parent) {
        const std::string what = "node " + std::to_string(index);
        try {
            return parent * nodeTransform(gltf_.nodes[std::size_t(index)], file_, what);
        } catch (const std::invalid_argument&) {
            out_.report.notes.push_back(what +
                                        " has a singular transform (zero scale): it and its children are left out");
            return std::nullopt;
        }
    }

    void placeNode(int index, const Transform& world) {
        const tinygltf::Node& node = gltf_.nodes[std::size_t(index)];
        if (node.mesh >= 0)
            placeMesh(node.mesh, world);
        else if (node.mesh < -1)
            fail("node " + std::to_string(index) + " names mesh " + std::to_string(node.mesh));
        if (node.camera >= 0) {
            if (std::size_t(node.camera) >= gltf_.cameras.size())
                fail("node " + std::to_string(index) + " names camera " + std::to_string(node.camera) +
                     ", which does not exist");
            cameras_.push_back({node.camera, world});
        }
        const auto light = node.extensions.find("KHR_lights_punctual");
        if (light != node.extensions.end() && light->second.Has("light")) {
            const double l = numberValue(light->second.Get("light"), file_, "node " + std::to_string(index) + " light");
            if (!(l >= 0 && l < double(gltf_.lights.size())))
                fail("node " + std::to_string(index) + " names KHR_lights_punctual light " + std::to_string(l) +
                     ", which does not exist");
            lights_.push_back({int(l), world});
        }
    }

    void placeMesh(int mesh, const Transform& world) {
        if (std::size_t(mesh) >= gltf_.meshes.size())
            fail("mesh " + std::to_string(mesh) + " does not exist (the file has " +
                 std::to_string(gltf_.meshes.size()) + ")");
        meshesPlaced_.insert(mesh);
        const std::vector<tinygltf::Primitive>& primitives = gltf_.meshes[std::size_t(mesh)].primitives;
        for (std::size_t p = 0; p < primitives.size(); ++p) {
            const ConvertedMesh converted =
                assembly_.mesh({mesh, int(p)}, [&] { return convertPrimitive(mesh, int(p)); });
            assembly_.place(
                converted, [&] { return materialFor(primitives[p].material); }, world);
        }
    }

    ConvertedMesh convertPrimitive(int meshIndex, int primitiveIndex) {
        const tinygltf::Mesh& mesh = gltf_.meshes[std::size_t(meshIndex)];
        const tinygltf::Primitive& prim = mesh.primitives[std::size_t(primitiveIndex)];
        const std::string what = "mesh " + std::to_string(meshIndex) + " primitive " + std::to_string(primitiveIndex);
        std::optional<Topology> topology = topologyOf(prim.mode, what);
        if (!topology) return {};
        const auto position = prim.attributes.find("POSITION");
        if (position == prim.attributes.end()) {
            out_.report.notes.push_back(what + " has no POSITION attribute: skipped");
            return {};
        }
        const std::vector<Point3f> points = reader_.points(position->second, what + " POSITION");
        std::vector<std::uint32_t> vertices;
        if (prim.indices >= 0) {
            vertices = reader_.indices(prim.indices, points.size(), what + " indices");
        } else {
            vertices.resize(points.size());
            std::iota(vertices.begin(), vertices.end(), 0u);
        }
        const std::vector<std::uint32_t> corners = triangleCorners(*topology, vertices);
        const std::string base = mesh.name.empty() ? "mesh" + std::to_string(meshIndex) : mesh.name;
        ModelBuilder model =
            assembly_.newModel(mesh.primitives.size() > 1 ? base + "_" + std::to_string(primitiveIndex) : base,
                               "mesh" + std::to_string(meshIndex));
        model.reserveTriangles(corners.size() / 3);
        const VertexData data = vertexData(prim, points.size(), what);
        for (std::size_t i = 0; i + 3 <= corners.size(); i += 3)
            model.addTriangleWithData(data.corner(points, corners[i]), data.corner(points, corners[i + 1]),
                                      data.corner(points, corners[i + 2]));
        return assembly_.addModel(std::move(model));
    }

    // A primitive's NORMAL, TEXCOORD_0, COLOR_0 and TANGENT. One whose count differs from POSITION's
    // is left out with a note: the geometry is still good.
    VertexData vertexData(const tinygltf::Primitive& prim, std::size_t vertices, const std::string& what) {
        VertexData data;
        const auto read = [&](const char* attribute, int components, std::vector<float>& to) {
            const auto found = prim.attributes.find(attribute);
            if (found == prim.attributes.end()) return;
            to = reader_.attribute(found->second, components, what + " " + attribute);
            if (to.size() == vertices * std::size_t(components)) return;
            assembly_.report().notes.push_back(what + " " + attribute + " has " +
                                               std::to_string(to.size() / std::size_t(components)) + " values for " +
                                               std::to_string(vertices) + " vertices: not used");
            to.clear();
        };
        read("NORMAL", 3, data.normals);
        read("TEXCOORD_0", 2, data.uvs);
        read("COLOR_0", 3, data.colors);
        read("TANGENT", 4, data.tangents);
        return data;
    }

    std::optional<Topology> topologyOf(int mode, const std::string& what) {
        switch (mode) {
            case TINYGLTF_MODE_TRIANGLES:
                return Topology::Triangles;
            case TINYGLTF_MODE_TRIANGLE_STRIP:
                return Topology::Strip;
            case TINYGLTF_MODE_TRIANGLE_FAN:
                return Topology::Fan;
            case TINYGLTF_MODE_POINTS:
                ++out_.report.droppedPoints;
                return std::nullopt;
            case TINYGLTF_MODE_LINE:
            case TINYGLTF_MODE_LINE_LOOP:
            case TINYGLTF_MODE_LINE_STRIP:
                ++out_.report.droppedLines;
                return std::nullopt;
            default:
                fail(what + " has the unknown mode " + std::to_string(mode));
        }
    }

    std::uint32_t materialFor(int index) {
        return assembly_.material(index, "material" + std::to_string(index), [&] { return convertMaterial(index); });
    }

    Material convertMaterial(int index) {
        if (index < -1 || index >= int(gltf_.materials.size()))
            fail("material " + std::to_string(index) + " does not exist (the file has " +
                 std::to_string(gltf_.materials.size()) + ")");
        // A primitive without material: rt's plain white diffuse default (docs/conversion.md),
        // single-sided as glTF's default material is.
        Material m;
        m.name = "default";
        m.doubleSided = false;
        if (index >= 0) {
            const tinygltf::Material& gm = gltf_.materials[std::size_t(index)];
            const std::string what = "material " + std::to_string(index);
            m = phongFromMetallicRoughness(metallicRoughness(gm, what));
            m.name = gm.name;
            m.doubleSided = gm.doubleSided;  // false, as glTF's default, when the file leaves it out
            m.colorTexture = textureFor(gm.pbrMetallicRoughness.baseColorTexture, what + " baseColorTexture");
            m.emission.color = color(gm.emissiveFactor, what + " emissiveFactor") * emissiveStrength(gm, what);
            if (!(std::max({m.emission.color.r, m.emission.color.g, m.emission.color.b}) <= kMaxColorValue))
                fail(what + ": emissiveFactor times emissiveStrength is beyond 1e15");
            if (m.emission.color != Color{})
                m.emission.texture = textureFor(gm.emissiveTexture, what + " emissiveTexture");
            keepMetallicRoughnessTexture(gm, what, m);
            keepTransmissionTexture(gm, what, m);
            readClearcoat(gm, what, m);
            readAlphaMode(gm, what, m);
            m.normalMap.texture = textureFor(gm.normalTexture, what + " normalTexture");
            if (m.normalMap.texture)
                m.normalMap.scale = float(numberWithin(gm.normalTexture.scale, -kMaxTextureTransform,
                                                       kMaxTextureTransform, file_, what + " normal scale"));
        }
        return m;
    }

    // The path tracer follows the texture per hit, with the factors it scales (the Phong mapping
    // above had to guess them: metallicRoughness()).
    void keepMetallicRoughnessTexture(const tinygltf::Material& gm, const std::string& what, Material& m) {
        const tinygltf::PbrMetallicRoughness& pbr = gm.pbrMetallicRoughness;
        if (pbr.metallicRoughnessTexture.index < 0 || !m.pbr.factors) return;
        m.pbr.texture = textureFor(pbr.metallicRoughnessTexture, what + " metallicRoughnessTexture");
        if (!m.pbr.texture) return;
        m.pbr.factors->metallic = std::clamp(float(pbr.metallicFactor), 0.0f, 1.0f);
        m.pbr.factors->roughness = std::clamp(float(pbr.roughnessFactor), 0.0f, 1.0f);
    }

    // Both integrators follow the transmission texture per hit (its red channel times the
    // factor), so the weight is the factor again (metallicRoughness() halved it for the Phong
    // coefficients, which cannot follow the texture).
    void keepTransmissionTexture(const tinygltf::Material& gm, const std::string& what, Material& m) {
        const auto ext = gm.extensions.find("KHR_materials_transmission");
        if (ext == gm.extensions.end() || !ext->second.Has("transmissionTexture") || !m.transmission.passesLight())
            return;
        const tinygltf::Value& info = ext->second.Get("transmissionTexture");
        tinygltf::TextureInfo reference;
        if (info.Has("index")) reference.index = info.Get("index").GetNumberAsInt();
        if (info.Has("texCoord")) reference.texCoord = info.Get("texCoord").GetNumberAsInt();
        m.transmission.texture = textureFor(reference, what + " transmissionTexture");
        if (m.transmission.texture) m.transmission.weight = std::min(1.0f, m.transmission.weight * 2);
    }

    // alphaMode MASK is a cut-out at alphaCutoff of the base colour's alpha (factor times the
    // texture's); BLEND, which a ray tracer without transparency sorting cannot follow, is
    // taken as MASK at 0.5 (docs/conversion.md). OPAQUE ignores alpha.
    void readAlphaMode(const tinygltf::Material& gm, const std::string& what, Material& m) {
        if (gm.alphaMode != "MASK" && gm.alphaMode != "BLEND") return;
        const bool blend = gm.alphaMode == "BLEND";
        m.opacity.cutoff = blend ? 0.5f : float(numberWithin(gm.alphaCutoff, 0, 1, file_, what + " alphaCutoff"));
        const std::vector<double>& factor = gm.pbrMetallicRoughness.baseColorFactor;
        if (factor.size() == 4)
            m.opacity.alpha = float(std::clamp(finiteNumber(factor[3], file_, what + " alpha"), 0.0, 1.0));
        m.opacity.texture = m.colorTexture;
        if (blend)
            assembly_.report().notes.push_back(what + " (" + gm.name + "): alphaMode BLEND drawn as a cut-out at 0.5");
    }

    float emissiveStrength(const tinygltf::Material& gm, const std::string& what) const {
        const auto ext = gm.extensions.find("KHR_materials_emissive_strength");
        if (ext == gm.extensions.end() || !ext->second.Has("emissiveStrength")) return 1;
        const double strength = numberValue(ext->second.Get("emissiveStrength"), file_, what + " emissiveStrength");
        return float(numberWithin(std::max(0.0, strength), 0, kMaxColorValue, file_, what + " emissiveStrength"));
    }

    // The scene texture for a material's texture reference: an image file beside the model or
    // one the file embeds (gltf_images.h), read by TEXCOORD_0.
    template <class Info>
    std::optional<std::uint32_t> textureFor(const Info& info, const std::string& what) {
        if (info.index < 0) return std::nullopt;
        if (std::size_t(info.index) >= gltf_.textures.size())
            fail(what + " names texture " + std::to_string(info.index) + ", which does not exist");
        const tinygltf::Texture& gt = gltf_.textures[std::size_t(info.index)];
        if (gt.source < 0 || std::size_t(gt.source) >= gltf_.images.size()) return std::nullopt;
        const tinygltf::Image& image = gltf_.images[std::size_t(gt.source)];
        const ImageBytes& embedded = embeddedBytes(gt.source);
        if ((image.uri.empty() && !embedded) || info.texCoord != 0) {
            ++unusedTextures_;
            return std::nullopt;
        }
        Texture t = embedded ? Texture{} : textureBeside(file_, image.uri);
        if (embedded) {
            t.file = embeddedImageFile(image, gt.source, *embedded);
            t.name = std::filesystem::path(t.file).stem().string();
            t.embedded = embedded;
        }
        if (!image.name.empty()) t.name = image.name;
        if (gt.sampler >= 0 && std::size_t(gt.sampler) < gltf_.samplers.size()) {
            t.wrapS = wrapOf(gltf_.samplers[std::size_t(gt.sampler)].wrapS);
            t.wrapT = wrapOf(gltf_.samplers[std::size_t(gt.sampler)].wrapT);
        }
        readTextureTransform(info.extensions, t, what);
        return addTexture(out_.scene, std::move(t));
    }

    // Each embedded image's bytes once, however many textures use it.
    const ImageBytes& embeddedBytes(int image) {
        auto [it, added] = embeddedImages_.try_emplace(image);
        if (added) it->second = embeddedImage(gltf_, image, file_);
        return it->second;
    }

    static Texture::Wrap wrapOf(int glWrap) {
        if (glWrap == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE) return Texture::Wrap::Clamp;
        if (glWrap == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT) return Texture::Wrap::Mirror;
        return Texture::Wrap::Repeat;
    }

    // KHR_texture_transform: offset, rotation, scale (texCoord overrides are not followed).
    void readTextureTransform(const tinygltf::ExtensionMap& extensions, Texture& t, const std::string& what) const {
        const auto ext = extensions.find("KHR_texture_transform");
        if (ext == extensions.end()) return;
        const tinygltf::Value& v = ext->second;
        const auto pair = [&](const char* key, std::array<float, 2>& to) {
            if (!v.Has(key) || !v.Get(key).IsArray() || v.Get(key).ArrayLen() < 2) return;
            for (int i = 0; i < 2; ++i)
                to[std::size_t(i)] = float(transformNumber(v.Get(key).Get(i), what + " " + key));
        };
        pair("offset", t.offset);
        pair("scale", t.scale);
        if (v.Has("rotation")) t.rotation = float(transformNumber(v.Get("rotation"), what + " rotation"));
    }

    double transformNumber(const tinygltf::Value& v, const std::string& what) const {
        return numberWithin(numberValue(v, file_, what), -kMaxTextureTransform, kMaxTextureTransform, file_, what);
    }

    PbrMaterialFactors metallicRoughness(const tinygltf::Material& gm, const std::string& what) const {
        const tinygltf::PbrMetallicRoughness& pbr = gm.pbrMetallicRoughness;
        PbrMaterialFactors in;
        in.baseColor = color(pbr.baseColorFactor, what + " baseColorFactor");
        in.factors.metallic = float(colorValue(pbr.metallicFactor, what + " metallicFactor"));
        in.factors.roughness = float(colorValue(pbr.roughnessFactor, what + " roughnessFactor"));
        // The texture, which a Phong material cannot follow per hit, usually holds the real
        // values and leaves the factors at 1 (rough metal): take a dielectric of middle roughness.
        if (pbr.metallicRoughnessTexture.index >= 0) {
            in.factors.metallic = 0;
            in.factors.roughness *= 0.5f;
        }
        const auto ior = gm.extensions.find("KHR_materials_ior");
        if (ior != gm.extensions.end() && ior->second.Has("ior"))
            in.ior = float(numberWithin(numberValue(ior->second.Get("ior"), file_, what + " ior"), 0, kMaxIor, file_,
                                        what + " ior"));
        const auto specular = gm.extensions.find("KHR_materials_specular");
        if (specular != gm.extensions.end()) {
            const tinygltf::Value& ext = specular->second;
            if (ext.Has("specularFactor"))
                in.factors.specular = float(colorValue(
                    numberValue(ext.Get("specularFactor"), file_, what + " specularFactor"), what + " specularFactor"));
            if (ext.Has("specularColorFactor") && ext.Get("specularColorFactor").IsArray())
                in.specularColor = color(numbers(ext.Get("specularColorFactor"), what), what + " specularColorFactor");
        }
        readTransmission(gm, in, what);
        return in;
    }

    // KHR_materials_transmission and KHR_materials_volume. For the Phong coefficients a
    // transmissionTexture, which usually holds the real values (a paper lamp shade's fibres), is
    // taken as mid-grey, half the factor, as the metallicRoughnessTexture is (the renderers then
    // follow it per hit: keepTransmissionTexture()).
    void readTransmission(const tinygltf::Material& gm, PbrMaterialFactors& in, const std::string& what) const {
        const auto number = [&](const tinygltf::Value& ext, const char* key, float& to) {
            to = extensionNumber(ext, key, to, what);
        };
        const auto transmission = gm.extensions.find("KHR_materials_transmission");
        if (transmission != gm.extensions.end()) {
            number(transmission->second, "transmissionFactor", in.transmission);
            if (transmission->second.Has("transmissionTexture")) in.transmission *= 0.5f;
        }
        const auto volume = gm.extensions.find("KHR_materials_volume");
        if (volume == gm.extensions.end()) return;
        const tinygltf::Value& ext = volume->second;
        number(ext, "thicknessFactor", in.thickness);
        number(ext, "attenuationDistance", in.attenuationDistance);
        if (ext.Has("attenuationColor") && ext.Get("attenuationColor").IsArray())
            in.attenuationColor = color(numbers(ext.Get("attenuationColor"), what), what + " attenuationColor");
    }

    // KHR_materials_clearcoat's factors, for the path tracer (its textures and normal are not read).
    void readClearcoat(const tinygltf::Material& gm, const std::string& what, Material& m) const {
        const auto ext = gm.extensions.find("KHR_materials_clearcoat");
        if (ext == gm.extensions.end()) return;
        const auto factor = [&](const char* key) {
            return std::clamp(extensionNumber(ext->second, key, 0, what), 0.0f, 1.0f);
        };
        m.clearcoat.weight = factor("clearcoatFactor");
        m.clearcoat.roughness = factor("clearcoatRoughnessFactor");
    }

    // The number `key` of a material extension's object, `fallback` without one.
    float extensionNumber(const tinygltf::Value& ext, const char* key, float fallback, const std::string& what) const {
        if (!ext.Has(key)) return fallback;
        return float(colorValue(numberValue(ext.Get(key), file_, what + " " + key), what + " " + key));
    }

    std::vector<double> numbers(const tinygltf::Value& array, const std::string& what) const {
        std::vector<double> v;
        for (int i = 0; i < int(array.ArrayLen()); ++i) v.push_back(numberValue(array.Get(i), file_, what));
        return v;
    }

    Color color(const std::vector<double>& v, const std::string& what) const {
        if (v.size() < 3) fail(what + " needs 3 numbers");
        return {float(colorValue(v[0], what)), float(colorValue(v[1], what)), float(colorValue(v[2], what))};
    }

    // A colour channel, factor or intensity: kept within kMaxColorValue either way.
    double colorValue(double v, const std::string& what) const {
        return numberWithin(v, -kMaxColorValue, kMaxColorValue, file_, what);
    }

    // --camera NAME|INDEX, else the first perspective camera a node places; none for --camera auto.
    // Every other perspective camera placed follows it (rt-render --camera picks one).
    void takeCamera(const Aabb& bounds) {
        ImportReport& report = out_.report;
        report.camerasInFile = gltf_.cameras.size();
        if (options_.camera == kFramingCamera) return;
        const Placed* chosen = nullptr;
        for (const Placed& c : cameras_) {
            const tinygltf::Camera& cam = gltf_.cameras[std::size_t(c.index)];
            const bool named =
                options_.camera == std::to_string(c.index) || (!cam.name.empty() && options_.camera == cam.name);
            if (options_.camera.empty() ? cam.type == "perspective" : named) {
                chosen = &c;
                break;
            }
        }
        if (!chosen && !options_.camera.empty())
            fail("no node of the scene places a camera named or numbered \"" + options_.camera + "\"");
        if (!chosen) {
            if (!cameras_.empty()) report.notes.push_back(std::to_string(cameras_.size()) + " camera(s) not used");
            return;
        }
        out_.scene.camera = perspectiveCamera(*chosen, bounds);
        const tinygltf::Camera& cam = gltf_.cameras[std::size_t(chosen->index)];
        report.cameraUsed = cam.name.empty() ? "#" + std::to_string(chosen->index) : cam.name;
        for (const Placed& c : cameras_)
            if (&c != chosen && usablePerspective(gltf_.cameras[std::size_t(c.index)]))
                out_.scene.extraCameras.push_back(perspectiveCamera(c, bounds));
        if (const std::size_t unused = cameras_.size() - 1 - out_.scene.extraCameras.size())
            report.notes.push_back(std::to_string(unused) +
                                   " other camera(s) not used: not perspective, or no valid yfov");
    }

    static bool usablePerspective(const tinygltf::Camera& cam) {
        return cam.type == "perspective" && cam.perspective.yfov > 0 && cam.perspective.yfov < kPi;
    }

    // The camera a node places, named as in the file; fails if rt cannot use it.
    Camera perspectiveCamera(const Placed& placed, const Aabb& bounds) {
        const tinygltf::Camera& cam = gltf_.cameras[std::size_t(placed.index)];
        const std::string what = "camera " + std::to_string(placed.index);
        if (cam.type != "perspective") fail(what + " is " + cam.type + "; rt cameras are perspective");
        const double yfov = finiteNumber(cam.perspective.yfov, file_, what + " yfov");
        if (!(yfov > 0 && yfov < kPi)) fail(what + ": yfov must lie between 0 and pi");
        double aspect = cam.perspective.aspectRatio;
        if (!(aspect > 0) || !std::isfinite(aspect)) {
            aspect = options_.aspect;
            out_.report.notes.push_back(what + " has no aspect ratio: its horizontal fov assumes " +
                                        std::to_string(aspect));
        }
        const Transform& w = placed.world;
        const Vec3 forward = w.vector(Vec3(0, 0, -1)), up = w.vector(Vec3(0, 1, 0));
        // A sheared or degenerate node matrix can turn the view and up directions into one.
        if (!(length(cross(normalize(forward), normalize(up))) > 1e-6))
            fail(what + ": its node's matrix makes the view and up directions parallel (sheared or degenerate)");
        Camera camera = viewCamera(w.point(Vec3()), forward, up, horizontalFov(yfov, aspect), bounds);
        if (!(camera.fovDegrees && *camera.fovDegrees > 0 && *camera.fovDegrees < 180)) {
            std::ostringstream message;
            message << what << ": yfov " << yfov << " and aspectRatio " << aspect
                    << " make a horizontal fov of 180 degrees or more";
            fail(message.str());
        }
        camera.name = cam.name;
        return camera;
    }

    // KHR_lights_punctual, exactly (import/punctual_light.h): colour times intensity in rt's
    // units, the node's position and -Z axis, range and cone.
    void takeLights() {
        out_.report.lightsInFile = gltf_.lights.size();
        for (const Placed& p : lights_) {
            const tinygltf::Light& gl = gltf_.lights[std::size_t(p.index)];
            const std::string what = "light " + std::to_string(p.index) + " (" + gl.type + ")";
            const std::optional<Light::Type> type = parseNamed(kLightTypeNames, gl.type);
            if (!type) fail(what + " has an unknown type");
            PunctualLight light;
            light.type = *type;
            const double intensity = lightIntensity(gl, p.index) * kRtPerPhotometricUnit;
            light.color = (gl.color.empty() ? Color(1, 1, 1) : color(gl.color, what + " color")) * float(intensity);
            light.range = std::max(0.0, finiteNumber(gl.range, file_, what + " range"));
            light.innerConeRadians = finiteNumber(gl.spot.innerConeAngle, file_, what + " innerConeAngle");
            light.outerConeRadians = finiteNumber(gl.spot.outerConeAngle, file_, what + " outerConeAngle");
            out_.scene.lights.push_back(placeLight(light, p.world, options_.scale, file_ + ": " + what));
        }
    }

    double lightIntensity(const tinygltf::Light& light, int index) const {
        const double i = colorValue(light.intensity, "light " + std::to_string(index) + " intensity");
        if (i < 0) fail("light " + std::to_string(index) + " has a negative intensity");
        return i;
    }

    void noteTextures() {
        if (unusedTextures_)
            out_.report.notes.push_back(std::to_string(unusedTextures_) +
                                        " texture reference(s) to other texture coordinates than TEXCOORD_0 or to "
                                        "images without data are not used (the factor is kept)");
    }

    const tinygltf::Model& gltf_;
    const std::string& file_;
    const ImportOptions& options_;
    ImportResult& out_;
    SceneAssembly<std::pair<int, int>, int> assembly_;  // models by (mesh, primitive), materials by index
    GltfAccessorReader reader_;
    std::set<int> meshesPlaced_;
    std::vector<Placed> cameras_;
    std::vector<Placed> lights_;
    std::size_t unusedTextures_ = 0;
    std::map<int, ImageBytes> embeddedImages_;
};

}  // namespace

bool hasGlbMagic(const std::string& path) { return fileStartsWith(path, kGlbMagic); }

ImportResult importGltf(const std::string& path, const ImportOptions& options) {
    if (!std::ifstream(path, std::ios::binary)) throw InputError(path + ": cannot open the file");
    ImportResult result;
    const bool binary = hasGlbMagic(path);
    const tinygltf::Model gltf = loadGltf(path, binary, FileAccess(path, options.filesOutsideModelFolder),
                                          result.report, [&](auto& loader, auto& model, auto& e, auto& w) {
                                              return binary ? loader.LoadBinaryFromFile(&model, &e, &w, path)
                                                            : loader.LoadASCIIFromFile(&model, &e, &w, path);
                                          });
    GltfSceneBuilder(gltf, path, options, result).build(rootTransform(options));
    return result;
}

ImportResult importGltfBytes(const std::string& bytes, const std::string& name, const ImportOptions& options) {
    if (bytes.size() > std::numeric_limits<unsigned>::max()) throw InputError(name + ": larger than 4 GiB");
    ImportResult result;
    const bool binary = bytes.starts_with(kGlbMagic);
    const auto size = unsigned(bytes.size());
    const tinygltf::Model gltf = loadGltf(
        name, binary, FileAccess("./-", options.filesOutsideModelFolder), result.report,
        [&](auto& loader, auto& model, auto& e, auto& w) {
            return binary ? loader.LoadBinaryFromMemory(&model, &e, &w,
                                                        reinterpret_cast<const unsigned char*>(bytes.data()), size, ".")
                          : loader.LoadASCIIFromString(&model, &e, &w, bytes.data(), size, ".");
        });
    GltfSceneBuilder(gltf, name, options, result).build(rootTransform(options));
    return result;
}

}  // namespace rt
