#include "io/obj_import.h"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <filesystem>
#include <fstream>
#include <istream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <tuple>

#include "core/error.h"
#include "io/line_tracking_file.h"
#include "io/obj_syntax.h"
#include "io/polygon.h"
#include "io/scene_assembly.h"
#include "os/sandbox.h"

namespace rt {
namespace {

// Reads the .mtl files an OBJ names, relative to the OBJ's folder: regular files of at
// most kMaxMtlBytes only (not a device or a pipe that never ends). A file that defines no
// material counts as not loaded (tinyobjloader would otherwise index an empty array).
class MtlReader : public tinyobj::MaterialReader {
public:
    static constexpr std::uintmax_t kMaxMtlBytes = std::uintmax_t(64) << 20;

    explicit MtlReader(std::string objPath)
        : objPath_(std::move(objPath)), folder_(std::filesystem::path(objPath_).parent_path()) {}

    bool operator()(const std::string& name, std::vector<tinyobj::material_t>* materials,
                    std::map<std::string, int>* byName, std::string* warn, std::string* err) override {
        const std::filesystem::path path = folder_ / name;
        requireInsideSandbox(path.string(), "material file " + name, objPath_);
        std::error_code ec;
        if (!std::filesystem::is_regular_file(path, ec) || std::filesystem::file_size(path, ec) > kMaxMtlBytes) {
            *warn += "material file \"" + name + "\" not found, not a file, or larger than 64 MiB\n";
            return false;
        }
        std::ifstream in(path);
        const std::size_t before = materials->size();
        std::string mtlWarnings;
        tinyobj::LoadMtl(byName, materials, &in, &mtlWarnings, err);
        *warn += withoutUnusedDataWarnings(mtlWarnings);
        // LoadMtl always appends the material it was filling; without a "newmtl" it has no name.
        if (materials->size() > before && materials->back().name.empty()) {
            const auto unnamed = byName->find("");
            if (unnamed != byName->end() && std::size_t(unnamed->second) == materials->size() - 1)
                byName->erase(unnamed);
            materials->pop_back();
        }
        if (materials->size() > before) return true;
        *warn += "material file \"" + name + "\" defines no material\n";
        return false;
    }

private:
    // tinyobjloader warns once per material that defines both d and Tr (35 lines for one public
    // OBJ), and takes d, as rt's mapping says (docs/conversion.md).
    static std::string withoutUnusedDataWarnings(const std::string& warnings) {
        std::istringstream lines(warnings);
        std::string kept;
        for (std::string line; std::getline(lines, line);)
            if (line.find("Both `d` and `Tr`") == std::string::npos) kept += line + "\n";
        return kept;
    }

    std::string objPath_;
    std::filesystem::path folder_;
};

// The texture maps of an MTL material that rt has no input for, by their MTL keywords: the
// material's specular and shininess are numbers, not textures, and rt has no ambient term of
// its own, displacement, reflection map or MTL's PBR maps (docs/conversion.md).
struct DroppedMaterialData {
    std::map<std::string, std::size_t> materialsWithMap;  // keyword: how many materials name it

    void count(const tinyobj::material_t& m) {
        const std::pair<const char*, const std::string*> maps[] = {{"map_Ka", &m.ambient_texname},
                                                                   {"map_Ks", &m.specular_texname},
                                                                   {"map_Ns", &m.specular_highlight_texname},
                                                                   {"disp", &m.displacement_texname},
                                                                   {"refl", &m.reflection_texname},
                                                                   {"map_Pr", &m.roughness_texname},
                                                                   {"map_Pm", &m.metallic_texname},
                                                                   {"map_Ps", &m.sheen_texname}};
        for (const auto& [keyword, file] : maps)
            if (!file->empty()) ++materialsWithMap[keyword];
    }

