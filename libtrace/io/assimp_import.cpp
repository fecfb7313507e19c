#include "io/assimp_import.h"

#include <assimp/BaseImporter.h>
#include <assimp/DefaultIOSystem.h>
#include <assimp/config.h>
#include <assimp/importerdesc.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>

#include "core/error.h"
#include "io/assimp_contained.h"
#include "io/camera_3ds.h"
#include "io/punctual_light.h"
#include "io/scene_assembly.h"
#include "io/scene_defaults.h"
#include "os/input_file.h"
#include "os/sandbox.h"

namespace rt {
namespace {

Transform toTransform(const aiMatrix4x4& m) {
    Transform::Matrix r{};
    const ai_real* rows[4] = {&m.a1, &m.b1, &m.c1, &m.d1};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r[i][j] = Real(rows[i][j]);
    return Transform(r);  // throws std::invalid_argument when singular or not affine
}

Vec3 toVec3(const aiVector3D& v) { return {Real(v.x), Real(v.y), Real(v.z)}; }

// An importer without Assimp's glTF readers, which abort on some broken files.
// UnregisterLoader hands the reader back to the caller, who deletes it.
void removeGltfImporters(Assimp::Importer& importer) {
    for (const char* ext : {"gltf", "glb"}) {
        while (Assimp::BaseImporter* reader = importer.GetImporter(ext)) {
            importer.UnregisterLoader(reader);
            delete reader;
        }
    }
}

// The name of the importer that reads the file. Without an extension Assimp knows, Assimp
// guesses the format from the content: binary formats have signatures, but text formats are
// guessed from keywords ("v ", "f " for OBJ) that garbage can contain too (as an OSS-Fuzz case
// of Assimp's does: docs/conversion.md), so such a guess is only trusted for a binary format.
std::string formatName(const Assimp::Importer& importer, const std::string& path) {
    const std::string::size_type dot = path.find_last_of("./");
    const std::string ext = dot == std::string::npos || path[dot] == '/' ? "" : path.substr(dot + 1);
    const std::size_t byExtension = ext.empty() ? std::size_t(-1) : importer.GetImporterIndex(ext.c_str());
    if (byExtension != std::size_t(-1)) return importer.GetImporterInfo(byExtension)->mName;
    for (std::size_t i = 0; i < importer.GetImporterCount(); ++i) {
        if (!importer.GetImporter(i)->CanRead(path, importer.GetIOHandler(), true)) continue;
        const aiImporterDesc* desc = importer.GetImporterInfo(i);
        if (!(desc->mFlags & aiImporterFlags_SupportBinaryFlavour))
            throw InputError(path + ": the file name has no known extension and the content looks like " + desc->mName +
                             " text only by its keywords; rename it with the right extension");
        return desc->mName;
    }
    throw InputError(path + ": unknown file format (no known extension, no recognised signature)");
}

constexpr const char* k3dsImporter = "Discreet 3DS Importer";

// Assimp's 3DS reader turns the scene from 3D Studio's Z-up to Y-up (a root node transform);
// the other readers leave the file's axes alone, except Collada's, which applies the file's
// <up_axis> unless told not to (importAssimp does when --up-axis is given).
UpAxis importerUpAxis(const std::string& format) { return format == k3dsImporter ? UpAxis::Z : UpAxis::Y; }

class AssimpSceneBuilder {
public:
    AssimpSceneBuilder(const aiScene& ai, const std::string& file, const ImportOptions& options, ImportResult& out)
        : ai_(ai), file_(file), options_(options), out_(out), assembly_(out, options) {}

    void build(const Transform& root) {
        // 3DS file coordinates in the scene: the quarter turn about x with which Assimp's 3DS
        // reader makes the file Y-up, under the root (only 3DS cameras use it).
        fileToWorld_ = root * Transform::rotateX(-kPi / 2);
        std::vector<std::pair<const aiNode*, Transform>> stack{{ai_.mRootNode, root}};
        std::set<const aiNode*> visited;
        while (!stack.empty()) {  // depth first, without recursion
            auto [node, parent] = stack.back();
            stack.pop_back();
            if (!node || !visited.insert(node).second) fail("the node tree is not a tree");
            std::optional<Transform> world = worldTransform(*node, parent);
            if (!world) continue;
            worldByName_.emplace(node->mName.C_Str(), *world);
            for (unsigned i = 0; i < node->mNumMeshes; ++i) placeMesh(node->mMeshes[i], *world);
            for (unsigned i = node->mNumChildren; i-- > 0;) stack.emplace_back(node->mChildren[i], *world);
        }
        out_.report.meshes = meshesPlaced_.size();
        const Aabb bounds = sceneBounds(out_.scene);
        takeCamera(bounds);
        takeLights();
    }

private:
    [[noreturn]] void fail(const std::string& message) const { throw InputError(file_ + ": " + message); }

