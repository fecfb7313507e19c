#include "io/xml_writer.h"

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <fstream>
#include <optional>
#include <pugixml.hpp>
#include <span>
#include <sstream>

#include "io/base64.h"
#include "io/raw_model.h"
#include "os/atomic_file.h"
#include "scene/unique_names.h"

namespace rt {
namespace {

// The shortest text that reads back as the same number (std::to_chars without a format).
template <typename T>
std::string shortest(T value) {
    char buffer[64];
    const auto end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
    return {buffer, end};
}

template <typename T>
void setNumber(pugi::xml_node node, const char* name, T value) {
    node.append_attribute(name).set_value(shortest(value).c_str());
}

void setXyz(pugi::xml_node node, const Vec3& p) {
    setNumber(node, "x", p.x);
    setNumber(node, "y", p.y);
    setNumber(node, "z", p.z);
}

void setRgb(pugi::xml_node node, const Color& c) {
    setNumber(node, "r", c.r);
    setNumber(node, "g", c.g);
    setNumber(node, "b", c.b);
}

std::string numberList(std::initializer_list<float> values) {
    std::string text;
    for (float v : values) {
        if (!text.empty()) text += ' ';
        text += shortest(v);
    }
    return text;
}

void setColor(pugi::xml_node node, const char* name, const Color& c) {
    node.append_attribute(name).set_value(numberList({c.r, c.g, c.b}).c_str());
}

// The transmission attributes (rt extension), written only for materials that let light through.
void setTransmission(pugi::xml_node node, const Transmission& t) {
    if (!t.passesLight()) return;
    setNumber(node, "transmission", t.weight);
    if (t.color != Color{1, 1, 1}) setColor(node, "transmission_color", t.color);
    setNumber(node, "ior", t.ior);
    if (t.thin) node.append_attribute("thin").set_value("true");
    if (!t.absorbs()) return;
    setColor(node, "attenuation_color", t.attenuationColor);
    setNumber(node, "attenuation_distance", t.attenuationDistance);
}

// A loose object as its element, one overload per primitive kind (the loader reads them back).
pugi::xml_node addObject(pugi::xml_node parent, const Triangle& t) {
    pugi::xml_node node = parent.append_child("triangle");
    for (const Vec3& p : {t.p0, t.p1, t.p2}) setXyz(node.append_child("vertex"), p);
    return node;
}

pugi::xml_node addObject(pugi::xml_node parent, const Sphere& s) {
    pugi::xml_node node = parent.append_child("sphere");
    setXyz(node, s.center);
    setNumber(node, "r", s.radius);
    return node;
}

void setEnds(pugi::xml_node node, const Frustum& f) {
    for (const auto& [end, p] : {std::pair{"0", f.base}, std::pair{"1", f.top}}) {
        setNumber(node, (std::string("x") + end).c_str(), p.x);
        setNumber(node, (std::string("y") + end).c_str(), p.y);
        setNumber(node, (std::string("z") + end).c_str(), p.z);
    }
}

pugi::xml_node addObject(pugi::xml_node parent, const Cylinder& c) {
    pugi::xml_node node = parent.append_child("cylinder");
    setEnds(node, c);
    setNumber(node, "r", c.baseRadius);
    return node;
}

pugi::xml_node addObject(pugi::xml_node parent, const Cone& c) {
    pugi::xml_node node = parent.append_child("cone");
    setEnds(node, c);
    setNumber(node, "r0", c.baseRadius);
    setNumber(node, "r1", c.topRadius);
    return node;
}

pugi::xml_node addObject(pugi::xml_node parent, const Disk& d) {
    pugi::xml_node node = parent.append_child("disk");
    setXyz(node, d.center);
    setNumber(node, "nx", d.planeNormal.x);
    setNumber(node, "ny", d.planeNormal.y);
    setNumber(node, "nz", d.planeNormal.z);
    setNumber(node, "r", d.radius);
    return node;
}

// A thesis point light as the thesis wrote it; the rt extension's attributes only where they
// are not the defaults the loader assumes.
void addLight(pugi::xml_node node, const Light& light) {
    if (light.type != Light::Type::Point) node.append_attribute("type").set_value(nameOf(kLightTypeNames, light.type));
    if (light.headlight) node.append_attribute("headlight").set_value("true");
    if (light.type != Light::Type::Directional && !light.headlight) setXyz(node, light.position);
    setRgb(node, light.color);
    if (light.type != Light::Type::Directional) setNumber(node, "size", light.size);
    if (light.type != Light::Type::Point) {
        setNumber(node, "dx", light.direction.x);
        setNumber(node, "dy", light.direction.y);
        setNumber(node, "dz", light.direction.z);
    }
    if (light.falloff != Light::Falloff::None)
        node.append_attribute("falloff").set_value(nameOf(kLightFalloffNames, light.falloff));
    if (light.range > 0) setNumber(node, "range", light.range);
    if (light.type != Light::Type::Spot) return;
    setNumber(node, "inner_cone", light.innerConeDegrees);
    setNumber(node, "outer_cone", light.outerConeDegrees);
}

// Data inside the element, base64 in lines of 76 characters (inline models and images).
void addInlineData(pugi::xml_node node, std::span<const std::uint8_t> bytes) {
    node.append_attribute("encoding").set_value("base64");
    node.append_child(pugi::node_pcdata).set_value(("\n" + encodeBase64(bytes, 76) + "\n").c_str());
}

// An embedded image: the file written beside the scene, or its name and its bytes inline.
void addEmbeddedImage(pugi::xml_node node, const std::vector<std::uint8_t>& bytes, const std::string& file,
                      bool inlineData) {
    node.append_attribute("file").set_value(file.c_str());
    if (inlineData) addInlineData(node, bytes);
}

// Names as written: non-empty and unique (case-insensitively when `caseless`, for file
// names on case-insensitive file systems), so that every reference finds its target.
std::vector<std::string> uniqueNames(std::vector<std::string> names, const std::string& fallback, bool caseless) {
    NameTable table(caseless);
    for (std::string& name : names) name = table.claim(name, fallback);
    return names;
}

// One camera keeps its name or none; several are all named, uniquely, so --camera finds each.
std::vector<std::string> cameraNames(const Scene& scene) {
    std::vector<std::string> names{scene.camera.name};
    if (scene.extraCameras.empty()) return names;
    for (const Camera& c : scene.extraCameras) names.push_back(c.name);
    return uniqueNames(names, "camera", false);
}

class SceneXmlWriter {
public:
    // `folder`: where the XML goes, for texture files relative to it; empty: standard output.
    // `modelFiles`, `imageFiles`: each model's and each embedded image's file as the XML names it,
    // or empty to write its data inline.
    SceneXmlWriter(const Scene& scene, std::vector<std::string> modelFiles, std::vector<std::string> imageFiles,
                   std::string folder);
    void build(pugi::xml_document& doc) const;

private:
    static void addCamera(pugi::xml_node parent, const Camera& c, const std::string& name);
    void addMaterials(pugi::xml_node parent) const;
    void addTextures(pugi::xml_node parent) const;
    std::string textureFile(const Texture& t) const;
    void addModels(pugi::xml_node parent) const;
    void addObjects(pugi::xml_node parent) const;
    void addLights(pugi::xml_node parent) const;
    void setMaterial(pugi::xml_node node, std::uint32_t material) const {
        node.append_attribute("material").set_value(materialNames_.at(material).c_str());
    }
    // The texture's name as attribute `name`, if the material has one there (the reader's useTexture).
    void setTexture(pugi::xml_node node, const char* name, const std::optional<std::uint32_t>& texture) const {
        if (texture) node.append_attribute(name).set_value(textureNames_.at(*texture).c_str());
    }

