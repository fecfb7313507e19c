// The scene XML of thesis 3.4.2, read strictly (docs/scene-format.md is the reference).
// Sections are read in document order, except <objects>, which are read last so that
// they may name any material or model of the file.
#include "io/xml_loader.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <unordered_map>

#include "core/error.h"
#include "io/base64.h"
#include "io/model_file.h"
#include "io/raw_model.h"
#include "io/xml_reader.h"
#include "os/input_file.h"
#include "os/sandbox.h"

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

// A material's factor `name` (rt extension), 0-1.
float unitFactor(const XmlElement& e, const char* name, float fallback) {
    const float value = e.nonNegativeFloat(name, fallback);
    if (value > 1) e.fail(std::string("<material> ") + name + " must be between 0 and 1");
    return value;
}

// A material's transmission attributes (rt extension); without them it is opaque.
Transmission readTransmission(const XmlElement& e) {
    Transmission t;
    t.weight = float(e.nonNegative("transmission", t.weight));
    if (t.weight > 1) e.fail("<material> transmission must be between 0 and 1");
    t.color = e.color("transmission_color", t.color);
    if (e.has("ior")) t.ior = float(e.positive("ior"));
    if (t.ior > kMaxIor) e.fail("<material> ior must be at most 100");
    t.thin = e.boolean("thin", t.thin);
    t.attenuationColor = e.color("attenuation_color", t.attenuationColor);
    if (e.has("attenuation_distance")) t.attenuationDistance = float(e.positive("attenuation_distance"));
    return t;
}

class SceneBuilder {
public:
    SceneBuilder(const XmlFile& file, std::string baseDir) : file_(file), baseDir_(std::move(baseDir)) {}
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
    void readEnvironment(const XmlElement& e, bool& seen);
    void readCamera(const XmlElement& e, bool& seen);
    Vec3 readPoint(pugi::xml_node node) const;
    void readMaterial(const XmlElement& e);
    void readMetallicRoughness(const XmlElement& e, Material& m);
    void readCutout(const XmlElement& e, std::uint32_t index, Material& m);
    // Where a material keeps a texture: a function, not a member pointer, as most of a material's
    // textures are inside its groups (NormalMap::texture ...).
    using TextureIndex = std::optional<std::uint32_t>;
    using TextureSlot = TextureIndex& (*)(Material&);
    void useTexture(const XmlElement& e, const char* attribute, std::uint32_t index, TextureSlot slot);
    void readTexture(const XmlElement& e);
    void resolveTextures();
    struct TextureUse;
    std::uint32_t textureNamed(const TextureUse& use) const;
    void readModel(const XmlElement& e);
    Model readModelData(const XmlElement& e, const std::string& name) const;
    std::vector<std::uint8_t> inlineData(const XmlElement& e, const std::string& what) const;
    void readLight(const XmlElement& e);
    static void readLightDirection(const XmlElement& e, Light& light);
    void readObjects(pugi::xml_node parent, const Transform& toWorld, int depth);
    static bool isTransform(std::string_view tag);
    Transform readTransform(pugi::xml_node node) const;
    Transform placedBy(pugi::xml_node node, const Transform& toWorld) const;
    void addSphere(const XmlElement& e, const Transform& toWorld);
    template <class K>
    void addFrustum(const XmlElement& e, const Transform& toWorld, Real baseRadius, Real topRadius);
    void addDisk(const XmlElement& e, const Transform& toWorld);
    template <class K>
    void addLoose(const XmlElement& e, const K& primitive, std::uint32_t material);
    void addPolygon(const XmlElement& e, const Transform& toWorld, std::size_t corners);
    void addInstance(const XmlElement& e, const Transform& toWorld);
    std::uint32_t materialOf(const XmlElement& e);
    void define(std::unordered_map<std::string, Definition>& names, const char* kind, const std::string& name,
                std::uint32_t index, const XmlElement& e);

