#include "io/assimp_reply.h"

#include <assimp/material.h>

#include <cstdint>
#include <cstring>
#include <iterator>
#include <type_traits>

#include "core/error.h"

namespace rt {
namespace {

constexpr char kMagic[4] = {'r', 't', 'A', 'R'};
constexpr std::uint32_t kVersion = 1;
enum VertexData : std::uint8_t { kNormals = 1, kUvs = 2, kColors = 4 };

// The material keys rt's importers ask for, each sent as Assimp answers the importer's own
// question: numbers and colours as aiGetMaterialFloatArray gives them (up to 4 floats, so that a
// colour reads back as it did, whatever the property held), strings as aiString, wrap modes as
// the aiMaterial::Get template reads them (a buffer holding the enum).
enum class KeyKind : std::uint8_t { Floats, String, WrapMode };
struct MaterialKey {
    const char* key;
    unsigned semantic;
    unsigned index;
    KeyKind kind;
};
const MaterialKey kMaterialKeys[] = {
    {AI_MATKEY_COLOR_DIFFUSE, KeyKind::Floats},
    {AI_MATKEY_COLOR_SPECULAR, KeyKind::Floats},
    {AI_MATKEY_COLOR_EMISSIVE, KeyKind::Floats},
    {AI_MATKEY_SHININESS_STRENGTH, KeyKind::Floats},
    {AI_MATKEY_SHININESS, KeyKind::Floats},
    {AI_MATKEY_REFLECTIVITY, KeyKind::Floats},
    {AI_MATKEY_OPACITY, KeyKind::Floats},
    {AI_MATKEY_TRANSPARENCYFACTOR, KeyKind::Floats},
    {AI_MATKEY_REFRACTI, KeyKind::Floats},
    {AI_MATKEY_NAME, KeyKind::String},
    {AI_MATKEY_TEXTURE_DIFFUSE(0), KeyKind::String},
    {AI_MATKEY_MAPPINGMODE_U_DIFFUSE(0), KeyKind::WrapMode},
    {AI_MATKEY_MAPPINGMODE_V_DIFFUSE(0), KeyKind::WrapMode},
};
constexpr std::size_t kMaterialKeyCount = std::size(kMaterialKeys);

// ---------------------------------------------------------------------------------------------
// Writing, in the child

class ReplyWriter {
public:
    std::string bytes;