    const Scene& scene_;
    std::vector<std::string> modelFiles_;  // relative references, or empty for inline data
    std::vector<std::string> imageFiles_;  // the same for the textures' embedded images
    std::vector<std::string> materialNames_;
    std::vector<std::string> modelNames_;
    std::vector<std::string> cameraNames_;  // the camera's, then each extra camera's
    std::vector<std::string> textureNames_;
    std::string folder_;
};

template <typename Named>
std::vector<std::string> namesOf(const std::vector<Named>& items) {
    std::vector<std::string> names;
    for (const Named& item : items) names.push_back(item.name);
    return names;
}

SceneXmlWriter::SceneXmlWriter(const Scene& scene, std::vector<std::string> modelFiles,
                               std::vector<std::string> imageFiles, std::string folder)
    : scene_(scene),
      modelFiles_(std::move(modelFiles)),
      imageFiles_(std::move(imageFiles)),
      materialNames_(uniqueNames(namesOf(scene.materials), "material", false)),
      modelNames_(uniqueNames(namesOf(scene.models), "model", false)),
      cameraNames_(cameraNames(scene)),

      textureNames_(uniqueNames(namesOf(scene.textures), "texture", false)),
      folder_(std::move(folder)) {}

void SceneXmlWriter::build(pugi::xml_document& doc) const {
    pugi::xml_node decl = doc.append_child(pugi::node_declaration);
    decl.append_attribute("version").set_value("1.0");
    pugi::xml_node root = doc.append_child("scene");
    setRgb(root.append_child("background"), scene_.background);
    if (const std::optional<Environment>& sky = scene_.environment) {
        pugi::xml_node node = root.append_child("environment");
        node.append_attribute("texture").set_value(textureNames_.at(sky->texture).c_str());
        if (sky->intensity != 1) setNumber(node, "intensity", sky->intensity);
        if (sky->rotation != 0) setNumber(node, "rotation", sky->rotation);
    }
    addCamera(root, scene_.camera, cameraNames_[0]);
    for (std::size_t i = 0; i < scene_.extraCameras.size(); ++i)
        addCamera(root, scene_.extraCameras[i], cameraNames_[i + 1]);
    if (!scene_.textures.empty()) addTextures(root.append_child("textures"));
    if (!scene_.materials.empty()) addMaterials(root.append_child("materials"));
    if (!scene_.models.empty()) addModels(root.append_child("models"));
    if (scene_.looseObjects.size() > 0 || !scene_.instances.empty()) addObjects(root.append_child("objects"));
    if (!scene_.lights.empty()) addLights(root.append_child("lights"));
}

void SceneXmlWriter::addCamera(pugi::xml_node parent, const Camera& c, const std::string& name) {
    pugi::xml_node camera = parent.append_child("camera");
    if (!name.empty()) camera.append_attribute("name").set_value(name.c_str());
    if (c.fovDegrees) setNumber(camera, "fov", *c.fovDegrees);
    if (c.focalDistance) setNumber(camera, "f", *c.focalDistance);
    setNumber(camera, "zoom", c.zoom);
    setXyz(camera.append_child("origin"), c.origin);
    setXyz(camera.append_child("destination"), c.destination);
    setXyz(camera.append_child("up"), c.up);
}

void SceneXmlWriter::addMaterials(pugi::xml_node parent) const {
    for (std::size_t i = 0; i < scene_.materials.size(); ++i) {
        const Material& m = scene_.materials[i];
        pugi::xml_node node = parent.append_child("material");
        node.append_attribute("name").set_value(materialNames_[i].c_str());
        setRgb(node, m.color);
        setNumber(node, "ambient", m.phong.ambient);
        setNumber(node, "diffuse", m.phong.diffuse);
        setNumber(node, "specular", m.phong.specular);
        setNumber(node, "shininess", m.phong.shininess);
        setNumber(node, "reflection", m.phong.reflection);
        setNumber(node, "spread", m.phong.spread);
        setTexture(node, "texture", m.colorTexture);
        if (m.emission.color != Color{}) setColor(node, "emission", m.emission.color);
        setTexture(node, "emission_texture", m.emission.texture);
        if (const auto& f = m.pbr.factors) {
            setNumber(node, "metallic", f->metallic);
            setNumber(node, "roughness", f->roughness);
            setNumber(node, "specular_factor", f->specular);
        }
        if (m.clearcoat.weight > 0) {
            setNumber(node, "clearcoat", m.clearcoat.weight);
            setNumber(node, "clearcoat_roughness", m.clearcoat.roughness);
        }
        setTexture(node, "metallic_roughness_texture", m.pbr.texture);
        if (m.opacity.cutoff) setNumber(node, "alpha_cutoff", *m.opacity.cutoff);
        if (m.opacity.alpha != 1) setNumber(node, "alpha", m.opacity.alpha);
        setTexture(node, "transmission_texture", m.transmission.texture);
        setTexture(node, "alpha_texture", m.opacity.texture);
        setTexture(node, "normal_texture", m.normalMap.texture);
        if (m.normalMap.scale != 1) setNumber(node, "normal_scale", m.normalMap.scale);
        setTransmission(node, m.transmission);
        if (!m.doubleSided) node.append_attribute("double_sided").set_value("false");
    }
}

void SceneXmlWriter::addTextures(pugi::xml_node parent) const {
    static const char* const kWraps[] = {"repeat", "clamp", "mirror"};
    for (std::size_t i = 0; i < scene_.textures.size(); ++i) {
        const Texture& t = scene_.textures[i];
        pugi::xml_node node = parent.append_child("texture");
        node.append_attribute("name").set_value(textureNames_[i].c_str());
        if (t.kind == Texture::Kind::Checker) {
            node.append_attribute("type").set_value("checker");
            node.append_attribute("color_a").set_value(numberList({t.colorA.r, t.colorA.g, t.colorA.b}).c_str());
            node.append_attribute("color_b").set_value(numberList({t.colorB.r, t.colorB.g, t.colorB.b}).c_str());
            setNumber(node, "size", t.size);
            continue;
        }
        if (t.embedded)
            addEmbeddedImage(node, *t.embedded, imageFiles_[i].empty() ? t.file : imageFiles_[i],
                             imageFiles_[i].empty());
        else
            node.append_attribute("file").set_value(textureFile(t).c_str());
        node.append_attribute("wrap_s").set_value(kWraps[int(t.wrapS)]);
        node.append_attribute("wrap_t").set_value(kWraps[int(t.wrapT)]);
        node.append_attribute("offset").set_value(numberList({t.offset[0], t.offset[1]}).c_str());
        node.append_attribute("scale").set_value(numberList({t.scale[0], t.scale[1]}).c_str());
        setNumber(node, "rotation", t.rotation);
    }
}

// The image's file as the written scene must name it: relative to the XML's folder, or
// absolute for a scene on standard output.
std::string SceneXmlWriter::textureFile(const Texture& t) const {
    const std::filesystem::path image = std::filesystem::absolute(t.path);
    if (folder_.empty()) return image.lexically_normal().generic_string();
    return image.lexically_normal().lexically_relative(std::filesystem::absolute(folder_)).generic_string();
}

void SceneXmlWriter::addModels(pugi::xml_node parent) const {
    for (std::size_t i = 0; i < scene_.models.size(); ++i) {
        pugi::xml_node node = parent.append_child("model");
        node.append_attribute("name").set_value(modelNames_[i].c_str());
        if (!modelFiles_[i].empty()) node.append_attribute("file").set_value(modelFiles_[i].c_str());
        node.append_attribute("type").set_value("raw");
        if (!modelFiles_[i].empty()) continue;
        std::ostringstream raw;
        writeRaw(raw, scene_.models[i]);
        const std::string bytes = raw.str();
        addInlineData(node, {reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()});
    }
}

void SceneXmlWriter::addObjects(pugi::xml_node parent) const {
    const Primitives& loose = scene_.looseObjects;
    for (std::uint32_t id = 0; id < loose.size(); ++id) {
        pugi::xml_node node = loose.visit(id, [&](const auto& p) { return addObject(parent, p); });
        setMaterial(node, loose.material(id));
    }
    for (const Instance& inst : scene_.instances) {
        pugi::xml_node at = parent;
        if (!inst.transform.isIdentity()) {
            std::string m;
            for (int row = 0; row < 3; ++row)
                for (int col = 0; col < 4; ++col) {
                    if (!m.empty()) m += ' ';
                    m += shortest(inst.transform.matrix()[row][col]);
                }
            at = parent.append_child("matrix");
            at.append_attribute("m").set_value(m.c_str());
        }
        pugi::xml_node node = at.append_child("model");
        node.append_attribute("name").set_value(modelNames_.at(inst.model).c_str());
        setMaterial(node, inst.material);
    }
}

void SceneXmlWriter::addLights(pugi::xml_node parent) const {
    for (const Light& light : scene_.lights) addLight(parent.append_child("light"), light);
}

}  // namespace

std::string modelFolderFor(const std::string& xmlPath) {
    const std::filesystem::path p(xmlPath);
    return p.has_extension() ? std::filesystem::path(p).replace_extension().string() : xmlPath + ".models";
}

void saveSceneXml(const Scene& scene, const std::string& path) {
    const std::string xmlFolder =
        path == "-" ? "" : std::filesystem::absolute(path).parent_path().lexically_normal().string();
    const auto saveXml = [&](std::vector<std::string> modelFiles, std::vector<std::string> imageFiles,
                             std::ostream& out) {
        pugi::xml_document doc;
        SceneXmlWriter(scene, std::move(modelFiles), std::move(imageFiles), xmlFolder).build(doc);
        doc.save(out, "  ");
        out.flush();
        return bool(out);
    };
    const bool embedsImages =
        std::any_of(scene.textures.begin(), scene.textures.end(), [](const Texture& t) { return bool(t.embedded); });
    if (path == "-" || (scene.models.empty() && !embedsImages)) {
        writeFileAtomically(path, [&](std::ostream& out) {
            saveXml(std::vector<std::string>(scene.models.size()), std::vector<std::string>(scene.textures.size()),
                    out);
        });
        return;
    }
    // The RAW files and the embedded images go to a new folder and the XML to a temporary file;
    // only when all are written are they published together, so a failure leaves the previous
    // scene as it was, a successful save leaves no stale file, and concurrent saves take turns.
    const std::filesystem::path folder = modelFolderFor(path);
    NameTable table(true);  // file names: unique ignoring case
    std::vector<std::string> files, modelFiles, imageFiles(scene.textures.size());
    for (const Model& m : scene.models) files.push_back(table.claim(safeName(m.name), "model") + ".raw");
    for (std::size_t i = 0; i < scene.textures.size(); ++i) {
        if (!scene.textures[i].embedded) continue;
        const std::filesystem::path file(scene.textures[i].file);
        const std::string extension = file.extension().string();  // ".png": safeName would turn the dot
        imageFiles[i] = table.claim(safeName(file.stem().string()), "image") +
                        (extension.empty() ? "" : "." + safeName(extension.substr(1)));
    }
    const auto reference = [&](const std::string& file) { return (folder.filename() / file).generic_string(); };
    for (const std::string& file : files) modelFiles.push_back(reference(file));
    const auto write = [&](const std::string& tempXml, const std::string& tempFolder) {
        const std::filesystem::path to(tempFolder);
        for (std::size_t i = 0; i < scene.models.size(); ++i) writeRawFile((to / files[i]).string(), scene.models[i]);
        std::vector<std::string> images(scene.textures.size());
        for (std::size_t i = 0; i < scene.textures.size(); ++i) {
            if (imageFiles[i].empty()) continue;
            const std::vector<std::uint8_t>& bytes = *scene.textures[i].embedded;
            writeFileAtomically((to / imageFiles[i]).string(), [&](std::ostream& out) {
                out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
            });
            images[i] = reference(imageFiles[i]);
        }
        std::ofstream out(tempXml, std::ios::binary | std::ios::trunc);
        return out && saveXml(modelFiles, images, out);
    };
    commitFileAndFolderAtomically(path, folder.string(), write);
}

}  // namespace rt