    const XmlFile& file_;
    std::string baseDir_;
    Scene scene_;
    std::unordered_map<std::string, Definition> materials_;
    std::unordered_map<std::string, Definition> models_;
    std::unordered_map<std::string, Definition> cameras_;
    std::unordered_map<std::string, Definition> textures_;
    // Texture names of materials, resolved when every <texture> is known.
    struct TextureUse {
        std::uint32_t material;
        TextureSlot slot;
        std::string name;
        pugi::xml_node node;
    };
    std::vector<TextureUse> textureUses_;
    std::optional<TextureUse> environmentTexture_;  // <environment>'s (no material, no slot)
    std::size_t dropped_ = 0;
};

Scene SceneBuilder::build() {
    const pugi::xml_node root = file_.document().document_element();
    if (std::string_view(root.name()) != "scene") file_.failAt(root, "the root element must be <scene>");
    for (const pugi::xml_node& n : file_.document().children())
        if (n != root) file_.failAt(n, "the file must hold one <scene> element and nothing else");
    const XmlElement scene(file_, root, {});
    scene.requireOnlyChildren(
        {"background", "environment", "camera", "materials", "textures", "models", "objects", "lights"});
    bool hasBackground = false, hasCamera = false, hasEnvironment = false;
    std::vector<pugi::xml_node> objects;
    for (const pugi::xml_node& section : root.children()) {
        const std::string_view tag = section.name();
        if (tag == "background") {
            readBackground(XmlElement(file_, section, {"r", "g", "b"}), hasBackground);
        } else if (tag == "environment") {
            readEnvironment(XmlElement(file_, section, {"texture", "intensity", "rotation"}), hasEnvironment);
        } else if (tag == "camera") {
            readCamera(XmlElement(file_, section, {"name", "fov", "f", "zoom"}), hasCamera);
        } else if (tag == "objects") {
            XmlElement(file_, section, {});  // checks that it has no attributes
            objects.push_back(section);
        } else {
            readList(XmlElement(file_, section, {}));
        }
    }
    if (!hasCamera) scene.fail("<scene> needs a <camera>");
    resolveTextures();
    for (const pugi::xml_node& section : objects) readObjects(section, Transform(), 0);

    scene_.placeHeadlights();
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

// <materials>, <textures>, <models> and <lights>: lists of <material>, <texture>, <model> and <light>.
void SceneBuilder::readList(const XmlElement& list) {
    const std::string_view tag = list.node().name();
    list.requireOnlyChildren({tag.substr(0, tag.size() - 1)});
    for (const pugi::xml_node& item : list.node().children()) {
        if (tag == "materials")
            readMaterial(XmlElement(file_, item,
                                    {"name",
                                     "r",
                                     "g",
                                     "b",
                                     "ambient",
                                     "diffuse",
                                     "specular",
                                     "shininess",
                                     "reflection",
                                     "spread",
                                     "texture",
                                     "emission",
                                     "emission_texture",
                                     "metallic",
                                     "roughness",
                                     "specular_factor",
                                     "metallic_roughness_texture",
                                     "clearcoat",
                                     "clearcoat_roughness",
                                     "alpha",
                                     "alpha_texture",
                                     "alpha_cutoff",
                                     "normal_texture",
                                     "normal_scale",
                                     "transmission",
                                     "transmission_color",
                                     "transmission_texture",
                                     "ior",
                                     "thin",
                                     "attenuation_color",
                                     "attenuation_distance",
                                     "double_sided"}));
        else if (tag == "textures")
            readTexture(XmlElement(file_, item,
                                   {"name", "type", "file", "wrap", "wrap_s", "wrap_t", "offset", "scale", "rotation",
                                    "color_a", "color_b", "size", "encoding"}));
        else if (tag == "models")
            readModel(XmlElement(file_, item, {"name", "file", "type", "encoding"}));
        else
            readLight(XmlElement(file_, item,
                                 {"x", "y", "z", "r", "g", "b", "size", "type", "dx", "dy", "dz", "falloff", "range",
                                  "inner_cone", "outer_cone", "headlight"}));
    }
}

void SceneBuilder::readBackground(const XmlElement& e, bool& seen) {
    once(e, seen);
    e.requireNoChildren();
    scene_.background = e.rgb(0);
}

// rt extension: the path tracer's sky, an image <texture> (resolved with the materials' ones).
void SceneBuilder::readEnvironment(const XmlElement& e, bool& seen) {
    once(e, seen);
    e.requireNoChildren();
    Environment environment;
    environment.intensity = e.nonNegativeFloat("intensity", environment.intensity);
    environment.rotation = e.floatWithin("rotation", environment.rotation, kMaxTextureTransform);
    scene_.environment = environment;
    environmentTexture_ = TextureUse{0, nullptr, e.string("texture"), e.node()};
}

// Thesis 3.4.2: fov is the horizontal angle in degrees, f the focal distance in pixels;
// with neither, f is the distance from origin to destination. zoom scales f, in percent.
// rt extension: several cameras, each with an optional unique name; the first is rendered
// unless rt-render's --camera picks another.
void SceneBuilder::readCamera(const XmlElement& e, bool& seen) {
    e.requireOnlyChildren({"origin", "destination", "up"});
    Camera& camera = seen ? scene_.extraCameras.emplace_back() : scene_.camera;
    seen = true;
    if (e.has("name")) {
        camera.name = e.string("name");
        define(cameras_, "camera", camera.name, std::uint32_t(scene_.extraCameras.size()), e);
    }
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
    m.phong.ambient = e.nonNegativeFloat("ambient", m.phong.ambient);
    m.phong.diffuse = e.nonNegativeFloat("diffuse", m.phong.diffuse);
    m.phong.specular = e.nonNegativeFloat("specular", m.phong.specular);
    m.phong.shininess = e.nonNegativeFloat("shininess", m.phong.shininess);
    m.phong.reflection = e.nonNegativeFloat("reflection", m.phong.reflection);
    m.phong.spread = e.nonNegativeFloat("spread", m.phong.spread);
    if (m.phong.reflection > 1) e.fail("<material> reflection must be between 0 and 1");
    m.emission.color = e.color("emission", m.emission.color);
    readMetallicRoughness(e, m);
    m.clearcoat.weight = unitFactor(e, "clearcoat", m.clearcoat.weight);
    m.clearcoat.roughness = unitFactor(e, "clearcoat_roughness", m.clearcoat.roughness);
    m.transmission = readTransmission(e);
    const auto index = std::uint32_t(scene_.materials.size());
    useTexture(e, "texture", index, [](Material& t) -> TextureIndex& { return t.colorTexture; });
    useTexture(e, "emission_texture", index, [](Material& t) -> TextureIndex& { return t.emission.texture; });
    useTexture(e, "metallic_roughness_texture", index, [](Material& t) -> TextureIndex& { return t.pbr.texture; });
    useTexture(e, "transmission_texture", index, [](Material& t) -> TextureIndex& { return t.transmission.texture; });
    readCutout(e, index, m);
    useTexture(e, "normal_texture", index, [](Material& t) -> TextureIndex& { return t.normalMap.texture; });
    m.normalMap.scale = e.floatWithin("normal_scale", m.normalMap.scale, kMaxTextureTransform);
    m.doubleSided = e.boolean("double_sided", m.doubleSided);
    scene_.materials.push_back(std::move(m));
}

// Material `index` takes the texture its attribute names, if it has one, in `slot`.
void SceneBuilder::useTexture(const XmlElement& e, const char* attribute, std::uint32_t index, TextureSlot slot) {
    if (const auto name = e.optionalString(attribute)) textureUses_.push_back({index, slot, *name, e.node()});
}

// rt extension: the path tracer's glTF metallic-roughness factors, each 0-1; given one, the
// others take glTF's defaults (metallic 1, roughness 1, specular_factor 1).
void SceneBuilder::readMetallicRoughness(const XmlElement& e, Material& m) {
    if (!e.has("metallic") && !e.has("roughness") && !e.has("specular_factor")) return;
    m.pbr.factors = MetallicRoughness{unitFactor(e, "metallic", 1), unitFactor(e, "roughness", 1),
                                      unitFactor(e, "specular_factor", 1)};
}

// rt extension: a cut-out material has alpha_cutoff; alpha and alpha_texture give its opacity.
void SceneBuilder::readCutout(const XmlElement& e, std::uint32_t index, Material& m) {
    if (e.has("alpha_cutoff")) m.opacity.cutoff = e.nonNegativeFloat("alpha_cutoff", 0.5f);
    m.opacity.alpha = e.nonNegativeFloat("alpha", m.opacity.alpha);
    if (m.opacity.alpha > 1) e.fail("<material> alpha must be between 0 and 1");
    useTexture(e, "alpha_texture", index, [](Material& t) -> TextureIndex& { return t.opacity.texture; });
}

// rt extension: an image file (any format OpenImageIO reads) or a procedural checker.
void SceneBuilder::readTexture(const XmlElement& e) {
    const bool inlineImage = e.has("encoding");
    if (inlineImage && e.string("encoding") != "base64") e.fail("a <texture>'s encoding must be base64");
    if (!inlineImage) e.requireNoChildren();
    Texture t;
    t.name = e.string("name");
    define(textures_, "texture", t.name, std::uint32_t(scene_.textures.size()), e);
    const std::string type = e.optionalString("type").value_or("image");
    if (type != "image" && type != "checker") e.fail("unknown texture type '" + type + "' (image or checker)");
    t.kind = type == "image" ? Texture::Kind::Image : Texture::Kind::Checker;
    if (t.kind == Texture::Kind::Image) {
        t.file = e.string("file");
        std::filesystem::path path(t.file);
        t.path = (path.is_relative() ? std::filesystem::path(baseDir_) / path : path).string();
        if (const std::optional<std::string> why = sandboxRefusal(t.path, t.file))
            e.fail("texture '" + t.name + "': " + *why);
    }
    if (inlineImage) {  // rt extension: the picture's bytes inside the element, `file` only names it
        if (t.kind != Texture::Kind::Image) e.fail("only image textures have inline data");
        t.embedded = std::make_shared<const std::vector<std::uint8_t>>(inlineData(e, "texture '" + t.name + "'"));
        t.path.clear();
    }
    const auto wrap = [&](const char* attribute, Texture::Wrap fallback) {
        const std::optional<std::string> w = e.optionalString(attribute);
        if (!w) return fallback;
        if (*w == "repeat") return Texture::Wrap::Repeat;
        if (*w == "clamp") return Texture::Wrap::Clamp;
        if (*w == "mirror") return Texture::Wrap::Mirror;
        e.fail("unknown " + std::string(attribute) + " '" + *w + "' (repeat, clamp or mirror)");
    };
    const Texture::Wrap both = wrap("wrap", Texture::Wrap::Repeat);
    t.wrapS = wrap("wrap_s", both);
    t.wrapT = wrap("wrap_t", both);
    const auto pair = [&](const char* attribute, std::array<float, 2> fallback) {
        if (!e.has(attribute)) return fallback;
        const std::vector<Real> v = e.numbers(attribute, 2);
        if (std::abs(double(v[0])) > kMaxTextureTransform || std::abs(double(v[1])) > kMaxTextureTransform)
            e.fail("<texture> attribute '" + std::string(attribute) + "' is out of range (at most 1e6 in magnitude)");
        return std::array<float, 2>{float(v[0]), float(v[1])};
    };
    t.offset = pair("offset", t.offset);
    t.scale = pair("scale", t.scale);
    t.rotation = e.floatWithin("rotation", 0, kMaxTextureTransform);
    t.colorA = e.color("color_a", t.colorA);
    t.colorB = e.color("color_b", t.colorB);
    if (e.has("size")) t.size = float(e.positive("size"));
    scene_.textures.push_back(std::move(t));
}

void SceneBuilder::resolveTextures() {
    for (const TextureUse& use : textureUses_) use.slot(scene_.materials[use.material]) = textureNamed(use);
    if (!environmentTexture_) return;
    scene_.environment->texture = textureNamed(*environmentTexture_);
    if (scene_.textures[scene_.environment->texture].kind != Texture::Kind::Image)
        file_.failAt(environmentTexture_->node, "the environment's texture must be an image");
}

std::uint32_t SceneBuilder::textureNamed(const TextureUse& use) const {
    const auto it = textures_.find(use.name);
    if (it == textures_.end()) file_.failAt(use.node, "unknown texture '" + use.name + "'");
    return it->second.index;
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
        if (const std::optional<std::string> why = sandboxRefusal(path.string(), *file))
            e.fail("model '" + name + "': " + *why);
        Model model = placed([&] { return readModelFile(path.string(), *format); });
        model.file = *file;
        model.format = *format;
        return model;
    }
    if (e.optionalString("encoding") != "base64") e.fail("<model> needs a file or encoding=\"base64\" data");
    if (format && *format != Model::Format::Raw) e.fail("inline model data must be RAW");
    const std::vector<std::uint8_t> bytes = inlineData(e, "model '" + name + "'");
    return placed([&] { return readRawBytes(bytes, "inline RAW data"); });
}