    // One note for all of them, each map with the number of materials that name it.
    void note(std::vector<std::string>& notes) const {
        if (materialsWithMap.empty()) return;
        std::string counts;
        for (const auto& [keyword, materials] : materialsWithMap)
            counts += (counts.empty() ? "" : ", ") + std::string(keyword) + " in " + std::to_string(materials) +
                      " material(s)";
        notes.push_back("texture maps rt's material has no input for, ignored: " + counts);
    }
};

// What light an MTL material lets through: illum 6 and 7 ("refraction on") are glass of index
// Ni; otherwise a dissolve d below 1 (Tr = 1 - d) lets 1 - d through without bending.
void applyTransparency(const tinyobj::material_t& mtl, Material& m) {
    if (mtl.illum == 6 || mtl.illum == 7) {
        const bool indexGiven = std::isfinite(mtl.ior) && mtl.ior > 0;
        m.transmission = {.weight = 1, .ior = indexGiven ? float(mtl.ior) : 1.0f};
        m.phong.reflection = 0;  // the Fresnel term reflects
        return;
    }
    applyOpacity(m, float(mtl.dissolve), 1);
}

// Kd, Ks and Ns as classic Phong; illum 3, 4 and 5 (ray-traced reflection) mirror with
// lum(Ks) as well; Ke is the emission; Ni, d, Tr and illum 6-7 transparency (docs/conversion.md).
Material materialFromMtl(const tinyobj::material_t& mtl) {
    const auto color = [](const tinyobj::real_t(&c)[3]) { return fileColor(c[0], c[1], c[2]); };
    Material m = classicPhong(color(mtl.diffuse), color(mtl.specular), mtl.shininess);
    if (mtl.illum >= 3 && mtl.illum <= 5) m.phong.reflection = m.phong.specular;
    m.emission.color = color(mtl.emission);
    applyTransparency(mtl, m);
    return m;
}

// The numbers of an option of a map_* line (-o, -s, -bm) within kMaxTextureTransform; if one is
// beyond it (1e39, which tinyobjloader reads as +inf), the option takes its default and a note:
// a bad material file is notes, not an error (docs/conversion.md).
template <std::size_t N>
std::array<float, N> textureOption(const std::array<float, N>& values, float fallback, const std::string& what,
                                   std::vector<std::string>& notes) {
    const auto within = [](float v) { return std::isfinite(v) && std::abs(v) <= kMaxTextureTransform; };
    if (std::all_of(values.begin(), values.end(), within)) return values;
    std::ostringstream note;
    note << what;
    for (const float v : values) note << " " << v;
    note << " is out of range (at most 1e6 in magnitude): " << fallback << " used";
    notes.push_back(note.str());
    std::array<float, N> defaults;
    defaults.fill(fallback);
    return defaults;
}

// A map_* texture, its file relative to the .obj's folder. OBJ's -o and -s work with v up the
// image; rt's v runs down (v' = 1 - v), so the v offset becomes 1 - s - o.
Texture mapTexture(const std::string& file, const tinyobj::texture_option_t& o, const std::string& objPath,
                   std::vector<std::string>& notes) {
    Texture t = textureBeside(objPath, file);
    t.wrapS = t.wrapT = o.clamp ? Texture::Wrap::Clamp : Texture::Wrap::Repeat;
    const std::string what = "texture " + file + ": ";
    t.scale = textureOption(std::array{float(o.scale[0]), float(o.scale[1])}, 1, what + "-s", notes);
    const auto offset =
        textureOption(std::array{float(o.origin_offset[0]), float(o.origin_offset[1])}, 0, what + "-o", notes);
    t.offset = {offset[0], 1 - t.scale[1] - offset[1]};
    return t;
}

// Cut-outs: map_d is a mask (its alpha channel, or its grey); without it, the alpha channel of
// map_Kd, as McGuire's archive models (scrub-pine) expect. An image without alpha then cuts
// nothing, and the renderer drops the material from the cut-out test (render/cutout.h).
void readCutout(const tinyobj::material_t& mtl, const std::string& objPath, ImportResult& out, Material& m) {
    if (!mtl.alpha_texname.empty())
        m.opacity.texture =
            addTexture(out.scene, mapTexture(mtl.alpha_texname, mtl.alpha_texopt, objPath, out.report.notes));
    else
        m.opacity.texture = m.colorTexture;
    if (m.opacity.texture) m.opacity.cutoff = 0.5f;
}

// The normal map: `norm`, else `map_bump` or `bump`, read as a tangent-space normal map in
// glTF's convention (as Blender writes them), -bm as its scale. A grey height map is not.
void readNormalMap(const tinyobj::material_t& mtl, const std::string& objPath, ImportResult& out, Material& m) {
    const bool norm = !mtl.normal_texname.empty();
    const std::string& file = norm ? mtl.normal_texname : mtl.bump_texname;
    if (file.empty()) return;
    const tinyobj::texture_option_t& o = norm ? mtl.normal_texopt : mtl.bump_texopt;
    m.normalMap.texture = addTexture(out.scene, mapTexture(file, o, objPath, out.report.notes));
    m.normalMap.scale =
        textureOption(std::array{float(o.bump_multiplier)}, 1, "texture " + file + ": -bm", out.report.notes)[0];
}

// The emission map: map_Ke times Ke, as map_Kd is times Kd; a map without Ke (or with Ke 0)
// glows at the map's own colour: a file that names a map wants it to show (display screens).
void readEmissionMap(const tinyobj::material_t& mtl, const std::string& objPath, ImportResult& out, Material& m) {
    if (mtl.emissive_texname.empty()) return;
    m.emission.texture =
        addTexture(out.scene, mapTexture(mtl.emissive_texname, mtl.emissive_texopt, objPath, out.report.notes));
    if (m.emission.color == Color{}) m.emission.color = {1, 1, 1};
}

class ObjSceneBuilder {
public:
    ObjSceneBuilder(const std::string& path, const ImportOptions& options, ImportResult& out)
        : path_(path), file_(path), out_(out), assembly_(out, options) {}

