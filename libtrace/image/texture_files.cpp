#include "image/texture_files.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagecache.h>
#include <OpenImageIO/texture.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <mutex>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>

#include "core/error.h"
#include "image/image_header.h"
#include "image/tiled_textures.h"

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

// The picture `t` names, as messages name it.
std::string sourceName(const Texture& t) { return t.embedded ? "embedded " + t.file : t.path; }

// The image `t` names, checked (image/image_header.h): a refused one is an input error.
ImageHeaderCheck checkedHeader(const Texture& t) {
    ImageHeaderCheck check = t.embedded ? checkImageHeader(*t.embedded, t.file) : checkImageHeader(t.path);
    if (check.refusal) throw InputError("texture '" + t.name + "': " + sourceName(t) + " " + *check.refusal);
    return check;
}

// Measured peaks above an untextured render, per byte of the picture decoded (docs/robustness.md,
// "Limits"), rounded up: making a tiled copy reads the picture whole and builds its MIP levels
// (an 18000 x 18000 RGB PNG, 0.97 GB decoded: 5.8 GB); read as it is, OpenImageIO holds the
// picture and its levels (2.6 GB).
constexpr double kCopyBytesPerDecodedByte = 6;
constexpr double kHeldBytesPerDecodedByte = 3;

// Texture systems outlive the TextureFiles that use them. OpenImageIO 2.4 keeps a texture
// system's private image cache when the system is destroyed (LeakSanitizer reports it after every
// render), and destroying the cache too is worse: a cache later made at the same address found the
// old one's tiles through the render threads' per-thread data (a rewritten file read stale, in
// NormalMap.APlaneShadesAsThePerturbedNormalPredicts). So systems are kept for the process and
// reused, one per TextureFiles alive at a time, emptied before each reuse.
class TextureSystemPool {
public:
    static OIIO::TextureSystem* take() {
        TextureSystemPool& pool = instance();
        const std::lock_guard lock(pool.mutex_);
        if (pool.idle_.empty()) return OIIO::TextureSystem::create(false);
        OIIO::TextureSystem* system = pool.idle_.back();
        pool.idle_.pop_back();
        return system;
    }
    static void give(OIIO::TextureSystem* system) {
        system->invalidate_all(/*force=*/true);
        TextureSystemPool& pool = instance();
        const std::lock_guard lock(pool.mutex_);
        pool.idle_.push_back(system);
    }

private:
    static TextureSystemPool& instance() {
        static TextureSystemPool* pool = new TextureSystemPool;  // never freed: the systems stay reachable
        return *pool;
    }
    std::mutex mutex_;
    std::vector<OIIO::TextureSystem*> idle_;
};

struct SystemReturn {
    void operator()(OIIO::TextureSystem* system) const { TextureSystemPool::give(system); }
};

// The most anisotropy a lookup's filter takes (TextureOpt::anisotropic; OpenImageIO probes up to
// twice as many points along the footprint, on each of two MIP levels). OpenImageIO's default, 32,
// took up to 63 probes a level; a camera ray's 8 (15 probes, about a GPU's 16x) and a ray cone's 3
// after a bounce come closer to a supersampled render of a checker floor seen towards the horizon,
// directly and in a mirror (TextureFiles.RayDifferentialsFilterADistantCheckerFloor,
// ACheckerSeenInAMirrorIsFilteredToo; docs/benchmarks.md), for fewer probes: OpenImageIO clamps
// the footprint's aspect by widening its minor axis, so its finer levels' aliasing is blurred away.
constexpr int kCameraProbes = 8;
constexpr int kConeProbes = 3;

// The sRGB transfer function, inverted (IEC 61966-2-1).
float srgbToLinear(float v) { return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f); }

}  // namespace