// Thesis 3.4.2: a point light without falloff. rt extension: type, direction, falloff,
// range and the spot's cone, as docs/scene-format.md describes them.
// The base64 text inside an element (an inline model or image); `what` names it in errors.
std::vector<std::uint8_t> SceneBuilder::inlineData(const XmlElement& e, const std::string& what) const {
    std::string text;
    for (const pugi::xml_node& child : e.node().children()) {
        if (child.type() == pugi::node_element) file_.failAt(child, "unexpected element in inline " + e.tag());
        text += child.value();
    }
    std::size_t badAt = 0;
    std::optional<std::vector<std::uint8_t>> bytes = decodeBase64(text, badAt);
    if (!bytes) e.fail(what + ": bad base64 at character " + std::to_string(badAt));
    return std::move(*bytes);
}

void SceneBuilder::readLight(const XmlElement& e) {
    e.requireNoChildren();
    Light light;
    light.type = e.named("type", kLightTypeNames, Light::Type::Point);
    light.color = e.rgb(1);
    const bool directional = light.type == Light::Type::Directional;
    for (const char* a : {"x", "y", "z", "size", "falloff", "range"})
        if (directional && e.has(a)) e.fail("a directional light has no '" + std::string(a) + "'");
    light.headlight = e.boolean("headlight", false);
    if (light.headlight && light.type != Light::Type::Point) e.fail("a headlight is a point light");
    for (const char* a : {"x", "y", "z"})
        if (light.headlight && e.has(a)) e.fail("a headlight sits at the camera: it has no '" + std::string(a) + "'");
    light.position = e.xyz(0);
    light.size = e.nonNegative("size", 0);
    light.falloff = e.named("falloff", kLightFalloffNames, Light::Falloff::None);
    if (e.has("range") && light.falloff != Light::Falloff::InverseSquare)
        e.fail("'range' needs falloff=\"inverse_square\"");
    light.range = e.has("range") ? e.positive("range") : 0;
    readLightDirection(e, light);
    scene_.lights.push_back(light);
}

