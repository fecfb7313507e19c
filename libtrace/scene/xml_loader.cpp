// The scene XML of thesis 3.4.2, read strictly (docs/scene-format.md is the reference).
// Sections are read in document order, except <objects>, which are read last so that
// they may name any material or model of the file.
#include "scene/xml_loader.h"

#include <filesystem>
#include <functional>
#include <stdexcept>
#include <unordered_map>

#include "core/error.h"
#include "scene/base64.h"
#include "scene/input_file.h"
#include "scene/model_file.h"
#include "scene/raw_model.h"
#include "scene/xml_reader.h"

namespace rt {
namespace {

// Deeper nesting than this is surely a broken or hostile file; it would only cost stack.
constexpr int kMaxNesting = 256;
// Objects without a material attribute use the material of this name; a white matte
// one (the Material defaults) is added if the scene does not define it.
constexpr const char* kDefaultMaterial = "default";

// Untransformed points are kept exactly as written (x + 0 would turn -0 into +0), so
// that a saved scene loads back bit for bit.
Vec3 place(const Transform& toWorld, const Vec3& p) { return toWorld.isIdentity() ? p : toWorld.point(p); }

class SceneBuilder {
public:
    SceneBuilder(const XmlFile& file, std::string baseDir, const ModelFileReader& readModelFile)
        : file_(file), baseDir_(std::move(baseDir)), readModelFile_(readModelFile) {}
    Scene build();

private:
    // A material or model name and where it was defined, for the duplicate message.
    struct Definition {
        std::uint32_t index;
        int line;
    };

    static void once(const XmlElement& e, bool& seen);
    void readList(const XmlElement& list);
    void readBackground(const XmlElement& e, bool& seen);
    void readCamera(const XmlElement& e, bool& seen);
    Vec3 readPoint(pugi::xml_node node) const;
    void readMaterial(const XmlElement& e);
    void readModel(const XmlElement& e);
    Model readModelData(const XmlElement& e, const std::string& name) const;
    void readLight(const XmlElement& e);
    void readObjects(pugi::xml_node parent, const Transform& toWorld, int depth);
    static bool isTransform(std::string_view tag);
    Transform readTransform(pugi::xml_node node) const;
    Transform placedBy(pugi::xml_node node, const Transform& toWorld) const;
    void addSphere(const XmlElement& e, const Transform& toWorld);
    void addPolygon(const XmlElement& e, const Transform& toWorld, std::size_t corners);
    void addInstance(const XmlElement& e, const Transform& toWorld);
    std::uint32_t materialOf(const XmlElement& e);
    void define(std::unordered_map<std::string, Definition>& names, const char* kind, const std::string& name,
                std::uint32_t index, const XmlElement& e);