// One texture as the lookups need it; `file` empty for one that cannot be read (or a checker).
struct TextureFiles::Impl {
    struct Entry {
        OIIO::ustring file;
        OIIO::TextureSystem::TextureHandle* handle = nullptr;  // the file, found once rather than per lookup
        OIIO::TextureOpt options;
        int channels = 0;
        int alphaChannel = -1;  // none
        bool srgb = false;
        // Every channel of a picture of one colour (constantTexels): its lookups return it without
        // asking OpenImageIO, which filters the same texels to the same value at some thousand
        // instructions a lookup. Empty for any other picture.
        std::vector<float> constant;
    };
    std::string txCache;  // tiled_textures.h; "off" once a copy could not be made
    std::uint64_t txCacheBytes = 0;
    std::function<void(const std::string&)> announce;  // TextureCacheSettings::announce
    std::vector<TiledCopy> copies;                     // in use: no other render removes them while this one runs
    std::vector<Entry> entries;
    // Readers of the embedded images and their bytes, alive as long as the system, which may reopen them.
    std::vector<std::unique_ptr<OIIO::Filesystem::IOMemReader>> memoryReaders;
    std::vector<std::shared_ptr<const std::vector<std::uint8_t>>> embeddedBytes;
    // Given back to the pool however the TextureFiles ends, a constructor that throws included; declared
    // after what it reads so that it is emptied before they go.
    std::unique_ptr<OIIO::TextureSystem, SystemReturn> system{TextureSystemPool::take()};

    // The first three channels at `at` as stored (a grey image's one in all three), filtered
    // over the footprint its derivatives give (mip-mapped, anisotropic up to kCameraProbes; a ray
    // cone's footprint up to kConeProbes, render/ray_differential.h); `c` is left as it is when
    // the image cannot be read.
    bool sample(const Entry& e, const TexCoord& at, Color& c) const {
        if (e.file.empty()) return false;
        float rgb[3] = {c.r, c.g, c.b};
        if (!e.constant.empty())
            std::copy_n(e.constant.begin(), e.channels, rgb);
        else if (!filter(e, at, rgb))
            return false;
        if (e.channels == 1) rgb[1] = rgb[2] = rgb[0];
        c = {rgb[0], rgb[1], rgb[2]};
        return true;
    }

    // What a render thread keeps for this TextureFiles: OpenImageIO's per-thread info, found once
    // rather than by a thread-specific lookup in every texture() call, and the last alpha() asked
    // for. Keyed by `instanceSerial`, not the system's address: the pool reuses systems, and a thread's info
    // is found anew (its stale tiles dropped) for every TextureFiles.
    struct PerThread {
        std::uint64_t owner = 0;
        OIIO::TextureSystem::Perthread* info = nullptr;
        std::uint32_t index = 0;  // the last alpha(): texture, channel, coordinates and value
        int channel = -1;
        float s = 0, t = 0, alpha = 1;
    };
    std::uint64_t instanceSerial = 0;  // unique in the process

    PerThread& perThread() const {
        thread_local PerThread mine;
        if (mine.owner != instanceSerial) mine = {.owner = instanceSerial, .info = system->get_perthread_info()};
        return mine;
    }

    // OpenImageIO's lookup of e's first `e.channels` channels into `rgb`.
    bool filter(const Entry& e, const TexCoord& at, float* rgb) const {
        OIIO::TextureOpt options = e.options;  // per call: the system may write to it
        options.anisotropic = at.isotropic ? kConeProbes : kCameraProbes;
        return system->texture(e.handle, perThread().info, options, at.s, at.t, at.dsdx, at.dtdx, at.dsdy, at.dtdy,
                               e.channels, rgb);
    }

    // The channel alpha() reads (a mask without alpha: its first), or -1 for none.
    static int alphaChannel(const Entry& e, bool mask) {
        if (e.file.empty()) return -1;
        return e.alphaChannel >= 0 ? e.alphaChannel : mask ? 0 : -1;
    }