    template <class T>
    void put(const T& value) {
        static_assert(std::is_trivially_copyable_v<T>);
        bytes.append(reinterpret_cast<const char*>(&value), sizeof(T));
    }
    template <class T>
    void putArray(const T* values, std::size_t count) {
        bytes.append(reinterpret_cast<const char*>(values), count * sizeof(T));
    }
    void putName(const aiString& name) {
        put(std::uint32_t(name.length));
        bytes.append(name.data, name.length);
    }
    void putVector(const aiVector3D& v) { putArray(&v.x, 3); }
};

void writeMesh(ReplyWriter& w, const aiMesh& mesh) {
    w.put(std::uint32_t(mesh.mMaterialIndex));
    w.put(std::uint32_t(mesh.mNumVertices));
    const std::uint8_t has =
        (mesh.mNormals ? kNormals : 0) | (mesh.mTextureCoords[0] ? kUvs : 0) | (mesh.mColors[0] ? kColors : 0);
    w.put(has);
    for (unsigned i = 0; i < mesh.mNumVertices; ++i) w.putVector(mesh.mVertices[i]);
    if (has & kNormals)
        for (unsigned i = 0; i < mesh.mNumVertices; ++i) w.putVector(mesh.mNormals[i]);
    if (has & kUvs)
        for (unsigned i = 0; i < mesh.mNumVertices; ++i) w.putArray(&mesh.mTextureCoords[0][i].x, 2);
    if (has & kColors) w.putArray(&mesh.mColors[0][0].r, 4 * std::size_t(mesh.mNumVertices));
    w.put(std::uint32_t(mesh.mNumFaces));
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
        w.put(std::uint32_t(mesh.mFaces[f].mNumIndices));
        w.putArray(mesh.mFaces[f].mIndices, mesh.mFaces[f].mNumIndices);
    }
}

void writeMaterial(ReplyWriter& w, const aiMaterial& material) {
    ReplyWriter entries;
    std::uint32_t count = 0;
    for (std::uint8_t k = 0; k < kMaterialKeyCount; ++k) {
        const MaterialKey& key = kMaterialKeys[k];
        ai_real floats[4];
        unsigned n = 4;
        aiString text;
        aiTextureMapMode mode;
        if (key.kind == KeyKind::Floats &&
            aiGetMaterialFloatArray(&material, key.key, key.semantic, key.index, floats, &n) == AI_SUCCESS && n > 0) {
            entries.put(k);
            entries.put(std::uint8_t(n));
            entries.putArray(floats, n);
        } else if (key.kind == KeyKind::String && material.Get(key.key, key.semantic, key.index, text) == AI_SUCCESS) {
            entries.put(k);
            entries.putName(text);
        } else if (key.kind == KeyKind::WrapMode &&
                   material.Get(key.key, key.semantic, key.index, mode) == AI_SUCCESS) {
            entries.put(k);
            entries.put(std::int32_t(mode));
        } else {
            continue;
        }
        ++count;
    }
    w.put(count);
    w.bytes += entries.bytes;
}

void writeCamera(ReplyWriter& w, const aiCamera& camera) {
    w.putName(camera.mName);
    w.putVector(camera.mPosition);
    w.putVector(camera.mUp);
    w.putVector(camera.mLookAt);
    w.put(float(camera.mHorizontalFOV));
    w.put(float(camera.mOrthographicWidth));
}

void writeLight(ReplyWriter& w, const aiLight& light) {
    w.putName(light.mName);
    w.put(std::uint32_t(light.mType));
    w.putVector(light.mPosition);
    w.putVector(light.mDirection);
    w.putArray(&light.mColorDiffuse.r, 3);
    for (float v : {light.mAttenuationConstant, light.mAttenuationLinear, light.mAttenuationQuadratic,
                    light.mAngleInnerCone, light.mAngleOuterCone})
        w.put(v);
}

void writeNode(ReplyWriter& w, const aiNode& node, std::size_t depth, const std::string& path) {
    if (depth > kMaxReplyNodeDepth)
        throw InputError(path + ": the node tree is deeper than " + std::to_string(kMaxReplyNodeDepth) + " levels");
    w.putName(node.mName);
    w.putArray(&node.mTransformation.a1, 16);
    w.put(std::uint32_t(node.mNumMeshes));
    w.putArray(node.mMeshes, node.mNumMeshes);
    w.put(std::uint32_t(node.mNumChildren));
    for (unsigned c = 0; c < node.mNumChildren; ++c) writeNode(w, *node.mChildren[c], depth + 1, path);
}

// ---------------------------------------------------------------------------------------------
// Reading, in the tool: every count is checked against the bytes left, and what the scene will
// hold against a budget of kBytesPerReplyByte for each byte received (plus kBudgetSlack), before
// anything is allocated for it. An honest reply takes about 3 bytes a byte (a triangle's aiFace
// and its indices against its 16 bytes); an aiString of 1 KiB in every mesh, node, camera, light
// and material property makes the small things dear, hence the slack.

constexpr std::size_t kBytesPerReplyByte = 4;
constexpr std::size_t kBudgetSlack = std::size_t(64) << 20;

class ReplyReader {
public:
    ReplyReader(const std::string& bytes, const std::string& path)
        : bytes_(bytes), path_(path), budget_(kBytesPerReplyByte * bytes.size() + kBudgetSlack) {}

    [[noreturn]] void fail(const std::string& what) const {
        throw inputErrorAtByte(path_, at_, "the reply of Assimp's process is malformed: " + what);
    }