    void read() {
        tinyobj::callback_t callbacks;
        // The coordinates are read again from the line (obj_syntax.h): tinyobjloader reads
        // what it cannot parse as 0.
        callbacks.vertex_cb = [](void* self, tinyobj::real_t, tinyobj::real_t, tinyobj::real_t, tinyobj::real_t) {
            static_cast<ObjSceneBuilder*>(self)->vertex();
        };
        callbacks.normal_cb = [](void* self, tinyobj::real_t x, tinyobj::real_t y, tinyobj::real_t z) {
            static_cast<ObjSceneBuilder*>(self)->normals_.push_back({finite(x), finite(y), finite(z)});
        };
        // OBJ's v runs up the image, rt's down (glTF's convention).
        callbacks.texcoord_cb = [](void* self, tinyobj::real_t u, tinyobj::real_t v, tinyobj::real_t) {
            static_cast<ObjSceneBuilder*>(self)->uvs_.push_back({finite(u), 1 - finite(v)});
        };
        callbacks.index_cb = [](void* self, tinyobj::index_t* corners, int count) {
            static_cast<ObjSceneBuilder*>(self)->face(corners, count);
        };
        callbacks.usemtl_cb = [](void* self, const char* name, int material) {
            static_cast<ObjSceneBuilder*>(self)->useMaterial(name, material);
        };
        callbacks.mtllib_cb = [](void* self, const tinyobj::material_t* materials, int count) {
            static_cast<ObjSceneBuilder*>(self)->mtl_.assign(materials, materials + count);
        };
        callbacks.group_cb = [](void* self, const char** names, int count) {
            static_cast<ObjSceneBuilder*>(self)->group(names, count);
        };
        callbacks.object_cb = [](void* self, const char* name) { static_cast<ObjSceneBuilder*>(self)->object(name); };
        std::istream in(&file_);
        MtlReader mtlReader(path_);
        std::string warn, err;
        tinyobj::LoadObjWithCallback(in, callbacks, this, &mtlReader, &warn, &err);
        if (file_.tooLong()) fail("line longer than 1 MiB");
        if (file_.readFailed()) fail("read error");
        std::istringstream messages(warn + err);
        for (std::string line; std::getline(messages, line);)
            if (!line.empty()) out_.report.notes.push_back(line);
    }

    // The models, one per part, each placed once under `root`.
    void build(const Transform& root) {
        for (Part& part : parts_)
            assembly_.place(
                convertPart(part), [&] { return materialFor(part.material); }, root);
        out_.report.meshes = out_.scene.models.size();
        dropped_.note(out_.report.notes);
        if (undefinedData_)
            out_.report.notes.push_back(
                std::to_string(undefinedData_) +
                " face corner(s) name texture coordinates or normals that are not defined: ignored");
        if (fannedConcave_)
            out_.report.notes.push_back(std::to_string(fannedConcave_) + " concave polygon(s) with more than " +
                                        std::to_string(kMaxEarClippedCorners) +
                                        " corners, or not simple, triangulated as a fan");
    }

private:
    static constexpr std::uint32_t kNone = ~0u;
    // A face corner: indices of its position, texture coordinates and normal (kNone: not given).
    struct ObjCorner {
        std::uint32_t v, vt = kNone, vn = kNone;
    };