    Entry open(const Texture& t, std::size_t index, std::vector<std::string>& warnings) {
        Entry e;
        if (t.kind != Texture::Kind::Image) return e;
        const ImageHeaderCheck check = checkedHeader(t);
        if (check.unreadable) {
            warnUnreadable(t, *check.unreadable, warnings);
            return e;
        }
        const OIIO::ustring file = t.embedded ? addEmbedded(t, index) : OIIO::ustring(t.path);
        const OIIO::ImageSpec* spec = system->imagespec(file);
        if (!spec) {
            warnUnreadable(t, system->geterror(), warnings);
            return e;
        }
        e.file = tiled(t, file, check.header, warnings);
        e.handle = system->get_texture_handle(e.file);
        spec = system->imagespec(e.file);  // tiled() has read it
        e.channels = std::min(spec->nchannels, 3);
        e.alphaChannel = spec->alpha_channel >= 0 ? spec->alpha_channel : spec->nchannels == 2 ? 1 : -1;
        e.srgb = !spec->format.is_floating_point();
        e.constant = constantTexels(e.handle, *spec);
        e.options.swrap = wrapOf(t.wrapS);
        e.options.twrap = wrapOf(t.wrapT);
        // Bilinear: OpenImageIO's default (smart bicubic) blurs a magnified texture with a B-spline.
        e.options.interpmode = OIIO::TextureOpt::InterpBilinear;
        return e;
    }

    // Files already named in a warning: a picture that several textures use (an OBJ's map in
    // several materials) is one line, not one per use.
    std::set<std::string> unreadable;

    // "texture file F: cannot read it (why): white is used", once per file (the tools fold a
    // `why` of several lines, as OpenImageIO's are, into one).
    void warnUnreadable(const Texture& t, const std::string& why, std::vector<std::string>& warnings) {
        const std::string file = sourceName(t);
        if (unreadable.insert(file).second)
            warnings.push_back("texture file " + file + ": cannot read it (" + why + "): white is used");
    }