    std::optional<Transform> worldTransform(const aiNode& node, const Transform& parent) {
        try {
            return parent * toTransform(node.mTransformation);
        } catch (const std::invalid_argument& e) {
            out_.report.notes.push_back("node \"" + std::string(node.mName.C_Str()) + "\": " + e.what() +
                                        ": it and its children are left out");
            return std::nullopt;
        }
    }

    void placeMesh(unsigned meshIndex, const Transform& world) {
        if (meshIndex >= ai_.mNumMeshes)
            fail("a node names mesh " + std::to_string(meshIndex) + ", which does not exist");
        meshesPlaced_.insert(meshIndex);
        const ConvertedMesh converted = assembly_.mesh(meshIndex, [&] { return convertMesh(meshIndex); });
        assembly_.place(
            converted, [&] { return materialFor(ai_.mMeshes[meshIndex]->mMaterialIndex); }, world);
    }

    ConvertedMesh convertMesh(unsigned meshIndex) {
        const aiMesh& mesh = *ai_.mMeshes[meshIndex];
        const std::string what = "mesh " + std::to_string(meshIndex);
        std::vector<Point3f> points(mesh.mNumVertices);
        for (unsigned i = 0; i < mesh.mNumVertices; ++i) {
            const aiVector3D& v = mesh.mVertices[i];
            if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
                fail(what + " vertex " + std::to_string(i) + " has a NaN or infinite coordinate");
            points[i] = {float(v.x), float(v.y), float(v.z)};
        }
        ModelBuilder model = assembly_.newModel(mesh.mName.C_Str(), "mesh" + std::to_string(meshIndex));
        const VertexData data = vertexData(mesh);
        for (unsigned f = 0; f < mesh.mNumFaces; ++f) addFace(mesh.mFaces[f], points, data, model, what);
        return assembly_.addModel(std::move(model));
    }

    // A mesh's normals, first texture coordinates and first colours; non-finite values read
    // as 0. Assimp's v runs up the image (OpenGL), rt's down (glTF): v becomes 1 - v.
    static VertexData vertexData(const aiMesh& mesh) {
        const auto finite = [](ai_real v) { return std::isfinite(v) ? float(v) : 0.0f; };
        VertexData data;
        for (unsigned i = 0; i < mesh.mNumVertices; ++i) {
            if (mesh.mNormals) {
                const aiVector3D& n = mesh.mNormals[i];
                data.normals.insert(data.normals.end(), {finite(n.x), finite(n.y), finite(n.z)});
            }
            if (mesh.mTextureCoords[0]) {
                const aiVector3D& t = mesh.mTextureCoords[0][i];
                data.uvs.insert(data.uvs.end(), {finite(t.x), 1 - finite(t.y)});
            }
            if (mesh.mColors[0]) {
                const aiColor4D& c = mesh.mColors[0][i];
                data.colors.insert(data.colors.end(), {finite(c.r), finite(c.g), finite(c.b)});
            }
        }
        return data;
    }

    // Triangles as they are; a polygon Triangulate left (it should leave none) as a fan.
    void addFace(const aiFace& face, const std::vector<Point3f>& points, const VertexData& data, ModelBuilder& model,
                 const std::string& what) {
        assembly_.countFaceWithoutArea(face.mNumIndices);
        for (unsigned i = 0; i < face.mNumIndices; ++i)
            if (face.mIndices[i] >= points.size())
                fail(what + " has a face with vertex index " + std::to_string(face.mIndices[i]) + " out of range");
        const unsigned* v = face.mIndices;
        for (unsigned i = 1; i + 1 < face.mNumIndices; ++i)
            model.addTriangleWithData(data.corner(points, v[0]), data.corner(points, v[i]),
                                      data.corner(points, v[i + 1]));
    }

    std::uint32_t materialFor(unsigned index) {
        return assembly_.material(index, "material" + std::to_string(index), [&] { return convertMaterial(index); });
    }