    // The faces of one object, group and material, as corners (3 per triangle).
    // Deques grow without copying, so the peak stays near the data itself.
    struct Part {
        std::string name;
        int material = -1;
        std::deque<ObjCorner> corners;
    };

    static float finite(tinyobj::real_t v) { return std::isfinite(v) ? float(v) : 0.0f; }

    Corner corner(const ObjCorner& c) const {
        return {positions_[c.v], c.vn == kNone ? nullptr : normals_[c.vn].data(),
                c.vt == kNone ? nullptr : uvs_[c.vt].data()};
    }

    // Each part is converted once and placed once, so no cache is needed.
    ConvertedMesh convertPart(Part& part) {
        ModelBuilder model = assembly_.newModel(part.name, "mesh");
        model.reserveTriangles(part.corners.size() / 3);
        for (std::size_t i = 0; i + 2 < part.corners.size(); i += 3)
            model.addTriangleWithData(corner(part.corners[i]), corner(part.corners[i + 1]),
                                      corner(part.corners[i + 2]));
        part.corners = {};  // free as we go: the models take their place
        return assembly_.addModel(std::move(model));
    }

    [[noreturn]] void fail(const std::string& message) const {
        throw inputErrorAt(path_, int(file_.lineNumber()), message);
    }

    // A line cut at the length limit must not be read as if it were whole.
    void checkLineLength() const {
        if (file_.tooLong()) fail("line longer than 1 MiB");
    }

    void vertex() {
        checkLineLength();
        const std::optional<Point3f> p = parseObjVertex(file_.lineText());
        if (!p) fail("vertex coordinates are not three finite numbers: \"" + std::string(file_.lineText()) + "\"");
        if (positions_.size() == std::numeric_limits<std::uint32_t>::max()) fail("more than 2^32 - 1 vertices");
        positions_.push_back(*p);
    }

    // OBJ counts vertices from 1, or backwards from the last one defined (-1).
    std::uint32_t vertexIndex(int index) const {
        if (index == 0) fail("face refers to vertex 0, but OBJ counts vertices from 1 (or from -1 backwards)");
        const long long resolved = index > 0 ? index - 1LL : (long long)positions_.size() + index;
        if (resolved < 0 || resolved >= (long long)positions_.size())
            fail("face refers to vertex " + std::to_string(index) + ", but " + std::to_string(positions_.size()) +
                 " vertices are defined before it");
        return std::uint32_t(resolved);
    }

    // A texture coordinate or normal index, counted as vertices are; 0 means none. One that
    // is not defined is ignored and counted (files that worked before data was read keep working).
    template <class Deque>
    std::uint32_t dataIndex(int index, const Deque& values) {
        const long long resolved = index > 0 ? index - 1LL : (long long)values.size() + index;
        if (index == 0) return kNone;
        if (resolved >= 0 && resolved < (long long)values.size()) return std::uint32_t(resolved);
        ++undefinedData_;
        return kNone;
    }

    void face(const tinyobj::index_t* corners, int count) {
        checkLineLength();
        if (!isObjFace(file_.lineText()))
            fail("face corners are not v, v/t, v//n or v/t/n with vertex numbers of at most 9 digits: \"" +
                 std::string(file_.lineText()) + "\"");
        polygon_.clear();
        for (int i = 0; i < count; ++i)
            polygon_.push_back({vertexIndex(corners[i].vertex_index), dataIndex(corners[i].texcoord_index, uvs_),
                                dataIndex(corners[i].normal_index, normals_)});
        assembly_.countFaceWithoutArea(std::size_t(count));
        if (count < 3) return;
        if (count > 3) dropRepeatedCorners();
        // Each polygon accounts for n - 2 triangles, kept or dropped, as Assimp's counts do.
        assembly_.dropDegenerate(std::size_t(count) - std::max<std::size_t>(polygon_.size(), 2));
        if (polygon_.size() < 3) return;
        cornerPositions_.clear();
        for (const ObjCorner& c : polygon_) cornerPositions_.push_back(positions_[c.v]);
        triangles_.clear();
        if (!triangulatePolygon(cornerPositions_, triangles_)) ++fannedConcave_;
        std::deque<ObjCorner>& out = currentPart().corners;
        for (const std::uint32_t corner : triangles_) out.push_back(polygon_[corner]);
    }

