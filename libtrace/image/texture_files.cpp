#include "image/texture_files.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>

#include "core/error.h"
#include "core/parallel_errors.h"
#include "image/image_header.h"
#include "os/stderr_capture.h"

namespace rt {

namespace {

// The picture `t` names, as messages name it.
std::string sourceName(const Texture& t) { return t.embedded ? "embedded " + t.file : t.path; }

// The image `t` names, checked (image/image_header.h): a refused one is an input error.
ImageHeaderCheck checkedHeader(const Texture& t) {
    ImageHeaderCheck check = t.embedded ? checkImageHeader(*t.embedded, t.file) : checkImageHeader(t.path);
    if (check.refusal) throw InputError("texture '" + t.name + "': " + sourceName(t) + " " + *check.refusal);
    return check;
}

// What tells two pictures apart: the file, or the embedded bytes (shared by the textures of one
// glTF image).
std::string pictureKey(const Texture& t) {
    return t.embedded ? "embedded:" + std::to_string(reinterpret_cast<std::uintptr_t>(t.embedded.get()))
                      : "file:" + t.path;
}

// The distinct pictures of the scene's image textures, in the order textures first name them,
// and for each texture the index of its picture (-1: not an image).
struct Pictures {
    std::vector<const Texture*> first;  // the first texture naming each picture
    std::vector<int> ofTexture;
};

Pictures distinctPictures(const Scene& scene) {
    Pictures p;
    std::map<std::string, int> seen;
    for (const Texture& t : scene.textures) {
        if (t.kind != Texture::Kind::Image) {
            p.ofTexture.push_back(-1);
            continue;
        }
        const auto [at, added] = seen.emplace(pictureKey(t), int(p.first.size()));
        if (added) p.first.push_back(&t);
        p.ofTexture.push_back(at->second);
    }
    return p;
}

// The bytes a channel of a picture takes as a MIP map stores it (image/mip_map.h): 8- and 16-bit
// integers and half floats as they are, the rest as float.
std::uint64_t storedChannelBytes(const ImageHeader& h) { return h.channelBytes <= 2 ? h.channelBytes : 4; }

// The bytes the MIP map of a picture with header `h` takes (at most 4 channels are kept).
std::uint64_t mipMapBytesOf(const ImageHeader& h) {
    return mipMapBytes(h.width, h.height, std::uint64_t(std::min(h.channels, 4)) * storedChannelBytes(h));
}

// The most anisotropy a lookup's filter takes: up to this many trilinear probes along the
// footprint. A camera ray's 8 (about a GPU's 16x) and a ray cone's 3 after a bounce come close to
// a supersampled render of a checker floor seen towards the horizon, directly and in a mirror
// (TextureFiles.RayDifferentialsFilterADistantCheckerFloor, ACheckerSeenInAMirrorIsFilteredToo).
constexpr int kCameraProbes = 8;
constexpr int kConeProbes = 3;

// A picture as read: its MIP map and how its channels are used, or why it cannot be read.
struct Picture {
    std::optional<MipMap> map;
    int colourChannels = 0;  // 1 (grey, its value in all three) or 3
    int alphaChannel = -1;   // none
    bool encoded16 = false;  // 16-bit integers: sRGB-encoded fractions, decoded after filtering
    std::string unreadable;  // why it cannot be read
};

// Level 0 of `in`'s picture, its first `channels` channels read as `type` into T.
template <class T>
std::optional<MipMap> readMipMap(OIIO::ImageInput& in, int channels, OIIO::TypeDesc type, std::string& why) {
    const OIIO::ImageSpec& spec = in.spec();
    std::vector<T> texels(std::size_t(spec.width) * std::size_t(spec.height) * std::size_t(channels));
    if (!in.read_image(0, 0, 0, channels, type, texels.data())) {
        why = in.geterror();
        return std::nullopt;
    }
    return MipMap(spec.width, spec.height, channels, std::move(texels));
}

// Decodes the picture `t` names with OpenImageIO (its header checked already), into a MIP map in
// the type that holds its values: 8 bits, half or float.
Picture readPicture(const Texture& t) {
    std::optional<OIIO::Filesystem::IOMemReader> memory;
    if (t.embedded) memory.emplace(t.embedded->data(), t.embedded->size());
    const std::unique_ptr<OIIO::ImageInput> in =
        OIIO::ImageInput::open(t.embedded ? t.file : t.path, nullptr, memory ? &*memory : nullptr);
    Picture p;
    if (!in) {
        p.unreadable = OIIO::geterror();
        return p;
    }
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.depth != 1) {
        p.unreadable = "a volume of " + std::to_string(spec.depth) + " slices, not a picture";
        return p;
    }
    const int channels = std::min(spec.nchannels, 4);
    p.colourChannels = channels >= 3 ? 3 : 1;
    p.alphaChannel = spec.alpha_channel >= 0 ? spec.alpha_channel : spec.nchannels == 2 ? 1 : -1;
    if (p.alphaChannel >= channels) p.alphaChannel = -1;
    const OIIO::TypeDesc::BASETYPE type = OIIO::TypeDesc::BASETYPE(spec.format.basetype);
    if (type == OIIO::TypeDesc::UINT8 || type == OIIO::TypeDesc::INT8)
        p.map = readMipMap<std::uint8_t>(*in, channels, OIIO::TypeDesc::UINT8, p.unreadable);
    else if (type == OIIO::TypeDesc::UINT16 || type == OIIO::TypeDesc::INT16)
        p.map = readMipMap<std::uint16_t>(*in, channels, OIIO::TypeDesc::UINT16, p.unreadable);
    else if (type == OIIO::TypeDesc::HALF)
        p.map = readMipMap<half>(*in, channels, OIIO::TypeDesc::HALF, p.unreadable);
    else
        p.map = readMipMap<float>(*in, channels, OIIO::TypeDesc::FLOAT, p.unreadable);
    p.encoded16 = p.map && !spec.format.is_floating_point() && !p.map->storesBytes();
    return p;
}

// The pictures `first` names, read several at a time; each is read whole and alone, so the MIP
// maps are the same for any number of threads. One picture alone builds its levels on every
// thread instead (image/mip_map.cpp: OpenMP runs a parallel loop inside another on one thread).
std::vector<Picture> readPictures(const std::vector<const Texture*>& first) {
    std::vector<Picture> pictures(first.size());
    ParallelErrors errors;
#pragma omp parallel for schedule(dynamic, 1) if (first.size() > 1)
    for (std::size_t i = 0; i < first.size(); ++i) errors.capture([&] { pictures[i] = readPicture(*first[i]); });
    errors.rethrowIfAny();
    return pictures;
}

std::string megabytes(std::uint64_t bytes) { return std::to_string((bytes + 999'999) / 1'000'000) + " MB"; }

}  // namespace

// One texture as the lookups need it; `map` null for one that cannot be read (or a checker).
struct TextureFiles::Impl {
    struct Entry {
        const MipMap* map = nullptr;
        MipLookup colour, data;  // lookup() and data(): channels, wrap modes, filter, 8-bit decoding
        int alphaChannel = -1;   // none
        bool encoded16 = false;  // Picture::encoded16
    };
    std::vector<Picture> pictures;
    std::vector<Entry> entries;

    // The first three channels at `at` as `how` reads them (a grey image's one in all three),
    // filtered over the footprint its derivatives give.
    static Color sample(const Entry& e, MipLookup how, const TexCoord& at) {
        how.maxProbes = at.isotropic ? kConeProbes : kCameraProbes;
        float v[3];
        e.map->lookup(at, how, v);
        if (how.channels == 1) return {v[0], v[0], v[0]};
        return {v[0], v[1], v[2]};
    }

    // The channel alpha() reads (a mask without alpha: its first), or -1 for none.
    static int alphaChannel(const Entry& e, bool mask) {
        if (!e.map) return -1;
        return e.alphaChannel >= 0 ? e.alphaChannel : mask ? 0 : -1;
    }

    Entry entry(const Texture& t, const Picture& p, TextureFilter filter) const {
        Entry e;
        if (!p.map) return e;
        e.map = &*p.map;
        e.alphaChannel = p.alphaChannel;
        e.encoded16 = p.encoded16;
        e.data = {.filter = filter, .wrapS = t.wrapS, .wrapT = t.wrapT, .channels = p.colourChannels};
        e.data.decoding.table = linearByteTable();
        e.colour = e.data;
        e.colour.decoding.table = srgbByteTable();
        return e;
    }
};

std::uint64_t estimateTextureMemory(const Scene& scene) {
    const Pictures pictures = distinctPictures(scene);
    std::uint64_t maps = 0;
    std::vector<std::uint64_t> decoded;
    std::vector<std::string> unreadable;  // told again in TextureFiles' warnings
    StderrCapture libraries;
    for (const Texture* t : pictures.first) {
        const ImageHeaderCheck check = checkedHeader(*t);
        if (check.unreadable) {  // white
            unreadable.push_back(*check.unreadable);
            continue;
        }
        maps += mipMapBytesOf(check.header);
        decoded.push_back(check.header.decodedBytes);
    }
    writeToStderr(withoutToldLibpngErrors(libraries.take(), unreadable));
    // A reader may hold its picture whole while it is read (OpenImageIO's PNG reader does), one per thread.
    std::sort(decoded.rbegin(), decoded.rend());
    decoded.resize(std::min(decoded.size(), std::size_t(std::max(1, omp_get_max_threads()))));
    std::uint64_t reading = 0;
    for (std::uint64_t d : decoded) reading += d;
    return maps + reading;
}

TextureFiles::TextureFiles(const Scene& scene, std::vector<std::string>& warnings, const TextureSettings& settings)
    : ImageTextures(scene), impl_(std::make_unique<Impl>()) {
    const Pictures pictures = distinctPictures(scene);
    std::string printed;  // what the libraries print themselves (libpng's error lines), told in the warnings below
    std::vector<std::optional<std::string>> unreadable;  // by the header check
    std::uint64_t bytes = 0;
    {
        StderrCapture libraries;
        for (const Texture* t : pictures.first) {
            const ImageHeaderCheck check = checkedHeader(*t);
            unreadable.push_back(check.unreadable);
            if (!check.unreadable) bytes += mipMapBytesOf(check.header);
        }
        printed = libraries.take();
    }
    // On standard error itself, before the reading it announces (not held with the captured text).
    if (settings.announce && !pictures.first.empty())
        settings.announce("reading " + std::to_string(pictures.first.size()) + " texture picture" +
                          (pictures.first.size() == 1 ? "" : "s") + " (" + megabytes(bytes) + " with MIP levels)");
    std::vector<const Texture*> toRead;
    for (std::size_t i = 0; i < pictures.first.size(); ++i)
        if (!unreadable[i]) toRead.push_back(pictures.first[i]);
    std::vector<Picture> read;
    {
        StderrCapture libraries;
        read = readPictures(toRead);
        printed += libraries.take();
    }
    // The unreadable ones say why, as their header check did; a picture several textures use (an
    // OBJ's map in several materials) is one warning, named as the first texture names it.
    impl_->pictures.resize(pictures.first.size());
    std::set<std::string> named;
    std::vector<std::string> told;
    for (std::size_t i = 0, next = 0; i < pictures.first.size(); ++i) {
        const Texture& t = *pictures.first[i];
        Picture& p = impl_->pictures[i];
        if (unreadable[i])
            p.unreadable = *unreadable[i];
        else
            p = std::move(read[next++]);
        if (!p.map && named.insert(sourceName(t)).second)
            warnings.push_back("texture file " + sourceName(t) + ": cannot read it (" + p.unreadable +
                               "): white is used");
        if (!p.map) told.push_back(p.unreadable);
    }
    writeToStderr(withoutToldLibpngErrors(printed, told));
    for (std::size_t i = 0; i < scene.textures.size(); ++i) {
        const int picture = pictures.ofTexture[i];
        impl_->entries.push_back(
            picture < 0 ? Impl::Entry{}
                        : impl_->entry(scene.textures[i], impl_->pictures[std::size_t(picture)], settings.filter));
    }
}

TextureFiles::~TextureFiles() = default;

const MipMap* TextureFiles::mipMap(std::uint32_t index) const { return impl_->entries[index].map; }

Color TextureFiles::lookup(std::uint32_t index, const TexCoord& at) const {
    const Impl::Entry& e = impl_->entries[index];
    if (!e.map) return {1, 1, 1};
    const Color c = Impl::sample(e, e.colour, at);
    if (!e.encoded16) return c;
    return {srgbToLinear(c.r), srgbToLinear(c.g), srgbToLinear(c.b)};
}

Color TextureFiles::data(std::uint32_t index, const TexCoord& at) const {
    const Impl::Entry& e = impl_->entries[index];
    if (!e.map) return {0.5f, 0.5f, 1};
    return Impl::sample(e, e.data, at);
}

bool TextureFiles::hasAlpha(std::uint32_t index, bool mask) const {
    const Impl::Entry& e = impl_->entries[index];
    const int channel = Impl::alphaChannel(e, mask);
    return channel >= 0 && !e.map->allOne(channel);
}

float TextureFiles::alpha(std::uint32_t index, float s, float t, bool mask) const {
    const Impl::Entry& e = impl_->entries[index];
    const int channel = Impl::alphaChannel(e, mask);
    if (channel < 0) return 1;
    // Read during traversal, where rays carry no differentials: the finest level, bilinear.
    MipLookup how = e.data;
    how.firstChannel = channel;
    how.channels = 1;
    return e.map->bilinear(s, t, how);
}

}  // namespace rt