    // Diffuse colour, specular = luminance(Ks) * shininess strength, shininess as the Phong
    // exponent, reflectivity as the mirror coefficient (docs/conversion.md).
    Material convertMaterial(unsigned index) {
        if (index >= ai_.mNumMaterials)
            fail("a mesh names material " + std::to_string(index) + ", which does not exist");
        const aiMaterial& am = *ai_.mMaterials[index];
        aiColor3D kd(1, 1, 1), ks(0, 0, 0);
        float strength = 1, shininess = 0, reflectivity = 0;
        am.Get(AI_MATKEY_COLOR_DIFFUSE, kd);
        am.Get(AI_MATKEY_COLOR_SPECULAR, ks);
        am.Get(AI_MATKEY_SHININESS_STRENGTH, strength);
        am.Get(AI_MATKEY_SHININESS, shininess);
        am.Get(AI_MATKEY_REFLECTIVITY, reflectivity);
        Material m = classicPhong(toColor(kd), toColor(ks) * (std::isfinite(strength) ? strength : 1), shininess);
        m.phong.reflection = std::isfinite(reflectivity) ? std::clamp(reflectivity, 0.0f, 1.0f) : 0.0f;
        aiColor3D ke(0, 0, 0);
        am.Get(AI_MATKEY_COLOR_EMISSIVE, ke);
        m.emission.color = toColor(ke);
        m.colorTexture = diffuseTexture(am);
        applyOpacity(m, opacity(am), refractionIndex(am));
        aiString name;
        am.Get(AI_MATKEY_NAME, name);
        m.name = name.C_Str();
        return m;
    }

    // AI_MATKEY_OPACITY (3DS transparency), else 1 - AI_MATKEY_TRANSPARENCYFACTOR; 1 if neither.
    static float opacity(const aiMaterial& am) {
        float opacity = 1, transparency = 0;
        if (am.Get(AI_MATKEY_OPACITY, opacity) == AI_SUCCESS) return opacity;
        return am.Get(AI_MATKEY_TRANSPARENCYFACTOR, transparency) == AI_SUCCESS ? 1 - transparency : 1;
    }

    static float refractionIndex(const aiMaterial& am) {
        float ior = 1;
        am.Get(AI_MATKEY_REFRACTI, ior);
        return ior;
    }

    // The first diffuse texture, a file relative to the model's folder (embedded ones, "*0",
    // are not used), read by the first texture coordinates.
    std::optional<std::uint32_t> diffuseTexture(const aiMaterial& am) {
        aiString file;
        aiTextureMapMode mode[2] = {aiTextureMapMode_Wrap, aiTextureMapMode_Wrap};
        if (am.GetTexture(aiTextureType_DIFFUSE, 0, &file) != AI_SUCCESS || file.length == 0 || file.C_Str()[0] == '*')
            return std::nullopt;
        am.Get(AI_MATKEY_MAPPINGMODE_U(aiTextureType_DIFFUSE, 0), mode[0]);
        am.Get(AI_MATKEY_MAPPINGMODE_V(aiTextureType_DIFFUSE, 0), mode[1]);
        const auto wrap = [](aiTextureMapMode m) {
            return m == aiTextureMapMode_Clamp    ? Texture::Wrap::Clamp
                   : m == aiTextureMapMode_Mirror ? Texture::Wrap::Mirror
                                                  : Texture::Wrap::Repeat;
        };
        Texture t = textureBeside(file_, file.C_Str());
        t.wrapS = wrap(mode[0]);
        t.wrapT = wrap(mode[1]);
        return addTexture(out_.scene, std::move(t));
    }

    static Color toColor(const aiColor3D& c) { return fileColor(c.r, c.g, c.b); }

    const Transform* placement(const aiString& name) const {
        const auto it = worldByName_.find(name.C_Str());
        return it == worldByName_.end() ? nullptr : &it->second;
    }