void SceneBuilder::readLightDirection(const XmlElement& e, Light& light) {
    const bool spot = light.type == Light::Type::Spot;
    for (const char* a : {"inner_cone", "outer_cone"})
        if (!spot && e.has(a)) e.fail("'" + std::string(a) + "' is for spot lights");
    if (light.type == Light::Type::Point) {
        for (const char* a : {"dx", "dy", "dz"})
            if (e.has(a)) e.fail("a point light has no direction ('" + std::string(a) + "')");
        return;
    }
    const Vec3 d{e.number("dx", 0), e.number("dy", 0), e.number("dz", -1)};
    if (!(length(d) > 0)) e.fail("the light's direction (dx, dy, dz) is zero");
    light.direction = isUnitLength(d) ? d : normalize(d);  // unit as written: kept, so save and load agree
    light.innerConeDegrees = float(e.nonNegative("inner_cone", 0));
    light.outerConeDegrees = float(e.nonNegative("outer_cone", 45));
    if (!(light.innerConeDegrees <= light.outerConeDegrees && light.outerConeDegrees <= 90))
        e.fail("a spot needs 0 <= inner_cone <= outer_cone <= 90 (degrees)");
}

void SceneBuilder::readObjects(pugi::xml_node parent, const Transform& toWorld, int depth) {
    for (const pugi::xml_node& child : parent.children()) {
        if (child.type() != pugi::node_element)
            file_.failAt(child, "unexpected text in <" + std::string(parent.name()) + ">");
        const std::string_view tag = child.name();
        if (tag == "sphere") {
            addSphere(XmlElement(file_, child, {"x", "y", "z", "r", "material"}), toWorld);
        } else if (tag == "cylinder") {
            const XmlElement e(file_, child, {"x0", "y0", "z0", "x1", "y1", "z1", "r", "material"});
            addFrustum<Cylinder>(e, toWorld, e.number("r"), e.number("r"));
        } else if (tag == "cone") {
            const XmlElement e(file_, child, {"x0", "y0", "z0", "x1", "y1", "z1", "r0", "r1", "material"});
            addFrustum<Cone>(e, toWorld, e.number("r0"), e.number("r1"));
        } else if (tag == "disk") {
            addDisk(XmlElement(file_, child, {"x", "y", "z", "nx", "ny", "nz", "r", "material"}), toWorld);
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
    addLoose(e, Sphere{place(toWorld, e.xyz(0)), e.number("r") * toWorld.maxScale()}, material);
}

// The end centres are transformed; the radii, as a sphere's, take the largest stretch.
template <class K>
void SceneBuilder::addFrustum(const XmlElement& e, const Transform& toWorld, Real baseRadius, Real topRadius) {
    e.requireNoChildren();
    const std::uint32_t material = materialOf(e);
    K k;
    k.base = place(toWorld, {e.number("x0"), e.number("y0"), e.number("z0")});
    k.top = place(toWorld, {e.number("x1"), e.number("y1"), e.number("z1")});
    k.baseRadius = baseRadius * toWorld.maxScale();
    k.topRadius = topRadius * toWorld.maxScale();
    addLoose(e, k, material);
}

// The centre is transformed, the normal as a normal; the radius, as a sphere's, takes the largest
// stretch. A normal of zero length makes the disk degenerate (dropped and counted).
void SceneBuilder::addDisk(const XmlElement& e, const Transform& toWorld) {
    e.requireNoChildren();
    const std::uint32_t material = materialOf(e);
    const Vec3 written{e.number("nx"), e.number("ny"), e.number("nz")};
    const Vec3 n = toWorld.isIdentity() ? written : toWorld.normal(written);
    addLoose(e, Disk{place(toWorld, e.xyz(0)), isUnitLength(n) ? n : normalize(n), e.number("r") * toWorld.maxScale()},
             material);
}

template <class K>
void SceneBuilder::addLoose(const XmlElement& e, const K& primitive, std::uint32_t material) {
    const Aabb box = primitive.bounds();
    const Real reach = std::max({std::abs(box.lo.x), std::abs(box.lo.y), std::abs(box.lo.z), std::abs(box.hi.x),
                                 std::abs(box.hi.y), std::abs(box.hi.z)});
    if (!(reach <= kMaxCoordinate)) e.fail(e.tag() + " reaches beyond 1e15 from the origin, where no ray can find it");
    if (primitive.degenerate())
        ++dropped_;
    else
        scene_.looseObjects.add<K>(primitive, material);
}

// A quad is added as two triangles sharing the diagonal from its first to its third vertex.
void SceneBuilder::addPolygon(const XmlElement& e, const Transform& toWorld, std::size_t corners) {
    e.requireOnlyChildren({"vertex"});
    const std::uint32_t material = materialOf(e);
    std::vector<Vec3> v;
    for (const pugi::xml_node& child : e.node().children()) v.push_back(place(toWorld, readPoint(child)));
    if (v.size() != corners)
        e.fail(e.tag() + " needs " + std::to_string(corners) + " <vertex> elements, not " + std::to_string(v.size()));
    for (std::size_t i = 2; i < corners; ++i) addLoose(e, Triangle{v[0], v[i - 1], v[i]}, material);
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
                const SceneParameters& parameters) {
    const XmlFile file(std::move(xml), name, parameters);
    return SceneBuilder(file, baseDir).build();
}

}  // namespace

Scene loadSceneXml(const std::string& path, const SceneParameters& parameters) {
    if (path == "-") return loadScene(readStandardInput(), "<stdin>", ".", parameters);
    requireInsideSandbox(path, "the scene", path);
    const std::string folder = std::filesystem::path(path).parent_path().string();
    return loadScene(readInputFile(path), path, folder.empty() ? "." : folder, parameters);
}

Scene loadSceneXmlFromString(const std::string& xml, const std::string& name, const std::string& baseDir,
                             const SceneParameters& parameters) {
    return loadScene(xml, name, baseDir, parameters);
}

}  // namespace rt
