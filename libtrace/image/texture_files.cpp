#include "image/texture_files.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagecache.h>
#include <OpenImageIO/texture.h>

#include <cmath>

namespace rt {

namespace {

OIIO::TextureOpt::Wrap wrapOf(Texture::Wrap w) {
    switch (w) {
        case Texture::Wrap::Clamp:
            return OIIO::TextureOpt::WrapClamp;
        case Texture::Wrap::Mirror:
            return OIIO::TextureOpt::WrapMirror;
        case Texture::Wrap::Repeat:
            break;
    }
    return OIIO::TextureOpt::WrapPeriodic;
}

// The sRGB transfer function, inverted (IEC 61966-2-1).
float srgbToLinear(float v) { return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f); }

}  // namespace

// One texture as the lookups need it; `file` empty for one that cannot be read (or a checker).
struct TextureFiles::Impl {
    struct Entry {
        OIIO::ustring file;
        OIIO::TextureOpt options;
        int channels = 0;
        bool srgb = false;
    };
    OIIO::TextureSystem* system = nullptr;
    std::vector<Entry> entries;
    // Readers of the embedded images and their bytes, alive as long as the system, which may reopen them.
    std::vector<std::unique_ptr<OIIO::Filesystem::IOMemReader>> memoryReaders;
    std::vector<std::shared_ptr<const std::vector<std::uint8_t>>> embeddedBytes;

    Entry open(const Texture& t, std::size_t index, std::vector<std::string>& warnings) {
        Entry e;
        if (t.kind != Texture::Kind::Image) return e;
        const OIIO::ustring file = t.embedded ? addEmbedded(t, index) : OIIO::ustring(t.path);
        const OIIO::ImageSpec* spec = system->imagespec(file);
        if (!spec) {
            warnings.push_back("texture '" + t.name + "': cannot read " + (t.embedded ? "embedded " + t.file : t.path) +
                               " (" + system->geterror() + "): white is used");
            return e;
        }
        e.file = file;
        e.channels = std::min(spec->nchannels, 3);
        e.srgb = !spec->format.is_floating_point();
        e.options.swrap = wrapOf(t.wrapS);
        e.options.twrap = wrapOf(t.wrapT);
        // Bilinear: OpenImageIO's default (smart bicubic) blurs a magnified texture with a B-spline.
        e.options.interpmode = OIIO::TextureOpt::InterpBilinear;
        return e;
    }

    // An embedded image, read from memory through an IOProxy (OpenImageIO's PNG, JPEG, WebP,
    // TIFF and EXR readers take one) under a name no file has; its extension picks the reader.
    OIIO::ustring addEmbedded(const Texture& t, std::size_t index) {
        const OIIO::ustring name("rt-embedded:" + std::to_string(index) + "/" + t.file);
        embeddedBytes.push_back(t.embedded);
        memoryReaders.push_back(
            std::make_unique<OIIO::Filesystem::IOMemReader>(t.embedded->data(), t.embedded->size()));
        OIIO::ImageSpec config;
        void* proxy = memoryReaders.back().get();
        config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
        system->imagecache()->add_file(name, nullptr, &config);
        return name;
    }
};

TextureFiles::TextureFiles(const Scene& scene, std::vector<std::string>& warnings, float cacheMegabytes)
    : impl_(std::make_unique<Impl>()) {
    impl_->system = OIIO::TextureSystem::create(false);
    impl_->system->attribute("max_memory_MB", cacheMegabytes);
    impl_->system->attribute("automip", 1);
    for (std::size_t i = 0; i < scene.textures.size(); ++i)
        impl_->entries.push_back(impl_->open(scene.textures[i], i, warnings));
}

TextureFiles::~TextureFiles() { OIIO::TextureSystem::destroy(impl_->system); }

Color TextureFiles::lookup(std::uint32_t index, float s, float t) const {
    const Impl::Entry& e = impl_->entries[index];
    if (e.file.empty()) return {1, 1, 1};
    float rgb[3] = {1, 1, 1};
    OIIO::TextureOpt options = e.options;  // per call: the system may write to it
    // No ray differentials yet: the finest level, filtered bilinearly.
    if (!impl_->system->texture(e.file, options, s, t, 0, 0, 0, 0, e.channels, rgb)) return {1, 1, 1};
    if (e.channels == 1) rgb[1] = rgb[2] = rgb[0];
    if (e.srgb)
        for (float& c : rgb) c = srgbToLinear(c);
    return {rgb[0], rgb[1], rgb[2]};
}

}  // namespace rt