    // --camera NAME|INDEX, else the first perspective camera a node places; none for
    // --camera auto. Every other usable camera follows it, in file order (rt-render --camera).
    // Assimp's mHorizontalFOV is half the horizontal angle. 3DS cameras come from the file's
    // chunks, which Assimp's values cannot be turned back into.
    void takeCamera(const Aabb& bounds) {
        ImportReport& report = out_.report;
        report.camerasInFile = ai_.mNumCameras;
        if (ai_.mNumCameras == 0 || options_.camera == kFramingCamera) return;
        const std::vector<Camera3ds> chunks =
            report.format == k3dsImporter ? read3dsCamerasFromFile(file_) : std::vector<Camera3ds>();
        for (unsigned i = 0; i < ai_.mNumCameras; ++i) {
            const std::string name = ai_.mCameras[i]->mName.C_Str();
            const bool wanted =
                options_.camera.empty() || options_.camera == std::to_string(i) || options_.camera == name;
            if (!wanted) continue;
            const std::optional<Camera> camera = cameraAt(i, chunks, bounds);
            if (!camera) continue;
            out_.scene.camera = *camera;
            report.cameraUsed = name;
            if (name.empty())
                report.cameraUsed.append("#").append(std::to_string(i));  // (GCC 12 -Wrestrict misfires on "#" + s)
            takeOtherCameras(i, chunks, bounds);
            return;
        }
        if (!options_.camera.empty()) fail("no node places a camera named or numbered \"" + options_.camera + "\"");
    }

    // Camera i of the file, named as there, if a node places it and rt can use it.
    std::optional<Camera> cameraAt(unsigned i, const std::vector<Camera3ds>& chunks, const Aabb& bounds) {
        const aiCamera& cam = *ai_.mCameras[i];
        const std::string name = cam.mName.C_Str();
        const Transform* world = placement(cam.mName);
        if (!world) return std::nullopt;
        const std::string what = "camera " + std::to_string(i) + " \"" + name + "\"";
        std::optional<Camera> camera = out_.report.format == k3dsImporter ? camera3ds(chunks, name, what)
                                                                          : assimpCamera(cam, *world, what, bounds);
        if (camera) camera->name = name;
        return camera;
    }

    // The cameras after the one taken; one that cannot be used is a note, whatever --camera asked.
    void takeOtherCameras(unsigned taken, const std::vector<Camera3ds>& chunks, const Aabb& bounds) {
        otherCameras_ = true;
        for (unsigned i = 0; i < ai_.mNumCameras; ++i)
            if (i != taken)
                if (const std::optional<Camera> camera = cameraAt(i, chunks, bounds))
                    out_.scene.extraCameras.push_back(*camera);
    }

    // A camera not used is an error when --camera asked for it, else a note.
    std::nullopt_t unusable(const std::string& what, const std::string& why) {
        if (!options_.camera.empty() && !otherCameras_) fail(what + " " + why);
        out_.report.notes.push_back(what + " " + why + ": not used");
        return std::nullopt;
    }

    std::optional<Camera> assimpCamera(const aiCamera& cam, const Transform& world, const std::string& what,
                                       const Aabb& bounds) {
        if (cam.mOrthographicWidth > 0 || !(cam.mHorizontalFOV > 0 && cam.mHorizontalFOV < kPi / 2))
            return unusable(what, "is orthographic or has an invalid fov");
        return viewCamera(world.point(toVec3(cam.mPosition)), world.vector(toVec3(cam.mLookAt)),
                          world.vector(toVec3(cam.mUp)), 2.0 * cam.mHorizontalFOV, bounds);
    }

    // The camera chunk of the same name, in the file's coordinates under the root node.
    std::optional<Camera> camera3ds(const std::vector<Camera3ds>& chunks, const std::string& name,
                                    const std::string& what) {
        const auto chunk =
            std::find_if(chunks.begin(), chunks.end(), [&](const Camera3ds& c) { return c.name == name; });
        if (chunk == chunks.end()) return unusable(what, "has no camera chunk of that name");
        if (chunk->target == chunk->position) return unusable(what, "looks at its own position");
        const double fov = fovDegreesFromLens(chunk->lensMm);
        if (!(fov > 0 && fov < 180)) return unusable(what, "has a lens of " + std::to_string(chunk->lensMm) + " mm");
        return cameraFrom3ds(*chunk, fileToWorld_);
    }