    // A polygon that visits the same point twice in a row has a corner with no angle, which
    // ear clipping cannot place; it is triangulated without the repeat, whose triangle (of
    // no area) counts as a dropped degenerate one.
    void dropRepeatedCorners() {
        const auto same = [&](const ObjCorner& a, const ObjCorner& b) { return positions_[a.v] == positions_[b.v]; };
        polygon_.erase(std::unique(polygon_.begin(), polygon_.end(), same), polygon_.end());
        while (polygon_.size() > 1 && same(polygon_.front(), polygon_.back())) polygon_.pop_back();
    }

    void useMaterial(const char* name, int material) {
        if (material < 0 && missingMaterials_.insert(name).second)
            out_.report.notes.push_back("material \"" + std::string(name) + "\" is not defined: default used");
        material_ = material;
        current_ = nullptr;
    }

    void group(const char** names, int count) {
        group_.clear();
        for (int i = 0; i < count; ++i) {
            if (i) group_ += ' ';  // names hold no blanks; the model name turns it into '_'
            group_ += names[i];
        }
        current_ = nullptr;
    }

    void object(const char* name) {
        object_ = name;
        group_.clear();
        current_ = nullptr;
    }

    Part& currentPart() {
        if (current_) return *current_;
        auto [it, added] = partByKey_.try_emplace({object_, group_, material_}, nullptr);
        if (added) {
            const std::string& name = !group_.empty() ? group_ : object_;
            it->second = &parts_.emplace_back(
                Part{name.empty() ? std::filesystem::path(path_).stem().string() : name, material_, {}});
        }
        return *(current_ = it->second);
    }

    std::uint32_t materialFor(int index) {
        return assembly_.material(index, "default", [&] { return convertMaterial(index); });
    }

    // A material of the .mtl files, or rt's default for an index tinyobjloader does not know.
    Material convertMaterial(int index) {
        if (index < 0 || std::size_t(index) >= mtl_.size()) return Material{};
        const tinyobj::material_t& mtl = mtl_[std::size_t(index)];
        dropped_.count(mtl);
        Material m = materialFromMtl(mtl);
        m.name = mtl.name;
        if (!mtl.diffuse_texname.empty())
            m.colorTexture =
                addTexture(out_.scene, mapTexture(mtl.diffuse_texname, mtl.diffuse_texopt, path_, out_.report.notes));
        readCutout(mtl, path_, out_, m);
        readNormalMap(mtl, path_, out_, m);
        readEmissionMap(mtl, path_, out_, m);
        return m;
    }

    const std::string& path_;
    LineTrackingFile file_;
    ImportResult& out_;
    SceneAssembly<std::size_t, int> assembly_;  // materials by .mtl index (models are not looked up)
    std::deque<Point3f> positions_;
    std::deque<std::array<float, 3>> normals_;
    std::deque<std::array<float, 2>> uvs_;
    std::vector<tinyobj::material_t> mtl_;
    std::string object_, group_;
    int material_ = -1;
    std::deque<Part> parts_;  // stable addresses for partByKey_
    std::map<std::tuple<std::string, std::string, int>, Part*> partByKey_;
    Part* current_ = nullptr;
    std::set<std::string> missingMaterials_;  // each named once in the notes
    DroppedMaterialData dropped_;             // of the materials used
    std::size_t fannedConcave_ = 0;
    std::size_t undefinedData_ = 0;   // corners naming a vt or vn that is not defined
    std::vector<ObjCorner> polygon_;  // scratch for face()
    std::vector<std::uint32_t> triangles_;
    std::vector<Point3f> cornerPositions_;
};

}  // namespace

ImportResult importObj(const std::string& path, const ImportOptions& options) {
    if (!options.camera.empty()) throw InputError(path + ": OBJ files hold no cameras, so --camera cannot pick one");
    ImportResult result;
    result.report.format = "Wavefront OBJ";
    ObjSceneBuilder builder(path, options, result);
    builder.read();
    builder.build(rootTransform(options));
    return result;
}

}  // namespace rt