    // Every channel of the picture `handle` (stored as `spec`) if it is of one colour, as a texel
    // reads (OpenImageIO's filter of equal texels gave it within rounding in the last bit): told by
    // the mark its tiled copy carries (oiio:ConstantColor, by make_texture's constant_color_detect),
    // whose own values are rounded to six digits. Empty for any other picture.
    std::vector<float> constantTexels(OIIO::TextureSystem::TextureHandle* handle, const OIIO::ImageSpec& spec) {
        std::vector<float> texel(spec.nchannels);
        OIIO::TextureOpt options;
        if (!system->get_texture_info(handle, nullptr, 0, OIIO::ustring("constantcolor"),
                                      OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, spec.nchannels), texel.data()) ||
            !system->get_texels(handle, nullptr, options, 0, spec.x, spec.x + 1, spec.y, spec.y + 1, spec.z, spec.z + 1,
                                0, spec.nchannels, OIIO::TypeFloat, texel.data()))
            return {};
        return texel;
    }

    // The file the lookups read for `file`, the source of `t` whose header is `header`: a tiled,
    // MIP-mapped copy from the tx cache, or `file` itself when it is tiled and MIP-mapped already
    // or the cache is off. A copy that cannot be made is one warning, and the cache is off for the
    // rest of the textures.
    OIIO::ustring tiled(const Texture& t, OIIO::ustring file, const ImageHeader& header,
                        std::vector<std::string>& warnings) {
        if (txCacheOff(txCache) || header.tiledMipMapped) return file;
        try {
            const auto making = [&] {
                if (announce)
                    announce("making a tiled, MIP-mapped copy of " + sourceName(t) + " (" +
                             std::to_string(header.width) + " x " + std::to_string(header.height) + ") in " + txCache +
                             ", once for every later render");
            };
            TiledCopy copy = tiledCopy(txCache, {t.path, t.embedded, t.file}, txCacheBytes, making);
            const OIIO::ustring path(copy.path());
            if (!system->imagespec(path))
                throw std::runtime_error("cannot read " + path.string() + ": " + system->geterror());
            copies.push_back(std::move(copy));
            return path;
        } catch (const std::exception& e) {
            warnings.push_back("texture '" + t.name + "': no tiled copy (" + e.what() +
                               "): textures are read as they are, slower and beyond --texture-cache");
            txCache = "off";
            return file;
        }
    }

    // An embedded image, read from memory through an IOProxy (OpenImageIO's PNG, JPEG, WebP,
    // TIFF and EXR readers take one) under a name no file has; its extension picks the reader.
    OIIO::ustring addEmbedded(const Texture& t, std::size_t index) {
        // Numbered for the process: a reused system still knows the names of earlier readers.
        static std::atomic<std::uint64_t> serial{0};
        const OIIO::ustring name("rt-embedded:" + std::to_string(serial++) + ":" + std::to_string(index) + "/" +
                                 t.file);
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

std::uint64_t estimateTextureMemory(const Scene& scene, const TextureCacheSettings& cache) {
    double held = 0, largestCopy = 0;
    bool anyImage = false;
    for (const Texture& t : scene.textures) {
        if (t.kind != Texture::Kind::Image) continue;
        anyImage = true;
        const ImageHeaderCheck check = checkedHeader(t);
        if (check.unreadable || check.header.tiledMipMapped) continue;  // white, or read a tile at a time
        const double decoded = double(check.header.decodedBytes);
        if (txCacheOff(cache.txCache))
            held += decoded * kHeldBytesPerDecodedByte;
        else
            largestCopy = std::max(largestCopy, decoded * kCopyBytesPerDecodedByte);
    }
    const double cacheBytes = anyImage ? double(cache.megabytes) * 1024 * 1024 : 0;
    return std::uint64_t(cacheBytes + held + largestCopy);
}

bool TextureFiles::hasAlpha(std::uint32_t index, bool mask) const {
    const Impl::Entry& e = impl_->entries[index];
    const int channel = impl_->alphaChannel(e, mask);
    return channel >= 0 && (e.constant.empty() || e.constant[channel] != 1);
}

TextureFiles::TextureFiles(const Scene& scene, std::vector<std::string>& warnings, const TextureCacheSettings& cache)
    : ImageTextures(scene), impl_(std::make_unique<Impl>()) {
    static std::atomic<std::uint64_t> serials{0};
    impl_->instanceSerial = ++serials;
    impl_->system->attribute("max_memory_MB", cache.megabytes);
    impl_->txCache = cache.txCache;
    impl_->txCacheBytes = std::uint64_t(cache.txCacheMegabytes * 1024 * 1024);
    impl_->announce = cache.announce;
    impl_->system->attribute("automip", 1);
    for (std::size_t i = 0; i < scene.textures.size(); ++i)
        impl_->entries.push_back(impl_->open(scene.textures[i], i, warnings));
}

TextureFiles::~TextureFiles() = default;

Color TextureFiles::lookup(std::uint32_t index, const TexCoord& at) const {
    const Impl::Entry& e = impl_->entries[index];
    Color c{1, 1, 1};
    if (!impl_->sample(e, at, c) || !e.srgb) return c;
    return {srgbToLinear(c.r), srgbToLinear(c.g), srgbToLinear(c.b)};
}

Color TextureFiles::data(std::uint32_t index, const TexCoord& at) const {
    Color c{0.5f, 0.5f, 1};
    impl_->sample(impl_->entries[index], at, c);
    return c;
}

float TextureFiles::alpha(std::uint32_t index, float s, float t, bool mask) const {
    const Impl::Entry& e = impl_->entries[index];
    const int channel = impl_->alphaChannel(e, mask);
    if (channel < 0) return 1;
    if (!e.constant.empty()) return e.constant[channel];
    // A ray's traversal often asks again for the hit it just tested (a triangle in two leaves of
    // the tree): the same arguments, the same value.
    Impl::PerThread& mine = impl_->perThread();
    if (mine.channel == channel && mine.index == index && mine.s == s && mine.t == t) return mine.alpha;
    float a = 1;
    OIIO::TextureOpt options = e.options;
    options.firstchannel = channel;
    // Read during traversal, where rays carry no differentials: the finest level, one bilinear
    // probe, which OpenImageIO's no-MIP mode reaches without the footprint's set-up.
    options.mipmode = OIIO::TextureOpt::MipModeNoMIP;
    if (!impl_->system->texture(e.handle, mine.info, options, s, t, 0, 0, 0, 0, 1, &a)) a = 1;
    mine.index = index;
    mine.channel = channel;
    mine.s = s;
    mine.t = t;
    mine.alpha = a;
    return a;
}

}  // namespace rt