    // Point, spot and directional lights as they are (import/punctual_light.h), area lights as
    // point lights, ambient lights dropped. Assimp gives no units: colours are scaled together
    // to a peak of 1 (docs/conversion.md).
    void takeLights() {
        out_.report.lightsInFile = ai_.mNumLights;
        for (unsigned i = 0; i < ai_.mNumLights; ++i) {
            const aiLight& al = *ai_.mLights[i];
            const std::string what = "light " + std::to_string(i) + " \"" + std::string(al.mName.C_Str()) + "\"";
            const Transform* world = placement(al.mName);
            if (!world || al.mType == aiLightSource_AMBIENT || al.mType == aiLightSource_UNDEFINED) {
                out_.report.notes.push_back(what + (world ? " is ambient: dropped" : " is placed by no node: dropped"));
                continue;
            }
            out_.scene.lights.push_back(placeLight(punctual(al, what), *world, options_.scale, file_ + ": " + what));
        }
        scaleLightsToUnitPeak(out_.scene.lights);
    }

    // aiLight's attenuation is 1 / (constant + linear d + quadratic d^2): a pure quadratic is
    // the inverse square, anything else is drawn without falloff (a note says so).
    PunctualLight punctual(const aiLight& al, const std::string& what) {
        PunctualLight light;
        light.position = toVec3(al.mPosition);
        light.direction = toVec3(al.mDirection);
        light.color = toColor(al.mColorDiffuse);
        if (al.mType == aiLightSource_DIRECTIONAL) light.type = Light::Type::Directional;
        if (al.mType == aiLightSource_SPOT) {
            light.type = Light::Type::Spot;
            light.outerConeRadians = std::clamp(double(al.mAngleOuterCone), 0.0, double(kPi) / 2);
            light.innerConeRadians = std::clamp(double(al.mAngleInnerCone), 0.0, light.outerConeRadians);
        }
        if (al.mType == aiLightSource_AREA) out_.report.notes.push_back(what + " (area) approximated by a point light");
        const bool quadratic =
            al.mAttenuationQuadratic > 0 && al.mAttenuationConstant == 0 && al.mAttenuationLinear == 0;
        light.inverseSquare = quadratic && light.type != Light::Type::Directional;
        if (light.inverseSquare) light.color = light.color * (1 / al.mAttenuationQuadratic);
        if (!light.inverseSquare && light.type != Light::Type::Directional &&
            (al.mAttenuationLinear != 0 || al.mAttenuationQuadratic != 0))
            out_.report.notes.push_back(what + " has a falloff other than the inverse square: drawn without falloff");
        return light;
    }

    const aiScene& ai_;
    const std::string& file_;
    const ImportOptions& options_;
    ImportResult& out_;
    SceneAssembly<unsigned, unsigned> assembly_;  // models by aiMesh, materials by aiMaterial
    std::set<unsigned> meshesPlaced_;
    std::map<std::string, Transform> worldByName_;
    bool otherCameras_ = false;  // taking the cameras after the one --camera asked for
    Transform fileToWorld_;      // from a 3DS file's own coordinates
};

// The files a reader opens beside the model (an MD5 mesh's animation, a Collada include) obey
// --sandbox as the model does: one outside it cannot be opened.
class SandboxedFiles : public Assimp::DefaultIOSystem {
public:
    Assimp::IOStream* Open(const char* file, const char* mode) override {
        return sandboxRefusal(file, file) ? nullptr : DefaultIOSystem::Open(file, mode);
    }
};

}  // namespace

ImportResult importAssimpScene(const aiScene& scene, const std::string& path, const std::string& format,
                               const ImportOptions& options) {
    ImportResult result;
    result.report.format = format;
    AssimpSceneBuilder(scene, path, options, result).build(rootTransform(options, importerUpAxis(format)));
    return result;
}

ImportResult importAssimp(const std::string& path, const ImportOptions& options) {
    Assimp::Importer importer;
    removeGltfImporters(importer);
    const std::string format = formatName(importer, path);
    const std::unique_ptr<aiScene> ai = readContained(path, inputFileSize(path), [&](Assimp::Importer& reader) {
        removeGltfImporters(reader);
        reader.SetIOHandler(new SandboxedFiles);  // the Importer deletes it
        // --up-axis describes the file, so it takes the place of a Collada file's own <up_axis>.
        if (options.upAxis) reader.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, true);
        const aiScene* scene = reader.ReadFile(path, aiProcess_Triangulate | aiProcess_ValidateDataStructure);
        if (!scene || !scene->mRootNode) {
            const std::string why = reader.GetErrorString();
            throw InputError(path + ": " + (why.empty() ? "Assimp cannot read the file" : why));
        }
        return scene;
    });
    return importAssimpScene(*ai, path, format, options);
}

}  // namespace rt