    template <class T>
    T get() {
        T value;
        getArray(&value, 1);
        return value;
    }
    template <class T>
    void getArray(T* values, std::size_t count) {
        static_assert(std::is_trivially_copyable_v<T>);
        if (count > left() / sizeof(T)) fail("it ends early");
        if (count == 0) return;  // `values` may be null then (a node of no meshes), which memcpy must not see
        std::memcpy(values, bytes_.data() + at_, count * sizeof(T));
        at_ += count * sizeof(T);
    }

    // A count of things each taking at least `bytesEach` of what is left.
    std::uint32_t count(std::size_t bytesEach, const std::string& what) {
        const auto n = get<std::uint32_t>();
        if (n > left() / bytesEach)
            fail(what + ": " + std::to_string(n) + ", more than the " + std::to_string(left()) + " bytes left hold");
        return n;
    }

    aiString name() {
        const auto length = get<std::uint32_t>();
        if (length >= MAXLEN)
            fail("a name of " + std::to_string(length) + " bytes (at most " + std::to_string(MAXLEN - 1) + ")");
        char text[MAXLEN];
        getArray(text, length);
        aiString name;
        name.Set(std::string(text, length));
        return name;
    }

    aiVector3D vector() {
        aiVector3D v;
        getArray(&v.x, 3);
        return v;
    }

    bool atEnd() const { return at_ == bytes_.size(); }

    // Counts `count` things of `size` bytes against the budget.
    void charge(std::size_t count, std::size_t size) {
        if (count > (budget_ - spent_) / size)
            fail("the scene would take more than the " + std::to_string(budget_ >> 20) +
                 " MiB its length allows the tool to spend on it");
        spent_ += count * size;
    }

    // A new array of `n` elements, each value-initialised (null pointers stay null, so that a
    // scene left half-read by an error frees itself); null for none.
    template <class T>
    T* newArray(std::size_t n) {
        charge(n, sizeof(T));
        return n ? new T[n]() : nullptr;
    }

private:
    std::size_t left() const { return bytes_.size() - at_; }