    const XmlFile& file_;
    std::string baseDir_;
    const ModelFileReader& readModelFile_;
    Scene scene_;
    std::unordered_map<std::string, Definition> materials_;
    std::unordered_map<std::string, Definition> models_;
    std::size_t dropped_ = 0;
};

Scene SceneBuilder::build() {
    const pugi::xml_node root = file_.document().document_element();
    if (std::string_view(root.name()) != "scene") file_.failAt(root, "the root element must be <scene>");
    for (const pugi::xml_node& n : file_.document().children())
        if (n != root) file_.failAt(n, "the file must hold one <scene> element and nothing else");
    const XmlElement scene(file_, root, {});
    scene.requireOnlyChildren({"background", "camera", "materials", "models", "objects", "lights"});
    bool hasBackground = false, hasCamera = false;
    std::vector<pugi::xml_node> objects;
    for (const pugi::xml_node& section : root.children()) {
        const std::string_view tag = section.name();
        if (tag == "background") {
            readBackground(XmlElement(file_, section, {"r", "g", "b"}), hasBackground);
        } else if (tag == "camera") {
            readCamera(XmlElement(file_, section, {"fov", "f", "zoom"}), hasCamera);
        } else if (tag == "objects") {
            XmlElement(file_, section, {});  // checks that it has no attributes
            objects.push_back(section);
        } else {
            readList(XmlElement(file_, section, {}));
        }
    }
    if (!hasCamera) scene.fail("<scene> needs a <camera>");
    for (const pugi::xml_node& section : objects) readObjects(section, Transform(), 0);

    dropped_ += scene_.flatten();
    scene_.droppedDegenerate = dropped_;
    if (dropped_ > 0)
        scene_.warnings.push_back("dropped " + std::to_string(dropped_) +
                                  " degenerate primitives (zero-area triangles, spheres with radius <= 0)");
    return std::move(scene_);
}

void SceneBuilder::once(const XmlElement& e, bool& seen) {
    if (seen) e.fail("a second " + e.tag() + " in <scene>");
    seen = true;
}

// <materials>, <models> and <lights>: lists of <material>, <model> and <light>.
void SceneBuilder::readList(const XmlElement& list) {
    const std::string_view tag = list.node().name();
    list.requireOnlyChildren({tag.substr(0, tag.size() - 1)});
    for (const pugi::xml_node& item : list.node().children()) {
        if (tag == "materials")
            readMaterial(XmlElement(file_, item, {"name", "r", "g", "b", "ambient", "diffuse", "specular", "shininess",
                                                  "reflection", "spread"}));
        else if (tag == "models")
            readModel(XmlElement(file_, item, {"name", "file", "type", "encoding"}));
        else
            readLight(XmlElement(file_, item, {"x", "y", "z", "r", "g", "b", "size"}));
    }
}

void SceneBuilder::readBackground(const XmlElement& e, bool& seen) {
    once(e, seen);
    e.requireNoChildren();
    scene_.background = e.rgb(0);
}

// Thesis 3.4.2: fov is the horizontal angle in degrees, f the focal distance in pixels;
// with neither, f is the distance from origin to destination. zoom scales f, in percent.
void SceneBuilder::readCamera(const XmlElement& e, bool& seen) {
    once(e, seen);
    e.requireOnlyChildren({"origin", "destination", "up"});
    Camera& camera = scene_.camera;
    if (e.has("fov") && e.has("f")) e.fail("<camera> takes fov or f, not both");
    if (e.has("fov")) {
        camera.fovDegrees = e.number("fov");
        if (!(*camera.fovDegrees > 0 && *camera.fovDegrees < 180))
            e.fail("<camera> fov must be between 0 and 180 degrees");
    }
    if (e.has("f")) camera.focalDistance = e.positive("f");
    if (e.has("zoom")) camera.zoom = e.positive("zoom");
    std::optional<Vec3> origin, destination, up;
    for (const pugi::xml_node& child : e.node().children()) {
        const std::string_view tag = child.name();
        std::optional<Vec3>& slot = tag == "origin" ? origin : tag == "destination" ? destination : up;
        if (slot) file_.failAt(child, "a second <" + std::string(tag) + "> in <camera>");
        slot = readPoint(child);
    }
    if (!origin || !destination) e.fail("<camera> needs <origin> and <destination>");
    camera.origin = *origin;
    camera.destination = *destination;
    camera.up = up.value_or(camera.up);
    const Vec3 view = camera.destination - camera.origin;
    if (!(length(view) > 0)) e.fail("camera origin and destination coincide");
    if (!(length(cross(camera.up, view)) > 0)) e.fail("camera up vector is zero or parallel to the view direction");
}

Vec3 SceneBuilder::readPoint(pugi::xml_node node) const {
    const XmlElement e(file_, node, {"x", "y", "z"});
    e.requireNoChildren();
    return e.xyz(0);
}

void SceneBuilder::define(std::unordered_map<std::string, Definition>& names, const char* kind, const std::string& name,
                          std::uint32_t index, const XmlElement& e) {
    if (name.empty()) e.fail(std::string(kind) + " name must not be empty");
    const auto [it, added] = names.emplace(name, Definition{index, e.line()});
    if (!added)
        e.fail("duplicate " + std::string(kind) + " '" + name + "' (first defined on line " +
               std::to_string(it->second.line) + ")");
}

void SceneBuilder::readMaterial(const XmlElement& e) {
    e.requireNoChildren();
    Material m;
    m.name = e.string("name");
    define(materials_, "material", m.name, std::uint32_t(scene_.materials.size()), e);
    m.color = e.rgb(1);
    m.ambient = e.nonNegativeFloat("ambient", m.ambient);
    m.diffuse = e.nonNegativeFloat("diffuse", m.diffuse);
    m.specular = e.nonNegativeFloat("specular", m.specular);
    m.shininess = e.nonNegativeFloat("shininess", m.shininess);
    m.reflection = e.nonNegativeFloat("reflection", m.reflection);
    m.spread = e.nonNegativeFloat("spread", m.spread);
    if (m.reflection > 1) e.fail("<material> reflection must be between 0 and 1");
    scene_.materials.push_back(std::move(m));
}

void SceneBuilder::readModel(const XmlElement& e) {
    const std::string name = e.string("name");
    define(models_, "model", name, std::uint32_t(scene_.models.size()), e);
    Model model = readModelData(e, name);
    model.name = name;
    scene_.models.push_back(std::move(model));
}

// A model's data comes from its file (relative to the scene's folder) or, as an rt
// extension, from base64 RAW bytes inside the element (a scene and its models in one stream).
Model SceneBuilder::readModelData(const XmlElement& e, const std::string& name) const {
    const std::optional<std::string> type = e.optionalString("type");
    std::optional<Model::Format> format;
    if (type && !(format = modelFormatFromName(*type))) e.fail("unknown model type '" + *type + "' (raw or 3ds)");
    // Errors in the model's data get the scene file's line in front.
    const auto placed = [&](const std::function<Model()>& load) {
        try {
            return load();
        } catch (const InputError& error) {
            e.fail("model '" + name + "': " + error.what());
        }
    };
    if (const std::optional<std::string> file = e.optionalString("file")) {
        if (e.has("encoding")) e.fail("<model> takes a file or inline data (encoding), not both");
        e.requireNoChildren();
        if (!format && !(format = modelFormatFromExtension(*file)))
            e.fail("<model> needs type=\"raw\" or type=\"3ds\" (the file name does not tell)");
        std::filesystem::path path(*file);
        if (path.is_relative()) path = std::filesystem::path(baseDir_) / path;
        Model model = placed([&] { return readModelFile_(path.string(), *format); });
        model.file = *file;
        model.format = *format;
        return model;
    }
    if (e.optionalString("encoding") != "base64") e.fail("<model> needs a file or encoding=\"base64\" data");
    if (format && *format != Model::Format::Raw) e.fail("inline model data must be RAW");
    std::string text;
    for (const pugi::xml_node& child : e.node().children()) {
        if (child.type() == pugi::node_element) file_.failAt(child, "unexpected element in inline <model>");
        text += child.value();
    }
    std::size_t badAt = 0;
    const std::optional<std::vector<std::uint8_t>> bytes = decodeBase64(text, badAt);
    if (!bytes) e.fail("model '" + name + "': bad base64 at character " + std::to_string(badAt));
    return placed([&] { return readRawBytes(*bytes, "inline RAW data"); });
}

void SceneBuilder::readLight(const XmlElement& e) {
    e.requireNoChildren();
    Light light;
    light.position = e.xyz(0);
    light.color = e.rgb(1);
    light.size = e.nonNegative("size", 0);
    scene_.lights.push_back(light);
}

void SceneBuilder::readObjects(pugi::xml_node parent, const Transform& toWorld, int depth) {
    for (const pugi::xml_node& child : parent.children()) {
        if (child.type() != pugi::node_element)
            file_.failAt(child, "unexpected text in <" + std::string(parent.name()) + ">");
        const std::string_view tag = child.name();
        if (tag == "sphere") {
            addSphere(XmlElement(file_, child, {"x", "y", "z", "r", "material"}), toWorld);
        } else if (tag == "triangle" || tag == "quad") {
            addPolygon(XmlElement(file_, child, {"material"}), toWorld, tag == "triangle" ? 3 : 4);
        } else if (tag == "model") {
            addInstance(XmlElement(file_, child, {"name", "material"}), toWorld);
        } else if (isTransform(tag)) {
            if (depth == kMaxNesting)
                file_.failAt(child, "transforms nested deeper than " + std::to_string(kMaxNesting));
            // The outer element applies first (thesis 3.4.2: <scale> around <rotate> around
            // <translate> scales, then rotates, then translates), so each element's transform
            // goes on the left of what its ancestors built.
            readObjects(child, placedBy(child, toWorld), depth + 1);
        } else {
            file_.failAt(child, "unknown element <" + std::string(tag) + "> in <" + parent.name() + ">");
        }
    }
}

bool SceneBuilder::isTransform(std::string_view tag) {
    return tag == "translate" || tag == "transform" || tag == "rotate" || tag == "scale" || tag == "matrix";
}

Transform SceneBuilder::readTransform(pugi::xml_node node) const {
    const std::string_view tag = node.name();
    if (tag == "translate" || tag == "transform")  // the thesis's list calls it <transform>
        return Transform::translate(XmlElement(file_, node, {"x", "y", "z"}).xyz(0));
    if (tag == "rotate") {
        // Degrees (x, y, z) or multiples of pi (rx, ry, rz); X applies first, then Y, then Z.
        const XmlElement e(file_, node, {"x", "y", "z", "rx", "ry", "rz"});
        Real radians[3];
        for (int axis = 0; axis < 3; ++axis) {
            const std::string degrees(1, char('x' + axis)), turns = "r" + degrees;
            if (e.has(degrees.c_str()) && e.has(turns.c_str()))
                e.fail("<rotate> takes " + degrees + " or " + turns + ", not both");
            radians[axis] = e.number(degrees.c_str(), 0) * kPi / 180 + e.number(turns.c_str(), 0) * kPi;
        }
        return Transform::rotateZ(radians[2]) * Transform::rotateY(radians[1]) * Transform::rotateX(radians[0]);
    }
    if (tag == "scale") {
        const XmlElement e(file_, node, {"factor", "x", "y", "z"});
        if (e.has("factor") && (e.has("x") || e.has("y") || e.has("z")))
            e.fail("<scale> takes factor or x, y, z, not both");
        const Real f = e.number("factor", 1);
        const Vec3 s = e.has("factor") ? Vec3(f, f, f) : e.xyz(1);
        if (s.x == 0 || s.y == 0 || s.z == 0) e.fail("<scale> factors must not be zero");
        return Transform::scale(s);
    }
    // <matrix m="..."> (rt extension): the top three rows of an affine matrix, row-major.
    const XmlElement e(file_, node, {"m"});
    const std::vector<Real> v = e.numbers("m", 12);
    Transform::Matrix m{};
    for (int i = 0; i < 12; ++i) m[i / 4][i % 4] = v[i];
    m[3][3] = 1;
    try {
        return Transform(m);
    } catch (const std::invalid_argument&) {
        e.fail("<matrix> is singular");
    }
}

// The transform below `node`: its own after its ancestors'. Each factor may be fine and their
// product not (two scales by 1e100 overflow, by 1e-200 underflow, one by 1e308 has no finite
// inverse): what reaches the geometry must be finite and invertible, or the scene is bad input.
Transform SceneBuilder::placedBy(pugi::xml_node node, const Transform& toWorld) const {
    try {
        const Transform placed = readTransform(node) * toWorld;
        Transform{placed.matrix()};  // throws for a singular or non-finite matrix
        return placed;
    } catch (const std::invalid_argument&) {
        file_.failAt(node, "<" + std::string(node.name()) + "> makes the transform singular or not finite");
    }
}

void SceneBuilder::addSphere(const XmlElement& e, const Transform& toWorld) {
    e.requireNoChildren();
    const std::uint32_t material = materialOf(e);
    // Under a non-uniform scale the radius takes the largest stretch, as Scene::flatten does.
    const Sphere sphere{place(toWorld, e.xyz(0)), e.number("r") * toWorld.maxScale()};
    if (sphere.degenerate())
        ++dropped_;
    else
        scene_.looseObjects.add<Sphere>(sphere, material);
}

// A quad is added as two triangles sharing the diagonal from its first to its third vertex.
void SceneBuilder::addPolygon(const XmlElement& e, const Transform& toWorld, std::size_t corners) {
    e.requireOnlyChildren({"vertex"});
    const std::uint32_t material = materialOf(e);
    std::vector<Vec3> v;
    for (const pugi::xml_node& child : e.node().children()) v.push_back(place(toWorld, readPoint(child)));
    if (v.size() != corners)
        e.fail(e.tag() + " needs " + std::to_string(corners) + " <vertex> elements, not " + std::to_string(v.size()));
    for (std::size_t i = 2; i < corners; ++i) {
        const Triangle t{v[0], v[i - 1], v[i]};
        if (t.degenerate())
            ++dropped_;
        else
            scene_.looseObjects.add<Triangle>(t, material);
    }
}

void SceneBuilder::addInstance(const XmlElement& e, const Transform& toWorld) {
    e.requireNoChildren();
    const std::string name = e.string("name");
    const auto model = models_.find(name);
    if (model == models_.end()) e.fail("unknown model '" + name + "'");
    scene_.instances.push_back({model->second.index, materialOf(e), toWorld});
}

std::uint32_t SceneBuilder::materialOf(const XmlElement& e) {
    const std::string name = e.optionalString("material").value_or(kDefaultMaterial);
    if (const auto it = materials_.find(name); it != materials_.end()) return it->second.index;
    if (name != kDefaultMaterial) e.fail("unknown material '" + name + "'");
    Material fallback;
    fallback.name = kDefaultMaterial;
    const auto index = std::uint32_t(scene_.materials.size());
    scene_.materials.push_back(fallback);
    materials_.emplace(fallback.name, Definition{index, 0});
    return index;
}

Scene loadScene(std::string xml, const std::string& name, const std::string& baseDir,
                const ModelFileReader& readModelFile) {
    const XmlFile file(std::move(xml), name);
    return SceneBuilder(file, baseDir, readModelFile).build();
}

}  // namespace

Scene loadSceneXml(const std::string& path, const ModelFileReader& readModelFile) {
    if (path == "-") return loadScene(readStandardInput(), "<stdin>", ".", readModelFile);
    const std::string folder = std::filesystem::path(path).parent_path().string();
    return loadScene(readInputFile(path), path, folder.empty() ? "." : folder, readModelFile);
}

Scene loadSceneXmlFromString(const std::string& xml, const std::string& name, const std::string& baseDir,
                             const ModelFileReader& readModelFile) {
    return loadScene(xml, name, baseDir, readModelFile);
}

}  // namespace rt