    const std::string& bytes_;
    const std::string& path_;
    std::size_t at_ = 0;
    const std::size_t budget_;
    std::size_t spent_ = 0;
};

// Into `to`, which owns the array before anything is read into it: a reply that ends part way
// leaves it to the mesh's destructor.
void readVectors(ReplyReader& r, aiVector3D*& to, unsigned n, unsigned components) {
    to = r.newArray<aiVector3D>(n);
    for (unsigned i = 0; i < n; ++i) r.getArray(&to[i].x, components);
}

void readFaces(ReplyReader& r, aiMesh& mesh, const std::string& what) {
    const std::uint32_t faces = r.count(sizeof(std::uint32_t), what + " faces");
    mesh.mFaces = r.newArray<aiFace>(faces);
    mesh.mNumFaces = faces;
    for (unsigned f = 0; f < faces; ++f) {
        aiFace& face = mesh.mFaces[f];
        const std::uint32_t corners = r.count(sizeof(std::uint32_t), what + " face " + std::to_string(f) + " corners");
        face.mIndices = r.newArray<unsigned>(corners);
        face.mNumIndices = corners;
        r.getArray(face.mIndices, corners);
        for (unsigned k = 0; k < corners; ++k)
            if (face.mIndices[k] >= mesh.mNumVertices)
                r.fail(what + " face " + std::to_string(f) + " names vertex " + std::to_string(face.mIndices[k]) +
                       " of " + std::to_string(mesh.mNumVertices));
    }
}

void readMesh(ReplyReader& r, aiMesh& mesh, const std::string& what) {
    mesh.mMaterialIndex = r.get<std::uint32_t>();
    const std::uint32_t n = r.count(3 * sizeof(float), what + " vertices");
    const auto has = r.get<std::uint8_t>();
    if (has & ~(kNormals | kUvs | kColors)) r.fail(what + " has unknown vertex data " + std::to_string(has));
    mesh.mNumVertices = n;
    readVectors(r, mesh.mVertices, n, 3);
    if (has & kNormals) readVectors(r, mesh.mNormals, n, 3);
    if (has & kUvs) {
        readVectors(r, mesh.mTextureCoords[0], n, 2);
        mesh.mNumUVComponents[0] = 2;
    }
    if ((has & kColors) && n > 0) {
        mesh.mColors[0] = r.newArray<aiColor4D>(n);
        r.getArray(&mesh.mColors[0][0].r, 4 * std::size_t(n));
    }
    readFaces(r, mesh, what);
}

void readMaterial(ReplyReader& r, aiMaterial& material, const std::string& what) {
    r.charge(5, sizeof(aiMaterialProperty*));  // the table aiMaterial's constructor allocates
    const std::uint32_t entries = r.count(5, what + " entries");
    for (unsigned e = 0; e < entries; ++e) {
        const auto k = r.get<std::uint8_t>();
        if (k >= kMaterialKeyCount) r.fail(what + " has unknown key " + std::to_string(k));
        const MaterialKey& key = kMaterialKeys[k];
        r.charge(1, sizeof(aiMaterialProperty) + sizeof(aiString) + 2 * sizeof(void*));
        if (key.kind == KeyKind::Floats) {
            const auto n = r.get<std::uint8_t>();
            if (n < 1 || n > 4) r.fail(what + " has " + std::to_string(n) + " numbers for " + key.key + " (1 to 4)");
            ai_real floats[4];
            r.getArray(floats, n);
            material.AddProperty(floats, n, key.key, key.semantic, key.index);
        } else if (key.kind == KeyKind::String) {
            const aiString text = r.name();
            material.AddProperty(&text, key.key, key.semantic, key.index);
        } else {
            const auto mode = r.get<std::int32_t>();
            material.AddBinaryProperty(&mode, sizeof(mode), key.key, key.semantic, key.index, aiPTI_Buffer);
        }
    }
}

void readCamera(ReplyReader& r, aiCamera& camera) {
    camera.mName = r.name();
    camera.mPosition = r.vector();
    camera.mUp = r.vector();
    camera.mLookAt = r.vector();
    camera.mHorizontalFOV = r.get<float>();
    camera.mOrthographicWidth = r.get<float>();
}

void readLight(ReplyReader& r, aiLight& light) {
    light.mName = r.name();
    const auto type = r.get<std::uint32_t>();
    if (type > aiLightSource_AREA) r.fail("a light of unknown type " + std::to_string(type));
    light.mType = aiLightSourceType(type);
    light.mPosition = r.vector();
    light.mDirection = r.vector();
    r.getArray(&light.mColorDiffuse.r, 3);
    for (float* v : {&light.mAttenuationConstant, &light.mAttenuationLinear, &light.mAttenuationQuadratic,
                     &light.mAngleInnerCone, &light.mAngleOuterCone})
        *v = r.get<float>();
}

// The smallest node: an empty name, the transform and two zero counts.
constexpr std::size_t kNodeBytes = 4 + 16 * sizeof(float) + 4 + 4;

void readNode(ReplyReader& r, aiNode& node, unsigned meshes, std::size_t depth) {
    if (depth > kMaxReplyNodeDepth)
        r.fail("the node tree is deeper than " + std::to_string(kMaxReplyNodeDepth) + " levels");
    node.mName = r.name();
    r.getArray(&node.mTransformation.a1, 16);
    const std::uint32_t meshCount = r.count(sizeof(std::uint32_t), "node meshes");
    node.mMeshes = r.newArray<unsigned>(meshCount);
    node.mNumMeshes = meshCount;
    r.getArray(node.mMeshes, meshCount);
    for (unsigned m = 0; m < meshCount; ++m)
        if (node.mMeshes[m] >= meshes)
            r.fail("node \"" + std::string(node.mName.C_Str()) + "\" names mesh " + std::to_string(node.mMeshes[m]) +
                   " of " + std::to_string(meshes));
    const std::uint32_t children = r.count(kNodeBytes, "node children");
    node.mChildren = r.newArray<aiNode*>(children);
    node.mNumChildren = children;
    for (unsigned c = 0; c < children; ++c) {
        r.charge(1, sizeof(aiNode));
        node.mChildren[c] = new aiNode;
        node.mChildren[c]->mParent = &node;
        readNode(r, *node.mChildren[c], meshes, depth + 1);
    }
}

// An array of `count` new T, each read by `read(reader, element, index)`; the scene owns it as
// it grows, so an error part way frees what was read.
template <class T, class Read>
void readAll(ReplyReader& r, T**& array, unsigned& count, std::size_t bytesEach, const std::string& what, Read&& read) {
    const std::uint32_t n = r.count(bytesEach, what + " count");
    array = r.newArray<T*>(n);
    count = n;
    for (unsigned i = 0; i < n; ++i) {
        r.charge(1, sizeof(T));
        array[i] = new T;
        read(*array[i], what + " " + std::to_string(i));
    }
}

}  // namespace

std::string writeAssimpReply(const aiScene& scene, const std::string& path) {
    ReplyWriter w;
    w.putArray(kMagic, 4);
    w.put(kVersion);
    w.put(std::uint32_t(scene.mNumMeshes));
    for (unsigned i = 0; i < scene.mNumMeshes; ++i) writeMesh(w, *scene.mMeshes[i]);
    w.put(std::uint32_t(scene.mNumMaterials));
    for (unsigned i = 0; i < scene.mNumMaterials; ++i) writeMaterial(w, *scene.mMaterials[i]);
    w.put(std::uint32_t(scene.mNumCameras));
    for (unsigned i = 0; i < scene.mNumCameras; ++i) writeCamera(w, *scene.mCameras[i]);
    w.put(std::uint32_t(scene.mNumLights));
    for (unsigned i = 0; i < scene.mNumLights; ++i) writeLight(w, *scene.mLights[i]);
    writeNode(w, *scene.mRootNode, 0, path);
    return std::move(w.bytes);
}

std::unique_ptr<aiScene> readAssimpReply(const std::string& reply, const std::string& path) {
    ReplyReader r(reply, path);
    char magic[4];
    r.getArray(magic, 4);
    if (std::memcmp(magic, kMagic, 4) != 0) r.fail("it does not start with rtAR");
    if (r.get<std::uint32_t>() != kVersion) r.fail("version other than " + std::to_string(kVersion));
    auto scene = std::make_unique<aiScene>();
    // Each thing's smallest size in the reply: a mesh of no vertices and faces, a material of no
    // entries, a camera and a light with empty names.
    readAll(r, scene->mMeshes, scene->mNumMeshes, 4 + 4 + 1 + 4, "mesh",
            [&](aiMesh& mesh, const std::string& what) { readMesh(r, mesh, what); });
    readAll(r, scene->mMaterials, scene->mNumMaterials, 4, "material",
            [&](aiMaterial& material, const std::string& what) { readMaterial(r, material, what); });
    for (unsigned i = 0; i < scene->mNumMeshes; ++i)
        if (scene->mMeshes[i]->mMaterialIndex >= scene->mNumMaterials)
            r.fail("mesh " + std::to_string(i) + " names material " +
                   std::to_string(scene->mMeshes[i]->mMaterialIndex) + " of " + std::to_string(scene->mNumMaterials));
    readAll(r, scene->mCameras, scene->mNumCameras, 4 + 11 * sizeof(float), "camera",
            [&](aiCamera& camera, const std::string&) { readCamera(r, camera); });
    readAll(r, scene->mLights, scene->mNumLights, 4 + 4 + 14 * sizeof(float), "light",
            [&](aiLight& light, const std::string&) { readLight(r, light); });
    r.charge(1, sizeof(aiNode));
    scene->mRootNode = new aiNode;
    readNode(r, *scene->mRootNode, scene->mNumMeshes, 0);
    if (!r.atEnd()) r.fail("bytes follow the node tree");
    return scene;
}

}  // namespace rt
